#include "app/viewer_settings.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "render/limits.h"

namespace pt {

using json = nlohmann::json;

namespace {

[[noreturn]] void refuse(const std::string& field, const std::string& why) {
  throw std::invalid_argument(field + ": " + why);
}

std::string shown(const json& v) { return v.dump(); }

int integer_in(const json& j, const char* key, long long lo, long long hi) {
  const json& v = j.at(key);
  if (!v.is_number_integer()) refuse(key, "expected an integer, got " + shown(v));
  const long long n = v.get<long long>();
  if (n < lo || n > hi) refuse(key, std::to_string(n) + " is not in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return int(n);
}

double number_in(const json& v, const std::string& key, double lo, double hi) {
  if (!v.is_number()) refuse(key, "expected a number, got " + shown(v));
  const double x = v.get<double>();
  if (!(std::isfinite(x) && x >= lo && x <= hi))
    refuse(key, shown(v) + " is not in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return x;
}

Vec3 vec3(const json& j, const char* key) {
  const json& v = j.at(key);
  if (!v.is_array() || v.size() != 3) refuse(key, "expected [x, y, z], got " + shown(v));
  Vec3 out;
  for (int i = 0; i < 3; ++i) out[i] = number_in(v[i], key, -1e30, 1e30);
  return out;
}

}  // namespace

json settings_json(const ViewerSettings& vs) {
  const RenderSettings& s = vs.render;
  return {{"samples", s.ns_aa},
          {"light_samples", s.ns_area_light},
          {"max_depth", s.max_ray_depth},
          {"accumulate", s.accumulate_bounces ? 1 : 0},
          {"hemisphere", s.direct_hemisphere_sample},
          {"adaptive", s.adaptive ? json{s.samples_per_batch, s.max_tolerance} : json(nullptr)},
          {"rr", s.rr_continue_prob},
          {"exposure", vs.exposure},
          {"width", s.width},
          {"height", s.height},
          {"seed", s.seed}};
}

ViewerSettings apply_settings_json(const ViewerSettings& current, const json& j, int threads) {
  if (!j.is_object()) refuse("settings", "expected a JSON object, got " + shown(j));
  ViewerSettings out = current;
  RenderSettings& s = out.render;
  for (const auto& [key, value] : j.items()) {
    if (key == "samples") s.ns_aa = integer_in(j, "samples", 1, kMaxSamples);
    else if (key == "light_samples") s.ns_area_light = integer_in(j, "light_samples", 1, kMaxLightSamples);
    else if (key == "max_depth") s.max_ray_depth = integer_in(j, "max_depth", 0, kMaxRayDepth);
    else if (key == "accumulate") s.accumulate_bounces = integer_in(j, "accumulate", 0, 1) == 1;
    else if (key == "width") s.width = integer_in(j, "width", 1, kMaxImageSide);
    else if (key == "height") s.height = integer_in(j, "height", 1, kMaxImageSide);
    else if (key == "seed") s.seed = uint64_t(integer_in(j, "seed", 0, 2147483647));
    else if (key == "rr") s.rr_continue_prob = number_in(value, "rr", 1e-3, 1.0);
    else if (key == "exposure") out.exposure = number_in(value, "exposure", -64, 64);
    else if (key == "hemisphere") {
      if (!value.is_boolean()) refuse(key, "expected true or false, got " + shown(value));
      s.direct_hemisphere_sample = value.get<bool>();
    } else if (key == "adaptive") {
      if (value.is_null()) {
        s.adaptive = false;
        continue;
      }
      if (!value.is_array() || value.size() != 2) refuse(key, "expected null or [batch, tolerance], got " + shown(value));
      json pair = {{"adaptive batch", value[0]}};
      s.samples_per_batch = integer_in(pair, "adaptive batch", 1, kMaxSamples);
      s.max_tolerance = number_in(value[1], "adaptive tolerance", 0, 1e30);
      s.adaptive = true;
    } else {
      refuse(key, "not a setting (samples, light_samples, max_depth, accumulate, hemisphere, adaptive, rr, exposure, "
                  "width, height, seed)");
    }
  }
  // What no field shows alone: the pixel count.
  if (std::string why = check_render_limits(s, threads); !why.empty()) refuse("settings", why);
  return out;
}

json camera_json(const ViewState& v) {
  auto arr = [](const Vec3& p) { return json{p.x, p.y, p.z}; };
  return {{"position", arr(v.position)}, {"target", arr(v.target)}, {"up", arr(v.up)},
          {"vfov", v.vfov},             {"near", v.near_clip},      {"far", v.far_clip}};
}

ViewState view_from_json(const json& j) {
  if (!j.is_object()) refuse("camera", "expected a JSON object, got " + shown(j));
  for (const auto& [key, value] : j.items())
    if (key != "position" && key != "target" && key != "up" && key != "vfov" && key != "near" && key != "far")
      refuse(key, "not a camera field (position, target, up, vfov, near, far)");
  for (const char* key : {"position", "target", "up", "vfov"})
    if (!j.contains(key)) refuse(key, "missing");
  ViewState v;
  v.position = vec3(j, "position");
  v.target = vec3(j, "target");
  v.up = vec3(j, "up");
  v.vfov = number_in(j.at("vfov"), "vfov", 1e-3, 179.9);
  if (j.contains("near")) v.near_clip = number_in(j.at("near"), "near", 1e-30, 1e30);
  if (j.contains("far")) v.far_clip = number_in(j.at("far"), "far", 1e-30, 1e300);
  if (!(v.far_clip > v.near_clip)) refuse("far", "must be greater than near");
  if (v.target == v.position) refuse("target", "must differ from the camera position");
  const Vec3 view = v.target - v.position;
  if (glm::length(glm::cross(v.up, view)) <= 1e-9 * glm::length(v.up) * glm::length(view))
    refuse("up", "must not be zero or parallel to the viewing direction");
  return v;
}

}  // namespace pt
