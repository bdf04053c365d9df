#pragma once
// The page's settings and camera as JSON, read with the same bounds as the
// command line (render/limits.h). Each reader throws std::invalid_argument
// with a message naming the field, which the server answers with a 400.
#include <nlohmann/json.hpp>

#include "app/viewer_session.h"
#include "render/settings.h"

namespace pt {

// What the page can change: the render flags and the PNG exposure.
struct ViewerSettings {
  RenderSettings render;
  double exposure = 0.0;
};

nlohmann::json settings_json(const ViewerSettings& s);
// `current` with the fields of `j` applied: samples, light_samples,
// max_depth, accumulate (0 or 1), hemisphere, adaptive (null or
// [batch, tolerance]), rr, exposure, width, height, seed. Unknown fields,
// wrong types and values out of bounds are refused.
ViewerSettings apply_settings_json(const ViewerSettings& current, const nlohmann::json& j, int threads);

// A camera file: position, target, up, vfov, near, far (scenes/README.md).
nlohmann::json camera_json(const ViewState& v);
ViewState view_from_json(const nlohmann::json& j);

}  // namespace pt
