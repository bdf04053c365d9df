// The worker's Part 2: the verifier's calls (proxies_part2.cpp) answered by
// the student's BVH. The worker keeps each tree it built, over its own copies
// of the primitives sent, and logs every primitive test a traversal makes on
// them (bvh_codec.h).
#include <sys/resource.h>

#include <deque>
#include <unordered_map>

#include "bvh_codec.h"
#include "geometry/mesh.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"
#include "hit_codec.h"

namespace pt::boundary {
namespace {

using bvh::PrimitiveTest;

// The BSDF of a primitive that has one on the verifier's side: a hit's BSDF
// only needs to be told apart from "none" and "something else".
const BSDF* own_bsdf() {
  static const DiffuseBSDF b{Spectrum(0.5)};
  return &b;
}

// The primitive tests of the traversal being answered. Not a member of the
// copies below: a student's code that reads a copy's bytes finds no pointer to
// the log to rewrite it through.
std::vector<PrimitiveTest>& test_log() {
  static std::vector<PrimitiveTest> log;
  return log;
}

// Built only for the test that proves the verifier replays each primitive
// test (tests/CMakeLists.txt, boundary:part2-lying-worker): this worker says
// the first test of every traversal answered the opposite of what it did.
#ifdef PT_BOUNDARY_LYING_WORKER
constexpr bool kLieAboutFirstTest = true;
#else
constexpr bool kLieAboutFirstTest = false;
#endif

// The worker's copy of a primitive sent: its box as the verifier's primitive
// gave it, and every test of it logged. It wraps the geometry (tested by the
// framework's, the solution's, Part 1) rather than being it, as the tests'
// counting primitives do: a traversal that casts it to a Triangle to call
// Triangle::intersect directly, unlogged, gets nothing to call.
class LoggedCopy final : public Primitive {
 public:
  LoggedCopy(uint32_t index, const BBox& box, std::unique_ptr<Primitive> shape)
      : index_(index), box_(box), shape_(std::move(shape)) {}
  BBox get_bbox() const override { return box_; }
  const BSDF* get_bsdf() const override { return shape_->get_bsdf(); }
  bool has_intersection(const Ray& r) const override {
    const Ray given = r;
    const bool hit = shape_->has_intersection(r);
    test_log().push_back({index_, false, hit, given});
    return hit;
  }
  bool intersect(const Ray& r, Intersection* isect) const override {
    const Ray given = r;
    const bool hit = shape_->intersect(r, isect);
    test_log().push_back({index_, true, hit, given});
    return hit;
  }
  const Primitive* shape() const { return shape_.get(); }

 private:
  uint32_t index_;
  BBox box_;
  std::unique_ptr<Primitive> shape_;
};

struct WorkerTree {
  uint64_t id = 0;
  Mesh meshes[2];  // triangles without a BSDF, and with one
  std::vector<std::unique_ptr<LoggedCopy>> copies;
  std::unordered_map<const Primitive*, int64_t> index_of;  // copy or shape -> its index
  std::unique_ptr<BVHAccel> accel;
  std::vector<const BVHNode*> preorder;
};

// The trees built last (bvh::kTreesKept), newest at the back.
using bvh::kTreesKept;
std::deque<std::unique_ptr<WorkerTree>>& trees() {
  static std::deque<std::unique_ptr<WorkerTree>> t;
  return t;
}

WorkerTree& tree_named(uint64_t id) {
  for (auto& t : trees())
    if (t->id == id) return *t;
  throw std::runtime_error("a traversal names a BVH the worker does not keep (it keeps the last " +
                           std::to_string(kTreesKept) + " built)");
}

// Reads the primitives sent into `t`'s copies, in order.
void read_primitives(Reader& in, WorkerTree& t, uint64_t count) {
  struct Sent {
    BBox box;
    bool with_bsdf;
    bvh::Shape shape;
    uint32_t first;  // triangle: its first vertex in its mesh
    Vec3 o;
    double r, r2;
  };
  std::vector<Sent> sent;
  sent.reserve(static_cast<size_t>(count));
  for (uint64_t i = 0; i < count; ++i) {
    Sent s{};
    in.get(s.box);
    s.with_bsdf = in.get<uint8_t>() != 0;
    s.shape = in.get<bvh::Shape>();
    if (s.shape == bvh::Shape::Triangle) {
      Mesh& mesh = t.meshes[s.with_bsdf];
      s.first = static_cast<uint32_t>(mesh.positions.size());
      for (int k = 0; k < 3; ++k) mesh.positions.push_back(in.get<Vec3>());
      for (int k = 0; k < 3; ++k) mesh.normals.push_back(in.get<Vec3>());
      mesh.faces.push_back({s.first, s.first + 1, s.first + 2});
    } else if (s.shape == bvh::Shape::Sphere) {
      in.get(s.o);
      in.get(s.r);
      in.get(s.r2);
    } else {
      throw std::runtime_error("a primitive of unknown shape");
    }
    sent.push_back(s);
  }
  // The meshes are complete: a triangle refers to its mesh's vertices.
  t.meshes[1].bsdf = own_bsdf();
  for (uint32_t i = 0; i < sent.size(); ++i) {
    const Sent& s = sent[i];
    std::unique_ptr<Primitive> shape;
    if (s.shape == bvh::Shape::Triangle) {
      shape = std::make_unique<Triangle>(&t.meshes[s.with_bsdf], s.first, s.first + 1, s.first + 2);
    } else {
      auto sphere = std::make_unique<Sphere>(s.o, s.r, s.with_bsdf ? own_bsdf() : nullptr);
      sphere->r2 = s.r2;
      shape = std::move(sphere);
    }
    t.copies.push_back(std::make_unique<LoggedCopy>(i, s.box, std::move(shape)));
    // A hit names the shape (its intersect writes itself); a student's code
    // may name the copy.
    t.index_of[t.copies.back().get()] = i;
    t.index_of[t.copies.back()->shape()] = i;
  }
}

int64_t index_in(const WorkerTree& t, const Primitive* p) {
  if (!p) return bvh::kNoPrimitive;
  const auto found = t.index_of.find(p);
  return found == t.index_of.end() ? bvh::kElsewhere : found->second;
}

void build(Reader& in, Writer& out) {
  auto t = std::make_unique<WorkerTree>();
  t->id = in.get<uint64_t>();
  const auto max_leaf_size = static_cast<size_t>(in.get<uint64_t>());
  const auto room = in.get<int64_t>();
  const auto count = in.get<uint64_t>();
  if (count > kMaxPayload / 64) throw std::runtime_error("more primitives than the message holds");
  read_primitives(in, *t, count);
  std::vector<Primitive*> input;
  for (auto& p : t->copies) input.push_back(p.get());
  {
    const bvh::AddressSpaceRoom limit(room);
    t->accel = std::make_unique<BVHAccel>(std::move(input), max_leaf_size);  // the student's construct_bvh
  }
  std::vector<int64_t> order;
  for (const Primitive* p : t->accel->primitives()) order.push_back(index_in(*t, p));
  out.put_vector(order);
  bvh::put_tree(out, t->accel->root(), t->preorder);
  if (trees().size() == kTreesKept) trees().pop_front();
  trees().push_back(std::move(t));
}

void traverse(Reader& in, Writer& out, bool closest) {
  WorkerTree& t = tree_named(in.get<uint64_t>());
  const auto node_id = in.get<int64_t>();
  if (node_id < -1 || node_id >= static_cast<int64_t>(t.preorder.size()))
    throw std::runtime_error("a traversal from a node the tree does not have");
  const BVHNode* node = node_id < 0 ? nullptr : t.preorder[static_cast<size_t>(node_id)];
  const auto ray = in.get<Ray>();
  const bool with_hit = in.get<uint8_t>() != 0;
  if (with_hit != closest) throw std::runtime_error("a hit record for has_intersection, or none for intersect");
  Intersection hit;
  if (with_hit) {
    in.get(hit.t);
    in.get(hit.n);
    in.get(hit.barycentric);
    hit.primitive = in.get<int64_t>() == bvh::kNoPrimitive ? nullptr : elsewhere_primitive();
    hit.bsdf = in.get<uint8_t>() ? elsewhere_bsdf() : nullptr;
  }
  test_log().clear();
  const uint64_t visits_before = work_counters().node_visits;
  const bool result = closest ? t.accel->intersect(ray, &hit, node) : t.accel->has_intersection(ray, node);
  out.put(static_cast<uint8_t>(result)).put(ray.min_t).put(ray.max_t);
  if (with_hit) {
    out.put(hit.t).put(hit.n).put(hit.barycentric).put(index_in(t, hit.primitive));
    const BSDF* own = hit.primitive ? hit.primitive->get_bsdf() : nullptr;
    out.put(!hit.bsdf ? Points::Nothing : hit.bsdf == own ? Points::Asked : Points::Elsewhere);
  }
  out.put(work_counters().node_visits - visits_before);
  if (kLieAboutFirstTest && !test_log().empty()) test_log().front().hit = !test_log().front().hit;
  bvh::put_tests(out, test_log());
  test_log().clear();
}

}  // namespace

void serve_task_calls(Link& link) {
  link.on(Call::BoxIntersect, [](Reader& in, Writer& out) {
    const auto box = in.get<BBox>();
    const auto ray = in.get<Ray>();
    auto t0 = in.get<double>(), t1 = in.get<double>();
    const bool hit = box.intersect(ray, t0, t1);
    out.put(static_cast<uint8_t>(hit)).put(t0).put(t1);
  });
  link.on(Call::BuildBvh, build);
  link.on(Call::BvhIntersect, [](Reader& in, Writer& out) { traverse(in, out, true); });
  link.on(Call::BvhHasIntersection, [](Reader& in, Writer& out) { traverse(in, out, false); });
}

}  // namespace pt::boundary
