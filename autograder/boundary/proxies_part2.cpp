// The verifier's Part 2: each task function asks the worker (README.md and
// bvh_codec.h beside this file). construct_bvh sends the primitives and
// rebuilds the tree the worker's build made; the traversals name that tree
// and replay, on the verifier's own primitives, every primitive test the
// worker's traversal made, so that the tests' counting primitives log them here.
#include <mutex>
#include <string>
#include <typeinfo>
#include <unordered_map>

#include "bvh_codec.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"
#include "hit_codec.h"
#include "support/bvh_checks.h"
#include "verifier_link.h"

namespace pt {
namespace {

using boundary::Call;
using boundary::call_worker;
using boundary::Reader;
using boundary::Writer;
namespace bvh = boundary::bvh;

// What stands where the worker's build left something that is not one of the
// primitives sent (a null pointer, a primitive of its own): nothing hits it,
// and the tests' permutation check reports it.
class NotSent final : public Primitive {
 public:
  BBox get_bbox() const override { return BBox(); }
  bool has_intersection(const Ray&) const override { return false; }
  bool intersect(const Ray&, Intersection*) const override { return false; }
  const BSDF* get_bsdf() const override { return nullptr; }
};
NotSent* not_sent() {
  static NotSent p;
  return &p;
}

// A tree the worker built, as the verifier keeps it.
struct BuiltTree {
  uint64_t id = 0;
  const BVHNode* root = nullptr;
  std::unordered_map<const BVHNode*, int64_t> node_ids;  // position in preorder
  std::vector<Primitive*> sent;                           // the primitives, in the order sent
};

// By accelerator. A BVHAccel's destructor is the framework's and says nothing
// here, so an entry can outlive its accelerator: a new one at the same address
// replaces it when it is built, and a traversal checks that the root it is
// asked about is the one built (an accelerator with no primitives has no root
// and never asks). Only the last bvh::kTreesKept are kept, as in the worker.
using bvh::kTreesKept;
std::unordered_map<const BVHAccel*, BuiltTree>& built_trees() {
  static std::unordered_map<const BVHAccel*, BuiltTree> trees;
  return trees;
}

void keep(const BVHAccel* accel, BuiltTree tree) {
  auto& trees = built_trees();
  trees[accel] = std::move(tree);
  if (trees.size() <= kTreesKept) return;
  auto oldest = trees.begin();
  for (auto it = trees.begin(); it != trees.end(); ++it)
    if (it->second.id < oldest->second.id) oldest = it;
  trees.erase(oldest);
}

const BuiltTree& built_tree(const BVHAccel* accel, const BVHNode* root) {
  const auto found = built_trees().find(accel);
  if (found == built_trees().end() || found->second.root != root)
    throw std::logic_error("this BVHAccel's tree is not one of the last " + std::to_string(kTreesKept) +
                           " that construct_bvh built across the process boundary; only those can be traversed "
                           "there (autograder/boundary/README.md)");
  return found->second;
}

[[noreturn]] void cannot_cross(const Primitive& p) {
  throw std::logic_error(std::string("the process boundary cannot carry this primitive (") + typeid(p).name() +
                         ") to the worker: only triangles and spheres cross, bare or in the framework's and the "
                         "tests' counting wrappers (autograder/boundary/README.md)");
}

// The geometry of `p`, through the wrappers that count its tests.
void put_shape(Writer& in, const Primitive& p) {
  if (const auto* t = dynamic_cast<const Triangle*>(&p)) {
    in.put(bvh::Shape::Triangle).put(t->p1()).put(t->p2()).put(t->p3()).put(t->n1()).put(t->n2()).put(t->n3());
  } else if (const auto* s = dynamic_cast<const Sphere*>(&p)) {
    in.put(bvh::Shape::Sphere).put(s->o).put(s->r).put(s->r2);
  } else if (const auto* c = dynamic_cast<const test::p2::CountingPrimitive*>(&p)) {
    put_shape(in, *c->inner());
  } else {
    cannot_cross(p);
  }
}

Primitive* primitive_at(int64_t index, const std::vector<Primitive*>& sent) {
  if (index >= 0 && static_cast<uint64_t>(index) < sent.size()) return sent[static_cast<size_t>(index)];
  if (index == bvh::kNoPrimitive || index == bvh::kElsewhere) return not_sent();
  throw boundary::LinkBroken("a primitive index out of range");
}

// Makes each primitive test of the worker's traversal again on the verifier's
// own primitive: a counting one logs it here. An answer that differs from the
// verifier's is a lie about the worker's own work.
void replay(Reader& out, const BuiltTree& tree) {
  bvh::get_tests(out, [&](const bvh::PrimitiveTest& t) {
    if (t.index >= tree.sent.size()) throw boundary::LinkBroken("a primitive test of a primitive never sent");
    const Primitive& p = *tree.sent[t.index];
    Ray r = t.ray;
    Intersection scratch;
    const bool hit = t.closest ? p.intersect(r, &scratch) : p.has_intersection(r);
    if (hit != t.hit) throw boundary::LinkBroken("a primitive test whose answer is not the primitive's");
  });
}

// A traversal of the tree built for `accel`, from `node`.
bool traverse(const BVHAccel* accel, const BVHNode* root, const BVHNode* node, const Ray& r, Intersection* isect,
              bool closest) {
  const auto link = boundary::hold_link();
  const BuiltTree& tree = built_tree(accel, root);
  int64_t node_id = -1;
  if (node) {
    const auto found = tree.node_ids.find(node);
    if (found == tree.node_ids.end())
      throw std::logic_error("a traversal from a node that is not in this BVHAccel's tree cannot cross the process "
                             "boundary (autograder/boundary/README.md)");
    node_id = found->second;
  }
  Writer in(160);
  in.put(tree.id).put(node_id);
  in.put(r);
  const Primitive* before = isect ? isect->primitive : nullptr;
  in.put(static_cast<uint8_t>(isect != nullptr));
  if (isect) {
    in.put(isect->t).put(isect->n).put(isect->barycentric);
    in.put(before ? bvh::kElsewhere : bvh::kNoPrimitive).put(static_cast<uint8_t>(isect->bsdf != nullptr));
  }
  const std::string answer = call_worker(closest ? Call::BvhIntersect : Call::BvhHasIntersection, in);
  return boundary::read_answer([&] {
    Reader out(answer);
    const bool hit = out.get<uint8_t>() != 0;
    r.min_t = out.get<double>();
    r.max_t = out.get<double>();
    if (isect) {
      out.get(isect->t);
      out.get(isect->n);
      out.get(isect->barycentric);
      const auto primitive = out.get<int64_t>();
      const auto bsdf = out.get<boundary::Points>();
      isect->primitive = primitive == bvh::kNoPrimitive ? nullptr
                         : primitive == bvh::kElsewhere ? (before ? before : boundary::elsewhere_primitive())
                                                        : primitive_at(primitive, tree.sent);
      const BSDF* own = isect->primitive ? isect->primitive->get_bsdf() : nullptr;
      isect->bsdf = bsdf == boundary::Points::Nothing ? nullptr
                    : bsdf == boundary::Points::Asked ? own
                                                      : boundary::elsewhere_bsdf();
    }
    work_counters().node_visits += out.get<uint64_t>();
    replay(out, tree);
    out.finish();
    return hit;
  });
}

}  // namespace

bool BBox::intersect(const Ray& r, double& t0, double& t1) const {
  Writer in;
  in.put(*this).put(r).put(t0).put(t1);
  const std::string answer = call_worker(Call::BoxIntersect, in);
  return boundary::read_answer([&] {
    Reader out(answer);
    const bool hit = out.get<uint8_t>() != 0;
    out.get(t0);
    out.get(t1);
    out.finish();
    return hit;
  });
}

std::unique_ptr<BVHNode> BVHAccel::construct_bvh(PrimIter start, PrimIter end, size_t max_leaf_size) {
  if (start != primitives_.begin() || end != primitives_.end())
    throw std::logic_error("construct_bvh crosses the process boundary only over all of a BVHAccel's primitives, as "
                           "its constructor calls it (autograder/boundary/README.md)");
  const auto link = boundary::hold_link();
  static uint64_t next_id = 0;
  BuiltTree tree;
  tree.id = ++next_id;
  tree.sent = primitives_;
  Writer in(64 + tree.sent.size() * 200);
  // The worker builds within the address space this process may still map, so
  // that a build that never stops fails there as it would here: with
  // std::bad_alloc under a test's limit, not by taking the machine's memory.
  in.put(tree.id).put(static_cast<uint64_t>(max_leaf_size)).put(bvh::address_space_room());
  in.put(static_cast<uint64_t>(tree.sent.size()));
  for (const Primitive* p : tree.sent) {
    in.put(p->get_bbox()).put(static_cast<uint8_t>(p->get_bsdf() != nullptr));
    put_shape(in, *p);
  }
  const std::string answer = call_worker(Call::BuildBvh, in);
  std::vector<const BVHNode*> preorder;
  std::unique_ptr<BVHNode> root = boundary::read_answer([&] {
    Reader out(answer);
    const auto order = out.get_vector<int64_t>(boundary::kMaxPayload / sizeof(int64_t));
    std::vector<Primitive*> arranged;
    arranged.reserve(order.size());
    for (int64_t index : order) arranged.push_back(primitive_at(index, tree.sent));
    auto built = bvh::get_tree(out, preorder);
    out.finish();
    primitives_ = std::move(arranged);
    return built;
  });
  tree.root = root.get();
  for (size_t i = 0; i < preorder.size(); ++i) tree.node_ids[preorder[i]] = static_cast<int64_t>(i);
  keep(this, std::move(tree));
  return root;
}

bool BVHAccel::has_intersection(const Ray& r, const BVHNode* node) const {
  return traverse(this, root_.get(), node, r, nullptr, false);
}

bool BVHAccel::intersect(const Ray& r, Intersection* isect, const BVHNode* node) const {
  return traverse(this, root_.get(), node, r, isect, true);
}

}  // namespace pt
