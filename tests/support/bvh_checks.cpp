#include "support/bvh_checks.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "geometry/sphere.h"
#include "geometry/triangle.h"

namespace pt::test::part2 {

// --- Flattening ---------------------------------------------------------------

int FlatTree::max_depth() const {
  int d = 0;
  for (const auto& n : nodes) d = std::max(d, n.depth);
  return d;
}

size_t FlatTree::leaf_count() const {
  size_t c = 0;
  for (const auto& n : nodes) c += n.leaf();
  return c;
}

FlatTree flatten(const BVHAccel& bvh) {
  FlatTree t;
  t.prims.assign(bvh.primitives().begin(), bvh.primitives().end());
  if (!bvh.root()) return t;
  struct Item {
    const BVHNode* node;
    int index;
  };
  t.nodes.push_back({});
  std::vector<Item> stack{{bvh.root(), 0}};
  while (!stack.empty()) {
    Item it = stack.back();
    stack.pop_back();
    const BVHNode* n = it.node;
    FlatNode& f = t.nodes[size_t(it.index)];
    f.bb = n->bb;
    f.start = n->start;
    f.end = n->end;
    const BVHNode* kids[2] = {n->l.get(), n->r.get()};
    for (int k = 0; k < 2; ++k) {
      if (!kids[k]) continue;
      int ci = int(t.nodes.size());
      FlatNode c;
      c.parent = it.index;
      c.depth = t.nodes[size_t(it.index)].depth + 1;
      t.nodes.push_back(c);  // may reallocate: refer to nodes by index only
      (k == 0 ? t.nodes[size_t(it.index)].left : t.nodes[size_t(it.index)].right) = ci;
      stack.push_back({kids[k], ci});
    }
  }
  return t;
}

// --- Tight boxes and cost -------------------------------------------------------

namespace {

BBox range_box(const FlatTree& t, size_t start, size_t end) {
  BBox b;
  end = std::min(end, t.prims.size());
  for (size_t i = start; i < end; ++i) b.expand(t.prims[i]->get_bbox());
  return b;
}

bool children_tile(const FlatTree& t, const FlatNode& n) {
  if (n.left < 0 || n.right < 0) return false;
  const FlatNode* a = &t.nodes[size_t(n.left)];
  const FlatNode* b = &t.nodes[size_t(n.right)];
  if (b->start < a->start) std::swap(a, b);
  return a->start == n.start && a->end == b->start && b->end == n.end && a->start < a->end && b->start < b->end &&
         n.end <= t.prims.size();
}

}  // namespace

std::vector<BBox> tight_boxes(const FlatTree& t) {
  std::vector<BBox> tight(t.nodes.size());
  // Children always come after their parent in `nodes`: a reverse sweep is bottom-up.
  for (size_t i = t.nodes.size(); i-- > 0;) {
    const FlatNode& n = t.nodes[i];
    if (!n.leaf() && children_tile(t, n)) {
      tight[i] = tight[size_t(n.left)];
      tight[i].expand(tight[size_t(n.right)]);
    } else {
      tight[i] = range_box(t, n.start, n.end);
    }
  }
  return tight;
}

double sah_cost(const FlatTree& t) {
  if (t.nodes.empty()) return 0.0;
  std::vector<BBox> tight = tight_boxes(t);
  const double root_area = tight[0].surface_area();
  double cost = 0.0;
  for (size_t i = 0; i < t.nodes.size(); ++i) {
    double ratio = root_area > 0.0 ? tight[i].surface_area() / root_area : 1.0;
    const FlatNode& n = t.nodes[i];
    cost += n.leaf() ? ratio * double(n.size()) * kCostIntersect : ratio * kCostTraversal;
  }
  return cost;
}

// --- Structure ------------------------------------------------------------------

std::string StructureReport::summary() const {
  std::ostringstream os;
  os << nodes << " nodes, " << leaves << " leaves, depth " << max_depth << ", largest leaf " << largest_leaf;
  if (violation_count) {
    os << "; " << violation_count << " violation(s)";
    for (const auto& v : violations) os << "\n  - " << v;
    if (violation_count > violations.size()) os << "\n  - ...";
  }
  return os.str();
}

StructureReport check_structure(const FlatTree& t, const std::vector<const Primitive*>& input, size_t max_leaf_size) {
  StructureReport rep;
  auto violate = [&](const std::string& s) {
    if (rep.violations.size() < 8) rep.violations.push_back(s);
    ++rep.violation_count;
  };
  auto where = [&](size_t i) {
    const FlatNode& n = t.nodes[i];
    std::ostringstream os;
    os << (n.leaf() ? "leaf" : "node") << " #" << i << " (depth " << n.depth << ", primitives [" << n.start << ", "
       << n.end << "))";
    return os.str();
  };
  rep.nodes = t.nodes.size();
  rep.leaves = t.leaf_count();
  rep.max_depth = t.max_depth();
  const size_t N = input.size();

  // 1, 2
  if (N == 0 && !t.nodes.empty()) violate("a root exists although there are no primitives");
  if (N > 0 && t.nodes.empty()) violate("no root although there are " + std::to_string(N) + " primitives");
  {
    std::vector<const Primitive*> a(input), b(t.prims);
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    if (a != b)
      violate("primitives() is not a permutation of the input (" + std::to_string(t.prims.size()) + " entries for " +
              std::to_string(N) + " primitives; entries lost or duplicated)");
  }
  if (t.nodes.empty()) return rep;

  // 3, 4
  const size_t P = t.prims.size();
  if (t.nodes[0].start != 0 || t.nodes[0].end != P) {
    std::ostringstream os;
    os << "the root owns [" << t.nodes[0].start << ", " << t.nodes[0].end << ") instead of [0, " << P << ")";
    violate(os.str());
  }
  const size_t leaf_limit = std::max<size_t>(1, max_leaf_size);
  std::vector<unsigned> cover(P, 0);
  for (size_t i = 0; i < t.nodes.size(); ++i) {
    const FlatNode& n = t.nodes[i];
    if (!(n.start < n.end && n.end <= P)) {
      violate(where(i) + " has an empty or out-of-range primitive range (the array has " + std::to_string(P) + ")");
      continue;
    }
    if (n.leaf()) {
      rep.largest_leaf = std::max(rep.largest_leaf, n.size());
      if (n.size() > leaf_limit)
        violate(where(i) + " holds " + std::to_string(n.size()) + " primitives; max_leaf_size is " +
                std::to_string(max_leaf_size) + " (a range of two or more can always be split, by count if need be)");
      for (size_t k = n.start; k < n.end; ++k) ++cover[k];
      continue;
    }
    if (n.left < 0 || n.right < 0) {
      violate(where(i) + " has only one child");
      continue;
    }
    if (!children_tile(t, n)) {
      const FlatNode& a = t.nodes[size_t(n.left)];
      const FlatNode& b = t.nodes[size_t(n.right)];
      std::ostringstream os;
      os << where(i) << " has children owning [" << a.start << ", " << a.end << ") and [" << b.start << ", " << b.end
         << "), which do not split its range into two non-empty adjacent parts";
      violate(os.str());
    }
  }
  // 5
  size_t uncovered = 0, multiple = 0, first_bad = P;
  for (size_t k = 0; k < P; ++k) {
    if (cover[k] != 1) {
      first_bad = std::min(first_bad, k);
      (cover[k] == 0 ? uncovered : multiple)++;
    }
  }
  if (uncovered || multiple) {
    std::ostringstream os;
    os << uncovered << " primitive(s) in no leaf and " << multiple << " in more than one (first: index " << first_bad
       << ")";
    violate(os.str());
  }
  // 6, 7
  std::vector<BBox> tight = tight_boxes(t);
  double scale = 1.0;
  if (!tight[0].empty()) scale = std::max({scale, max_component(glm::abs(tight[0].min)), max_component(glm::abs(tight[0].max))});
  const double tol = 1e-9 * scale;
  auto within = [&](const BBox& outer, const BBox& inner) {  // inner inside outer, with the tolerance
    if (inner.empty()) return true;
    if (outer.empty()) return false;
    return glm::all(glm::lessThanEqual(outer.min, inner.min + tol)) &&
           glm::all(glm::greaterThanEqual(outer.max, inner.max - tol));
  };
  for (size_t i = 0; i < t.nodes.size(); ++i) {
    const FlatNode& n = t.nodes[i];
    if (!(n.start < n.end && n.end <= P)) continue;
    const BBox& b = n.bb;
    const BBox& tb = tight[i];
    bool nan = !is_finite(b.min) || !is_finite(b.max);
    if (nan || !within(b, tb) || !within(tb, b)) {
      std::ostringstream os;
      os.precision(17);
      os << where(i) << " has box " << b << " but its primitives span " << tb
         << (within(b, tb) ? " (not tight)" : " (primitives stick out)");
      violate(os.str());
    }
    if (n.parent >= 0 && !within(t.nodes[size_t(n.parent)].bb, b)) {
      std::ostringstream os;
      os.precision(17);
      os << where(i) << " has box " << b << ", not inside its parent's " << t.nodes[size_t(n.parent)].bb;
      violate(os.str());
    }
  }
  return rep;
}

// --- Traversal, scans ------------------------------------------------------------

bool linear_closest(const std::vector<const Primitive*>& prims, const Ray& r, Intersection* isect) {
  bool hit = false;
  for (const Primitive* p : prims) hit |= p->intersect(r, isect);
  return hit;
}

bool linear_any(const std::vector<const Primitive*>& prims, const Ray& r) {
  for (const Primitive* p : prims)
    if (p->has_intersection(r)) return true;
  return false;
}

// --- Counting ---------------------------------------------------------------------

QueryWork& QueryWork::operator+=(const QueryWork& o) {
  primitive_tests += o.primitive_tests;
  leaves += o.leaves;
  nodes += o.nodes;
  tests_after_first_hit += o.tests_after_first_hit;
  return *this;
}

std::ostream& operator<<(std::ostream& os, const WorkTotals& w) {
  return os << w.tests() << " primitive tests, " << w.leaves() << " leaves, " << w.nodes() << " nodes per ray ("
            << w.queries << " rays)";
}

WorkMeter::WorkMeter(const std::vector<const Primitive*>& prims) {
  for (size_t i = 0; i < prims.size(); ++i) {
    wrappers_.push_back(std::make_unique<CountingPrimitive>(prims[i], i, &log_));
    wrapped_.push_back(wrappers_.back().get());
  }
}

void WorkMeter::attach(const FlatTree& tree) {
  tree_ = &tree;
  leaf_of_.assign(wrapped_.size(), -1);
  for (size_t i = 0; i < tree.nodes.size(); ++i) {
    const FlatNode& n = tree.nodes[i];
    if (!n.leaf()) continue;
    for (size_t k = n.start; k < n.end && k < tree.prims.size(); ++k)
      if (auto* w = dynamic_cast<const CountingPrimitive*>(tree.prims[k]))
        if (w->index() < leaf_of_.size()) leaf_of_[w->index()] = int(i);
  }
  mark_.assign(tree.nodes.size(), 0);
}

QueryWork WorkMeter::stop(std::vector<int>* leaves_in_order) const {
  QueryWork w;
  ++stamp_;
  if (leaves_in_order) leaves_in_order->clear();
  bool seen_hit = false;
  for (const TestEvent& e : log_) {
    ++w.primitive_tests;
    if (seen_hit) ++w.tests_after_first_hit;
    seen_hit |= e.hit;
    int leaf = tree_ && e.index < leaf_of_.size() ? leaf_of_[e.index] : -1;
    if (leaf < 0 || mark_[size_t(leaf)] == stamp_) continue;
    ++w.leaves;
    if (leaves_in_order) leaves_in_order->push_back(leaf);
    for (int n = leaf; n >= 0 && mark_[size_t(n)] != stamp_; n = tree_->nodes[size_t(n)].parent) {
      mark_[size_t(n)] = stamp_;
      ++w.nodes;
    }
  }
  log_.clear();
  return w;
}

const Primitive* WorkMeter::unwrap(const Primitive* p) const {
  if (auto* w = dynamic_cast<const CountingPrimitive*>(p)) return w->inner();
  return p;
}

WorkTotals framework_work(const WorkMeter& meter, const FlatTree& tree, const std::vector<Ray>& rays) {
  WorkTotals total;
  for (const Ray& ray : rays) {
    Ray r = ray;
    Intersection isect;
    meter.start();
    framework_closest(tree, r, &isect);
    total.add(meter.stop());
  }
  return total;
}

CountedBVH::CountedBVH(const std::vector<const Primitive*>& prims, size_t max_leaf_size)
    : max_leaf_size_(max_leaf_size), meter_(prims) {
  std::vector<Primitive*> input;
  for (const Primitive* p : meter_.wrapped()) input.push_back(const_cast<Primitive*>(p));
  bvh_ = std::make_unique<BVHAccel>(std::move(input), max_leaf_size);  // the student's construct_bvh
  tree_ = flatten(*bvh_);
  meter_.attach(tree_);
}

CountedBVH::~CountedBVH() = default;

namespace {
// For the life of the object, whether the query's work is read
// (core/stats.h: across the process boundary every primitive test of such a
// query is seen one at a time; in the others, whose counts nothing reads, the
// verifier may answer a leaf's tests together).
class WorkRead {
 public:
  explicit WorkRead(bool read) : previous_(primitive_tests_read()) { primitive_tests_read() = read; }
  ~WorkRead() { primitive_tests_read() = previous_; }
  WorkRead(const WorkRead&) = delete;
  WorkRead& operator=(const WorkRead&) = delete;

 private:
  bool previous_;
};
}  // namespace

bool CountedBVH::closest(const Ray& r, Intersection* isect, QueryWork* work,
                         std::vector<int>* leaves_in_order) const {
  const WorkRead read(work || leaves_in_order);
  meter_.start();
  bool hit = bvh_->intersect(r, isect);
  isect->primitive = meter_.unwrap(isect->primitive);
  QueryWork w = meter_.stop(leaves_in_order);
  if (work) *work = w;
  return hit;
}

bool CountedBVH::any(const Ray& r, QueryWork* work) const {
  const WorkRead read(work != nullptr);
  meter_.start();
  bool hit = bvh_->has_intersection(r);
  QueryWork w = meter_.stop();
  if (work) *work = w;
  return hit;
}

bool CountedBVH::reference_closest(const Ray& r, Intersection* isect, QueryWork* work) const {
  meter_.start();
  bool hit = framework_closest(tree_, r, isect);
  isect->primitive = meter_.unwrap(isect->primitive);
  QueryWork w = meter_.stop();
  if (work) *work = w;
  return hit;
}

// --- The order of a closest-hit traversal -------------------------------------------------

std::vector<OrderViolation> child_order_violations(const FlatTree& tree, const Ray& r,
                                                   const std::vector<int>& leaves_in_order, int* checked) {
  // first[n]: the position in leaves_in_order of the first leaf entered below node n.
  std::vector<int> first(tree.nodes.size(), -1);
  for (size_t k = 0; k < leaves_in_order.size(); ++k)
    for (int n = leaves_in_order[k]; n >= 0 && first[size_t(n)] < 0; n = tree.nodes[size_t(n)].parent)
      first[size_t(n)] = int(k);
  std::vector<OrderViolation> out;
  for (size_t i = 0; i < tree.nodes.size(); ++i) {
    const FlatNode& n = tree.nodes[i];
    if (n.leaf() || n.left < 0 || n.right < 0 || first[size_t(n.left)] < 0 || first[size_t(n.right)] < 0) continue;
    double tl0 = r.min_t, tl1 = r.max_t, tr0 = r.min_t, tr1 = r.max_t;
    if (!slab_closed(tree.nodes[size_t(n.left)].bb, r, tl0, tl1) || !slab_closed(tree.nodes[size_t(n.right)].bb, r, tr0, tr1))
      continue;  // (cannot happen for leaves that were entered; a box the ray misses has no order)
    if (std::abs(tl0 - tr0) <= 1e-9 * std::max(1.0, std::max(std::abs(tl0), std::abs(tr0)))) continue;
    if (checked) ++*checked;
    bool left_went_first = first[size_t(n.left)] < first[size_t(n.right)];
    bool left_nearer = tl0 < tr0;
    if (left_went_first == left_nearer) continue;
    OrderViolation v;
    v.node = int(i);
    v.went_first = left_went_first ? n.left : n.right;
    v.nearer = left_nearer ? n.left : n.right;
    v.went_first_t0 = left_went_first ? tl0 : tr0;
    v.nearer_t0 = left_nearer ? tl0 : tr0;
    out.push_back(v);
  }
  return out;
}

// --- Comparing hits --------------------------------------------------------------------

std::string describe(const Primitive* p) {
  std::ostringstream os;
  os.precision(17);
  if (!p) return "(no primitive)";
  if (auto* t = dynamic_cast<const Triangle*>(p)) {
    os << "triangle " << t->p1() << " " << t->p2() << " " << t->p3();
  } else if (auto* s = dynamic_cast<const Sphere*>(p)) {
    os << "sphere centre " << s->o << " radius " << s->r;
  } else if (auto* w = dynamic_cast<const CountingPrimitive*>(p)) {
    return describe(w->inner());
  } else {
    os << "primitive with box " << p->get_bbox();
  }
  return os.str();
}

testing::AssertionResult same_closest_hit(const Ray& ray, bool bvh_hit, const Intersection& bvh, bool scan_hit,
                                          const Intersection& scan, const double* bvh_max_t) {
  std::ostringstream os;
  os.precision(17);
  os << "ray " << ray << "\n";
  if (bvh_hit != scan_hit) {
    os << "the BVH reports " << (bvh_hit ? "a hit" : "no hit") << " but the linear scan over every primitive "
       << (scan_hit ? "hits " + describe(scan.primitive) + " at t = " + std::to_string(scan.t) : "hits nothing");
    if (bvh_hit) os << "\nBVH hit: t = " << bvh.t << " on " << describe(bvh.primitive);
    return testing::AssertionFailure() << os.str();
  }
  if (!bvh_hit) return testing::AssertionSuccess();
  const double tol = 1e-9 * std::max(1.0, std::abs(scan.t));
  bool t_ok = std::abs(bvh.t - scan.t) <= tol;
  bool prim_ok = bvh.primitive == scan.primitive;
  if (t_ok && !prim_ok && bvh.primitive) {
    // A tie: accept another primitive if it really is hit at this distance.
    Ray fresh = ray;
    Intersection own;
    prim_ok = bvh.primitive->intersect(fresh, &own) && std::abs(own.t - bvh.t) <= tol;
  }
  if (!t_ok || !prim_ok) {
    os << "closest hit differs from the linear scan:\n  BVH:  t = " << bvh.t << " on " << describe(bvh.primitive)
       << "\n  scan: t = " << scan.t << " on " << describe(scan.primitive);
    return testing::AssertionFailure() << os.str();
  }
  if (bvh_max_t && *bvh_max_t != bvh.t) {
    os << "after the hit at t = " << bvh.t << " the ray's max_t is " << *bvh_max_t
       << ": intersect() must leave r.max_t at the closest hit (the Primitive contract)";
    return testing::AssertionFailure() << os.str();
  }
  return testing::AssertionSuccess();
}

}  // namespace pt::test::part2
