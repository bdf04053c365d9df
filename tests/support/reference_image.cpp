#include "support/reference_image.h"

#include <fstream>
#include <stdexcept>
#include <vector>

#include <nlohmann/json.hpp>
#include <tinyexr.h>

namespace pt::library {

ReferencePaths reference_paths(const std::string& dir, const std::string& name) {
  const std::string stem = dir + "/" + name;
  return {stem + ".exr", stem + "_sd.exr", stem + ".json", stem + ".png"};
}

ReferenceImage read_reference(const std::string& dir, const std::string& name) {
  const ReferencePaths p = reference_paths(dir, name);
  ReferenceImage r;
  r.name = name;
  r.mean = read_exr(p.mean);
  r.sd = read_exr(p.sd);
  if (r.sd.width != r.mean.width || r.sd.height != r.mean.height)
    throw std::runtime_error(p.sd + ": size differs from " + p.mean);
  std::ifstream in(p.sidecar);
  if (!in) throw std::runtime_error(p.sidecar + ": cannot open");
  try {
    const nlohmann::json j = nlohmann::json::parse(in).at("error_model");
    if (j.at("epsilon").get<double>() != error_model::kRelMSEEpsilon)
      throw std::runtime_error("error_model/epsilon differs from compare_images' offset");
    r.model.a = j.at("a").get<double>();
    r.model.c2 = j.at("c2").get<double>();
    r.model.c3 = j.at("c3").get<double>();
    r.model.reference_samples = j.at("reference_samples").get<int>();
    if (r.model.reference_samples < 2) throw std::runtime_error("error_model/reference_samples below 2");
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(p.sidecar + ": " + e.what());
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(p.sidecar + ": " + e.what());
  }
  return r;
}

void write_half_exr(const std::string& path, const Image& image) {
  std::vector<float> rgb(image.pixels.size() * 3);
  for (size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) rgb[3 * i + c] = float(image.pixels[i][c]);
  const char* err = nullptr;
  if (SaveEXR(rgb.data(), image.width, image.height, 3, /*save_as_fp16=*/1, path.c_str(), &err) != TINYEXR_SUCCESS) {
    std::string msg = err ? err : "unknown error";
    FreeEXRErrorMessage(err);
    throw std::runtime_error(path + ": cannot write EXR: " + msg);
  }
}

}  // namespace pt::library
