# Part 2 mutants: plausible student bugs in the BVH (P2T1 build, P2T2 slab
# test, P2T3 traversal). Each must make at least one graded test in
# tests/part2/ fail; the test expected to catch it is named above it.
set(p2 reference/part2_bvh.cpp)

# --- P2T2, the slab test -------------------------------------------------------

# No min/max swap: every slab with a negative direction component comes out
# reversed and the box is missed. Caught by BBoxSlab.HitsAndMisses (and every
# brute-force comparison).
pt_mutant(2 slab_no_swap ${p2} [[std::swap(t_near, t_far);]] [[(void)0;  // no swap]])

# Strict comparison: t0 == t1 counts as a miss, so every box of zero thickness
# (a flat mesh) is missed. Caught by BBoxSlab.FlatBoxes,
# BVHCorrectness.ClosestHitMatchesLinearScanOnMeshes (flat grids).
pt_mutant(2 slab_strict_flat ${p2} [[if (t0 > t1) return false;]] [[if (t0 >= t1) return false;]])

# std::max(t_near, t0) with the NaN first: 0 * inf = NaN (origin on a slab
# plane, zero direction component) then poisons the interval. Caught by
# BBoxSlab.AxisParallelRays (origin on the z = max plane).
pt_mutant(2 slab_nan_poison ${p2} [[    if (t_near > t0) t0 = t_near;
    if (t_far < t1) t1 = t_far;]] [[    t0 = std::max(t_near, t0);
    t1 = std::min(t_far, t1);]])

# Works on copies of t0 and t1: the right answer, but the caller's interval
# is never narrowed (so the traversal cannot order children by entry).
# Caught by BBoxSlab.NarrowsInterval (and the traversal work test).
pt_mutant(2 slab_not_narrowed ${p2} [[bool BBox::intersect(const Ray& r, double& t0, double& t1) const {]]
          [[bool BBox::intersect(const Ray& r, double& t0_out, double& t1_out) const {
  double t0 = t0_out, t1 = t1_out;  // the caller's [t0, t1] is never written]])

# Starts from the first slab instead of the incoming [t0, t1]: boxes behind
# the origin or beyond max_t count as hits. Caught by BBoxSlab.HitsAndMisses
# (box behind the origin), BBoxSlab.NarrowsInterval.
pt_mutant(2 slab_ignores_interval ${p2} [[    if (t_near > t0) t0 = t_near;
    if (t_far < t1) t1 = t_far;]] [[    if (a == 0 || t_near > t0) t0 = t_near;
    if (a == 0 || t_far < t1) t1 = t_far;]])

# --- P2T1, the build ------------------------------------------------------------

# The node's box misses the last primitive of its range. Caught by
# BVHStructure.InvariantsOnSoup (box not tight), brute-force comparisons.
pt_mutant(2 bbox_misses_last ${p2} [[node->bb.expand(b);]] [[if (it + 1 != end) node->bb.expand(b);]])

# The node stores a count where an index belongs. Caught by
# BVHStructure.InvariantsOnSoup (ranges do not tile), brute force.
pt_mutant(2 wrong_node_range ${p2} [[node->end = size_t(end - primitives_.begin());]]
          [[node->end = size_t(end - start);]])

# No fallback when no plane separates the centroids: a leaf of everything
# (the bounded form of "a split that never terminates on equal centroids").
# Caught by BVHDegenerate.AllCentroidsEqual (a leaf of 10,000 primitives).
pt_mutant(2 no_fallback_leaf ${p2} [[    mid = start + count / 2;]]
          [[    return node;  // cannot split: make a leaf of everything]])

# "Guarantees progress" by peeling one primitive off: terminates, but the
# tree over 10,000 equal centroids is 10,000 levels deep. Caught by
# BVHDegenerate.AllCentroidsEqual (depth bound).
pt_mutant(2 fallback_peels_one ${p2} [[    mid = start + count / 2;]] [[    mid = start + 1;]])

# The classic single-axis split: the middle of the centroid box along its
# longest axis, no cost model. Caught by BVHQuality.SahCostOnElongatedScene.
pt_mutant(2 single_axis_midpoint ${p2} [[Split split = best_binned_split(start, end, centroids);]]
          [[(void)&best_binned_split;  // no longer used
  Split split;
  split.axis = centroids.longest_axis();
  split.position = centroids.centroid()[split.axis];]])

# Only the x axis is ever considered. Caught by BVHQuality.SahCostOnMesh (and
# the other quality tests).
pt_mutant(2 x_axis_only ${p2} [[for (int axis = 0; axis < 3; ++axis) {]] [[for (int axis = 0; axis < 1; ++axis) {]])

# --- P2T3, traversal --------------------------------------------------------------

# Returns the first hit found in a leaf rather than the closest of the leaf.
# Caught by BVHCorrectness.ClosestHitMatchesLinearScanOnSoup.
pt_mutant(2 leaf_returns_first_hit ${p2} [[hit |= primitives_[i]->intersect(r, isect);]]
          [[if (primitives_[i]->intersect(r, isect)) return true;]])

# Returns as soon as the nearer child reports a hit: but boxes overlap, and
# the other child may hold a closer one. Caught by
# BVHCorrectness.ClosestHitMatchesLinearScanOnSoup.
pt_mutant(2 returns_first_child_hit ${p2} [[  bool hit = intersect(r, isect, first);
  if (tr0 <= r.max_t) hit |= intersect(r, isect, second);]] [[  if (intersect(r, isect, first)) return true;
  bool hit = false;
  if (tr0 <= r.max_t) hit |= intersect(r, isect, second);]])

# Tests primitives against a copy of the ray: max_t never shrinks, so a later,
# farther hit overwrites a nearer one (the traversal form of "forgetting to
# shrink max_t"; Triangle::intersect does shrink the ray it is given).
# Caught by BVHCorrectness.ClosestHitMatchesLinearScanOnSoup.
pt_mutant(2 ray_copy_no_shrink ${p2} [[hit |= primitives_[i]->intersect(r, isect);]]
          [[Ray copy = r;
      hit |= primitives_[i]->intersect(copy, isect);]])

# No pruning by max_t: every box along the ray is entered. Correct answers,
# more work. Caught by BVHTraversal.NearerChildFirstAndPruned.
pt_mutant(2 no_pruning ${p2} [[  double t0 = r.min_t, t1 = r.max_t;
  if (!node->bb.intersect(r, t0, t1)) return false;
  if (node->is_leaf()) {
    bool hit = false;
    for (size_t i = node->start; i < node->end; ++i) {
      ++work_counters().primitive_tests;
      hit |= primitives_[i]->intersect(r, isect);
    }
    return hit;
  }
  // Visit the child whose box the ray enters first; the far child is then
  // often pruned because intersect() has shrunk r.max_t below its entry.
  const BVHNode* first = node->l.get();
  const BVHNode* second = node->r.get();
  double tl0 = r.min_t, tl1 = r.max_t, tr0 = r.min_t, tr1 = r.max_t;
  bool hit_l = first->bb.intersect(r, tl0, tl1);
  bool hit_r = second->bb.intersect(r, tr0, tr1);
  if (hit_l && hit_r && tr0 < tl0) {
    std::swap(first, second);
    std::swap(tl0, tr0);
  } else if (!hit_l) {
    if (!hit_r) return false;
    return intersect(r, isect, second);
  } else if (!hit_r) {
    return intersect(r, isect, first);
  }
  bool hit = intersect(r, isect, first);
  if (tr0 <= r.max_t) hit |= intersect(r, isect, second);]] [[  double t0 = r.min_t, t1 = kInf;  // the box test ignores the current max_t
  if (!node->bb.intersect(r, t0, t1)) return false;
  if (node->is_leaf()) {
    bool hit = false;
    for (size_t i = node->start; i < node->end; ++i) {
      ++work_counters().primitive_tests;
      hit |= primitives_[i]->intersect(r, isect);
    }
    return hit;
  }
  // Both children, nearer first, but neither is ever skipped for lying
  // beyond the hit found so far.
  const BVHNode* first = node->l.get();
  const BVHNode* second = node->r.get();
  double tl0 = r.min_t, tl1 = kInf, tr0 = r.min_t, tr1 = kInf;
  bool hit_l = first->bb.intersect(r, tl0, tl1);
  bool hit_r = second->bb.intersect(r, tr0, tr1);
  if (hit_l && hit_r && tr0 < tl0) std::swap(first, second);
  bool hit = intersect(r, isect, first);
  hit |= intersect(r, isect, second);]])

# Visits the far child first (order reversed); pruning then rarely applies.
# Caught by BVHTraversal.NearerChildFirstAndPruned.
pt_mutant(2 far_child_first ${p2} [[if (hit_l && hit_r && tr0 < tl0) {]] [[if (hit_l && hit_r && tr0 > tl0) {]])

# Always the left child first, whatever the ray's direction. Caught by
# BVHTraversal.NearerChildFirstAndPruned.
pt_mutant(2 unordered_children ${p2} [[if (hit_l && hit_r && tr0 < tl0) {]] [[if (hit_l && hit_r && false) {]])

# any-hit never looks in the second child. Caught by
# BVHCorrectness.AnyHitAgreesWithLinearScan.
pt_mutant(2 anyhit_ignores_second_child ${p2}
          [[return has_intersection(r, node->l.get()) || has_intersection(r, node->r.get());]]
          [[return has_intersection(r, node->l.get());]])

# any-hit searches both children even after a hit. Caught by
# BVHTraversal.AnyHitStopsAtFirstHit.
pt_mutant(2 anyhit_no_early_exit ${p2}
          [[return has_intersection(r, node->l.get()) || has_intersection(r, node->r.get());]]
          [[bool hit_l = has_intersection(r, node->l.get());
  bool hit_r = has_intersection(r, node->r.get());
  return hit_l || hit_r;]])
