// Part 2's BVH across the boundary (boundary/bvh_codec.h): a tree crosses
// whole in preorder and is rebuilt without recursion, however deep; a tree no
// honest worker sends (nodes past its end, a node missing, children of no
// kind, deeper or larger than the wire carries) breaks the link; a tree the
// worker could only have made by a cycle is refused before it is sent; a
// build gets the address-space room the verifier had.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "bvh_codec.h"

namespace pt::boundary::bvh {
namespace {

std::unique_ptr<BVHNode> node(size_t start, size_t end, double x) {
  auto n = std::make_unique<BVHNode>();
  n->bb = BBox(Vec3(x, 0, 0), Vec3(x + 1, 1, 1));
  n->start = start;
  n->end = end;
  return n;
}

// A chain `depth` levels below the root: each node's left child is a leaf of
// one primitive, its right child the rest of the chain (a build that peels one
// primitive a level).
std::unique_ptr<BVHNode> peeled(size_t depth) {
  auto root = node(0, depth + 1, 0.0);
  BVHNode* at = root.get();
  for (size_t i = 0; i < depth; ++i) {
    at->l = node(i, i + 1, double(i));
    at->r = node(i + 1, depth + 1, double(i) + 0.5);
    at = at->r.get();
  }
  return root;
}

// Frees a chain from the top, without the recursion of ~BVHNode.
void free_chain(std::unique_ptr<BVHNode> n) {
  while (n) {
    std::unique_ptr<BVHNode> next = std::move(n->r);
    n.reset();
    n = std::move(next);
  }
}

std::string tree_bytes(uint64_t count, const std::vector<uint8_t>& follows) {
  Writer w;
  w.put(count);
  for (uint8_t f : follows) w.put(BBox(Vec3(0.0), Vec3(1.0))).put(uint64_t(0)).put(uint64_t(1)).put(f);
  return w.bytes();
}

TEST(BvhCodec, ATreeCrossesInPreorderLeftFirst) {
  auto root = node(0, 3, 0.0);
  root->l = node(0, 1, 1.0);
  root->r = node(1, 3, 2.0);
  root->r->r = node(2, 3, 3.0);  // a right child alone
  Writer w;
  std::vector<const BVHNode*> sent;
  put_tree(w, root.get(), sent);
  Reader r(w.bytes());
  std::vector<const BVHNode*> got;
  std::unique_ptr<BVHNode> copy = get_tree(r, got);
  r.finish();
  ASSERT_EQ(got.size(), 4u);
  ASSERT_EQ(sent.size(), 4u);
  const double xs[] = {0.0, 1.0, 2.0, 3.0};
  for (size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i]->bb.min.x, xs[i]) << "node " << i << " in preorder";
    EXPECT_EQ(got[i]->start, sent[i]->start) << "node " << i;
    EXPECT_EQ(got[i]->end, sent[i]->end) << "node " << i;
    EXPECT_EQ(bool(got[i]->l), bool(sent[i]->l)) << "node " << i;
    EXPECT_EQ(bool(got[i]->r), bool(sent[i]->r)) << "node " << i;
  }
  EXPECT_EQ(copy->r->r.get(), got[3]);
  EXPECT_FALSE(copy->r->l);
}

TEST(BvhCodec, NoTreeCrossesAsNone) {
  Writer w;
  std::vector<const BVHNode*> sent;
  put_tree(w, nullptr, sent);
  Reader r(w.bytes());
  std::vector<const BVHNode*> got;
  EXPECT_EQ(get_tree(r, got), nullptr);
  r.finish();
  EXPECT_TRUE(got.empty());
}

// 20,000 levels: a peeling build over the tests' largest scenes. Both ends
// walk it with a stack of their own, not the call stack.
TEST(BvhCodec, ADegenerateTreeCrossesWithoutRecursion) {
  const size_t depth = 20000;
  auto root = peeled(depth);
  Writer w;
  std::vector<const BVHNode*> sent;
  put_tree(w, root.get(), sent);
  Reader r(w.bytes());
  std::vector<const BVHNode*> got;
  auto copy = get_tree(r, got);
  r.finish();
  EXPECT_EQ(got.size(), 2 * depth + 1);
  size_t levels = 0;
  for (const BVHNode* n = copy.get(); n->r; n = n->r.get()) ++levels;
  EXPECT_EQ(levels, depth);
  free_chain(std::move(root));
  free_chain(std::move(copy));
}

TEST(BvhCodec, AMalformedTreeBreaksTheLink) {
  struct Case {
    const char* what;
    std::string bytes;
  };
  const Case cases[] = {
      {"nodes after the tree ends", tree_bytes(2, {0, 0})},
      {"a child announced and missing", tree_bytes(1, {kLeftFollows})},
      {"children of no kind", tree_bytes(1, {8})},
      {"more nodes than the wire carries", tree_bytes(kMaxNodes + 1, {})},
      {"fewer nodes than counted", tree_bytes(3, {kLeftFollows | kRightFollows, 0})},
  };
  for (const Case& c : cases) {
    Reader r(c.bytes);
    std::vector<const BVHNode*> got;
    EXPECT_THROW(get_tree(r, got), LinkBroken) << c.what;
  }
}

TEST(BvhCodec, ATreeDeeperThanTheWireCarriesBreaksTheLink) {
  std::vector<uint8_t> chain(kMaxDepth + 2, kLeftFollows);
  chain.back() = 0;
  const std::string bytes = tree_bytes(chain.size(), chain);
  Reader r(bytes);
  std::vector<const BVHNode*> got;
  EXPECT_THROW(get_tree(r, got), LinkBroken);
}

// A node that is its own child (only hostile code makes one): the worker
// stops at the wire's limit and says so instead of writing forever.
TEST(BvhCodec, ACycleIsRefusedBeforeItIsSent) {
  auto root = node(0, 1, 0.0);
  root->l.reset(root.get());
  Writer w;
  std::vector<const BVHNode*> sent;
  try {
    put_tree(w, root.get(), sent);
    ADD_FAILURE() << "a cyclic tree was written";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("levels deep"), std::string::npos) << e.what();
  }
  (void)root->l.release();
}

// The worker builds within the verifier's room: 64 MiB more than it maps
// cannot hold 256 MiB, and the limit it had comes back afterwards.
TEST(BvhCodec, ABuildGetsTheRoomTheVerifierHad) {
  rlimit before{};
  ASSERT_EQ(::getrlimit(RLIMIT_AS, &before), 0);
  {
    const AddressSpaceRoom room(int64_t(64) << 20);
    EXPECT_THROW(std::vector<char>(size_t(256) << 20), std::bad_alloc);
    std::vector<char> fits(size_t(8) << 20);
    EXPECT_EQ(fits.size(), size_t(8) << 20);
  }
  rlimit after{};
  ASSERT_EQ(::getrlimit(RLIMIT_AS, &after), 0);
  EXPECT_EQ(after.rlim_cur, before.rlim_cur);
  std::vector<char> again(size_t(256) << 20);  // no limit left behind
  EXPECT_EQ(again.size(), size_t(256) << 20);
  const AddressSpaceRoom none(-1);  // no limit sent: none set
  rlimit unchanged{};
  ASSERT_EQ(::getrlimit(RLIMIT_AS, &unchanged), 0);
  EXPECT_EQ(unchanged.rlim_cur, before.rlim_cur);
}

}  // namespace
}  // namespace pt::boundary::bvh
