#pragma once
// Every field of a primitive's hit record, on a hit and on a miss (P1T3,
// P1T4). A closest-hit query passes one Intersection to primitive after
// primitive: a hit must rewrite every field (a field left as an earlier hit
// of another primitive wrote it is that primitive's data on this one), and a
// miss must leave the record and the ray's range exactly as they were (they
// still describe the nearest hit so far).
#include <sstream>
#include <string>

#include "support/part1_builders.h"

namespace pt::test::part1 {

// What an earlier hit on another primitive left in the record: no field of
// it is what a hit on the primitive under test writes.
inline Intersection earlier_hit(const Primitive* other, const BSDF* other_bsdf) {
  Intersection e;
  e.t = 3.75;
  e.n = Vec3(0.0, 0.6, 0.8);
  e.barycentric = Vec3(0.25, 0.25, 0.5);
  e.primitive = other;
  e.bsdf = other_bsdf;
  return e;
}

inline std::string describe(const Intersection& i) {
  std::ostringstream os = stream15();
  os << "{t=" << i.t << " n=" << i.n << " barycentric=" << i.barycentric << " primitive=" << i.primitive
     << " bsdf=" << i.bsdf << "}";
  return os.str();
}

// Exact equality of every field (a miss copies nothing, rounds nothing).
inline ::testing::AssertionResult record_unchanged(const Intersection& after, const Intersection& before) {
  if (after.t == before.t && after.n == before.n && after.barycentric == before.barycentric &&
      after.primitive == before.primitive && after.bsdf == before.bsdf)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "the hit record changed on a miss: it was " << describe(before)
                                       << ", it is " << describe(after)
                                       << ". On a miss leave isect (and the ray) as they were: they still hold the "
                                          "nearest hit found so far.";
}

// The ray's range after a query that must not change it.
inline ::testing::AssertionResult range_unchanged(const char* query, const Ray& after, const Ray& before) {
  if (after.min_t == before.min_t && after.max_t == before.max_t) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << query << " changed the ray's range from [" << before.min_t << ", "
                                       << before.max_t << "] to [" << after.min_t << ", " << after.max_t
                                       << "]; only intersect() changes it, and only on a hit (max_t = t).";
}

// A ray that misses `prim`: neither query reports a hit, and neither changes
// the record (as `before` left it) or the ray's range.
inline ::testing::AssertionResult miss_changes_nothing(const Primitive& prim, const Ray& miss,
                                                       const Intersection& before) {
  Ray m = miss;
  if (prim.has_intersection(m)) return ::testing::AssertionFailure() << "has_intersection hit a ray that misses.";
  ::testing::AssertionResult same = range_unchanged("has_intersection", m, miss);
  if (!same) return same;
  Intersection isect = before;
  if (prim.intersect(m, &isect)) return ::testing::AssertionFailure() << "intersect hit a ray that misses.";
  same = record_unchanged(isect, before);
  if (!same) return same;
  return range_unchanged("intersect (a miss)", m, miss);
}

}  // namespace pt::test::part1
