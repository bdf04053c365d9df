#include "ladder.h"

#include <emmintrin.h>  // SSE2: part of every x86-64 target, so no -m flag is needed

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <stdexcept>

#include "geometry/triangle.h"

namespace pt::bench::ladder {
namespace {

// Deepest tree the steps take (the benchmark scenes' are 13 to 25 levels
// deep); the traversals' stacks hold three entries per level (4-wide nodes).
constexpr int kStackSize = 128;

int depth_of(const BVHNode* root) {
  struct Item {
    const BVHNode* n;
    int depth;
  };
  int deepest = 0;
  std::vector<Item> todo{{root, 0}};
  while (!todo.empty()) {
    Item it = todo.back();
    todo.pop_back();
    deepest = std::max(deepest, it.depth);
    if (!it.n->is_leaf()) {
      todo.push_back({it.n->l.get(), it.depth + 1});
      todo.push_back({it.n->r.get(), it.depth + 1});
    }
  }
  return deepest;
}

// Outward rounding to float, so that a float box contains the double one.
float round_down(double v) {
  float f = float(v);
  return double(f) > v ? std::nextafter(f, -INFINITY) : f;
}
float round_up(double v) {
  float f = float(v);
  return double(f) < v ? std::nextafter(f, INFINITY) : f;
}

// The double slab test of the reference, on a box given as lo[3], hi[3].
template <class T>
inline bool slab(const T* lo, const T* hi, const Ray& r, const Vec3& inv_d, double& t0, double& t1) {
  for (int a = 0; a < 3; ++a) {
    double t_near = (double(lo[a]) - r.o[a]) * inv_d[a];
    double t_far = (double(hi[a]) - r.o[a]) * inv_d[a];
    if (inv_d[a] < 0.0) std::swap(t_near, t_far);
    if (t_near > t0) t0 = t_near;
    if (t_far < t1) t1 = t_far;
  }
  return t0 <= t1;
}

// --- Leaf triangles ------------------------------------------------------------

// A triangle's vertices, stored in leaf order.
struct LeafTriangle {
  Vec3 p1, p2, p3;
};

// The arithmetic of reference/part1's watertight test, operation for
// operation, so that the hit distances agree with the reference to the bit.
inline bool watertight(const LeafTriangle& tri, const Ray& r, double* t_hit) {
  const Vec3 ad = glm::abs(r.d);
  const int kz = ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
  int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  if (r.d[kz] < 0.0) std::swap(kx, ky);
  const double sx = r.d[kx] / r.d[kz], sy = r.d[ky] / r.d[kz], sz = 1.0 / r.d[kz];
  const Vec3 a = tri.p1 - r.o, b = tri.p2 - r.o, c = tri.p3 - r.o;
  const double ax = a[kx] - sx * a[kz], ay = a[ky] - sy * a[kz];
  const double bx = b[kx] - sx * b[kz], by = b[ky] - sy * b[kz];
  const double cx = c[kx] - sx * c[kz], cy = c[ky] - sy * c[kz];
  const double u = cx * by - cy * bx, v = ax * cy - ay * cx, w = bx * ay - by * ax;
  if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return false;
  const double det = u + v + w;
  if (det == 0.0) return false;
  const double t = (u * (sz * a[kz]) + v * (sz * b[kz]) + w * (sz * c[kz])) / det;
  if (!(t >= r.min_t && t <= r.max_t)) return false;
  *t_hit = t;
  return true;
}

// Steps 3 to 5 copy triangles; they cannot take any other primitive.
const Triangle& as_triangle(const Primitive* p) {
  const auto* t = dynamic_cast<const Triangle*>(p);
  if (!t) throw std::invalid_argument("a primitive other than a triangle");
  return *t;
}

// The primitives of a tree, in leaf order: the BVH's own pointer array for
// the virtual calls of steps 1 and 2, copied triangles for steps 3 and 4.
struct Leaves {
  const std::vector<Primitive*>& prims;  // the BVH's, which outlives every step
  std::vector<LeafTriangle> triangles;   // empty unless copy_triangles

  explicit Leaves(const BVHAccel& bvh, bool copy_triangles) : prims(bvh.primitives()) {
    if (!copy_triangles) return;
    triangles.reserve(prims.size());
    for (const Primitive* p : prims) {
      const Triangle& t = as_triangle(p);
      triangles.push_back({t.p1(), t.p2(), t.p3()});
    }
  }

  // Closest hit among [first, first + count): shrinks r.max_t like Primitive::intersect.
  template <bool kTriangles>
  bool closest(uint32_t first, uint32_t count, const Ray& r) const {
    bool hit = false;
    for (uint32_t i = first; i < first + count; ++i) {
      if constexpr (kTriangles) {
        double t;
        if (watertight(triangles[i], r, &t)) {
          r.max_t = t;
          hit = true;
        }
      } else {
        Intersection isect;
        hit |= prims[i]->intersect(r, &isect);
      }
    }
    return hit;
  }
  template <bool kTriangles>
  bool any(uint32_t first, uint32_t count, const Ray& r) const {
    for (uint32_t i = first; i < first + count; ++i) {
      if constexpr (kTriangles) {
        double t;
        if (watertight(triangles[i], r, &t)) return true;
      } else if (prims[i]->has_intersection(r)) {
        return true;
      }
    }
    return false;
  }
  size_t bytes() const { return prims.size() * sizeof(Primitive*) + triangles.size() * sizeof(LeafTriangle); }
};

// --- The traversal every step shares -----------------------------------------------

// A subtree the traversal has deferred, and where the ray enters its box.
struct Pending {
  uint32_t node;
  double t_enter;
};

// The interior children of a node that the ray enters, farthest first.
struct Entered {
  int count = 0;
  Pending child[4];
  void add(uint32_t node, double t_enter) {
    int i = count++;
    for (; i > 0 && child[i - 1].t_enter < t_enter; --i) child[i] = child[i - 1];  // insertion sort
    child[i] = {node, t_enter};
  }
};

// Front to back, as the reference traverses: `expand(node, &entered)` tests
// the node's leaf children (shrinking r.max_t at hits; it returns whether one
// hit) and lists the interior children the ray enters. The nearest is taken
// next, the others wait with their entry distance and are dropped once the
// ray's closest hit lies before it.
template <class Expand>
bool closest_loop(uint32_t root, const Ray& r, const Expand& expand) {
  Pending stack[3 * kStackSize];
  int size = 0;
  uint32_t cur = root;
  bool hit = false;
  for (;;) {
    Entered e;
    hit |= expand(cur, &e);
    if (e.count > 0) {
      for (int i = 0; i < e.count - 1; ++i) stack[size++] = e.child[i];
      cur = e.child[e.count - 1].node;
      continue;
    }
    while (size > 0 && stack[size - 1].t_enter > r.max_t) --size;
    if (size == 0) return hit;
    cur = stack[--size].node;
  }
}

// The same for any hit: `expand` returns true at the first hit.
template <class Expand>
bool any_loop(uint32_t root, const Expand& expand) {
  uint32_t stack[3 * kStackSize];
  int size = 0;
  uint32_t cur = root;
  for (;;) {
    Entered e;
    if (expand(cur, &e)) return true;
    for (int i = 0; i < e.count; ++i) stack[size++] = e.child[i].node;  // the nearest is popped first
    if (size == 0) return false;
    cur = stack[--size];
  }
}

// --- Step 1: flat ------------------------------------------------------------------

struct alignas(64) FlatNode {
  BBox bb;
  uint32_t first = 0;  // leaf: its first primitive; interior: the left child (the right one follows it)
  uint32_t count = 0;  // leaf: its primitives; 0 for an interior node
};

class Flat final : public Step {
 public:
  explicit Flat(const BVHAccel& bvh) : leaves_(bvh, false) {
    struct Item {
      const BVHNode* src;
      uint32_t dst;
    };
    nodes_.emplace_back();
    std::vector<Item> todo{{bvh.root(), 0}};
    while (!todo.empty()) {
      Item it = todo.back();
      todo.pop_back();
      FlatNode& n = nodes_[it.dst];
      n.bb = it.src->bb;
      if (it.src->is_leaf()) {
        n.first = uint32_t(it.src->start);
        n.count = uint32_t(it.src->size());
        continue;
      }
      uint32_t left = uint32_t(nodes_.size());
      nodes_[it.dst].first = left;  // before emplace_back moves the array
      nodes_.emplace_back();
      nodes_.emplace_back();
      todo.push_back({it.src->r.get(), left + 1});
      todo.push_back({it.src->l.get(), left});
    }
  }
  std::string name() const override { return "flat"; }
  size_t bytes() const override { return nodes_.size() * sizeof(FlatNode) + leaves_.bytes(); }

  double closest(const Ray& ray) const override {
    Ray r = ray;
    const Vec3 inv_d = 1.0 / r.d;
    if (!enters_root(r, inv_d)) return kInf;
    auto expand = [&](uint32_t node, Entered* e) { return this->expand<false>(node, r, inv_d, e); };
    return closest_loop(0, r, expand) ? r.max_t : kInf;
  }

  bool any(const Ray& r) const override {
    const Vec3 inv_d = 1.0 / r.d;
    if (!enters_root(r, inv_d)) return false;
    return any_loop(0, [&](uint32_t node, Entered* e) { return expand<true>(node, r, inv_d, e); });
  }

 private:
  bool enters_root(const Ray& r, const Vec3& inv_d) const {
    double t0 = r.min_t, t1 = r.max_t;
    return slab(&nodes_[0].bb.min[0], &nodes_[0].bb.max[0], r, inv_d, t0, t1);
  }

  // A leaf node is tested; an interior one lists the children the ray enters.
  template <bool kAny>
  bool expand(uint32_t node, const Ray& r, const Vec3& inv_d, Entered* e) const {
    const FlatNode& n = nodes_[node];
    if (n.count) return kAny ? leaves_.any<false>(n.first, n.count, r) : leaves_.closest<false>(n.first, n.count, r);
    for (uint32_t c = n.first; c < n.first + 2; ++c) {
      double t0 = r.min_t, t1 = r.max_t;
      if (slab(&nodes_[c].bb.min[0], &nodes_[c].bb.max[0], r, inv_d, t0, t1)) e->add(c, t0);
    }
    return false;
  }

  std::vector<FlatNode> nodes_;
  Leaves leaves_;
};

// --- Steps 2 and 3: float pairs (with copied triangles) -----------------------------

// Both children of an interior node in one cache line.
struct alignas(64) PairNode {
  float lo[2][3], hi[2][3];
  uint32_t first[2];  // a leaf child: its first primitive; an interior child: its node
  uint32_t count[2];  // a leaf child: its primitives; 0: an interior child
};

// The root's box, and the root itself when it is a leaf (a tree of one leaf
// has no interior node to hold its box).
struct RootRef {
  float lo[3], hi[3];
  uint32_t first = 0, count = 0;  // count > 0: the root is a leaf
};

void set_box(float lo[3], float hi[3], const BBox& b) {
  for (int a = 0; a < 3; ++a) {
    lo[a] = round_down(b.min[a]);
    hi[a] = round_up(b.max[a]);
  }
}

template <bool kTriangles>
class FloatPairs final : public Step {
 public:
  explicit FloatPairs(const BVHAccel& bvh) : leaves_(bvh, kTriangles) {
    const BVHNode* root = bvh.root();
    set_box(root_.lo, root_.hi, root->bb);
    if (root->is_leaf()) {
      root_.first = uint32_t(root->start);
      root_.count = uint32_t(root->size());
      return;
    }
    struct Item {
      const BVHNode* src;
      uint32_t dst;
    };
    nodes_.emplace_back();
    std::vector<Item> todo{{root, 0}};
    while (!todo.empty()) {
      Item it = todo.back();
      todo.pop_back();
      const BVHNode* child[2] = {it.src->l.get(), it.src->r.get()};
      for (int c = 0; c < 2; ++c) {
        set_box(nodes_[it.dst].lo[c], nodes_[it.dst].hi[c], child[c]->bb);
        if (child[c]->is_leaf()) {
          nodes_[it.dst].first[c] = uint32_t(child[c]->start);
          nodes_[it.dst].count[c] = uint32_t(child[c]->size());
        } else {
          uint32_t k = uint32_t(nodes_.size());
          nodes_.emplace_back();
          nodes_[it.dst].first[c] = k;
          nodes_[it.dst].count[c] = 0;
          todo.push_back({child[c], k});
        }
      }
    }
  }
  std::string name() const override { return kTriangles ? "+ triangles" : "float pairs"; }
  size_t bytes() const override { return nodes_.size() * sizeof(PairNode) + leaves_.bytes(); }

  double closest(const Ray& ray) const override {
    Ray r = ray;
    const Vec3 inv_d = 1.0 / r.d;
    double t0 = r.min_t, t1 = r.max_t;
    if (!slab(root_.lo, root_.hi, r, inv_d, t0, t1)) return kInf;
    if (root_.count) return leaves_.template closest<kTriangles>(root_.first, root_.count, r) ? r.max_t : kInf;
    auto expand = [&](uint32_t node, Entered* e) { return this->template expand<false>(node, r, inv_d, e); };
    return closest_loop(0, r, expand) ? r.max_t : kInf;
  }

  bool any(const Ray& r) const override {
    const Vec3 inv_d = 1.0 / r.d;
    double t0 = r.min_t, t1 = r.max_t;
    if (!slab(root_.lo, root_.hi, r, inv_d, t0, t1)) return false;
    if (root_.count) return leaves_.template any<kTriangles>(root_.first, root_.count, r);
    return any_loop(0, [&](uint32_t node, Entered* e) { return this->template expand<true>(node, r, inv_d, e); });
  }

 private:
  // Tests both children's boxes from the one node; leaf children are tested
  // right away, interior ones listed.
  template <bool kAny>
  bool expand(uint32_t node, const Ray& r, const Vec3& inv_d, Entered* e) const {
    const PairNode& n = nodes_[node];
    bool hit = false;
    for (int c = 0; c < 2; ++c) {
      double t0 = r.min_t, t1 = r.max_t;
      if (!slab(n.lo[c], n.hi[c], r, inv_d, t0, t1)) continue;
      if (n.count[c] == 0) {
        e->add(n.first[c], t0);
      } else if (kAny) {
        if (leaves_.template any<kTriangles>(n.first[c], n.count[c], r)) return true;
      } else if (!(t0 > r.max_t)) {  // the other child's leaf may have shrunk max_t
        hit |= leaves_.template closest<kTriangles>(n.first[c], n.count[c], r);
      }
    }
    return hit;
  }

  RootRef root_;
  std::vector<PairNode> nodes_;
  Leaves leaves_;
};

// --- Step 4: four children per node, SSE box tests -----------------------------------

struct alignas(64) WideNode {
  float lo[3][4], hi[3][4];  // [axis][child]: one SSE register per row
  uint32_t first[4];
  uint32_t count[4];  // as in PairNode; kEmpty marks an unused slot
  static constexpr uint32_t kEmpty = 0xffffffffu;
};

// A ray as the SSE box test uses it. The float origin differs from the double
// one by up to half an ulp per axis; that shift, times |1/d|, widens every
// slab (delta), and a relative 2^-21 covers the float arithmetic, so the test
// never rejects a box the double test would enter.
struct WideRay {
  __m128 o[3], inv_d[3], delta[3];
  bool negative[3];
};

WideRay make_wide_ray(const Ray& r) {
  WideRay w;
  for (int a = 0; a < 3; ++a) {
    float o = float(r.o[a]);
    double inv = 1.0 / r.d[a];
    double err = std::abs(r.o[a] - double(o));
    w.o[a] = _mm_set1_ps(o);
    w.inv_d[a] = _mm_set1_ps(float(inv));
    w.delta[a] = _mm_set1_ps(err > 0.0 ? round_up(err * std::abs(inv) + 1e-30) : 0.0f);
    w.negative[a] = std::signbit(inv);
  }
  return w;
}

// The children of `n` the ray enters within [t0, t1], as a bit mask; their
// entry distances in *t_enter.
inline int enter_wide(const WideNode& n, const WideRay& w, float t0, float t1, float t_enter[4]) {
  const __m128 eps = _mm_set1_ps(1.0f / (1 << 21));
  const __m128 abs_mask = _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff));
  const __m128 largest = _mm_set1_ps(FLT_MAX);
  // The widening |t| 2^-21 + delta, at most FLT_MAX: an infinite t (a ray
  // parallel to the slab) stays infinite instead of becoming inf - inf = NaN.
  auto widening = [&](__m128 t, __m128 delta) {
    return _mm_min_ps(_mm_add_ps(_mm_mul_ps(_mm_and_ps(t, abs_mask), eps), delta), largest);
  };
  __m128 lo_t = _mm_set1_ps(t0), hi_t = _mm_set1_ps(t1);
  for (int a = 0; a < 3; ++a) {
    __m128 near_plane = _mm_load_ps(w.negative[a] ? n.hi[a] : n.lo[a]);
    __m128 far_plane = _mm_load_ps(w.negative[a] ? n.lo[a] : n.hi[a]);
    __m128 tn = _mm_mul_ps(_mm_sub_ps(near_plane, w.o[a]), w.inv_d[a]);
    __m128 tf = _mm_mul_ps(_mm_sub_ps(far_plane, w.o[a]), w.inv_d[a]);
    tn = _mm_sub_ps(tn, widening(tn, w.delta[a]));
    tf = _mm_add_ps(tf, widening(tf, w.delta[a]));
    // maxps/minps return their second operand when the first is NaN (0 * inf:
    // the origin on a slab plane), which leaves the interval alone.
    lo_t = _mm_max_ps(tn, lo_t);
    hi_t = _mm_min_ps(tf, hi_t);
  }
  _mm_storeu_ps(t_enter, lo_t);
  return _mm_movemask_ps(_mm_cmple_ps(lo_t, hi_t));
}

// --- The leaves of the 4-wide steps ---------------------------------------------------

// A leaf as a WideNode refers to it: `count` entries of the leaf set from `first`.
struct LeafRef {
  uint32_t first, count;
};

// Step 4's leaves: the copied triangles, tested one by one in double.
class CopiedTriangles {
 public:
  explicit CopiedTriangles(const BVHAccel& bvh) : leaves_(bvh, true) {}
  LeafRef add_leaf(uint32_t start, uint32_t count) { return {start, count}; }
  bool closest(LeafRef leaf, const Ray& r) const { return leaves_.closest<true>(leaf.first, leaf.count, r); }
  bool any(LeafRef leaf, const Ray& r) const { return leaves_.any<true>(leaf.first, leaf.count, r); }
  size_t bytes() const { return leaves_.bytes(); }
  static constexpr bool kExact = true;

 private:
  Leaves leaves_;
};

// Four triangles in the lanes of SSE registers, in float: Embree's
// "triangle4" leaves, tested with one Moller-Trumbore for all four.
struct alignas(16) TrianglePacket {
  float p1[3][4], e1[3][4], e2[3][4];  // [axis][lane]; an unused lane has zero edges (det = 0: never hit)
};

// Step 5's leaves: each leaf's triangles in packets of four.
class TrianglePackets {
 public:
  explicit TrianglePackets(const BVHAccel& bvh) : prims_(bvh.primitives()) {
    for (const Primitive* p : prims_) as_triangle(p);  // refuse other primitives before building anything
  }

  LeafRef add_leaf(uint32_t start, uint32_t count) {
    LeafRef ref{uint32_t(packets_.size()), (count + 3) / 4};
    for (uint32_t i = 0; i < count; i += 4) {
      TrianglePacket p{};
      for (uint32_t lane = 0; lane < 4 && i + lane < count; ++lane) {
        const Triangle& t = as_triangle(prims_[start + i + lane]);
        Vec3 e1 = t.p2() - t.p1(), e2 = t.p3() - t.p1();
        for (int a = 0; a < 3; ++a) {
          p.p1[a][lane] = float(t.p1()[a]);
          p.e1[a][lane] = float(e1[a]);
          p.e2[a][lane] = float(e2[a]);
        }
      }
      packets_.push_back(p);
    }
    return ref;
  }

  bool closest(LeafRef leaf, const Ray& r) const {
    const FloatRay q(r);
    bool hit = false;
    for (uint32_t k = leaf.first; k < leaf.first + leaf.count; ++k) {
      __m128 t;
      int mask = hits(packets_[k], q, r, &t);
      if (!mask) continue;
      alignas(16) float ts[4];
      _mm_store_ps(ts, t);
      for (; mask; mask &= mask - 1) {
        double tk = ts[__builtin_ctz(unsigned(mask))];
        if (tk <= r.max_t) {
          r.max_t = tk;
          hit = true;
        }
      }
    }
    return hit;
  }
  bool any(LeafRef leaf, const Ray& r) const {
    const FloatRay q(r);
    for (uint32_t k = leaf.first; k < leaf.first + leaf.count; ++k) {
      __m128 t;
      if (hits(packets_[k], q, r, &t)) return true;
    }
    return false;
  }
  size_t bytes() const { return packets_.size() * sizeof(TrianglePacket); }
  static constexpr bool kExact = false;

 private:
  struct FloatRay {
    __m128 o[3], d[3];
    explicit FloatRay(const Ray& r) {
      for (int a = 0; a < 3; ++a) {
        o[a] = _mm_set1_ps(float(r.o[a]));
        d[a] = _mm_set1_ps(float(r.d[a]));
      }
    }
  };

  // The lanes that hit within [r.min_t, r.max_t], and their t.
  static int hits(const TrianglePacket& p, const FloatRay& q, const Ray& r, __m128* t_out) {
    auto load = [](const float* v) { return _mm_load_ps(v); };
    __m128 e1x = load(p.e1[0]), e1y = load(p.e1[1]), e1z = load(p.e1[2]);
    __m128 e2x = load(p.e2[0]), e2y = load(p.e2[1]), e2z = load(p.e2[2]);
    __m128 sx = _mm_sub_ps(q.o[0], load(p.p1[0])), sy = _mm_sub_ps(q.o[1], load(p.p1[1])),
           sz = _mm_sub_ps(q.o[2], load(p.p1[2]));
    auto mul = [](__m128 a, __m128 b) { return _mm_mul_ps(a, b); };
    // s1 = d x e2, s2 = s x e1
    __m128 s1x = _mm_sub_ps(mul(q.d[1], e2z), mul(q.d[2], e2y));
    __m128 s1y = _mm_sub_ps(mul(q.d[2], e2x), mul(q.d[0], e2z));
    __m128 s1z = _mm_sub_ps(mul(q.d[0], e2y), mul(q.d[1], e2x));
    __m128 s2x = _mm_sub_ps(mul(sy, e1z), mul(sz, e1y));
    __m128 s2y = _mm_sub_ps(mul(sz, e1x), mul(sx, e1z));
    __m128 s2z = _mm_sub_ps(mul(sx, e1y), mul(sy, e1x));
    auto dot = [&](__m128 ax, __m128 ay, __m128 az, __m128 bx, __m128 by, __m128 bz) {
      return _mm_add_ps(_mm_add_ps(mul(ax, bx), mul(ay, by)), mul(az, bz));
    };
    __m128 det = dot(s1x, s1y, s1z, e1x, e1y, e1z);
    __m128 inv = _mm_div_ps(_mm_set1_ps(1.0f), det);
    __m128 t = mul(dot(s2x, s2y, s2z, e2x, e2y, e2z), inv);
    __m128 b1 = mul(dot(s1x, s1y, s1z, sx, sy, sz), inv);
    __m128 b2 = mul(dot(s2x, s2y, s2z, q.d[0], q.d[1], q.d[2]), inv);
    const __m128 zero = _mm_setzero_ps();
    __m128 ok = _mm_cmpneq_ps(det, zero);
    ok = _mm_and_ps(ok, _mm_cmpge_ps(b1, zero));
    ok = _mm_and_ps(ok, _mm_cmpge_ps(b2, zero));
    ok = _mm_and_ps(ok, _mm_cmple_ps(_mm_add_ps(b1, b2), _mm_set1_ps(1.0f)));
    ok = _mm_and_ps(ok, _mm_cmpge_ps(t, _mm_set1_ps(float(r.min_t))));
    ok = _mm_and_ps(ok, _mm_cmple_ps(t, _mm_set1_ps(float(r.max_t))));
    *t_out = t;
    return _mm_movemask_ps(ok);
  }

  const std::vector<Primitive*>& prims_;  // the BVH's, in leaf order
  std::vector<TrianglePacket> packets_;
};

// --- Steps 4 and 5: four children per node ----------------------------------------------

template <class LeafSet>
class Wide final : public Step {
 public:
  explicit Wide(const BVHAccel& bvh) : leaves_(bvh) {
    const BVHNode* root = bvh.root();
    set_box(root_.lo, root_.hi, root->bb);
    if (root->is_leaf()) {
      LeafRef ref = leaves_.add_leaf(uint32_t(root->start), uint32_t(root->size()));
      root_.first = ref.first;
      root_.count = ref.count;
      return;
    }
    build(root);
  }
  std::string name() const override { return LeafSet::kExact ? "4-wide" : "+ float triangles"; }
  size_t bytes() const override { return nodes_.size() * sizeof(WideNode) + leaves_.bytes(); }
  bool exact() const override { return LeafSet::kExact; }

  double closest(const Ray& ray) const override {
    Ray r = ray;
    const Vec3 inv_d = 1.0 / r.d;
    double t0 = r.min_t, t1 = r.max_t;
    if (!slab(root_.lo, root_.hi, r, inv_d, t0, t1)) return kInf;
    if (root_.count) return leaves_.closest({root_.first, root_.count}, r) ? r.max_t : kInf;
    const WideRay w = make_wide_ray(r);
    const float t_min = round_down(r.min_t);
    float t_max = round_up(r.max_t);  // follows r.max_t down as hits are found
    auto expand = [&](uint32_t node, Entered* e) {
      const WideNode& n = nodes_[node];
      float t_enter[4];
      bool hit = false;
      for (int mask = enter_wide(n, w, t_min, t_max, t_enter); mask; mask &= mask - 1) {
        int c = __builtin_ctz(unsigned(mask));
        if (n.count[c] == 0) {
          e->add(n.first[c], t_enter[c]);
        } else if (n.count[c] != WideNode::kEmpty && !(t_enter[c] > r.max_t) &&
                   leaves_.closest({n.first[c], n.count[c]}, r)) {
          hit = true;
          t_max = round_up(r.max_t);
        }
      }
      return hit;
    };
    return closest_loop(0, r, expand) ? r.max_t : kInf;
  }

  bool any(const Ray& r) const override {
    const Vec3 inv_d = 1.0 / r.d;
    double t0 = r.min_t, t1 = r.max_t;
    if (!slab(root_.lo, root_.hi, r, inv_d, t0, t1)) return false;
    if (root_.count) return leaves_.any({root_.first, root_.count}, r);
    const WideRay w = make_wide_ray(r);
    const float t_min = round_down(r.min_t), t_max = round_up(r.max_t);
    return any_loop(0, [&](uint32_t node, Entered* e) {
      const WideNode& n = nodes_[node];
      float t_enter[4];
      for (int mask = enter_wide(n, w, t_min, t_max, t_enter); mask; mask &= mask - 1) {
        int c = __builtin_ctz(unsigned(mask));
        if (n.count[c] == 0) {
          e->add(n.first[c], t_enter[c]);
        } else if (n.count[c] != WideNode::kEmpty && leaves_.any({n.first[c], n.count[c]}, r)) {
          return true;
        }
      }
      return false;
    });
  }

 private:
  // Collapses the binary tree: a node's up-to-four children are found by
  // opening, among its binary descendants, the interior one of largest area
  // (the one a ray is likeliest to enter) until there are four.
  uint32_t build(const BVHNode* src) {
    uint32_t me = uint32_t(nodes_.size());
    nodes_.emplace_back();
    std::vector<const BVHNode*> kids{src->l.get(), src->r.get()};
    while (kids.size() < 4) {
      int open = -1;
      for (int i = 0; i < int(kids.size()); ++i)
        if (!kids[i]->is_leaf() && (open < 0 || kids[i]->bb.surface_area() > kids[open]->bb.surface_area())) open = i;
      if (open < 0) break;
      const BVHNode* k = kids[open];
      kids.erase(kids.begin() + open);
      kids.push_back(k->l.get());
      kids.push_back(k->r.get());
    }
    for (int c = 0; c < 4; ++c) {
      WideNode& n = nodes_[me];
      if (c >= int(kids.size())) {
        for (int a = 0; a < 3; ++a) n.lo[a][c] = INFINITY, n.hi[a][c] = -INFINITY;
        n.first[c] = 0;
        n.count[c] = WideNode::kEmpty;
        continue;
      }
      for (int a = 0; a < 3; ++a) {
        n.lo[a][c] = round_down(kids[c]->bb.min[a]);
        n.hi[a][c] = round_up(kids[c]->bb.max[a]);
      }
      if (kids[c]->is_leaf()) {
        LeafRef ref = leaves_.add_leaf(uint32_t(kids[c]->start), uint32_t(kids[c]->size()));
        n.first[c] = ref.first;
        n.count[c] = ref.count;
      } else {
        uint32_t k = build(kids[c]);
        nodes_[me].first[c] = k;  // nodes_ may have moved: no reference kept across build()
        nodes_[me].count[c] = 0;
      }
    }
    return me;
  }

  RootRef root_;
  std::vector<WideNode> nodes_;
  LeafSet leaves_;
};

}  // namespace

std::vector<std::unique_ptr<Step>> make_steps(const BVHAccel& bvh, std::string* note) {
  std::vector<std::unique_ptr<Step>> steps;
  if (!bvh.root()) {
    *note = "no primitives: no steps";
    return steps;
  }
  if (depth_of(bvh.root()) >= kStackSize) {
    *note = "the tree is deeper than the steps' stacks (" + std::to_string(kStackSize) + "): no steps";
    return steps;
  }
  steps.push_back(std::make_unique<Flat>(bvh));
  steps.push_back(std::make_unique<FloatPairs<false>>(bvh));
  try {
    steps.push_back(std::make_unique<FloatPairs<true>>(bvh));
    steps.push_back(std::make_unique<Wide<CopiedTriangles>>(bvh));
    steps.push_back(std::make_unique<Wide<TrianglePackets>>(bvh));
  } catch (const std::invalid_argument& e) {
    *note = std::string("steps 3 to 5 left out: the scene has ") + e.what();
  }
  return steps;
}

std::vector<std::string> step_descriptions() {
  return {
      "flat: the reference's tree copied into one array of 64-byte nodes (double box, siblings adjacent), the same "
      "traversal: the compact flattened layout on its own",
      "float pairs: each 64-byte node holds both children's boxes in float (rounded outwards), so one cache line "
      "answers which children the ray enters",
      "+ triangles: the leaves' triangles copied in leaf order (three vertices), tested inline with Part 1's "
      "reference arithmetic (the watertight test): no virtual call, no index into the mesh",
      "4-wide: the tree collapsed into nodes of four children whose boxes are tested at once with SSE (float, "
      "widened so as never to miss what the double test enters), with the copied triangles",
      "+ float triangles: each leaf's triangles in packets of four, tested at once with SSE in float by "
      "Moller-Trumbore, as Embree's triangle4 leaves are (answers agree with the reference to float precision, not "
      "to the bit)",
  };
}

}  // namespace pt::bench::ladder
