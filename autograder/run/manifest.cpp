#include "run/manifest.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "report/atomic_file.h"

namespace pt::grade {
namespace {

using nlohmann::json;

// A test name ends up in a --gtest_filter: no pattern characters in it.
const std::regex kTestName(R"([A-Za-z_][A-Za-z0-9_]*\.[A-Za-z_][A-Za-z0-9_]*)");

ManifestTest parse_test(int part, const json& j) {
  if (!j.is_object()) throw std::runtime_error("not a JSON object");
  auto text = [&](const char* key) {
    auto it = j.find(key);
    if (it == j.end() || !it->is_string()) throw std::runtime_error(std::string("no string \"") + key + "\"");
    return it->get<std::string>();
  };
  ManifestTest t;
  t.name = text("test");
  t.task = text("task");
  const std::string visibility = text("visibility");
  auto points = j.find("points");
  if (points == j.end() || !points->is_number()) throw std::runtime_error("no number \"points\"");
  t.points = points->get<double>();
  if (!std::regex_match(t.name, kTestName)) throw std::runtime_error("\"" + t.name + "\" is not a Suite.Name");
  if (!std::regex_match(t.task, std::regex("P" + std::to_string(part) + "T[0-9]+")))
    throw std::runtime_error(t.name + ": task \"" + t.task + "\" is not a part " + std::to_string(part) + " task");
  if (!std::isfinite(t.points) || t.points <= 0 || t.points > 1000)
    throw std::runtime_error(t.name + ": points must be in (0, 1000]");
  if (visibility != "visible" && visibility != "hidden")
    throw std::runtime_error(t.name + ": visibility must be \"visible\" or \"hidden\"");
  t.hidden = visibility == "hidden";
  if (auto e = j.find("extension"); e != j.end()) {
    if (!e->is_boolean()) throw std::runtime_error(t.name + ": \"extension\" must be true or false");
    t.extension = e->get<bool>();
  }
  return t;
}

void check_unique(const PartManifest& tests) {
  std::set<std::string> seen;
  for (const auto& t : tests)
    if (!seen.insert(t.name).second) throw std::runtime_error(t.name + " is listed twice");
}

json to_json(const ManifestTest& t) {
  json j = {{"test", t.name}, {"task", t.task}, {"points", t.points}, {"visibility", t.hidden ? "hidden" : "visible"}};
  if (t.extension) j["extension"] = true;
  return j;
}

}  // namespace

int leave_extensions_uncounted(Manifest& manifest) {
  int n = 0;
  for (auto& [part, tests] : manifest.parts)
    for (auto& t : tests)
      if (t.extension) t.points = 0, ++n;
  return n;
}

PartManifest parse_listing(int part, const std::string& text) {
  PartManifest tests;
  std::istringstream in(text);
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (line.empty()) continue;
    try {
      tests.push_back(parse_test(part, json::parse(line)));
    } catch (const std::exception& e) {
      throw std::runtime_error("line " + std::to_string(number) + ": " + e.what());
    }
  }
  check_unique(tests);
  return tests;
}

Manifest read_manifest(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the manifest");
  Manifest m;
  try {
    const json doc = json::parse(in);
    for (const auto& [key, tests] : doc.at("parts").items()) {
      const int part = std::stoi(key);
      if (part < 1 || part > 99 || std::to_string(part) != key) throw std::runtime_error("bad part \"" + key + "\"");
      PartManifest& p = m.parts[part];
      for (const auto& t : tests) p.push_back(parse_test(part, t));
      check_unique(p);
    }
    for (const auto& h : doc.value("solution_lines", json::array()))
      m.solution_lines.insert(std::stoull(h.get<std::string>(), nullptr, 16));
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  return m;
}

void write_manifest(const std::string& path, const Manifest& manifest, const std::map<int, std::string>& sources) {
  json parts = json::object(), from = json::object();
  for (const auto& [part, tests] : manifest.parts) {
    json list = json::array();
    for (const auto& t : tests) list.push_back(to_json(t));
    parts[std::to_string(part)] = list;
  }
  for (const auto& [part, binary] : sources) from[std::to_string(part)] = binary;
  json lines = json::array();
  for (uint64_t h : manifest.solution_lines) {
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
    lines.push_back(hex);
  }
  const json doc = {{"format", "pt-grade manifest 1"}, {"listed_by", from}, {"parts", parts}, {"solution_lines", lines}};
  write_file_atomically(path, doc.dump(2) + "\n");
}

}  // namespace pt::grade
