// Part 2 reference: a binned surface-area-heuristic BVH with ordered traversal.
#include <algorithm>
#include <array>

#include "core/stats.h"
#include "geometry/bvh.h"

namespace pt {

namespace {

constexpr int kBins = 16;

struct Bin {
  BBox bounds;
  size_t count = 0;
};

// Cost of a split up to constants: sum over children of area x count (the
// expected number of primitive tests for a ray that hits the parent).
struct Split {
  int axis = -1;
  double position = 0.0;
  double cost = kInf;
};

Split best_binned_split(BVHAccel::PrimIter start, BVHAccel::PrimIter end, const BBox& centroids) {
  Split best;
  for (int axis = 0; axis < 3; ++axis) {
    double lo = centroids.min[axis], extent = centroids.max[axis] - lo;
    if (!(extent > 0.0)) continue;  // all centroids share this coordinate: no split here
    std::array<Bin, kBins> bins;
    for (auto it = start; it != end; ++it) {
      BBox b = (*it)->get_bbox();
      int i = std::min(kBins - 1, int(kBins * (b.centroid()[axis] - lo) / extent));
      bins[i].bounds.expand(b);
      ++bins[i].count;
    }
    // Sweep from the right to get suffix boxes, then from the left.
    std::array<double, kBins> right_cost{};
    BBox acc;
    size_t n = 0;
    for (int i = kBins - 1; i > 0; --i) {
      acc.expand(bins[i].bounds);
      n += bins[i].count;
      right_cost[i] = acc.surface_area() * n;
    }
    acc = BBox();
    n = 0;
    for (int i = 0; i < kBins - 1; ++i) {
      acc.expand(bins[i].bounds);
      n += bins[i].count;
      double cost = acc.surface_area() * n + right_cost[i + 1];
      if (n > 0 && cost < best.cost) best = {axis, lo + extent * (i + 1) / kBins, cost};
    }
  }
  return best;
}

}  // namespace

// P2T1
std::unique_ptr<BVHNode> BVHAccel::construct_bvh(PrimIter start, PrimIter end, size_t max_leaf_size) {
  auto node = std::make_unique<BVHNode>();
  BBox centroids;
  for (auto it = start; it != end; ++it) {
    BBox b = (*it)->get_bbox();
    node->bb.expand(b);
    centroids.expand(b.centroid());
  }
  node->start = size_t(start - primitives_.begin());
  node->end = size_t(end - primitives_.begin());
  const size_t count = size_t(end - start);
  if (count <= std::max<size_t>(1, max_leaf_size)) return node;

  Split split = best_binned_split(start, end, centroids);
  PrimIter mid = start;
  if (split.axis >= 0) {
    mid = std::partition(start, end, [&](Primitive* p) { return p->get_bbox().centroid()[split.axis] < split.position; });
  }
  if (mid == start || mid == end) {
    // No split separates the centroids (they coincide): halve the range by
    // count so that depth stays logarithmic and the build terminates.
    mid = start + count / 2;
  }
  node->l = construct_bvh(start, mid, max_leaf_size);
  node->r = construct_bvh(mid, end, max_leaf_size);
  return node;
}

// P2T2
bool BBox::intersect(const Ray& r, double& t0, double& t1) const {
  for (int a = 0; a < 3; ++a) {
    double inv = 1.0 / r.d[a];  // +-inf for axis-parallel rays: slabs become all-or-nothing
    double t_near = (min[a] - r.o[a]) * inv;
    double t_far = (max[a] - r.o[a]) * inv;
    if (inv < 0.0) std::swap(t_near, t_far);  // by the sign of inv, which a NaN t cannot confuse (d = -0.0)
    // 0 * inf = NaN when the origin lies on a slab plane of a parallel ray;
    // these comparisons are false for NaN, so such a slab leaves [t0, t1] alone.
    if (t_near > t0) t0 = t_near;
    if (t_far < t1) t1 = t_far;
    if (t0 > t1) return false;
  }
  return true;
}

// P2T3
bool BVHAccel::has_intersection(const Ray& r, const BVHNode* node) const {
  ++work_counters().node_visits;
  double t0 = r.min_t, t1 = r.max_t;
  if (!node->bb.intersect(r, t0, t1)) return false;
  if (node->is_leaf()) {
    for (size_t i = node->start; i < node->end; ++i) {
      ++work_counters().primitive_tests;
      if (primitives_[i]->has_intersection(r)) return true;
    }
    return false;
  }
  return has_intersection(r, node->l.get()) || has_intersection(r, node->r.get());
}

bool BVHAccel::intersect(const Ray& r, Intersection* isect, const BVHNode* node) const {
  ++work_counters().node_visits;
  double t0 = r.min_t, t1 = r.max_t;
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
  if (tr0 <= r.max_t) hit |= intersect(r, isect, second);
  return hit;
}

}  // namespace pt
