#pragma once
// Intel Embree 3 as a yardstick for pt-bench (compiled only when CMake finds
// Embree; PT_HAVE_EMBREE is then defined). One triangle geometry with float
// vertices, queried with the single-ray API (rtcIntersect1 / rtcOccluded1) so
// that it compares with the framework's one-ray-at-a-time traversal.
#include <embree3/rtcore.h>

#include <string>
#include <vector>

namespace pt::bench {

// A device; "threads=1" makes builds single-threaded like the reference
// builder. Queries run on the caller's threads whatever the device config.
class EmbreeDevice {
 public:
  explicit EmbreeDevice(const char* config);
  ~EmbreeDevice();
  EmbreeDevice(const EmbreeDevice&) = delete;
  EmbreeDevice& operator=(const EmbreeDevice&) = delete;
  RTCDevice get() const { return device_; }
  std::string describe() const;  // version and enabled features

 private:
  RTCDevice device_;
};

struct FloatMesh {
  std::vector<float> vertices;   // x y z per vertex
  std::vector<uint32_t> indices;  // three per triangle
  size_t triangles() const { return indices.size() / 3; }
};

class EmbreeScene {
 public:
  // Copies the triangles into Embree buffers; the BVH is built by commit().
  EmbreeScene(const EmbreeDevice& device, const FloatMesh& mesh, RTCBuildQuality quality);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Builds the acceleration structure; returns the seconds rtcCommitScene took.
  double commit();

  // Closest hit: t of the hit or +inf; any hit: whether anything is hit in
  // [tnear, tfar].
  float intersect(const float o[3], const float d[3], float tnear, float tfar) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRayHit rh;
    rh.ray = make_ray(o, d, tnear, tfar);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &ctx, &rh);
    return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? kMiss : rh.ray.tfar;
  }
  bool occluded(const float o[3], const float d[3], float tnear, float tfar) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRay r = make_ray(o, d, tnear, tfar);
    rtcOccluded1(scene_, &ctx, &r);
    return r.tfar < 0.0f;  // set to -inf on a hit
  }
  static constexpr float kMiss = __builtin_inff();

 private:
  static RTCRay make_ray(const float o[3], const float d[3], float tnear, float tfar) {
    RTCRay r;
    r.org_x = o[0];
    r.org_y = o[1];
    r.org_z = o[2];
    r.dir_x = d[0];
    r.dir_y = d[1];
    r.dir_z = d[2];
    r.tnear = tnear;
    r.tfar = tfar;
    r.time = 0.0f;
    r.mask = 0xFFFFFFFFu;
    r.id = 0;
    r.flags = 0;
    return r;
  }

  RTCScene scene_ = nullptr;
};

}  // namespace pt::bench
