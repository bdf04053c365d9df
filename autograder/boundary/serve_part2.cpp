// The worker's Part 2: the verifier's calls (proxies_part2.cpp) answered by
// the student's BVH. The worker keeps each tree it built, over handles of the
// primitives sent: a handle holds its box and whether it has a BSDF, never
// the geometry, and each test of it is a call back to the verifier, which
// makes it on its own primitive and counts it there (bvh_codec.h).
#include <deque>
#include <unordered_map>

#include <cstring>

#include "bvh_codec.h"
#include "hit_codec.h"

namespace pt::boundary {
namespace {

// The BSDF of a primitive that has one on the verifier's side: a hit's BSDF
// only needs to be told apart from "none" and "something else".
const BSDF* own_bsdf() {
  static const DiffuseBSDF b{Spectrum(0.5)};
  return &b;
}

Link* g_link = nullptr;

// What the student's build and traversal get for a primitive sent. Its
// intersect writes itself into a hit, as any primitive does (the handle
// crosses back as its index), with the hit's distance and nothing else of the
// shape (bvh::TestAnswer): a traversal that fires rays at it to find the
// shape behind it finds only the handle.
class Handle final : public Primitive {
 public:
  Handle(uint64_t tree, uint32_t index, const BBox& box, bool with_bsdf)
      : tree_(tree), index_(index), box_(box), with_bsdf_(with_bsdf) {}
  BBox get_bbox() const override { return box_; }
  const BSDF* get_bsdf() const override { return with_bsdf_ ? own_bsdf() : nullptr; }
  bool has_intersection(const Ray& r) const override { return test(r, nullptr, false); }
  bool intersect(const Ray& r, Intersection* isect) const override { return test(r, isect, true); }

 private:
  bool test(const Ray& r, Intersection* isect, bool closest) const;
  bool apply(const bvh::TestAnswer& a, const Ray& r, Intersection* isect, bool closest) const;

  uint64_t tree_;
  uint32_t index_;
  BBox box_;
  bool with_bsdf_;
};

struct WorkerTree {
  uint64_t id = 0;
  std::vector<std::unique_ptr<Handle>> handles;
  std::unordered_map<const Primitive*, int64_t> index_of;  // handle -> its index
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

// Reads the primitives sent into `t`'s handles, in order.
void read_primitives(Reader& in, WorkerTree& t, uint64_t count) {
  for (uint64_t i = 0; i < count; ++i) {
    const auto box = in.get<BBox>();
    const bool with_bsdf = in.get<uint8_t>() != 0;
    t.handles.push_back(std::make_unique<Handle>(t.id, static_cast<uint32_t>(i), box, with_bsdf));
    t.index_of[t.handles.back().get()] = static_cast<int64_t>(i);
  }
}

int64_t index_in(const WorkerTree& t, const Primitive* p) {
  if (!p) return bvh::kNoPrimitive;
  const auto found = t.index_of.find(p);
  return found == t.index_of.end() ? bvh::kElsewhere : found->second;
}

const Primitive* handle_at(const WorkerTree& t, int64_t h) {
  if (h >= 0 && static_cast<uint64_t>(h) < t.handles.size()) return t.handles[static_cast<size_t>(h)].get();
  if (h == bvh::kElsewhere) return elsewhere_primitive();
  if (h == bvh::kNoPrimitive) return nullptr;
  throw std::runtime_error("a hit on a primitive the tree does not have");
}

// The answers the verifier gave ahead, for the tests of a leaf (bvh_codec.h).
std::vector<bvh::Prefetched>& prefetched() {
  static std::vector<bvh::Prefetched> p;
  return p;
}

// The tree being built, not yet kept: a build may test its primitives too.
WorkerTree*& building() {
  static WorkerTree* t = nullptr;
  return t;
}

struct Building {
  explicit Building(WorkerTree& t) { building() = &t; }
  ~Building() { building() = nullptr; }
  Building(const Building&) = delete;
  Building& operator=(const Building&) = delete;
};

const WorkerTree* tree_of(uint64_t id) {
  if (building() && building()->id == id) return building();
  for (auto& t : trees())
    if (t->id == id) return t.get();
  return nullptr;
}

void build(Reader& in, Writer& out) {
  auto t = std::make_unique<WorkerTree>();
  t->id = in.get<uint64_t>();
  const auto max_leaf_size = static_cast<size_t>(in.get<uint64_t>());
  const auto room = in.get<int64_t>();
  const auto count = in.get<uint64_t>();
  if (count > kMaxPayload / sizeof(BBox)) throw std::runtime_error("more primitives than the message holds");
  read_primitives(in, *t, count);
  std::vector<Primitive*> input;
  for (auto& p : t->handles) input.push_back(p.get());
  prefetched().clear();
  {
    const Building now(*t);
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
    hit.primitive = handle_at(t, in.get<int64_t>());
    hit.bsdf = hit.primitive ? hit.primitive->get_bsdf() : nullptr;
  }
  prefetched().clear();
  const bool result = closest ? t.accel->intersect(ray, &hit, node) : t.accel->has_intersection(ray, node);
  out.put(static_cast<uint8_t>(result)).put(ray.min_t).put(ray.max_t);
  if (with_hit) out.put(hit.t).put(index_in(t, hit.primitive));
}

// Bit for bit (a -0.0 is not a 0.0 to a slab or a triangle test); Ray has padding.
bool same_ray(const Ray& a, const Ray& b) {
  const auto same = [](const auto& x, const auto& y) { return std::memcmp(&x, &y, sizeof x) == 0; };
  return same(a.o, b.o) && same(a.d, b.d) && same(a.min_t, b.min_t) && same(a.max_t, b.max_t) && a.depth == b.depth;
}

bool Handle::apply(const bvh::TestAnswer& a, const Ray& r, Intersection* isect, bool closest) const {
  r.min_t = a.min_t;
  r.max_t = a.max_t;
  if (a.hit && closest && isect) {
    *isect = Intersection();
    isect->t = a.t;
    isect->primitive = this;
    isect->bsdf = get_bsdf();
  }
  return a.hit != 0;
}

bvh::TestAnswer get_answer(Reader& in, bool closest) {
  bvh::TestAnswer a;
  in.get(a.hit);
  in.get(a.min_t);
  in.get(a.max_t);
  if (a.hit && closest) in.get(a.t);
  return a;
}

bool Handle::test(const Ray& r, Intersection* isect, bool closest) const {
  for (const bvh::Prefetched& p : prefetched())
    if (p.index == index_ && (p.closest != 0) == closest && same_ray(p.ray, r)) return apply(p.answer, r, isect, closest);
  if (!tree_of(tree_)) throw std::runtime_error("a primitive of a BVH the worker no longer keeps was tested");
  Writer args(96);
  args.put(tree_).put(index_).put(static_cast<uint8_t>(closest)).put(r);
  const std::string answer = g_link->call(Call::TestPrimitive, args);
  Reader out(answer);
  const bvh::TestAnswer a = get_answer(out, closest);
  const auto count = out.get<uint32_t>();
  if (count > bvh::kMaxPrefetched) throw LinkBroken("more answers than a leaf holds");
  prefetched().clear();
  for (uint32_t k = 0; k < count; ++k) {
    bvh::Prefetched p;
    out.get(p.index);
    p.closest = out.get<uint8_t>();
    out.get(p.ray);
    p.answer = get_answer(out, p.closest != 0);
    prefetched().push_back(p);
  }
  out.finish();
  return apply(a, r, isect, closest);
}

}  // namespace

void serve_task_calls(Link& link) {
  g_link = &link;
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
