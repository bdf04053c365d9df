#include "embree_scene.h"

#include <chrono>
#include <cstring>
#include <sstream>
#include <stdexcept>

namespace pt::bench {

namespace {
void check(RTCDevice device, const char* what) {
  RTCError e = rtcGetDeviceError(device);
  if (e != RTC_ERROR_NONE) throw std::runtime_error(std::string("Embree error ") + std::to_string(int(e)) + " in " + what);
}
}  // namespace

EmbreeDevice::EmbreeDevice(const char* config) : device_(rtcNewDevice(config)) {
  if (!device_) throw std::runtime_error("rtcNewDevice failed");
}

EmbreeDevice::~EmbreeDevice() { rtcReleaseDevice(device_); }

std::string EmbreeDevice::describe() const {
  std::ostringstream os;
  os << "Embree " << rtcGetDeviceProperty(device_, RTC_DEVICE_PROPERTY_VERSION_MAJOR) << "."
     << rtcGetDeviceProperty(device_, RTC_DEVICE_PROPERTY_VERSION_MINOR) << "."
     << rtcGetDeviceProperty(device_, RTC_DEVICE_PROPERTY_VERSION_PATCH);
  os << " (ray masks " << (rtcGetDeviceProperty(device_, RTC_DEVICE_PROPERTY_RAY_MASK_SUPPORTED) ? "on" : "off")
     << ", backface culling " << (rtcGetDeviceProperty(device_, RTC_DEVICE_PROPERTY_BACKFACE_CULLING_ENABLED) ? "on" : "off")
     << ", filter functions " << (rtcGetDeviceProperty(device_, RTC_DEVICE_PROPERTY_FILTER_FUNCTION_SUPPORTED) ? "on" : "off")
     << ")";
  return os.str();
}

EmbreeScene::EmbreeScene(const EmbreeDevice& device, const FloatMesh& mesh, RTCBuildQuality quality) {
  RTCDevice dev = device.get();
  scene_ = rtcNewScene(dev);
  rtcSetSceneBuildQuality(scene_, quality);
  RTCGeometry geom = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetGeometryBuildQuality(geom, quality);
  size_t nv = mesh.vertices.size() / 3;
  // rtcSetNewGeometryBuffer pads the buffer as Embree's SIMD loads require.
  auto* v = static_cast<float*>(
      rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), nv));
  std::memcpy(v, mesh.vertices.data(), mesh.vertices.size() * sizeof(float));
  auto* ix = static_cast<uint32_t*>(
      rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), mesh.triangles()));
  std::memcpy(ix, mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t));
  rtcCommitGeometry(geom);
  rtcAttachGeometry(scene_, geom);
  rtcReleaseGeometry(geom);
  check(dev, "scene set-up");
}

double EmbreeScene::commit() {
  auto t0 = std::chrono::steady_clock::now();
  rtcCommitScene(scene_);
  auto t1 = std::chrono::steady_clock::now();
  return std::chrono::duration<double>(t1 - t0).count();
}

EmbreeScene::~EmbreeScene() {
  if (scene_) rtcReleaseScene(scene_);
}

}  // namespace pt::bench
