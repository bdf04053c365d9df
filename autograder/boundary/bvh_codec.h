#pragma once
// Part 2 across the boundary (README.md beside this file): tasks.def's
// TreeBuild and Tree. A BVH's primitives cross once, when its constructor
// calls construct_bvh: each one's box and whether it has a BSDF, never its
// geometry. The worker builds over handles that hold only that, with the
// student's code, and sends back the order the build left them in and the
// tree in preorder; the verifier rebuilds the tree and keeps it. A traversal
// then names the tree and a node of it. Every primitive test the student's
// code makes on a handle is a call back to the verifier
// (Call::TestPrimitive), which makes it on its own primitive: the tests count
// work where they run, and the worker has no geometry to test any other way.
// A hit record's primitive crosses as its index (a handle). The verifier's
// halves are in bvh_verifier.cpp, the worker's in bvh_worker.cpp.
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <vector>

#include "crossing.h"
#include "hit_codec.h"
#include "geometry/bvh.h"
#include "objects.h"
#include "wire.h"

namespace pt::boundary::bvh {

// Neither end hears when a BVHAccel is freed (its destructor is the
// framework's): both keep the trees built last. A test holds a few at a time.
constexpr size_t kTreesKept = 16;

// What this process maps now: both ends measure the address-space room a
// build gets (the verifier's RLIMIT_AS minus this) with it.
inline rlim_t mapped_bytes() {
  unsigned long pages = 0;
  if (FILE* f = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(f, "%lu", &pages) != 1) pages = 0;
    std::fclose(f);
  }
  return static_cast<rlim_t>(pages) * static_cast<rlim_t>(::sysconf(_SC_PAGESIZE));
}

// The verifier's side: the address space it may still map (-1: no limit).
inline int64_t address_space_room() {
  rlimit l{};
  if (::getrlimit(RLIMIT_AS, &l) != 0 || l.rlim_cur == RLIM_INFINITY) return -1;
  const rlim_t mapped = mapped_bytes();
  return l.rlim_cur > mapped ? static_cast<int64_t>(l.rlim_cur - mapped) : 0;
}

// The worker's side: for the life of the object, at most `room` more bytes of
// address space than it maps now (no change for a negative room).
class AddressSpaceRoom {
 public:
  explicit AddressSpaceRoom(int64_t room) {
    if (room < 0 || ::getrlimit(RLIMIT_AS, &old_) != 0) return;
    rlimit l = old_;
    l.rlim_cur = std::min(old_.rlim_cur, mapped_bytes() + static_cast<rlim_t>(room));
    set_ = ::setrlimit(RLIMIT_AS, &l) == 0;
  }
  ~AddressSpaceRoom() {
    if (set_) ::setrlimit(RLIMIT_AS, &old_);
  }
  AddressSpaceRoom(const AddressSpaceRoom&) = delete;
  AddressSpaceRoom& operator=(const AddressSpaceRoom&) = delete;

 private:
  rlimit old_{};
  bool set_ = false;
};

// A tree in preorder: each node's box, range, and which of its children
// follow (left's subtree first). A valid tree over n primitives has 2n - 1
// nodes at most (the tests' largest scene: 21,000 primitives) and a useful one
// is shallow (the tests bound depth at 64; peeling one primitive a level over
// 21,000 goes 21,000 deep); the wire carries no more than these, so that a
// tree no honest build makes (a cycle, a chain of empty nodes) neither fills
// the link nor overflows the verifier's stack when it is freed.
constexpr uint8_t kLeftFollows = 1, kRightFollows = 2;
constexpr uint64_t kMaxNodes = uint64_t(1) << 20;
constexpr uint64_t kMaxDepth = uint64_t(1) << 16;

// The worker's side: fills `preorder` with the nodes in the order written.
inline void put_tree(Writer& out, const BVHNode* root, std::vector<const BVHNode*>& preorder) {
  preorder.clear();
  struct Item {
    const BVHNode* node;
    uint64_t depth;
  };
  std::vector<Item> stack;
  if (root) stack.push_back({root, 0});
  Writer nodes;
  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    if (preorder.size() >= kMaxNodes)
      throw std::runtime_error("construct_bvh made a tree of more than " + std::to_string(kMaxNodes) +
                               " nodes (a valid tree over n primitives has at most 2n - 1); the process boundary "
                               "carries no larger tree");
    if (item.depth > kMaxDepth)
      throw std::runtime_error("construct_bvh made a tree more than " + std::to_string(kMaxDepth) +
                               " levels deep; the process boundary carries no deeper tree");
    const BVHNode& n = *item.node;
    preorder.push_back(&n);
    const BBox box = n.bb;
    const uint8_t follows = (n.l ? kLeftFollows : 0) | (n.r ? kRightFollows : 0);
    nodes.put(box).put(static_cast<uint64_t>(n.start)).put(static_cast<uint64_t>(n.end)).put(follows);
    if (n.r) stack.push_back({n.r.get(), item.depth + 1});
    if (n.l) stack.push_back({n.l.get(), item.depth + 1});
  }
  out.put(static_cast<uint64_t>(preorder.size())).put_bytes(nodes.bytes());
}

// The verifier's side, without recursion: `preorder` gets the rebuilt nodes
// in the order read, so that a node crosses as its position there.
inline std::unique_ptr<BVHNode> get_tree(Reader& in, std::vector<const BVHNode*>& preorder) {
  preorder.clear();
  const auto count = in.get<uint64_t>();
  if (count > kMaxNodes) throw LinkBroken("a tree of more nodes than the link carries");
  std::unique_ptr<BVHNode> root;
  if (count == 0) return root;
  struct Slot {
    std::unique_ptr<BVHNode>* place;
    uint64_t depth;
  };
  std::vector<Slot> slots{{&root, 0}};
  for (uint64_t i = 0; i < count; ++i) {
    if (slots.empty()) throw LinkBroken("a tree whose nodes go on after its last one");
    const Slot slot = slots.back();
    slots.pop_back();
    if (slot.depth > kMaxDepth) throw LinkBroken("a tree deeper than the link carries");
    *slot.place = std::make_unique<BVHNode>();
    BVHNode& n = **slot.place;
    n.bb = in.get<BBox>();
    n.start = static_cast<size_t>(in.get<uint64_t>());
    n.end = static_cast<size_t>(in.get<uint64_t>());
    const auto follows = in.get<uint8_t>();
    if (follows & ~(kLeftFollows | kRightFollows)) throw LinkBroken("a tree node with children of no kind");
    preorder.push_back(&n);
    if (follows & kRightFollows) slots.push_back({&n.r, slot.depth + 1});
    if (follows & kLeftFollows) slots.push_back({&n.l, slot.depth + 1});
  }
  if (!slots.empty()) throw LinkBroken("a tree that ends before its last node");
  return root;
}

// What the worker learns of a primitive test: hit or not and the ray's range
// after it, and for a hit of intersect() its distance t. Never the normal or
// the barycentric coordinates, from which three hits would give a triangle
// back: the verifier keeps the hit records its primitives write and fills the
// traversal's answer from them.
struct TestAnswer {
  uint8_t hit = 0;
  double min_t = 0.0, max_t = 0.0;
  double t = 0.0;  // a hit of intersect(): its distance
};

// Besides the test asked for, in a query whose work nothing reads, the
// verifier answers the tests of the primitives that follow it in the build's
// order, each on the ray the one before left: the tests a traversal makes of
// the rest of a leaf, and often of the leaves after it. The worker answers a
// test from these when it asks exactly one of them, and calls back
// otherwise. What the tests count is never read in such a query, so that the
// tests answered ahead and never asked cost nothing but the verifier's time;
// in a query whose work is read, each test is a call back of its own.
struct Prefetched {
  uint32_t index;
  uint8_t closest;
  Ray ray;  // as the test would be given it
  TestAnswer answer;
};
constexpr uint32_t kMaxPrefetched = 32;

struct BuiltTree;
struct WorkerTree;
struct InUse;

}  // namespace pt::boundary::bvh

namespace pt::boundary {

// construct_bvh on all of a BVHAccel's primitives (BEGIN, END): their boxes
// go, the build's order and tree come back.
struct TreeBuild {
  static constexpr bool kCallsBack = true;
  struct Sent : SentObject {
    explicit Sent(BVHAccel& accel);
    ~Sent();
    void put(Writer& w) const;
    // BEGIN must be the first primitive, END past the last.
    void whole(BVHAccel::PrimIter at, bool begin) const;
    std::unique_ptr<BVHNode> get_tree(Reader& r);

   private:
    BVHAccel& accel_;
    std::unique_ptr<bvh::BuiltTree> tree_;
    std::unique_ptr<bvh::InUse> in_use_;
  };
  struct Held {
    explicit Held(Reader& in);
    ~Held();
    // The student's construct_bvh, called by the BVHAccel constructor.
    template <class Fn>
    std::unique_ptr<BVHNode> invoke(Fn, BVHAccel::PrimIter, BVHAccel::PrimIter, size_t max_leaf_size) {
      build(max_leaf_size);
      return nullptr;  // the tree is the accelerator's: put_tree sends it
    }
    void put_tree(Writer& w);
    void put_after(Writer&) const {}

   private:
    void build(size_t max_leaf_size);
    std::unique_ptr<bvh::WorkerTree> tree_;
    int64_t room_ = -1;
  };
};

// A traversal of a tree built across the boundary, from one of its nodes: the
// node crosses as its position in preorder, a hit record's primitive as its
// index.
struct Tree {
  static constexpr bool kCallsBack = true;
  struct Sent : SentObject {
    explicit Sent(const BVHAccel& accel);
    ~Sent();
    void put(Writer& w) const;
    void put_node(Writer& w, const BVHNode* node) const;
    void put_hit(Writer& w, const Intersection& h);
    void get_hit(Reader& r, Intersection& h) const;

   private:
    const bvh::BuiltTree& tree_;
    std::unique_ptr<bvh::InUse> in_use_;
    double t_before_ = 0.0;
    int64_t handle_before_ = 0;
  };
  struct Held : HeldObject<Held> {
    explicit Held(Reader& in);
    const BVHNode* get_node(Reader& r) const;
    void get_hit(Reader& r, Intersection& h) const;
    void put_hit(Writer& w, const Intersection& h) const;
    const BVHAccel& object() const;

   private:
    bvh::WorkerTree& tree_;
  };
};

}  // namespace pt::boundary
