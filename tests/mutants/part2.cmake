# Part 2 mutants: plausible student bugs in the BVH (P2T1 build, P2T2 slab
# test, P2T3 traversal). Each must make at least one graded test in
# tests/part2/ fail; the test expected to catch it is named above it.
set(p2 reference/part2_bvh.cpp)

# --- P2T2, the slab test -------------------------------------------------------

# No min/max swap: every slab with a negative direction component comes out
# reversed and the box is missed. Caught by BBoxSlab.HitsAndMisses (and every
# brute-force comparison),
#   BBoxSlab.AxisParallelRays, BVHCorrectness.DeepTreeManyDeferredSubtrees, BVHTraversal.AnyHitStaysWithinTheRayInterval.
pt_mutant(2 slab_no_swap ${p2} [[if (inv_d[a] < 0.0) std::swap(t_near, t_far);]] [[(void)0;  // no swap]])

# Swaps when t_near > t_far instead of by the sign of the direction: with a
# -0.0 component and the origin on a slab plane, one of them is NaN and the
# comparison is false, so the infinities stay reversed. Caught by
# BBoxSlab.AxisParallelRays, BBoxSlab.NegativeZeroOnSlabPlane (hidden),
# BVHCorrectness.NegativeZeroComponentsOnGridLines (hidden).
pt_mutant(2 slab_swap_by_t ${p2} [[if (inv_d[a] < 0.0) std::swap(t_near, t_far);]]
          [[if (t_near > t_far) std::swap(t_near, t_far);]])

# Strict comparison: t0 == t1 counts as a miss, so every box of zero thickness
# (a flat mesh) is missed. Caught by BBoxSlab.FlatBoxes,
# BVHCorrectness.ClosestHitMatchesLinearScanOnMeshes (flat grids),
#   BVHCorrectness.DeepTreeManyDeferredSubtrees.
pt_mutant(2 slab_strict_flat ${p2} [[return t0 <= t1;]] [[return t0 < t1;]])

# std::max(t_near, t0) with the NaN first: 0 * inf = NaN (origin on a slab
# plane, zero direction component) then poisons the interval. Caught by
# BBoxSlab.AxisParallelRays (origin on the z = max plane).
pt_mutant(2 slab_nan_poison ${p2} [[    if (t_near > t0) t0 = t_near;
    if (t_far < t1) t1 = t_far;]] [[    t0 = std::max(t_near, t0);
    t1 = std::min(t_far, t1);]])

# Works on copies of t0 and t1: the right answer, but the caller's interval
# is never narrowed (so a traversal could not order children by entry).
# Caught by every BBoxSlab test that checks the narrowed interval on a hit,
#   BBoxSlab.AxisParallelRays.
pt_mutant(2 slab_not_narrowed ${p2}
          [[bool BBox::intersect(const Ray& r, double& t0, double& t1) const { return slab_test(*this, r.o, 1.0 / r.d, t0, t1); }]]
          [[bool BBox::intersect(const Ray& r, double& t0, double& t1) const {
  double a = t0, b = t1;  // the caller's [t0, t1] is never written
  return slab_test(*this, r.o, 1.0 / r.d, a, b);
}]])

# Starts from the first slab instead of the incoming [t0, t1]: boxes behind
# the origin or beyond max_t count as hits. Caught by BBoxSlab.HitsAndMisses
# (box behind the origin), BBoxSlab.NarrowsInterval,
#   BBoxSlab.AxisParallelRays, BVHTraversal.AnyHitStaysWithinTheRayInterval.
pt_mutant(2 slab_ignores_interval ${p2} [[    if (t_near > t0) t0 = t_near;
    if (t_far < t1) t1 = t_far;]] [[    if (a == 0 || t_near > t0) t0 = t_near;
    if (a == 0 || t_far < t1) t1 = t_far;]])

# --- P2T1, the build ------------------------------------------------------------

# The node's box misses the last primitive of its range. Caught by
# BVHStructure.InvariantsOnSoup (box not tight), brute-force comparisons,
#   BVHCorrectness.DeepTreeManyDeferredSubtrees, BVHQuality.SahCostWithOneHugeTriangle, BVHTraversal.AnyHitStaysWithinTheRayInterval.
pt_mutant(2 bbox_misses_last ${p2} [[node->bb.expand(prims_[i].box);]]
          [[if (i + 1 != end) node->bb.expand(prims_[i].box);]])

# The node's box is the box of the centroids, not of the primitives. Caught by
# BVHStructure.InvariantsOnSoup (a primitive sticks out of its leaf's box),
# brute-force comparisons,
#   BVHCorrectness.DeepTreeManyDeferredSubtrees, BVHQuality.SahCostWithOneHugeTriangle, BVHTraversal.AnyHitStaysWithinTheRayInterval.
pt_mutant(2 bbox_of_centroids ${p2} [[node->bb.expand(prims_[i].box);]] [[node->bb.expand(prims_[i].centroid);]])

# The node stores a count where an index belongs. Caught by
# BVHStructure.InvariantsOnSoup (ranges do not tile), brute force,
#   BVHCorrectness.DeepTreeManyDeferredSubtrees, BVHQuality.SahCostWithOneHugeTriangle, BVHTraversal.AnyHitStaysWithinTheRayInterval.
pt_mutant(2 wrong_node_range ${p2} [[node->end = first_index_ + end;]] [[node->end = end - begin;]])

# No fallback when no plane separates the centroids: a leaf of everything
# (the bounded form of "a split that never terminates on equal centroids").
# Caught by BVHDegenerate.AllCentroidsEqual (a leaf of 10,000 primitives).
pt_mutant(2 no_fallback_leaf ${p2} [[      mid = begin + (end - begin) / 2;]]
          [[      return;  // cannot split: make a leaf of everything]])

# "Guarantees progress" by peeling one primitive off: terminates, but the
# tree over 10,000 equal centroids is 10,000 levels deep. Caught by
# BVHDegenerate.AllCentroidsEqual (depth bound).
pt_mutant(2 fallback_peels_one ${p2} [[      mid = begin + (end - begin) / 2;]] [[      mid = begin + 1;]])

# max_leaf_size 0 taken literally: a range of one primitive is never a leaf;
# it cannot be split, the fallback halves it into an empty and a full half,
# and the build recurses on the same primitive until the stack overflows.
# Caught by BVHDegenerate.LeafSizeZeroMeansOne (hidden; the test crashes).
pt_mutant(2 leaf_size_zero_recurses ${p2} [[max_leaf_size_(std::max<size_t>(1, max_leaf_size))]]
          [[max_leaf_size_(max_leaf_size)]])

# The same bug once the compiler has made the endless recursion a loop: the
# build allocates nodes without end. Across the process boundary it runs
# under the address-space room the verifier had (autograder/boundary/
# bvh_codec.h), so the hidden test's 256 MiB stops it with std::bad_alloc.
# Caught by BVHDegenerate.LeafSizeZeroMeansOne (hidden; "ran out of 256 MiB").
pt_mutant(2 leaf_size_zero_allocates ${p2} [[  auto root = std::make_unique<BVHNode>();
  Builder(prims]] [[  if (max_leaf_size == 0) {
    std::vector<std::unique_ptr<BVHNode>> halves;
    for (;;) halves.push_back(std::make_unique<BVHNode>());
  }
  auto root = std::make_unique<BVHNode>();
  Builder(prims]])

# The classic single-axis split: the middle of the centroid box along its
# longest axis, no cost model. Caught by BVHQuality.SahCostOnElongatedScene.
pt_mutant(2 single_axis_midpoint ${p2} [[    Split split = best_split(begin, end, centroids);]]
          [[    Split split;
    split.axis = centroids.longest_axis();
    double extent = centroids.extent()[split.axis];
    split.binning = {centroids.min[split.axis], kBins / extent};
    split.last_left = kBins / 2 - 1;  // the middle of the centroid box
    if (!(extent > 0.0)) split.axis = -1;]])

# Only the x axis is ever considered. Caught by BVHQuality.SahCostOnMesh (and
# the other quality tests).
pt_mutant(2 x_axis_only ${p2} [[    for (int a = 0; a < 3; ++a) {
      if (!usable[a]) continue;
      std::array<double, kBins> right_cost{};]] [[    for (int a = 0; a < 1; ++a) {
      if (!usable[a]) continue;
      std::array<double, kBins> right_cost{};]])

# --- P2T3, traversal --------------------------------------------------------------

# Stops testing a leaf at its first hit rather than finding the closest of
# the leaf. Caught by BVHCorrectness.ClosestHitMatchesLinearScanOnSoup.
pt_mutant(2 leaf_returns_first_hit ${p2} [[for (size_t i = node->start; i < node->end; ++i) hit |= primitives_[i]->intersect(r, isect);]]
          [[for (size_t i = node->start; i < node->end; ++i) {
        if (primitives_[i]->intersect(r, isect)) {
          hit = true;
          break;
        }
      }]])

# `hit = ...` for `hit |= ...`: a miss later in the leaf forgets the hit
# found before it (isect still holds it, but the query reports a miss).
# Caught by BVHCorrectness.ClosestHitMatchesLinearScanOnSoup,
#   BVHCorrectness.DeepTreeManyDeferredSubtrees.
pt_mutant(2 leaf_hit_overwritten ${p2} [[hit |= primitives_[i]->intersect(r, isect);]]
          [[hit = primitives_[i]->intersect(r, isect);]])

# Returns at the first leaf with a hit: but boxes overlap, and a deferred
# subtree may hold a closer one. Caught by
# BVHCorrectness.ClosestHitMatchesLinearScanOnSoup.
pt_mutant(2 returns_first_leaf_hit ${p2} [[hit |= primitives_[i]->intersect(r, isect);]]
          [[hit |= primitives_[i]->intersect(r, isect);
      if (hit) return true;  // the deferred subtrees are never looked at]])

# Tests primitives against a copy of the ray: max_t never shrinks, so a later,
# farther hit overwrites a nearer one (the traversal form of "forgetting to
# shrink max_t"; Triangle::intersect does shrink the ray it is given).
# Caught by BVHCorrectness.ClosestHitMatchesLinearScanOnSoup,
#   BVHCorrectness.DeepTreeManyDeferredSubtrees.
pt_mutant(2 ray_copy_no_shrink ${p2} [[hit |= primitives_[i]->intersect(r, isect);]]
          [[{
        Ray copy = r;
        hit |= primitives_[i]->intersect(copy, isect);
      }]])

# No pruning by max_t: neither are children's boxes tested against the
# closest hit found so far, nor are deferred subtrees dropped when the ray
# enters them beyond it. (Either one alone still prunes: 1.00-1.06x the
# work.) Correct answers, more work. Caught by
# BVHTraversal.NearerChildFirstAndPruned.
pt_mutant(2 no_pruning ${p2} [[      ChildrenEntered e = enter_children(*node, r, inv_d);
      work.node_visits += 2;
      if (e.count == 2) {
        // The far child waits with its entry distance (or, past the stack's
        // depth, is searched right away).
        if (size < kStackSize) {
          stack[size++] = {e.far, e.far_t0};
        } else {
          hit |= intersect(r, isect, e.far);
        }
      }
      if (e.count > 0) {
        node = e.near;
        continue;
      }
    }
    // Resume with the latest deferred subtree that can still hold a nearer
    // hit: one whose box the ray enters before the closest hit found so far.
    while (size > 0 && stack[size - 1].t_enter > r.max_t) --size;]]
          [[      Ray whole = r;
      whole.max_t = kInf;  // boxes are tested against [min_t, inf)
      ChildrenEntered e = enter_children(*node, whole, inv_d);
      work.node_visits += 2;
      if (e.count == 2) {
        // The far child waits with its entry distance (or, past the stack's
        // depth, is searched right away).
        if (size < kStackSize) {
          stack[size++] = {e.far, e.far_t0};
        } else {
          hit |= intersect(r, isect, e.far);
        }
      }
      if (e.count > 0) {
        node = e.near;
        continue;
      }
    }
    // every deferred subtree is resumed, wherever the ray enters it]])

# Visits the far child first (order reversed); pruning then rarely applies.
# Caught by BVHTraversal.NearerChildFirstAndPruned.
pt_mutant(2 far_child_first ${p2} [[if (b_t0 < a_t0) e = {2, b, a, a_t0};]] [[if (b_t0 > a_t0) e = {2, b, a, a_t0};]])

# Always the left child first, whatever the ray's direction. Caught by
# BVHTraversal.NearerChildFirstAndPruned.
pt_mutant(2 unordered_children ${p2} [[if (b_t0 < a_t0) e = {2, b, a, a_t0};]] [[if (false) e = {2, b, a, a_t0};]])

# any-hit never looks in the second child when the ray enters both. Caught by
# BVHCorrectness.AnyHitAgreesWithLinearScan,
#   BVHCorrectness.DeepTreeManyDeferredSubtrees, BVHTraversal.AnyHitStaysWithinTheRayInterval.
pt_mutant(2 anyhit_ignores_second_child ${p2} [[stack[size++] = e.far;]] [[(void)e.far;  // never visited]])

# any-hit tests the whole leaf before it returns. Caught by
# BVHTraversal.AnyHitStopsAtFirstHit.
pt_mutant(2 anyhit_no_early_exit ${p2} [[      for (size_t i = node->start; i < node->end; ++i)
        if (primitives_[i]->has_intersection(r)) return true;]] [[      bool found = false;
      for (size_t i = node->start; i < node->end; ++i)
        found |= primitives_[i]->has_intersection(r);  // the whole leaf, even after a hit
      if (found) return true;]])

# any-hit descends into both children without testing their boxes: the right
# answer, from brute-force work (every primitive of a ray that hits nothing).
# Caught by BVHTraversal.AnyHitTestsOnlyLeavesTheRayEnters (hidden),
#   BVHTraversal.AnyHitStaysWithinTheRayInterval.
pt_mutant(2 anyhit_no_box_tests ${p2} [[      ChildrenEntered e = enter_children(*node, r, inv_d);
      work.node_visits += 2;
      if (e.count == 2) {
        if (size < kStackSize) {
          stack[size++] = e.far;]] [[      ChildrenEntered e{2, node->l.get(), node->r.get(), 0.0};  // no box tests: both children, always
      if (e.count == 2) {
        if (size < kStackSize) {
          stack[size++] = e.far;]])

# Orders the children by where the ray LEAVES their boxes instead of where it
# enters them: the same answers with a little more work (1.00-1.04x the
# ordered traversal's primitive tests, 1.28x on the huge triangle), which no
# work bound can tell from noise. Caught by BVHTraversal.NearerChildByEntryDistance (hidden).
pt_mutant(2 children_by_exit ${p2} [[if (b_t0 < a_t0) e = {2, b, a, a_t0};]] [[if (b_t1 < a_t1) e = {2, b, a, a_t0};]])

# Orders the children by the middle of the ray's stretch inside each box.
# Caught by BVHTraversal.NearerChildByEntryDistance (hidden).
pt_mutant(2 children_by_midpoint ${p2} [[if (b_t0 < a_t0) e = {2, b, a, a_t0};]]
          [[if (b_t0 + b_t1 < a_t0 + a_t1) e = {2, b, a, a_t0};]])

# A split cost built on the boxes' volumes instead of their surface areas: on
# meshes 1.2-1.26x the baseline's SAH cost, but on a flat mesh every box has
# zero volume, every split costs 0 and the first candidate (the lowest bin on
# x) wins at every level. Caught by BVHQuality.SahCostOnFlatPlane.
pt_mutant(2 volume_cost ${p2} [[        right_cost[k] = box.surface_area() * double(n);
      }
      box = BBox();
      n = 0;
      for (int k = 0; k < kBins - 1; ++k) {
        box.expand(bins[a][k].box);
        n += bins[a][k].count;
        double cost = box.surface_area() * double(n) + right_cost[k + 1];]]
          [[        right_cost[k] = box.extent().x * box.extent().y * box.extent().z * double(n);
      }
      box = BBox();
      n = 0;
      for (int k = 0; k < kBins - 1; ++k) {
        box.expand(bins[a][k].box);
        n += bins[a][k].count;
        double cost = box.extent().x * box.extent().y * box.extent().z * double(n) + right_cost[k + 1];]])

# Binned SAH whose left-to-right sweep does not reset the box the right-to-left
# sweep grew: every left side costs the whole node's area, so the builder
# peels few primitives off the left at each level. Bad trees, right answers.
# Caught by BVHQuality.SahCostWithOneHugeTriangle (3.1-3.9x the baseline's cost, factor 2).
pt_mutant(2 sah_left_box_not_reset ${p2} [[      box = BBox();
      n = 0;
      for (int k = 0; k < kBins - 1; ++k) {]] [[      n = 0;
      for (int k = 0; k < kBins - 1; ++k) {]])

# any-hit written recursively, testing every box on [0, inf) instead of the
# ray's interval: right answers, but a shadow ray tests the primitives of
# every leaf along its line, beyond its light.
# Caught by BVHTraversal.AnyHitStaysWithinTheRayInterval.
pt_mutant(2 anyhit_range_blind ${p2} [[bool BVHAccel::has_intersection(const Ray& r, const BVHNode* node) const {
  QueryWork work;]] [[bool BVHAccel::has_intersection(const Ray& r, const BVHNode* node) const {
  {
    double b0 = 0.0, b1 = kInf;  // the box on the whole half-line
    if (!node->bb.intersect(r, b0, b1)) return false;
    if (node->is_leaf()) {
      for (size_t i = node->start; i < node->end; ++i)
        if (primitives_[i]->has_intersection(r)) return true;
      return false;
    }
    return has_intersection(r, node->l.get()) || has_intersection(r, node->r.get());
  }
  QueryWork work;]])

# A closest-hit stack of 16 entries that silently drops a far child when
# full: a ray that defers more than 16 subtrees at once misses its closest
# hit when it waits in a dropped one.
# Caught by BVHCorrectness.DeepTreeManyDeferredSubtrees.
pt_mutant(2 stack16_drops_far_child ${p2} [[        if (size < kStackSize) {
          stack[size++] = {e.far, e.far_t0};
        } else {
          hit |= intersect(r, isect, e.far);
        }]] [[        if (size < 16) stack[size++] = {e.far, e.far_t0};  // full: dropped]])
