// The worker's halves of TreeBuild and Tree (bvh_codec.h): the student's BVH
// over handles of the primitives sent. The worker keeps each tree it built: a
// handle holds its box and whether it has a BSDF, never the geometry, and each
// test of it is a call back to the verifier, which makes it on its own
// primitive and counts it there.
#include <cstring>
#include <deque>
#include <unordered_map>

#include "bvh_codec.h"
#include "hit_codec.h"
#include "scoped.h"
#include "worker_link.h"

namespace pt::boundary {
namespace bvh {

// What the student's build and traversal get for a primitive sent. Its
// intersect writes itself into a hit, as any primitive does (the handle
// crosses back as its index), with the hit's distance and nothing else of the
// shape (TestAnswer): a traversal that fires rays at it to find the
// shape behind it finds only the handle.
class Handle final : public Primitive {
 public:
  Handle(uint64_t tree, uint32_t index, const BBox& box, bool with_bsdf)
      : tree_(tree), index_(index), box_(box), with_bsdf_(with_bsdf) {}
  BBox get_bbox() const override { return box_; }
  const BSDF* get_bsdf() const override { return with_bsdf_ ? stand_in_bsdf() : nullptr; }
  bool has_intersection(const Ray& r) const override { return test(r, nullptr, false); }
  bool intersect(const Ray& r, Intersection* isect) const override { return test(r, isect, true); }

 private:
  bool test(const Ray& r, Intersection* isect, bool closest) const;
  bool apply(const TestAnswer& a, const Ray& r, Intersection* isect, bool closest) const;

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

// The trees built last (kTreesKept), newest at the back.
std::deque<std::unique_ptr<WorkerTree>>& trees() {
  static std::deque<std::unique_ptr<WorkerTree>> t;
  return t;
}

const Primitive* handle_at(const WorkerTree& t, int64_t h) {
  return object_at(h, t.handles.size(), [&](size_t k) { return t.handles[k].get(); }, elsewhere_primitive());
}

// The answers the verifier gave ahead, for the tests of a leaf (bvh_codec.h).
std::vector<Prefetched>& prefetched() {
  static std::vector<Prefetched> p;
  return p;
}

// The tree being built, not yet kept: a build may test its primitives too.
WorkerTree*& building() {
  static WorkerTree* t = nullptr;
  return t;
}

// A tree kept, or the one being built, by its id.
WorkerTree* tree_of(uint64_t id) {
  if (building() && building()->id == id) return building();
  for (auto& t : trees())
    if (t->id == id) return t.get();
  return nullptr;
}

WorkerTree& tree_named(uint64_t id) {
  if (WorkerTree* t = tree_of(id)) return *t;
  throw std::runtime_error("a traversal names a BVH the worker does not keep (it keeps the last " +
                           std::to_string(kTreesKept) + " built)");
}

// Bit for bit (a -0.0 is not a 0.0 to a slab or a triangle test); Ray has padding.
bool same_ray(const Ray& a, const Ray& b) {
  const auto same = [](const auto& x, const auto& y) { return std::memcmp(&x, &y, sizeof x) == 0; };
  return same(a.o, b.o) && same(a.d, b.d) && same(a.min_t, b.min_t) && same(a.max_t, b.max_t) && a.depth == b.depth;
}

bool Handle::apply(const TestAnswer& a, const Ray& r, Intersection* isect, bool closest) const {
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

TestAnswer get_answer(Reader& in, bool closest) {
  TestAnswer a;
  in.get(a.hit);
  in.get(a.min_t);
  in.get(a.max_t);
  if (a.hit && closest) in.get(a.t);
  return a;
}

bool Handle::test(const Ray& r, Intersection* isect, bool closest) const {
  for (const Prefetched& p : prefetched())
    if (p.index == index_ && (p.closest != 0) == closest && same_ray(p.ray, r)) return apply(p.answer, r, isect, closest);
  if (!tree_of(tree_)) throw std::runtime_error("a primitive of a BVH the worker no longer keeps was tested");
  Writer args(96);
  args.put(tree_).put(index_).put(static_cast<uint8_t>(closest)).put(r);
  const std::string answer = worker_link().call(Call::TestPrimitive, args);
  Reader out(answer);
  const TestAnswer a = get_answer(out, closest);
  const auto count = out.get<uint32_t>();
  if (count > kMaxPrefetched) throw LinkBroken("more answers than a leaf holds");
  prefetched().clear();
  for (uint32_t k = 0; k < count; ++k) {
    Prefetched p;
    out.get(p.index);
    p.closest = out.get<uint8_t>();
    out.get(p.ray);
    p.answer = get_answer(out, p.closest != 0);
    prefetched().push_back(p);
  }
  out.finish();
  return apply(a, r, isect, closest);
}

}  // namespace bvh

using bvh::WorkerTree;

TreeBuild::Held::Held(Reader& in) : tree_(std::make_unique<WorkerTree>()) {
  tree_->id = in.get<uint64_t>();
  room_ = in.get<int64_t>();
  const auto count = in.get<uint64_t>();
  if (count > kMaxPayload / sizeof(BBox)) throw std::runtime_error("more primitives than the message holds");
  for (uint32_t i = 0; i < count; ++i) {
    const auto box = in.get<BBox>();
    tree_->handles.push_back(std::make_unique<bvh::Handle>(tree_->id, i, box, in.get<uint8_t>() != 0));
    tree_->index_of[tree_->handles.back().get()] = i;
  }
}

TreeBuild::Held::~Held() = default;

void TreeBuild::Held::build(size_t max_leaf_size) {
  std::vector<Primitive*> input;
  for (auto& p : tree_->handles) input.push_back(p.get());
  bvh::prefetched().clear();
  const Scoped<bvh::WorkerTree*> now(bvh::building(), tree_.get());
  const bvh::AddressSpaceRoom limit(room_);
  tree_->accel = std::make_unique<BVHAccel>(std::move(input), max_leaf_size);  // the student's construct_bvh
}

void TreeBuild::Held::put_tree(Writer& w) {
  std::vector<int64_t> order;
  for (const Primitive* p : tree_->accel->primitives()) order.push_back(index_of(p, tree_->index_of));
  w.put_vector(order);
  bvh::put_tree(w, tree_->accel->root(), tree_->preorder);
  auto& kept = bvh::trees();
  if (kept.size() == bvh::kTreesKept) kept.pop_front();
  kept.push_back(std::move(tree_));
}

Tree::Held::Held(Reader& in) : tree_(bvh::tree_named(in.get<uint64_t>())) { bvh::prefetched().clear(); }

const BVHAccel& Tree::Held::object() const { return *tree_.accel; }

const BVHNode* Tree::Held::get_node(Reader& r) const {
  const auto node_id = r.get<int64_t>();
  if (node_id < -1 || node_id >= static_cast<int64_t>(tree_.preorder.size()))
    throw std::runtime_error("a traversal from a node the tree does not have");
  return node_id < 0 ? nullptr : tree_.preorder[static_cast<size_t>(node_id)];
}

void Tree::Held::get_hit(Reader& r, Intersection& h) const {
  r.get(h.t);
  h.primitive = bvh::handle_at(tree_, r.get<int64_t>());
  h.bsdf = h.primitive ? h.primitive->get_bsdf() : nullptr;
}

void Tree::Held::put_hit(Writer& w, const Intersection& h) const { w.put(h.t).put(index_of(h.primitive, tree_.index_of)); }

}  // namespace pt::boundary
