// The verifier's halves of TreeBuild and Tree (bvh_codec.h, README.md beside
// this file). construct_bvh sends the primitives' boxes and rebuilds the tree
// the worker's build made; the traversals name that tree. Every primitive
// test the worker's code makes is a call back to here, made on the verifier's
// own primitive, so that the tests' counting primitives count it where the
// tests run.
#include <algorithm>
#include <cstdio>
#include <mutex>
#include <string>
#include <typeinfo>
#include <unordered_map>

#include "bvh_codec.h"
#include "core/stats.h"
#include "geometry/counted.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"
#include "hit_codec.h"
#include "scoped.h"
#include "verifier_link.h"

namespace pt::boundary::bvh {

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
  std::unordered_map<const Primitive*, int64_t> handle_of;  // a primitive sent, or the one it wraps -> its index
  std::vector<int64_t> order;        // the index at each position of the build's order
  std::vector<uint32_t> position_of;  // each index sent -> its position there
};

// Where the build left each primitive sent (a null or a primitive of the
// worker's own stands nowhere).
void find_positions(BuiltTree& tree, std::vector<int64_t> order) {
  tree.position_of.assign(tree.sent.size(), UINT32_MAX);
  for (size_t k = 0; k < order.size(); ++k)
    if (order[k] >= 0 && static_cast<uint64_t>(order[k]) < tree.sent.size())
      tree.position_of[static_cast<size_t>(order[k])] = static_cast<uint32_t>(k);
  tree.order = std::move(order);
}

// By accelerator. A BVHAccel's destructor is the framework's and says nothing
// here, so an entry can outlive its accelerator: a new one at the same address
// replaces it when it is built, and a traversal checks that the root it is
// asked about is the one built (an accelerator with no primitives has no root
// and never asks). Only the last kTreesKept are kept, as in the worker.
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
                         "tests' counting wrappers (ForwardingPrimitive) (autograder/boundary/README.md)");
}

// Refuses, before anything is sent, a primitive that would behave otherwise
// here than in one process; maps it, and the shape a counting wrapper holds
// (which its intersect writes into a hit), to its index.
void index_primitive(BuiltTree& tree, const Primitive* p, int64_t index) {
  tree.handle_of[p] = index;
  if (dynamic_cast<const Triangle*>(p) || dynamic_cast<const Sphere*>(p)) return;
  if (const auto* c = dynamic_cast<const ForwardingPrimitive*>(p)) return index_primitive(tree, &c->wrapped(), index);
  cannot_cross(*p);
}

// What the build's order names at a position: a null or a primitive of the
// worker's own stands as one that nothing hits.
Primitive* primitive_at(int64_t index, const std::vector<Primitive*>& sent) {
  const Primitive* p = object_at(index, sent.size(), [&](size_t k) { return sent[k]; }, elsewhere_primitive());
  return p && p != elsewhere_primitive() ? const_cast<Primitive*>(p) : not_sent();
}

// What a handle of the worker's names here: a hit on something the worker
// made crosses as "something else", which no test's primitive equals.
const Primitive* named_by(const BuiltTree& tree, int64_t handle) {
  return object_at(handle, tree.sent.size(), [&](size_t k) { return tree.sent[k]; }, elsewhere_primitive());
}

// The build or traversal being answered: its tree, the only one whose
// primitives the worker may test (those of any other may be freed by now),
// and the hit records the verifier's primitives wrote, by index.
struct Query {
  const BuiltTree* tree;
  bool work_read;  // whether every test must be seen one at a time
  std::unordered_map<uint32_t, Intersection> written;
};
Query* g_query = nullptr;

struct InUse {
  InUse(const BuiltTree& tree, bool work_read) : query{&tree, work_read, {}} {}
  Query query;
  Scoped<Query*> scope{g_query, &query};
};

// One test on the verifier's own primitive: a counting one counts it here.
TestAnswer test_here(Query& q, uint32_t index, bool closest, const Ray& r) {
  const Primitive& p = *q.tree->sent[index];
  Intersection hit;
  TestAnswer a;
  a.hit = closest ? p.intersect(r, &hit) : p.has_intersection(r);
  a.min_t = r.min_t;
  a.max_t = r.max_t;
  if (a.hit && closest) {
    a.t = hit.t;
    q.written[index] = hit;
  }
  return a;
}

void put_answer(Writer& out, const TestAnswer& a, bool closest) {
  out.put(a.hit).put(a.min_t).put(a.max_t);
  if (a.hit && closest) out.put(a.t);
}

// A primitive test of the worker's code, made here. In a query whose work
// nothing reads, the tests of the primitives that follow it in the build's
// order come with it (bvh_codec.h).
void test_primitive(Reader& in, Writer& out) {
  const auto tree_id = in.get<uint64_t>();
  const auto index = in.get<uint32_t>();
  const bool closest = in.get<uint8_t>() != 0;
  Ray r = in.get<Ray>();
  if (!g_query || g_query->tree->id != tree_id)
    throw std::logic_error("a primitive of a BVH other than the one being built or traversed was tested; only that "
                           "one's primitives can be tested across the process boundary (autograder/boundary/README.md)");
  Query& q = *g_query;
  if (index >= q.tree->sent.size()) throw LinkBroken("a primitive test of a primitive never sent");
  TestAnswer a = test_here(q, index, closest, r);
  put_answer(out, a, closest);
  Writer prefetched;
  uint32_t count = 0;
  const BuiltTree& tree = *q.tree;
  const size_t from = !q.work_read && index < tree.position_of.size() ? size_t(tree.position_of[index]) + 1 : SIZE_MAX;
  for (size_t k = from; k < tree.order.size() && count < kMaxPrefetched; ++k) {
    if (a.hit && !closest) break;  // an any-hit query ends at its first hit
    if (tree.order[k] < 0 || static_cast<uint64_t>(tree.order[k]) >= tree.sent.size()) continue;
    const auto j = static_cast<uint32_t>(tree.order[k]);
    const Ray given = r;
    a = test_here(q, j, closest, r);
    prefetched.put(j).put(static_cast<uint8_t>(closest)).put(given);
    put_answer(prefetched, a, closest);
    ++count;
  }
  out.put(count).put_bytes(prefetched.bytes());
}

const bool kCallbackServed = (serve_callback(Call::TestPrimitive, test_primitive), true);

// The hit record a traversal's answer names: the one the verifier's primitive
// wrote at that distance, or, for what no test of this query wrote (a record
// the worker's code made up), the distance and primitive alone.
void fill_hit(Intersection& isect, const Query& q, int64_t handle, double t) {
  if (handle >= 0) {
    const auto written = q.written.find(static_cast<uint32_t>(handle));
    if (written != q.written.end() && written->second.t == t) {
      isect = written->second;
      return;
    }
  }
  isect = Intersection();
  isect.t = t;
  isect.primitive = named_by(*q.tree, handle);
  isect.bsdf = handle >= 0 ? isect.primitive->get_bsdf() : handle == kElsewhereObject ? elsewhere_bsdf() : nullptr;
}

}  // namespace pt::boundary::bvh

namespace pt::boundary {

using bvh::BuiltTree;
using bvh::InUse;

TreeBuild::Sent::Sent(BVHAccel& accel) : accel_(accel), tree_(std::make_unique<BuiltTree>()) {
  static uint64_t next_id = 0;
  tree_->id = ++next_id;
  tree_->sent = accel.primitives();
  for (size_t i = 0; i < tree_->sent.size(); ++i) bvh::index_primitive(*tree_, tree_->sent[i], static_cast<int64_t>(i));
  in_use_ = std::make_unique<InUse>(*tree_, true);  // a build may test primitives too
}

TreeBuild::Sent::~Sent() = default;

void TreeBuild::Sent::put(Writer& w) const {
  // The worker builds within the address space this process may still map, so
  // that a build that never stops fails there as it would here: with
  // std::bad_alloc under a test's limit, not by taking the machine's memory.
  w.put(tree_->id).put(bvh::address_space_room()).put(static_cast<uint64_t>(tree_->sent.size()));
  for (const Primitive* p : tree_->sent) w.put(p->get_bbox()).put(static_cast<uint8_t>(p->get_bsdf() != nullptr));
}

void TreeBuild::Sent::whole(BVHAccel::PrimIter at, bool begin) const {
  if (at != (begin ? accel_.primitives().begin() : accel_.primitives().end()))
    throw std::logic_error("construct_bvh crosses the process boundary only over all of a BVHAccel's primitives, as "
                           "its constructor calls it (autograder/boundary/README.md)");
}

std::unique_ptr<BVHNode> TreeBuild::Sent::get_tree(Reader& r) {
  in_use_.reset();
  std::vector<int64_t> order = r.get_vector<int64_t>(kMaxPayload / sizeof(int64_t));
  std::vector<Primitive*> arranged;
  arranged.reserve(order.size());
  for (int64_t index : order) arranged.push_back(bvh::primitive_at(index, tree_->sent));
  std::vector<const BVHNode*> preorder;
  std::unique_ptr<BVHNode> root = bvh::get_tree(r, preorder);
  // The accelerator's own array, in the order the build left it (construct_bvh
  // is the accelerator's member: its array is not const).
  const_cast<std::vector<Primitive*>&>(accel_.primitives()) = std::move(arranged);
  tree_->root = root.get();
  for (size_t i = 0; i < preorder.size(); ++i) tree_->node_ids[preorder[i]] = static_cast<int64_t>(i);
  bvh::find_positions(*tree_, std::move(order));
  bvh::keep(&accel_, std::move(*tree_));
  return root;
}

Tree::Sent::Sent(const BVHAccel& accel)
    : tree_(bvh::built_tree(&accel, accel.root())), in_use_(std::make_unique<InUse>(tree_, primitive_tests_read())) {}

Tree::Sent::~Sent() = default;

void Tree::Sent::put(Writer& w) const { w.put(tree_.id); }

void Tree::Sent::put_node(Writer& w, const BVHNode* node) const {
  int64_t node_id = -1;
  if (node) {
    const auto found = tree_.node_ids.find(node);
    if (found == tree_.node_ids.end())
      throw std::logic_error("a traversal from a node that is not in this BVHAccel's tree cannot cross the process "
                             "boundary (autograder/boundary/README.md)");
    node_id = found->second;
  }
  w.put(node_id);
}

void Tree::Sent::put_hit(Writer& w, const Intersection& h) {
  t_before_ = h.t;
  handle_before_ = index_of(h.primitive, tree_.handle_of);
  w.put(h.t).put(handle_before_);
}

void Tree::Sent::get_hit(Reader& r, Intersection& h) const {
  const auto t = r.get<double>();
  const auto handle = r.get<int64_t>();
  if (handle != handle_before_ || t != t_before_) bvh::fill_hit(h, in_use_->query, handle, t);
}

}  // namespace pt::boundary
