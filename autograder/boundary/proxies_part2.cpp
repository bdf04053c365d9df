// The verifier's Part 2: each task function asks the worker (README.md and
// bvh_codec.h beside this file). construct_bvh sends the primitives' boxes and
// rebuilds the tree the worker's build made; the traversals name that tree.
// Every primitive test the worker's code makes is a call back to here, made on
// the verifier's own primitive, so that the tests' counting primitives count
// it where the tests run.
#include <algorithm>
#include <cstdio>
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

// Refuses, before anything is sent, a primitive that would behave otherwise
// here than in one process; maps it, and the shape a counting wrapper holds
// (which its intersect writes into a hit), to its index.
void index_primitive(BuiltTree& tree, const Primitive* p, int64_t index) {
  tree.handle_of[p] = index;
  if (dynamic_cast<const Triangle*>(p) || dynamic_cast<const Sphere*>(p)) return;
  if (const auto* c = dynamic_cast<const test::p2::CountingPrimitive*>(p)) return index_primitive(tree, c->inner(), index);
  cannot_cross(*p);
}

Primitive* primitive_at(int64_t index, const std::vector<Primitive*>& sent) {
  if (index >= 0 && static_cast<uint64_t>(index) < sent.size()) return sent[static_cast<size_t>(index)];
  if (index == bvh::kNoPrimitive || index == bvh::kElsewhere) return not_sent();
  throw boundary::LinkBroken("a primitive index out of range");
}

// What a handle of the worker's names here: a hit on something the worker
// made crosses as "something else", which no test's primitive equals.
const Primitive* named_by(const BuiltTree& tree, int64_t handle) {
  if (handle == bvh::kNoPrimitive) return nullptr;
  return handle == bvh::kElsewhere ? boundary::elsewhere_primitive() : primitive_at(handle, tree.sent);
}

int64_t handle_in(const BuiltTree& tree, const Primitive* p) {
  if (!p) return bvh::kNoPrimitive;
  const auto found = tree.handle_of.find(p);
  return found == tree.handle_of.end() ? bvh::kElsewhere : found->second;
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

class InUse {
 public:
  InUse(const BuiltTree& tree, bool work_read) : query_{&tree, work_read, {}}, previous_(g_query) { g_query = &query_; }
  ~InUse() { g_query = previous_; }
  InUse(const InUse&) = delete;
  InUse& operator=(const InUse&) = delete;
  const Query& query() const { return query_; }

 private:
  Query query_;
  Query* previous_;
};

// One test on the verifier's own primitive: a counting one counts it here.
bvh::TestAnswer test_here(Query& q, uint32_t index, bool closest, const Ray& r) {
  const Primitive& p = *q.tree->sent[index];
  Intersection hit;
  bvh::TestAnswer a;
  a.hit = closest ? p.intersect(r, &hit) : p.has_intersection(r);
  a.min_t = r.min_t;
  a.max_t = r.max_t;
  if (a.hit && closest) {
    a.t = hit.t;
    q.written[index] = hit;
  }
  return a;
}

void put_answer(Writer& out, const bvh::TestAnswer& a, bool closest) {
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
  if (index >= q.tree->sent.size()) throw boundary::LinkBroken("a primitive test of a primitive never sent");
  bvh::TestAnswer a = test_here(q, index, closest, r);
  put_answer(out, a, closest);
  Writer prefetched;
  uint32_t count = 0;
  const BuiltTree& tree = *q.tree;
  const size_t from = !q.work_read && index < tree.position_of.size() ? size_t(tree.position_of[index]) + 1 : SIZE_MAX;
  for (size_t k = from; k < tree.order.size() && count < bvh::kMaxPrefetched; ++k) {
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

const bool kCallbackServed = (boundary::serve_callback(Call::TestPrimitive, test_primitive), true);

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
  isect.bsdf = handle >= 0 ? isect.primitive->get_bsdf() : handle == bvh::kElsewhere ? boundary::elsewhere_bsdf() : nullptr;
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
  in.put(static_cast<uint8_t>(isect != nullptr));
  const int64_t handle_before = isect ? handle_in(tree, isect->primitive) : bvh::kNoPrimitive;
  if (isect) in.put(isect->t).put(handle_before);
  const InUse in_use(tree, test::p2::query_work_is_read());
  const std::string answer = call_worker(closest ? Call::BvhIntersect : Call::BvhHasIntersection, in);
  return boundary::read_answer([&] {
    Reader out(answer);
    const bool hit = out.get<uint8_t>() != 0;
    r.min_t = out.get<double>();
    r.max_t = out.get<double>();
    if (isect) {
      const auto t = out.get<double>();
      const auto handle = out.get<int64_t>();
      if (handle != handle_before || t != isect->t) fill_hit(*isect, in_use.query(), handle, t);
    }
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
  Writer in(64 + tree.sent.size() * 64);
  // The worker builds within the address space this process may still map, so
  // that a build that never stops fails there as it would here: with
  // std::bad_alloc under a test's limit, not by taking the machine's memory.
  in.put(tree.id).put(static_cast<uint64_t>(max_leaf_size)).put(bvh::address_space_room());
  in.put(static_cast<uint64_t>(tree.sent.size()));
  for (size_t i = 0; i < tree.sent.size(); ++i) {
    const Primitive* p = tree.sent[i];
    index_primitive(tree, p, static_cast<int64_t>(i));
    in.put(p->get_bbox()).put(static_cast<uint8_t>(p->get_bsdf() != nullptr));
  }
  std::string answer;
  {
    const InUse in_use(tree, true);  // a build may test primitives too
    answer = call_worker(Call::BuildBvh, in);
  }
  std::vector<const BVHNode*> preorder;
  std::vector<int64_t> order;
  std::unique_ptr<BVHNode> root = boundary::read_answer([&] {
    Reader out(answer);
    order = out.get_vector<int64_t>(boundary::kMaxPayload / sizeof(int64_t));
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
  find_positions(tree, std::move(order));
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
