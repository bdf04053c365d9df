// The handout's baseline builder and its variants (support/part2_baseline.h).
// A near-solution to P2T1: the student release ships it compiled only.
#include "support/part2_baseline.h"

#include <algorithm>
#include <numeric>

namespace pt::test::part2 {

const char* method_name(SplitMethod m) {
  switch (m) {
    case SplitMethod::kMeanSAH: return "three axes, mean centroid, surface-area cost (the baseline)";
    case SplitMethod::kMedianSAH: return "three axes, median centroid, surface-area cost";
    case SplitMethod::kMidpointSAH: return "three axes, centroid-box midpoint, surface-area cost";
    case SplitMethod::kObjectMedianLongest: return "longest axis, equal counts (single axis, no cost)";
    case SplitMethod::kMidpointLongest: return "longest axis, midpoint (single axis, no cost)";
    case SplitMethod::kMeanLongest: return "longest axis, mean centroid (single axis, no cost)";
    case SplitMethod::kMidpointX: return "x axis only, midpoint";
  }
  return "?";
}

namespace {

class Builder {
 public:
  Builder(std::vector<const Primitive*> prims, size_t leaf, SplitMethod m)
      : prims_(std::move(prims)), leaf_(std::max<size_t>(1, leaf)), method_(m) {
    for (const Primitive* p : prims_) {
      boxes_.push_back(p->get_bbox());
      centroids_.push_back(boxes_.back().centroid());
    }
    order_.resize(prims_.size());
    std::iota(order_.begin(), order_.end(), size_t(0));
  }

  FlatTree run() {
    FlatTree t;
    if (!prims_.empty()) build(0, order_.size(), -1, 0, t);
    for (size_t i : order_) t.prims.push_back(prims_[i]);
    return t;
  }

 private:
  struct Candidate {
    int axis = -1;
    double pos = 0.0;
  };

  Candidate choose(size_t s, size_t e, const BBox& cb) {
    const size_t n = e - s;
    switch (method_) {
      case SplitMethod::kMidpointLongest: {
        int a = cb.longest_axis();
        return {a, cb.centroid()[a]};
      }
      case SplitMethod::kMeanLongest: {
        int a = cb.longest_axis();
        double sum = 0.0;
        for (size_t i = s; i < e; ++i) sum += centroids_[order_[i]][a];
        return {a, sum / double(n)};
      }
      case SplitMethod::kMidpointX: return {0, cb.centroid().x};
      case SplitMethod::kObjectMedianLongest: return {cb.longest_axis(), kInf};  // handled by build()
      case SplitMethod::kMidpointSAH:
      case SplitMethod::kMeanSAH:
      case SplitMethod::kMedianSAH: break;
    }
    Candidate best;
    double best_cost = kInf;
    std::vector<double> coords;
    for (int a = 0; a < 3; ++a) {
      if (!(cb.max[a] > cb.min[a])) continue;
      double pos;
      if (method_ == SplitMethod::kMidpointSAH) {
        pos = cb.centroid()[a];
      } else if (method_ == SplitMethod::kMeanSAH) {
        double sum = 0.0;
        for (size_t i = s; i < e; ++i) sum += centroids_[order_[i]][a];
        pos = sum / double(n);
      } else {
        coords.clear();
        for (size_t i = s; i < e; ++i) coords.push_back(centroids_[order_[i]][a]);
        std::nth_element(coords.begin(), coords.begin() + coords.size() / 2, coords.end());
        pos = coords[coords.size() / 2];
      }
      BBox l, r;
      size_t nl = 0;
      for (size_t i = s; i < e; ++i) {
        size_t k = order_[i];
        if (centroids_[k][a] < pos) {
          l.expand(boxes_[k]);
          ++nl;
        } else {
          r.expand(boxes_[k]);
        }
      }
      if (nl == 0 || nl == n) continue;
      double cost = l.surface_area() * double(nl) + r.surface_area() * double(n - nl);
      if (cost < best_cost) {
        best_cost = cost;
        best = {a, pos};
      }
    }
    return best;
  }

  int build(size_t s, size_t e, int parent, int depth, FlatTree& t) {
    int idx = int(t.nodes.size());
    t.nodes.push_back({});
    BBox bb, cb;
    for (size_t i = s; i < e; ++i) {
      bb.expand(boxes_[order_[i]]);
      cb.expand(centroids_[order_[i]]);
    }
    FlatNode& n = t.nodes[size_t(idx)];
    n.bb = bb;
    n.start = s;
    n.end = e;
    n.parent = parent;
    n.depth = depth;
    if (e - s <= leaf_) return idx;
    Candidate c = choose(s, e, cb);
    size_t mid = s;
    if (method_ == SplitMethod::kObjectMedianLongest) {
      mid = s + (e - s) / 2;
      std::nth_element(order_.begin() + long(s), order_.begin() + long(mid), order_.begin() + long(e),
                       [&](size_t a, size_t b) { return centroids_[a][c.axis] < centroids_[b][c.axis]; });
    } else if (c.axis >= 0) {
      mid = size_t(std::partition(order_.begin() + long(s), order_.begin() + long(e),
                                  [&](size_t k) { return centroids_[k][c.axis] < c.pos; }) -
                   order_.begin());
    }
    if (mid == s || mid == e) mid = s + (e - s) / 2;
    int l = build(s, mid, idx, depth + 1, t);
    int r = build(mid, e, idx, depth + 1, t);
    t.nodes[size_t(idx)].left = l;
    t.nodes[size_t(idx)].right = r;
    return idx;
  }

  std::vector<const Primitive*> prims_;
  std::vector<BBox> boxes_;
  std::vector<Vec3> centroids_;
  std::vector<size_t> order_;
  size_t leaf_;
  SplitMethod method_;
};

}  // namespace

FlatTree build_framework_bvh(std::vector<const Primitive*> prims, size_t max_leaf_size, SplitMethod method) {
  return Builder(std::move(prims), max_leaf_size, method).run();
}

}  // namespace pt::test::part2
