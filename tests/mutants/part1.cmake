# Part 1 mutants: plausible student bugs in ray generation (P1T1), pixel
# sampling (P1T2), triangle (P1T3) and sphere (P1T4) intersection. Each one
# must make at least one graded test in tests/part1/ fail; "Caught by" lists
# every graded test that fails with the mutant (measured, not assumed), the
# image tests (ImageP1.*) aside: scenes/README.md counts which mutants they catch.
set(p1 reference/part1_raygen_intersect.cpp)

# ---- P1T1 Camera::generate_ray ----

# Forgets to normalise the direction.
# Caught by CameraRay.BottomLeftIsImageOrigin, CameraRay.CornersSpanTheSensor,
#   CameraRay.DirectionIsUnitLength, CameraRay.SensorIsAPlane (hidden),
#   CameraRay.PosedCameraMatchesLookAt (hidden).
pt_mutant(1 cam_not_normalised ${p1} [[Ray r(pos, glm::normalize(c2w * sensor));]] [[Ray r(pos, c2w * sensor);]])

# Uses the full field of view where the half angle belongs: tan(fov) for tan(fov/2).
# Caught by CameraRay.BottomLeftIsImageOrigin, CameraRay.CornersSpanTheSensor,
#   CameraRay.EdgeMidpointsAreHalfFovOffAxis, CameraRay.SensorIsAPlane (hidden),
#   CameraRay.PosedCameraMatchesLookAt (hidden).
pt_mutant(1 cam_full_fov ${p1}
  [[Vec3 sensor((2.0 * x - 1.0) * std::tan(glm::radians(hfov) / 2.0), (2.0 * y - 1.0) * std::tan(glm::radians(vfov) / 2.0),
              -1.0);]]
  [[Vec3 sensor((2.0 * x - 1.0) * std::tan(glm::radians(hfov)), (2.0 * y - 1.0) * std::tan(glm::radians(vfov)), -1.0);]])

# Passes the field of view in degrees to std::tan.
# Caught by CameraRay.BottomLeftIsImageOrigin, CameraRay.CornersSpanTheSensor,
#   CameraRay.EdgeMidpointsAreHalfFovOffAxis, CameraRay.SensorIsAPlane (hidden),
#   CameraRay.PosedCameraMatchesLookAt (hidden).
pt_mutant(1 cam_degrees ${p1}
  [[Vec3 sensor((2.0 * x - 1.0) * std::tan(glm::radians(hfov) / 2.0), (2.0 * y - 1.0) * std::tan(glm::radians(vfov) / 2.0),
              -1.0);]]
  [[Vec3 sensor((2.0 * x - 1.0) * std::tan(hfov / 2.0), (2.0 * y - 1.0) * std::tan(vfov / 2.0), -1.0);]])

# Image y taken as pointing down (row 0 at the top).
# Caught by CameraRay.BottomLeftIsImageOrigin, CameraRay.CornersSpanTheSensor,
#   CameraRay.SensorIsAPlane (hidden), CameraRay.PosedCameraMatchesLookAt (hidden).
pt_mutant(1 cam_y_flipped ${p1} [[(2.0 * y - 1.0)]] [[(1.0 - 2.0 * y)]])

# Maps x to [0, 1] on the sensor instead of [-1, 1]: the image is off-centre.
# Caught by CameraRay.CentreLooksAtTarget, CameraRay.BottomLeftIsImageOrigin, CameraRay.CornersSpanTheSensor,
#   CameraRay.EdgeMidpointsAreHalfFovOffAxis, CameraRay.SensorIsAPlane (hidden),
#   CameraRay.PosedCameraMatchesLookAt (hidden).
pt_mutant(1 cam_x_not_centred ${p1} [[(2.0 * x - 1.0)]] [[x]])

# Leaves the direction in camera space (ignores c2w).
# Caught by CameraRay.CentreLooksAtTarget, CameraRay.EdgeMidpointsAreHalfFovOffAxis,
#   CameraRay.PosedCameraMatchesLookAt (hidden).
pt_mutant(1 cam_ignores_c2w ${p1} [[glm::normalize(c2w * sensor)]] [[glm::normalize(sensor)]])

# Spreads angles linearly over the image instead of positions over the
# sensor plane: right at the corners, edges and centre, wrong in between.
# Caught by CameraRay.SensorIsAPlane (hidden), CameraRay.PosedCameraMatchesLookAt (hidden).
pt_mutant(1 cam_angle_linear ${p1}
  [[Vec3 sensor((2.0 * x - 1.0) * std::tan(glm::radians(hfov) / 2.0), (2.0 * y - 1.0) * std::tan(glm::radians(vfov) / 2.0),
              -1.0);]]
  [[Vec3 sensor(std::tan((2.0 * x - 1.0) * glm::radians(hfov) / 2.0), std::tan((2.0 * y - 1.0) * glm::radians(vfov) / 2.0),
              -1.0);]])

# Leaves the ray's t range at its defaults instead of the clip distances.
# Caught by CameraRay.OriginAndClipRange.
pt_mutant(1 cam_no_clip_range ${p1} [[  r.min_t = near_clip;
  r.max_t = far_clip;
]] [[]])

# ---- P1T2 PathTracer::raytrace_pixel ----

# Every sample through the pixel's bottom-left corner.
# Caught by PixelSampling.SingleSampleGoesThroughPixelCentre, PixelSampling.SamplesAreJitteredAcrossThePixel,
#   PixelSampling.JitterComesFromTheRngPassedIn,
#   PixelSampling.EverySampleIsUniformInThePixel.
pt_mutant(1 px_corner ${p1} [[Vec2 u = n == 1 ? Vec2(0.5) : rng.uniform2();]] [[Vec2 u(0.0);]])

# No jitter: every sample through the pixel centre.
# Caught by PixelSampling.SamplesAreJitteredAcrossThePixel, PixelSampling.JitterComesFromTheRngPassedIn,
#   PixelSampling.EverySampleIsUniformInThePixel.
pt_mutant(1 px_no_jitter ${p1} [[Vec2 u = n == 1 ? Vec2(0.5) : rng.uniform2();]] [[Vec2 u(0.5);]])

# Jitters the single sample too (ns_aa = 1 must go through the centre).
# Caught by PixelSampling.SingleSampleGoesThroughPixelCentre.
pt_mutant(1 px_jitter_single_sample ${p1} [[Vec2 u = n == 1 ? Vec2(0.5) : rng.uniform2();]] [[Vec2 u = rng.uniform2();]])

# Jitters around the pixel's corner, [-1/2, 1/2)^2, instead of inside the pixel.
# Caught by PixelSampling.SamplesStayInsideTheirPixel, PixelSampling.SamplesAreJitteredAcrossThePixel,
#   PixelSampling.EverySampleIsUniformInThePixel.
pt_mutant(1 px_jitter_around_corner ${p1} [[Vec2 u = n == 1 ? Vec2(0.5) : rng.uniform2();]]
  [[Vec2 u = n == 1 ? Vec2(0.5) : rng.uniform2() - 0.5;]])

# One random number for both axes: samples lie on the pixel's diagonal.
# Caught by PixelSampling.SamplesAreJitteredAcrossThePixel,
#   PixelSampling.EverySampleIsUniformInThePixel.
pt_mutant(1 px_same_random_both_axes ${p1} [[Vec2 u = n == 1 ? Vec2(0.5) : rng.uniform2();]]
  [[Vec2 u = n == 1 ? Vec2(0.5) : Vec2(rng.uniform());]])

# Divides y by the image width.
# Caught by PixelSampling.SingleSampleGoesThroughPixelCentre, PixelSampling.SamplesStayInsideTheirPixel,
#   PixelSampling.SamplesAreJitteredAcrossThePixel,
#   PixelSampling.EverySampleIsUniformInThePixel.
pt_mutant(1 px_width_for_y ${p1} [[(y + u.y) / settings.height]] [[(y + u.y) / settings.width]])

# Off by one: ns_aa + 1 samples.
# Caught by PixelSampling.TakesExactlyNsAaSamples, PixelSampling.AveragesTheSamples,
#   PixelSampling.SingleSampleGoesThroughPixelCentre, PixelSampling.SamplesStayInsideTheirPixel,
#   PixelSampling.SamplesAreJitteredAcrossThePixel,
#   PixelSampling.EstimatesDrawFromTheRngPassedIn, PixelSampling.EverySampleIsUniformInThePixel.
pt_mutant(1 px_loop_off_by_one ${p1} [[for (int i = 0; i < n; ++i)]] [[for (int i = 0; i <= n; ++i)]])

# Returns the sum of the samples instead of their mean.
# Caught by PixelSampling.AveragesTheSamples.
pt_mutant(1 px_sum_not_mean ${p1} [[return {sum / double(n), n};]] [[return {sum, n};]])

# Divides by the wrong count.
# Caught by PixelSampling.AveragesTheSamples.
pt_mutant(1 px_divide_by_n_plus_1 ${p1} [[return {sum / double(n), n};]] [[return {sum / double(n + 1), n};]])

# Does not record the sample count.
# Caught by PixelSampling.RecordsSampleCount.
pt_mutant(1 px_count_not_recorded ${p1} [[return {sum / double(n), n};]] [[return {sum / double(n), 1};]])

# Jitters with a generator of its own, seeded from the pixel: every sample
# lands in its pixel and is uniform, but the image no longer depends on the
# render's seed and the rng passed in is never used.
# Caught by PixelSampling.JitterComesFromTheRngPassedIn,
#   PixelSampling.EverySampleIsUniformInThePixel.
pt_mutant(1 px_own_rng ${p1} [[  for (int i = 0; i < n; ++i) {
    Vec2 u = n == 1 ? Vec2(0.5) : rng.uniform2();]] [[  Rng own = Rng::for_pixel(0, uint32_t(x), uint32_t(y));
  for (int i = 0; i < n; ++i) {
    Vec2 u = n == 1 ? Vec2(0.5) : own.uniform2();]])

# The first sample through the pixel's centre, the others jittered: the
# centre weighs 1/N extra (a biased pixel).
# Caught by PixelSampling.EverySampleIsUniformInThePixel.
pt_mutant(1 px_first_sample_centred ${p1} [[Vec2 u = n == 1 ? Vec2(0.5) : rng.uniform2();]]
          [[Vec2 u = n == 1 || i == 0 ? Vec2(0.5) : rng.uniform2();]])

# Hands the radiance estimates a copy of the generator: each estimate draws
# the numbers the next sample's jitter draws again.
# Caught by PixelSampling.EstimatesDrawFromTheRngPassedIn.
pt_mutant(1 px_estimate_gets_copy ${p1} [[    sum += est_radiance_global_illumination(r, rng);]]
          [[    Rng copy = rng;
    sum += est_radiance_global_illumination(r, copy);]])

# The radiance estimates draw from a generator of the loop's own: the pixel
# no longer depends on the rng passed in, and two calls alike differ.
# Caught by PixelSampling.EstimatesDrawFromTheRngPassedIn.
pt_mutant(1 px_estimate_own_rng ${p1} [[    sum += est_radiance_global_illumination(r, rng);]]
          [[    static thread_local Rng own(12345);
    sum += est_radiance_global_illumination(r, own);]])

# ---- P1T3 Triangle::has_intersection, Triangle::intersect ----
# The reference is the watertight test (u, v, w: the edge functions, the
# unnormalised weights of p1, p2, p3); each mutant is the bug a student makes
# in Moller-Trumbore, written in its terms.

# Exchanges the weights of n2 and n3 in the interpolated normal.
# Caught by TriangleIntersect.InterpolatedNormal,
#   TriangleIntersect.HitRecordOnHitAndMiss.
pt_mutant(1 tri_swapped_normal_weights ${p1} [[hit.b0 * n1() + hit.b1 * n2() + hit.b2 * n3()]]
  [[hit.b0 * n1() + hit.b2 * n2() + hit.b1 * n3()]])

# Forgets to normalise the interpolated normal.
# Caught by TriangleIntersect.InterpolatedNormal,
#   TriangleIntersect.HitRecordOnHitAndMiss.
pt_mutant(1 tri_normal_not_normalised ${p1} [[isect->n = glm::normalize(hit.b0 * n1() + hit.b1 * n2() + hit.b2 * n3());]]
  [[isect->n = hit.b0 * n1() + hit.b1 * n2() + hit.b2 * n3();]])

# Stores the barycentrics in the wrong order.
# Caught by TriangleIntersect.Barycentrics, TriangleIntersect.RandomRaysMatchIndependentSolver (hidden),
#   TriangleIntersect.TinyHugeAndSliverTriangles (hidden),
#   TriangleIntersect.HitRecordOnHitAndMiss.
pt_mutant(1 tri_barycentrics_rotated ${p1} [[isect->barycentric = Vec3(hit.b0, hit.b1, hit.b2);]]
  [[isect->barycentric = Vec3(hit.b1, hit.b2, hit.b0);]])

# Strict inside test on every edge (Moller-Trumbore's b1 > 0, b2 > 0,
# b1 + b2 < 1): a ray through a shared edge slips between the triangles.
# Caught by TriangleIntersect.SharedEdgeCannotSlipThrough (hidden).
pt_mutant(1 tri_strict_edges ${p1} [[if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return false;]]
  [[if ((u <= 0.0 || v <= 0.0 || w <= 0.0) && (u >= 0.0 || v >= 0.0 || w >= 0.0)) return false;]])

# Strict on the edge p2-p3 only (Moller-Trumbore's b1 + b2 < 1): that edge leaks.
# Caught by TriangleIntersect.SharedEdgeCannotSlipThrough (hidden).
pt_mutant(1 tri_strict_one_edge ${p1} [[if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return false;]]
  [[if ((u <= 0.0 || v < 0.0 || w < 0.0) && (u >= 0.0 || v > 0.0 || w > 0.0)) return false;]])

# Forgets the edge p2-p3 (Moller-Trumbore without b1 + b2 <= 1): hits
# beyond it.
# Caught by TriangleIntersect.MissesBesideEachEdge,
#   TriangleIntersect.RandomRaysMatchIndependentSolver (hidden),
#   TriangleIntersect.TinyHugeAndSliverTriangles (hidden),
#   TriangleIntersect.HitRecordOnHitAndMiss.
pt_mutant(1 tri_no_sum_test ${p1} [[if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return false;]]
  [[if ((v < 0.0 || w < 0.0) && (v > 0.0 || w > 0.0)) return false;]])

# Ignores min_t: hits behind the origin (and before the near clip).
# Caught by TriangleIntersect.RespectsTRange, TriangleIntersect.RandomRaysMatchIndependentSolver (hidden),
#   TriangleIntersect.HitRecordOnHitAndMiss.
pt_mutant(1 tri_ignores_min_t ${p1} [[t >= r.min_t && ]] [[]])

# Ignores max_t: farther triangles replace the nearest hit.
# Caught by TriangleIntersect.RespectsTRange, TriangleIntersect.KeepsNearerHit,
#   TriangleIntersect.RandomRaysMatchIndependentSolver (hidden),
#   TriangleIntersect.HitRecordOnHitAndMiss.
pt_mutant(1 tri_ignores_max_t ${p1} [[ && t <= r.max_t]] [[]])

# Does not shrink r.max_t on a hit.
# Caught by TriangleIntersect.ShrinksMaxT, TriangleIntersect.KeepsNearerHit,
#   TriangleIntersect.HitRecordOnHitAndMiss.
pt_mutant(1 tri_no_max_t_update ${p1} [[  r.max_t = hit.t;
]] [[]])

# Back-face culling (one winding rejected): triangles are two-sided here.
# Caught by TriangleIntersect.HitDistanceAndPoint, TriangleIntersect.Barycentrics,
#   TriangleIntersect.InterpolatedNormal, TriangleIntersect.HitsBothFaces, TriangleIntersect.ShrinksMaxT,
#   TriangleIntersect.SharedEdgeCannotSlipThrough (hidden),
#   TriangleIntersect.RandomRaysMatchIndependentSolver (hidden),
#   TriangleIntersect.HitsExactlyAtTheEndsOfTheRange (hidden),
#   TriangleIntersect.TinyHugeAndSliverTriangles (hidden),
#   TriangleIntersect.HitRecordOnHitAndMiss.
pt_mutant(1 tri_backface_culling ${p1} [[if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return false;]]
  [[if (u < 0.0 || v < 0.0 || w < 0.0) return false;]])

# No determinant check and rejection tests that NaN slips through: a
# zero-area triangle or a ray in the triangle's plane "hits" with t = NaN.
# Caught by TriangleIntersect.DegenerateNeverHits, TriangleIntersect.RayInItsPlaneMisses (hidden).
pt_mutant(1 tri_nan_unsafe ${p1}
  [[  if (det == 0.0) return false;  // ray in the triangle's plane, or a degenerate triangle
  const double t = (u * (sz * a[kz]) + v * (sz * b[kz]) + w * (sz * c[kz])) / det;
  // Written so that NaN (a zero direction, infinite vertices) is never a hit.
  if (!(t >= r.min_t && t <= r.max_t)) return false;]]
  [[  const double t = (u * (sz * a[kz]) + v * (sz * b[kz]) + w * (sz * c[kz])) / det;
  if (t < r.min_t || t > r.max_t) return false;]])

# has_intersection tests the whole line, forgetting the ray's t range.
# Caught by TriangleIntersect.RespectsTRange, TriangleIntersect.HasIntersectionAgreesWithIntersect,
#   TriangleIntersect.RandomRaysMatchIndependentSolver (hidden),
#   TriangleIntersect.HitRecordOnHitAndMiss.
pt_mutant(1 tri_any_hit_ignores_range ${p1} [[bool Triangle::has_intersection(const Ray& r) const {
  TriangleHit hit;
  return watertight(r, p1(), p2(), p3(), &hit);]]
  [[bool Triangle::has_intersection(const Ray& r) const {
  TriangleHit hit;
  Ray line(r.o, r.d);
  line.min_t = -kInf;
  return watertight(line, p1(), p2(), p3(), &hit);]])

# Does not record the primitive and BSDF hit.
# Caught by TriangleIntersect.RecordsPrimitiveAndBsdf, TriangleIntersect.KeepsNearerHit,
#   TriangleIntersect.HitRecordOnHitAndMiss.
pt_mutant(1 tri_no_primitive_bsdf ${p1} [[  isect->primitive = this;
  isect->bsdf = get_bsdf();
  return true;
}

// P1T4]] [[  return true;
}

// P1T4]])

# An absolute epsilon on the determinant (the 1e-6 printed in the original
# Moller-Trumbore paper): right for triangles of about unit size, blind to
# small ones and thin slivers, whose determinant (twice their projected area)
# is below it.
# Caught by TriangleIntersect.TinyHugeAndSliverTriangles (hidden).
pt_mutant(1 tri_absolute_det_epsilon ${p1} [[if (det == 0.0) return false;]] [[if (std::abs(det) < 1e-6) return false;]])

# Strict range test, min_t < t < max_t: a hit exactly at max_t (a ray
# re-tested after intersect set max_t = t) or at min_t is lost.
# Caught by TriangleIntersect.HitsExactlyAtTheEndsOfTheRange (hidden).
pt_mutant(1 tri_strict_t_range ${p1} [[if (!(t >= r.min_t && t <= r.max_t)) return false;]]
  [[if (!(t > r.min_t && t < r.max_t)) return false;]])

# has_intersection shrinks the ray's max_t as intersect does: only
# intersect() may change the range.
# Caught by TriangleIntersect.HitRecordOnHitAndMiss.
pt_mutant(1 tri_has_shrinks_max_t ${p1} [[  TriangleHit hit;
  return watertight(r, p1(), p2(), p3(), &hit);]] [[  TriangleHit hit;
  if (!watertight(r, p1(), p2(), p3(), &hit)) return false;
  r.max_t = hit.t;
  return true;]])

# ---- P1T4 Sphere::test, Sphere::has_intersection, Sphere::intersect ----

# Roots not put in order (t1 is the larger root whenever b < 0).
# Caught by SphereTest.RootsInOrder, SphereTest.NonUnitDirection, SphereIntersect.NearRootFromOutside,
#   SphereIntersect.RespectsTRange, SphereIntersect.KeepsNearerHit, SphereIntersect.OutwardUnitNormal,
#   SphereIntersect.TinyAndHugeSpheres (hidden), SphereIntersect.RandomRaysMatchClosedForm (hidden),
#   SphereIntersect.HitRecordOnHitAndMiss.
pt_mutant(1 sph_roots_unordered ${p1} [[  if (t1 > t2) std::swap(t1, t2);
]] [[]])

# Takes the far root when the near one is in range.
# Caught by SphereIntersect.NearRootFromOutside, SphereIntersect.RespectsTRange,
#   SphereIntersect.KeepsNearerHit, SphereIntersect.OutwardUnitNormal,
#   SphereIntersect.TinyAndHugeSpheres (hidden), SphereIntersect.RandomRaysMatchClosedForm (hidden),
#   SphereIntersect.HitsExactlyAtTheEndsOfTheRange (hidden),
#   SphereIntersect.HitRecordOnHitAndMiss.
pt_mutant(1 sph_far_root ${p1} [[*t = t1;]] [[*t = t2;]])

# Tries only the near root: from inside the sphere (t1 < 0) it misses.
# Caught by SphereIntersect.OriginInsideHitsFarRoot, SphereIntersect.RespectsTRange,
#   SphereIntersect.TinyAndHugeSpheres (hidden), SphereIntersect.RandomRaysMatchClosedForm (hidden),
#   SphereIntersect.HitsExactlyAtTheEndsOfTheRange (hidden),
#   SphereIntersect.HitRecordOnHitAndMiss.
pt_mutant(1 sph_near_root_only ${p1} [[  if (t2 >= ray.min_t && t2 <= ray.max_t) {
    *t = t2;
    return true;
  }
]] [[]])

# Ignores min_t for the near root: hits behind the origin.
# Caught by SphereIntersect.OriginInsideHitsFarRoot, SphereIntersect.SphereBehindMisses,
#   SphereIntersect.RespectsTRange, SphereIntersect.TinyAndHugeSpheres (hidden),
#   SphereIntersect.RandomRaysMatchClosedForm (hidden), SphereIntersect.HitsExactlyAtTheEndsOfTheRange (hidden),
#   SphereTest.TangentRayFromAPointOnTheSphere (hidden),
#   SphereIntersect.HitRecordOnHitAndMiss.
pt_mutant(1 sph_ignores_min_t ${p1} [[if (t1 >= ray.min_t && t1 <= ray.max_t)]] [[if (t1 <= ray.max_t)]])

# Inward normal.
# Caught by SphereIntersect.TangentRayTouches, SphereIntersect.OriginInsideHitsFarRoot,
#   SphereIntersect.OutwardUnitNormal, SphereIntersect.RandomRaysMatchClosedForm (hidden),
#   SphereTest.TangentRayFromAPointOnTheSphere (hidden),
#   SphereIntersect.HitRecordOnHitAndMiss.
pt_mutant(1 sph_inward_normal ${p1} [[glm::normalize(ray.at(t) - o)]] [[glm::normalize(o - ray.at(t))]])

# Normal not divided by the radius.
# Caught by SphereIntersect.TangentRayTouches, SphereIntersect.OriginInsideHitsFarRoot,
#   SphereIntersect.OutwardUnitNormal, SphereIntersect.RandomRaysMatchClosedForm (hidden),
#   SphereTest.TangentRayFromAPointOnTheSphere (hidden),
#   SphereIntersect.HitRecordOnHitAndMiss.
pt_mutant(1 sph_normal_not_unit ${p1} [[isect->n = glm::normalize(ray.at(t) - o);]] [[isect->n = ray.at(t) - o;]])

# Treats a zero discriminant as a miss: tangent rays slip past.
# Caught by SphereIntersect.TangentRayTouches, SphereTest.TangentRayFromAPointOnTheSphere (hidden).
pt_mutant(1 sph_tangent_misses ${p1} [[if (disc < 0.0) return false;]] [[if (disc <= 0.0) return false;]])

# Forgets the square root of the discriminant.
# Caught by SphereTest.RootsInOrder, SphereTest.NonUnitDirection, SphereIntersect.NearRootFromOutside,
#   SphereIntersect.OriginInsideHitsFarRoot, SphereIntersect.RespectsTRange, SphereIntersect.KeepsNearerHit,
#   SphereIntersect.OutwardUnitNormal, SphereIntersect.TinyAndHugeSpheres (hidden),
#   SphereIntersect.RandomRaysMatchClosedForm (hidden), SphereIntersect.HitsExactlyAtTheEndsOfTheRange (hidden),
#   SphereIntersect.HitRecordOnHitAndMiss.
pt_mutant(1 sph_no_sqrt ${p1} [[std::copysign(std::sqrt(disc), b)]] [[std::copysign(disc, b)]])

# Assumes a unit direction (a = 1).
# Caught by SphereTest.NonUnitDirection, SphereIntersect.RandomRaysMatchClosedForm (hidden),
#   SphereIntersect.HitsExactlyAtTheEndsOfTheRange (hidden).
pt_mutant(1 sph_assumes_unit_direction ${p1} [[double a = glm::dot(ray.d, ray.d);]] [[double a = 1.0;]])

# Uses r instead of r^2 in c = |o - centre|^2 - r^2.
# Caught by SphereTest.RootsInOrder, SphereTest.NonUnitDirection, SphereIntersect.NearRootFromOutside,
#   SphereIntersect.TangentRayTouches, SphereIntersect.OriginInsideHitsFarRoot,
#   SphereIntersect.OutwardUnitNormal, SphereIntersect.TinyAndHugeSpheres (hidden),
#   SphereIntersect.RandomRaysMatchClosedForm (hidden), SphereIntersect.HitsExactlyAtTheEndsOfTheRange (hidden),
#   SphereTest.TangentRayFromAPointOnTheSphere (hidden),
#   SphereIntersect.HitRecordOnHitAndMiss.
pt_mutant(1 sph_radius_not_squared ${p1} [[double c = glm::dot(oc, oc) - r2;]] [[double c = glm::dot(oc, oc) - r;]])

# Computes the discriminant in single precision: roots good to about 1e-7
# at unit scale, and meaningless for a tiny sphere far away.
# Caught by SphereTest.RootsInOrder, SphereTest.NonUnitDirection, SphereIntersect.NearRootFromOutside,
#   SphereIntersect.OriginInsideHitsFarRoot, SphereIntersect.OutwardUnitNormal,
#   SphereIntersect.TinyAndHugeSpheres (hidden), SphereIntersect.RandomRaysMatchClosedForm (hidden),
#   SphereIntersect.HitRecordOnHitAndMiss.
pt_mutant(1 sph_float_discriminant ${p1} [[double disc = b * b - 4.0 * a * c;]]
  [[double disc = float(b) * float(b) - 4.0f * float(a) * float(c);]])

# Does not shrink ray.max_t on a hit.
# Caught by SphereIntersect.KeepsNearerHit,
#   SphereIntersect.HitRecordOnHitAndMiss.
pt_mutant(1 sph_no_max_t_update ${p1} [[  ray.max_t = t;
]] [[]])

# Strict range test, min_t < t < max_t: a root exactly on an end of the
# interval (a ray re-tested after intersect set max_t = t) is lost.
# Caught by SphereIntersect.HitsExactlyAtTheEndsOfTheRange (hidden),
#   SphereTest.TangentRayFromAPointOnTheSphere (hidden).
pt_mutant(1 sph_strict_range ${p1} [[  if (t1 >= ray.min_t && t1 <= ray.max_t) {
    *t = t1;
    return true;
  }
  if (t2 >= ray.min_t && t2 <= ray.max_t) {]] [[  if (t1 > ray.min_t && t1 < ray.max_t) {
    *t = t1;
    return true;
  }
  if (t2 > ray.min_t && t2 < ray.max_t) {]])

# No q = 0 case in the stable roots: with the origin on the sphere and the ray
# tangent to it (b = c = 0), t2 = c / q = 0 / 0 is NaN.
# Caught by SphereTest.TangentRayFromAPointOnTheSphere (hidden).
pt_mutant(1 sph_no_q_zero_case ${p1} [[  if (q == 0.0) {
    t1 = t2 = 0.0;  // origin on the sphere, ray tangent to it
    return true;
  }
]] [[]])

# The stable form with the wrong sign: q = -(b - sign(b) sqrt(disc)) / 2 is the
# cancelling root, computed first. From an origin on the sphere heading in
# (c = 0, sqrt(disc) = |b|) q is 0 and both roots come out 0: the exit is
# lost; 1e-5 inside a sphere of radius 1e4 the exit c / q is off by 1e-4 to 7e-4.
# Caught by SphereTest.OriginOnTheSphereHeadingIn (hidden).
pt_mutant(1 sph_cancelling_root_first ${p1} [[double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));]]
          [[double q = -0.5 * (b - std::copysign(std::sqrt(disc), b));]])

# The same without the q = 0 case: on the sphere t2 = c / q = 0 / 0 is NaN.
# Caught by SphereTest.OriginOnTheSphereHeadingIn (hidden),
#   SphereTest.TangentRayFromAPointOnTheSphere (hidden).
pt_mutant(1 sph_cancelling_root_no_q_zero_case ${p1} [[double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  if (q == 0.0) {
    t1 = t2 = 0.0;  // origin on the sphere, ray tangent to it
    return true;
  }]] [[double q = -0.5 * (b - std::copysign(std::sqrt(disc), b));]])

# Leaves the barycentric weights as an earlier hit wrote them (a triangle's),
# where a sphere's are 0.
# Caught by SphereIntersect.HitRecordOnHitAndMiss.
pt_mutant(1 sphere_keeps_barycentric ${p1} [[  isect->barycentric = Vec3(0.0);
]] [[]])

