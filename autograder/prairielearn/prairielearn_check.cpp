// pt-prairielearn-check: checks PrairieLearn's grader export and the
// results.json its entry point wrote (test_prairielearn.sh).
//
//   pt-prairielearn-check image DIR --from IMAGE
//       DIR is the export (target prairielearn-grader). Its Dockerfile starts
//       FROM IMAGE; every COPY source is in DIR; every path of the image that
//       a RUN or the ENTRYPOINT names is a file one COPY put there (the
//       ENTRYPOINT's executable); README.md's info.json block is JSON whose
//       externalGradingOptions name that entry point and a timeout of at most
//       600 s, a minute more than the budget in grading.args at least.
//   pt-prairielearn-check results FILE --manifest M [--passed 1,5]
//       [--not-implemented 1,2] [--images] [--ungradable]
//       FILE is PrairieLearn's results.json, checked field by field: at most
//       1 MB; gradable, score in [0, 1], message, output, images ({label, url}
//       with a PNG data: URL) and tests (name, description, points,
//       max_points, message, output), nothing else; every graded test of M
//       once, a hidden one by its task alone (no hidden test's name anywhere
//       in the file), its maximum M's; the score the points over their
//       maximum. --passed: every test of those parts earned its points;
//       --not-implemented: every test of those parts failed, a visible one
//       with "not implemented: PnT" of its part in its output; every other
//       test scored 0. --images: a render and its stored reference for at
//       least one scene; else none. --ungradable: gradable false with its
//       format_errors, and no test.
// Exit status 0 when it holds, 1 (naming each problem) when not, 2 when it
// could not check.
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "run/manifest.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::vector<std::string> problems;
void problem(const std::string& what) { problems.push_back(what); }

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::set<int> parts_list(const std::string& text) {
  std::set<int> parts;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) parts.insert(std::stoi(item));
  return parts;
}

// --- image ------------------------------------------------------------------

struct Copy {
  std::string source, destination;
};

// The export's file at `image_path` in the image, through the COPYs ("" when none put it there).
fs::path exported(const fs::path& dir, const std::vector<Copy>& copies, const std::string& image_path) {
  for (const auto& c : copies) {
    if (image_path == c.destination) return dir / c.source;
    if (image_path.rfind(c.destination + "/", 0) == 0) return dir / c.source / image_path.substr(c.destination.size() + 1);
  }
  return {};
}

std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g s", s);
  return buf;
}

double budget_in(const fs::path& args_file) {
  std::istringstream in(read_text(args_file));
  for (std::string line; std::getline(in, line);)
    if (line == "--budget" && std::getline(in, line)) return std::stod(line);
  return 600;  // pt-grade submission's default
}

int check_image(const fs::path& dir, const std::string& from) {
  std::istringstream dockerfile(read_text(dir / "Dockerfile"));
  std::vector<Copy> copies;
  std::vector<std::string> run_paths;
  std::string entrypoint, base;
  for (std::string line; std::getline(dockerfile, line);) {
    std::istringstream words(line);
    std::string instruction;
    words >> instruction;
    if (instruction == "FROM") {
      words >> base;
    } else if (instruction == "COPY") {
      Copy c;
      words >> c.source >> c.destination;
      if (c.source.empty() || c.destination.empty() || c.source.rfind("--", 0) == 0)
        problem("Dockerfile: a COPY this check does not read: " + line);
      else if (!fs::exists(dir / c.source))
        problem("Dockerfile: COPY " + c.source + ": no such file in the export");
      copies.push_back(c);
    } else if (instruction == "RUN") {
      for (std::string w; words >> w;)
        if (w.rfind("/", 0) == 0) run_paths.push_back(w);
    } else if (instruction == "ENTRYPOINT") {
      std::string rest;
      std::getline(words, rest);
      try {
        entrypoint = json::parse(rest).at(0).get<std::string>();
      } catch (const json::exception&) {
        problem("Dockerfile: ENTRYPOINT is not an exec-form array: " + line);
      }
    }
  }
  if (base != from) problem("Dockerfile: FROM " + base + ", not " + from);
  for (const auto& p : run_paths)
    if (const fs::path f = exported(dir, copies, p); f.empty() || !fs::exists(f))
      problem("Dockerfile: RUN names " + p + ", which no COPY puts in the image");
  const fs::path entry = exported(dir, copies, entrypoint);
  if (entrypoint.empty() || entry.empty() || !fs::is_regular_file(entry))
    problem("Dockerfile: ENTRYPOINT " + entrypoint + " is not a file the COPYs put in the image");
  else if ((fs::status(entry).permissions() & fs::perms::owner_exec) == fs::perms::none)
    problem("the entry point " + entry.string() + " is not executable");

  // The set-up the README gives, against the image.
  const std::string readme = read_text(dir / "README.md");
  const std::string open = "```json\n";
  const size_t start = readme.find(open), end = readme.find("```", start + open.size());
  if (start == std::string::npos || end == std::string::npos) {
    problem("README.md: no ```json block with info.json's externalGradingOptions");
  } else {
    try {
      const json options =
          json::parse(readme.substr(start + open.size(), end - start - open.size())).at("externalGradingOptions");
      if (options.at("entrypoint").get<std::string>() != entrypoint)
        problem("README.md: info.json's entrypoint " + options.at("entrypoint").get<std::string>() +
                " is not the image's " + entrypoint);
      const double timeout = options.at("timeout").get<double>();
      const fs::path args = entry.parent_path() / "grading.args";
      const double budget = !entry.empty() && fs::is_regular_file(args) ? budget_in(args) : 600;
      if (timeout > 600) problem("README.md: a timeout of " + seconds(timeout) + "; PrairieLearn allows 600 s");
      if (budget + 60 > timeout)
        problem("README.md: a timeout of " + seconds(timeout) + " leaves less than a minute past the budget of " +
                seconds(budget) + " in grading.args");
      if (!options.at("enabled").get<bool>()) problem("README.md: external grading not enabled");
      options.at("image").get<std::string>();
    } catch (const json::exception& e) {
      problem(std::string("README.md: info.json's block: ") + e.what());
    }
  }
  return 0;
}

// --- results ----------------------------------------------------------------

void expect_string(const json& j, const char* key, const std::string& where) {
  if (!j.contains(key) || !j[key].is_string()) problem(where + ": \"" + key + "\" is not a string");
}

void expect_only(const json& j, const std::set<std::string>& keys, const std::string& where) {
  for (const auto& [k, v] : j.items())
    if (!keys.count(k)) problem(where + ": a field PrairieLearn does not read: \"" + k + "\"");
}

// Base64's alphabet, padded to a multiple of 4 (a regex recurses per
// character: 100 KB of it overflows the stack).
bool is_base64(const std::string& data) {
  const size_t end = data.find_last_not_of('=') + 1;
  if (data.size() % 4 != 0 || data.size() - end > 2) return false;
  for (size_t i = 0; i < end; ++i)
    if (!std::isalnum(static_cast<unsigned char>(data[i])) && data[i] != '+' && data[i] != '/') return false;
  return true;
}

size_t check_images(const json& doc, const std::string& where) {
  if (!doc.contains("images")) return 0;
  if (!doc["images"].is_array()) {
    problem(where + ": images is not an array");
    return 0;
  }
  const std::string prefix = "data:image/png;base64,", signature = "iVBORw0KGgo";  // a PNG's first 8 bytes, in base64
  for (const auto& image : doc["images"]) {
    if (!image.is_object()) {
      problem(where + ": an image is not an object");
      continue;
    }
    expect_only(image, {"label", "url"}, where + ": an image");
    expect_string(image, "label", where + ": an image");
    expect_string(image, "url", where + ": an image");
    if (!image.contains("url") || !image["url"].is_string()) continue;
    const std::string url = image["url"];
    const std::string data = url.substr(std::min(url.size(), prefix.size()));
    if (url.rfind(prefix + signature, 0) != 0 || !is_base64(data))
      problem(where + ": image \"" + image.value("label", "") + "\" is not a PNG data: URL");
  }
  return doc["images"].size();
}

int check_results(const fs::path& file, const pt::grade::Manifest& manifest, const std::set<int>& passed,
                  const std::set<int>& not_implemented, bool images, bool ungradable) {
  const std::string text = read_text(file);
  if (text.size() > 1000000) problem("results.json is " + std::to_string(text.size()) + " bytes; PrairieLearn takes 1 MB");
  const json doc = json::parse(text);
  if (!doc.is_object()) throw std::runtime_error("results.json is not an object");
  expect_only(doc, {"gradable", "score", "message", "output", "images", "tests", "format_errors"}, "results");
  if (!doc.contains("gradable") || !doc["gradable"].is_boolean()) problem("results: \"gradable\" is not a boolean");
  if (!doc.contains("score") || !doc["score"].is_number() || doc["score"] < 0 || doc["score"] > 1)
    problem("results: \"score\" is not a number in [0, 1]");
  expect_string(doc, "message", "results");
  expect_string(doc, "output", "results");
  const size_t image_count = check_images(doc, "results");
  if (!doc.contains("tests") || !doc["tests"].is_array()) throw std::runtime_error("results: \"tests\" is not an array");

  if (ungradable) {
    if (doc.value("gradable", true)) problem("results: gradable, for a submission that cannot be graded");
    if (!doc.contains("format_errors") || !doc["format_errors"].is_array() || doc["format_errors"].empty() ||
        !doc["format_errors"][0].is_string())
      problem("results: not gradable without format_errors saying why");
    if (!doc["tests"].empty()) problem("results: tests listed for a submission that was not graded");
    return 0;
  }
  if (!doc.value("gradable", false)) problem("results: not gradable: " + doc.value("message", ""));
  if (doc.contains("format_errors")) problem("results: format_errors in a gradable submission's results");
  if (images && image_count < 2) problem("results: no render beside its stored reference");
  if (!images && image_count > 0) problem("results: images where no part earned a point");
  if (images) {
    bool render = false, reference = false;
    for (const auto& i : doc["images"]) {
      render = render || i.value("label", "").find("your render") != std::string::npos;
      reference = reference || i.value("label", "").find("stored reference") != std::string::npos;
    }
    if (!render || !reference) problem("results: the images are not a render and its stored reference");
  }

  // Every graded test once: a visible one by "TASK NAME", a hidden one by its task.
  std::map<std::string, const pt::grade::ManifestTest*> visible;
  std::map<std::string, int> hidden;  // task -> how many
  std::map<std::string, double> hidden_points;  // task -> their maximum together
  std::map<std::string, int> part_of;
  std::vector<std::string> hidden_names;
  for (const auto& [part, tests] : manifest.parts)
    for (const auto& t : tests) {
      part_of[t.task] = part;
      if (t.hidden) {
        ++hidden[t.task];
        hidden_points[t.task] += t.points;
        hidden_names.push_back(t.name);
      } else {
        visible[t.task + " " + t.name] = &t;
      }
    }
  for (const auto& name : hidden_names)
    if (text.find(name) != std::string::npos) problem("results: a hidden test's name is in the file: " + name);
  double earned = 0, possible = 0;
  std::set<std::string> seen;
  const std::regex hidden_name("(P([0-9]+)T[0-9]+) hidden test [0-9]+");
  for (const auto& t : doc["tests"]) {
    std::string name = t.value("name", "");
    const std::string where = "test \"" + name + "\"";
    expect_only(t, {"name", "description", "points", "max_points", "message", "output", "images"}, where);
    for (const char* key : {"name", "description", "message", "output"}) expect_string(t, key, where);
    check_images(t, where);
    if (!t.contains("points") || !t.contains("max_points") || !t["points"].is_number() || !t["max_points"].is_number()) {
      problem(where + ": points or max_points is not a number");
      continue;
    }
    const double points = t["points"], max_points = t["max_points"];
    if (points < 0 || points > max_points) problem(where + ": " + std::to_string(points) + " points of " + std::to_string(max_points));
    if (!seen.insert(name).second) problem(where + ": listed twice");
    // An extension test is graded at 0 points unless the instructor counts it, and says so.
    const std::string uncounted = " (extension, not counted)";
    if (name.size() > uncounted.size() && name.compare(name.size() - uncounted.size(), uncounted.size(), uncounted) == 0)
      name.resize(name.size() - uncounted.size());
    std::smatch m;
    std::string task;
    bool is_hidden = false;
    if (auto v = visible.find(name); v != visible.end()) {
      task = v->second->task;
      if (max_points != v->second->points) problem(where + ": max_points " + std::to_string(max_points) + ", the manifest's " + std::to_string(v->second->points));
      visible.erase(v);
    } else if (std::regex_match(name, m, hidden_name) && hidden.count(m[1].str()) && hidden[m[1].str()] > 0) {
      task = m[1].str();
      is_hidden = true;
      --hidden[task];
      hidden_points[task] -= max_points;
      if (!t.value("output", "").empty()) problem(where + ": a hidden test's output is shown");
    } else {
      problem(where + ": not a graded test of the manifest");
      continue;
    }
    earned += points;
    possible += max_points;
    const int part = part_of[task];
    if (passed.count(part)) {
      if (points != max_points || t.value("message", "") != "passed") problem(where + ": did not pass: " + t.value("message", ""));
    } else if (points != 0) {
      problem(where + ": scored " + std::to_string(points));
    }
    if (not_implemented.count(part)) {
      if (t.value("message", "") == "passed") problem(where + ": passed");
      const std::string wanted = "not implemented: P" + std::to_string(part) + "T";
      if (!is_hidden && t.value("output", "").find(wanted) == std::string::npos)
        problem(where + ": its output does not name a task of its part (\"" + wanted + "\"):\n" + t.value("output", ""));
    }
  }
  for (const auto& [name, t] : visible) problem("test \"" + name + "\" is missing");
  for (const auto& [task, count] : hidden)
    if (count > 0) problem(std::to_string(count) + " hidden test(s) of " + task + " missing");
  for (const auto& [task, points] : hidden_points)
    if (std::abs(points) > 1e-9) problem("the hidden tests of " + task + " are not worth the manifest's points");
  if (possible > 0 && doc.contains("score") && doc["score"].is_number() &&
      std::abs(doc["score"].get<double>() - earned / possible) > 1e-9)
    problem("results: score " + doc["score"].dump() + ", the tests' points give " + std::to_string(earned / possible));
  std::printf("%s: %zu bytes, score %s, %zu tests, %zu images\n", file.c_str(), text.size(), doc["score"].dump().c_str(),
              doc["tests"].size(), image_count);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  auto option = [&](const std::string& name) -> std::string {
    for (size_t i = 0; i + 1 < args.size(); ++i)
      if (args[i] == name) return args[i + 1];
    return "";
  };
  auto flag = [&](const std::string& name) {
    for (const auto& a : args)
      if (a == name) return true;
    return false;
  };
  try {
    if (args.size() >= 2 && args[0] == "image") {
      check_image(args[1], option("--from"));
    } else if (args.size() >= 2 && args[0] == "results" && !option("--manifest").empty()) {
      pt::grade::Manifest manifest = pt::grade::read_manifest(option("--manifest"));
      pt::grade::leave_extensions_uncounted(manifest);  // as pt-grade grades by default
      check_results(args[1], manifest, parts_list(option("--passed")),
                    parts_list(option("--not-implemented")), flag("--images"), flag("--ungradable"));
    } else {
      std::fprintf(stderr, "usage: pt-prairielearn-check image DIR --from IMAGE\n"
                           "       pt-prairielearn-check results FILE --manifest M [--passed PARTS] "
                           "[--not-implemented PARTS] [--images] [--ungradable]\n");
      return 2;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pt-prairielearn-check: %s\n", e.what());
    return 2;
  }
  for (const auto& p : problems) std::fprintf(stderr, "%s\n", p.c_str());
  if (problems.empty()) std::printf("pt-prairielearn-check %s: OK\n", args[0].c_str());
  return problems.empty() ? 0 : 1;
}
