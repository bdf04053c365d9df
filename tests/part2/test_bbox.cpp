// P2T2 BBox::intersect, the slab test. The box is closed (its faces belong to
// it); on a hit [t0, t1] must be narrowed to the part of the incoming interval
// inside the box (slab_check.h).
#include "slab_check.h"
#include "support/graded.h"

namespace pt::test::part2 {
namespace {

GRADED_TEST(BBoxSlab, HitsAndMisses, "P2T2", 1, Visible) {
  // Oblique rays through the box, along every sign combination of d.
  // From x = -5 with d.x = 1: x slab [4, 6]; y and z slabs are wider.
  EXPECT_TRUE(slab(kBox, ray({-5, 0.5, 0.5}, {1, 0.25, 0.125}), 0, kInf, true, 4, 6));
  EXPECT_TRUE(slab(kBox, ray({5, 0.5, 0.5}, {-1, -0.25, 0.125}), 0, kInf, true, 4, 6));
  EXPECT_TRUE(slab(kBox, ray({0.5, -10, 0.25}, {0.03125, 1, -0.125}), 0, kInf, true, 8, 12));
  EXPECT_TRUE(slab(kBox, ray({0.25, 0.5, 9}, {-0.0625, -0.125, -1}), 0, kInf, true, 6, 12));
  // o = (-2, -4, 0), d = (2, 4, 1): x [0.5, 1.5], y [0.5, 1.5], z [-3, 3] -> [0.5, 1.5]
  EXPECT_TRUE(slab(kBox, ray({-2, -4, 0}, {2, 4, 1}), 0, kInf, true, 0.5, 1.5));
  // o = (-3, 0, -4), d = (4, 1, 2): x [0.5, 1], y [-2, 2], z [0.5, 3.5] -> [0.5, 1]
  EXPECT_TRUE(slab(kBox, ray({-3, 0, -4}, {4, 1, 2}), 0, kInf, true, 0.5, 1));
  // A long direction: t is in units of d. d = (8, 2, 1) from x = -5: x [0.5, 0.75].
  EXPECT_TRUE(slab(kBox, ray({-5, 0, 0}, {8, 2, 1}), 0, kInf, true, 0.5, 0.75));

  // Misses: the slabs' intervals do not overlap.
  // x [4, 6] but y [-2, 2] (o.y = 0, d.y = 1) -> empty.
  EXPECT_TRUE(slab(kBox, ray({-5, 0, 0}, {1, 1, 0.125}), 0, kInf, false));
  EXPECT_TRUE(slab(kBox, ray({5, 0, 0}, {-1, -1, 0.125}), 0, kInf, false));
  // Passing above an edge: x slab [4, 6], z slab [-6.5, -0.5].
  EXPECT_TRUE(slab(kBox, ray({-5, 0, 3.5}, {1, 0, 1}), 0, kInf, false));
  // Pointing away from the box: its slabs lie behind the origin.
  EXPECT_TRUE(slab(kBox, ray({-5, 0.5, 0.5}, {-1, 0.25, 0.125}), 0, kInf, false));
  EXPECT_TRUE(slab(kBox, ray({0, 0, 10}, {0.125, 0.125, 1}), 0, kInf, false));
}

GRADED_TEST(BBoxSlab, RayStartingInside, "P2T2", 1, Visible) {
  // From the centre: every slab's entry is behind the origin, so t0 keeps the
  // incoming value; the exit is the nearest face ahead.
  EXPECT_TRUE(slab(kBox, ray({0, 0, 0}, {1, 1, 1}), 0, kInf, true, 0, 1));
  EXPECT_TRUE(slab(kBox, ray({0, 0, 0}, {-0.5, 1, -2}), 0, kInf, true, 0, 1.5));
  EXPECT_TRUE(slab(kBox, ray({0.5, -1, 2}, {-1, -1, -1}), 0, kInf, true, 0, 1));
  // With an incoming interval that starts later (a ray's min_t).
  EXPECT_TRUE(slab(kBox, ray({0, 0, 0}, {1, 1, 1}), 0.25, kInf, true, 0.25, 1));
  // A ray whose interval extends behind its origin: both ends come from the box.
  EXPECT_TRUE(slab(kBox, ray({0, 0, 0}, {1, 1, 1}), -kInf, kInf, true, -1, 1));
  EXPECT_TRUE(slab(kBox, ray({0.5, 0, 0}, {-0.5, 0.25, 0.25}), -kInf, kInf, true, -1, 3));
  // An interval that ends inside the box.
  EXPECT_TRUE(slab(kBox, ray({0, 0, 0}, {1, 1, 1}), 0, 0.5, true, 0, 0.5));
  // Starting on a face and moving inwards.
  EXPECT_TRUE(slab(kBox, ray({-1, 0, 0}, {1, 0.5, 0.25}), 0, kInf, true, 0, 2));
}

GRADED_TEST(BBoxSlab, AxisParallelRays, "P2T2", 1, Visible) {
  // Zero direction components: 1/d is +-inf and (min - o)/d is +-inf, so the
  // slab is all (origin between the planes) or nothing.
  EXPECT_TRUE(slab(kBox, ray({-5, 0.5, 0.5}, {1, 0, 0}), 0, kInf, true, 4, 6));
  EXPECT_TRUE(slab(kBox, ray({5, 0.5, 0.5}, {-1, 0, 0}), 0, kInf, true, 4, 6));
  EXPECT_TRUE(slab(kBox, ray({0.5, 0.5, -10}, {0, 0, 1}), 0, kInf, true, 7, 13));
  EXPECT_TRUE(slab(kBox, ray({0.5, 10, 0.5}, {0, -2, 0}), 0, kInf, true, 4, 6));
  EXPECT_TRUE(slab(kBox, ray({-5, 3, 0.5}, {1, 0, 0}), 0, kInf, false));     // beside the box in y
  EXPECT_TRUE(slab(kBox, ray({-5, 0.5, -3.5}, {1, 0, 0}), 0, kInf, false));  // below it in z
  EXPECT_TRUE(slab(kBox, ray({0.5, -2.5, -10}, {0, 0, 1}), 0, kInf, false));
  EXPECT_TRUE(slab(kBox, ray({1.5, 0.5, -10}, {0, 0, 1}), 0, kInf, false));
  // Negative zero: 1/(-0) = -inf; the answer must not change.
  EXPECT_TRUE(slab(kBox, ray({-5, 0.5, 0.5}, {1, -0.0, -0.0}), 0, kInf, true, 4, 6));
  EXPECT_TRUE(slab(kBox, ray({-5, 3, 0.5}, {1, -0.0, 0.0}), 0, kInf, false));
  EXPECT_TRUE(slab(kBox, ray({0.5, 0.5, -10}, {-0.0, -0.0, 1}), 0, kInf, true, 7, 13));
  // Inside, along an axis.
  EXPECT_TRUE(slab(kBox, ray({0, 0, 0}, {0, 1, 0}), 0, kInf, true, 0, 2));
  EXPECT_TRUE(slab(kBox, ray({0, 0, 0}, {0, 0, -0.5}), 0, kInf, true, 0, 6));
  // Two oblique components, one zero.
  EXPECT_TRUE(slab(kBox, ray({-3, -4, 0.5}, {2, 4, 0}), 0, kInf, true, 1, 1.5));
  EXPECT_TRUE(slab(kBox, ray({-3, -4, 3.25}, {2, 4, 0}), 0, kInf, false));

  // The origin exactly on a slab plane with a zero component: (min - o) / d
  // is 0 / 0 or 0 * inf = NaN. The box is closed, so a ray running along a
  // face (or an edge) hits it. Each axis in turn is the parallel one, so that
  // a NaN cannot hide behind a later axis.
  EXPECT_TRUE(slab(kBox, ray({1, 0.5, -10}, {0, 0, 1}), 0, kInf, true, 7, 13));    // on x = max
  EXPECT_TRUE(slab(kBox, ray({-1, 0.5, -10}, {0, 0, 1}), 0, kInf, true, 7, 13));   // on x = min
  EXPECT_TRUE(slab(kBox, ray({0.5, 2, -10}, {0, 0, 1}), 0, kInf, true, 7, 13));    // on y = max
  EXPECT_TRUE(slab(kBox, ray({1, -2, -10}, {0, 0, 1}), 0, kInf, true, 7, 13));     // along an edge
  EXPECT_TRUE(slab(kBox, ray({-5, 0.5, 3}, {1, 0.25, 0}), 0, kInf, true, 4, 6));   // on z = max
  EXPECT_TRUE(slab(kBox, ray({-5, 0.5, -3}, {1, 0.25, 0}), 0, kInf, true, 4, 6));  // on z = min
  EXPECT_TRUE(slab(kBox, ray({-5, -2, 0.5}, {1, 0, 0.125}), 0, kInf, true, 4, 6)); // on y = min
  EXPECT_TRUE(slab(kBox, ray({0.5, 10, -3}, {-0.0, -2, 0}), 0, kInf, true, 4, 6)); // on z = min, -0 in x
  // ... and with -0.0 in the parallel axis itself: 1 / -0.0 = -inf, so t_near
  // and t_far come out reversed and one of them is NaN. Swap by the sign of
  // the direction: a swap decided by comparing them (NaN) does not happen.
  EXPECT_TRUE(slab(kBox, ray({0.5, -2, -10}, {0, -0.0, 1}), 0, kInf, true, 7, 13));     // on y = min
  EXPECT_TRUE(slab(kBox, ray({-5, 2, 0.5}, {1, -0.0, 0.125}), 0, kInf, true, 4, 6));   // on y = max
  // On a slab plane but outside another slab: still a miss.
  EXPECT_TRUE(slab(kBox, ray({1, 5, -10}, {0, 0, 1}), 0, kInf, false));
  EXPECT_TRUE(slab(kBox, ray({-5, 2.5, 3}, {1, 0, 0}), 0, kInf, false));
}

GRADED_TEST(BBoxSlab, NarrowsInterval, "P2T2", 1, Visible) {
  // The ray enters at t = 4 and leaves at t = 6.
  const Ray r = ray({-5, 0.5, 0.5}, {1, 0.25, 0.125});
  EXPECT_TRUE(slab(kBox, r, 0, kInf, true, 4, 6));
  EXPECT_TRUE(slab(kBox, r, 0, 5, true, 4, 5));         // the interval ends inside the box
  EXPECT_TRUE(slab(kBox, r, 5, 100, true, 5, 6));       // ... starts inside the box
  EXPECT_TRUE(slab(kBox, r, 4.5, 5, true, 4.5, 5));     // ... lies inside the box
  EXPECT_TRUE(slab(kBox, r, -kInf, kInf, true, 4, 6));
  EXPECT_TRUE(slab(kBox, r, 0, 3.5, false));            // ends before the box (a nearer hit was found)
  EXPECT_TRUE(slab(kBox, r, 6.5, 100, false));          // starts after it
  EXPECT_TRUE(slab(kBox, r, 0, 4, true, 4, 4));         // touches the entry face: closed box
  // The same with negative components.
  const Ray q = ray({5, 0.5, 0.5}, {-1, -0.25, 0.125});
  EXPECT_TRUE(slab(kBox, q, 0, 5, true, 4, 5));
  EXPECT_TRUE(slab(kBox, q, 0, 3.5, false));
  EXPECT_TRUE(slab(kBox, q, 5.5, kInf, true, 5.5, 6));
  // The box lies entirely behind the origin: a miss for t >= 0 ...
  const Ray back = ray({5, 0.5, 0.5}, {1, -0.25, 0.125});
  EXPECT_TRUE(slab(kBox, back, 0, kInf, false));
  // ... but a hit for an interval reaching behind it.
  EXPECT_TRUE(slab(kBox, back, -kInf, kInf, true, -6, -4));
}

GRADED_TEST(BBoxSlab, FlatBoxes, "P2T2", 1, Visible) {
  // The box of a flat mesh has zero thickness: its entry and exit along that
  // axis coincide, and t0 == t1 is a hit (a strict t0 < t1 misses every flat mesh).
  const BBox flat(Vec3(-1, -1, 0), Vec3(1, 1, 0));
  EXPECT_TRUE(slab(flat, ray({0.25, 0.5, 2}, {0, 0, -1}), 0, kInf, true, 2, 2));
  EXPECT_TRUE(slab(flat, ray({0.5, 0.5, -1}, {0, 0, 1}), 0, kInf, true, 1, 1));
  EXPECT_TRUE(slab(flat, ray({0, 0, 4}, {0.125, 0.0625, -2}), 0, kInf, true, 2, 2));
  EXPECT_TRUE(slab(flat, ray({-3, 0, -1}, {2, 0.25, 0.5}), 0, kInf, true, 2, 2));
  EXPECT_TRUE(slab(flat, ray({3, 0, 1}, {0, 0, -1}), 0, kInf, false));           // beside it
  EXPECT_TRUE(slab(flat, ray({0, 0, 4}, {0.75, 0.0625, -2}), 0, kInf, false));   // reaches z = 0 at x = 1.5
  EXPECT_TRUE(slab(flat, ray({0.25, 0.5, 2}, {0, 0, -1}), 0, 1.5, false));       // interval ends before the plane
  EXPECT_TRUE(slab(flat, ray({0.25, 0.5, 2}, {0, 0, 1}), 0, kInf, false));       // moving away
  // A box flat in two axes (a segment along x) and in all three (a point).
  const BBox segment(Vec3(-1, 0, 0), Vec3(1, 0, 0));
  EXPECT_TRUE(slab(segment, ray({0, -1, -1}, {0.25, 1, 1}), 0, kInf, true, 1, 1));
  EXPECT_TRUE(slab(segment, ray({0, -1, -1}, {0.25, 1, 1.5}), 0, kInf, false));
  const BBox point(Vec3(0.5, 0.25, -0.5), Vec3(0.5, 0.25, -0.5));
  EXPECT_TRUE(slab(point, ray({-0.5, -0.75, -1.5}, {1, 1, 1}), 0, kInf, true, 1, 1));
  EXPECT_TRUE(slab(point, ray({-0.5, -0.75, -1.5}, {1, 1, 1.25}), 0, kInf, false));
}

}  // namespace
}  // namespace pt::test::part2
