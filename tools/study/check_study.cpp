// pt-study-check DIR: the study test's checker. It shares no code with
// pt-study: it reads the CSVs with its own parser, decodes every chart with
// stb_image (PNG) and pugixml (SVG), and checks that the figures point the way
// the handouts say, from the CSVs alone. Exit 0 when every check passes, 1
// with one line per failure, 2 on a bad command line.
//
// The direction checks use margins of 3 standard errors (from the CSV's
// relmse_se, energy_bias_se columns) so that noise in a correct quick run does
// not fail them (a one-sided 3-sigma excursion: about 1e-3 per check) while a
// reversed or missing effect does: hemisphere sampling's relMSE on the Cornell
// box is about 100x light sampling's at equal time, far beyond that margin.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <pugixml.hpp>
#include <tinyexr.h>
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>

namespace fs = std::filesystem;

namespace {

int failures = 0;
void fail(const std::string& what) {
  std::cout << "FAIL: " << what << "\n";
  ++failures;
}

struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  int col(const std::string& name) const {
    auto it = std::find(header.begin(), header.end(), name);
    return it == header.end() ? -1 : int(it - header.begin());
  }
  std::string text(size_t r, const std::string& name) const {
    const int c = col(name);
    return c < 0 || size_t(c) >= rows[r].size() ? "" : rows[r][c];
  }
  double num(size_t r, const std::string& name) const {
    const std::string s = text(r, name);
    if (s.empty() || s == "nan") return NAN;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    return end && *end == '\0' ? v : NAN;
  }
  // Rows whose `method` is m (and whose `scene`, when given, is scene).
  std::vector<size_t> of(const std::string& m, const std::string& scene = "") const {
    std::vector<size_t> out;
    for (size_t r = 0; r < rows.size(); ++r)
      if (text(r, "method") == m && (scene.empty() || text(r, "scene") == scene)) out.push_back(r);
    return out;
  }
};

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) out.push_back(cell);
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

bool read_csv(const fs::path& p, Csv* csv) {
  std::ifstream f(p);
  if (!f) return false;
  std::string line;
  if (!std::getline(f, line)) return false;
  csv->header = split(line);
  while (std::getline(f, line)) {
    if (line.empty()) continue;
    csv->rows.push_back(split(line));
    if (csv->rows.back().size() != csv->header.size())
      fail(p.filename().string() + ": row " + std::to_string(csv->rows.size()) + " has " +
           std::to_string(csv->rows.back().size()) + " cells, the header " + std::to_string(csv->header.size()));
  }
  return true;
}

// log-log interpolation of y(x) on points sorted by x; NaN outside.
double interp(std::vector<std::pair<double, double>> pts, double x) {
  std::sort(pts.begin(), pts.end());
  for (size_t i = 0; i + 1 < pts.size(); ++i) {
    const auto [x0, y0] = pts[i];
    const auto [x1, y1] = pts[i + 1];
    if (x < x0 || x > x1 || x0 <= 0 || x1 <= 0 || y0 <= 0 || y1 <= 0) continue;
    if (x0 == x1) return y0;
    const double w = std::log(x / x0) / std::log(x1 / x0);
    return std::exp(std::log(y0) + w * std::log(y1 / y0));
  }
  return NAN;
}

void check_png(const fs::path& p) {
  int w = 0, h = 0, n = 0;
  unsigned char* px = stbi_load(p.string().c_str(), &w, &h, &n, 3);
  if (!px) {
    fail(p.filename().string() + ": not a valid PNG (" + (stbi_failure_reason() ? stbi_failure_reason() : "?") + ")");
    return;
  }
  std::set<int> colours;
  for (int i = 0; i < w * h && colours.size() < 3; ++i) colours.insert(px[3 * i] << 16 | px[3 * i + 1] << 8 | px[3 * i + 2]);
  stbi_image_free(px);
  if (w < 400 || h < 300) fail(p.filename().string() + ": " + std::to_string(w) + "x" + std::to_string(h) + ", too small for a chart");
  if (colours.size() < 3) fail(p.filename().string() + ": fewer than 3 colours: a blank chart");
}

void check_svg(const fs::path& p) {
  pugi::xml_document doc;
  pugi::xml_parse_result r = doc.load_file(p.string().c_str());
  if (!r) {
    fail(p.filename().string() + ": not valid XML (" + r.description() + ")");
    return;
  }
  if (std::string(doc.document_element().name()) != "svg") fail(p.filename().string() + ": the root element is not <svg>");
  size_t paths = 0;
  for (pugi::xpath_node n : doc.select_nodes("//*[local-name()='path']")) (void)n, ++paths;
  if (paths < 5) fail(p.filename().string() + ": " + std::to_string(paths) + " <path> elements: no chart drawn");
}

void need_rows(const Csv& c, const std::string& file, const std::string& method, size_t at_least,
               const std::string& scene = "") {
  const size_t n = c.of(method, scene).size();
  if (n < at_least)
    fail(file + ": " + std::to_string(n) + " rows of method " + method + (scene.empty() ? "" : " (" + scene + ")") +
         ", expected at least " + std::to_string(at_least));
}

void check_rows(const Csv& c, const std::string& file) {
  for (const char* col : {"method", "parameter", "value", "samples", "rays", "wall_seconds", "wall_seconds_se", "relmse",
                          "relmse_se", "seeds", "reference_spp"})
    if (c.col(col) < 0) fail(file + ": no column " + col);
  for (size_t r = 0; r < c.rows.size(); ++r) {
    const std::string where = file + " row " + std::to_string(r + 2) + " (" + c.text(r, "method") + " " +
                              c.text(r, "parameter") + ")";
    if (!(c.num(r, "rays") > 0)) fail(where + ": rays not positive");
    if (!(c.num(r, "wall_seconds") > 0)) fail(where + ": wall_seconds not positive");
    if (std::isfinite(c.num(r, "reference_spp"))) {
      if (!std::isfinite(c.num(r, "relmse"))) fail(where + ": no relMSE although compared with a reference");
      if (!(c.num(r, "relmse_se") >= 0)) fail(where + ": no standard error of relMSE");
      if (!(c.num(r, "seeds") >= 2)) fail(where + ": fewer than 2 seeds");
    }
  }
}

// An EXR's RGB, row 0 at the top; empty when it does not load.
std::vector<float> read_rgb(const fs::path& p, int* w, int* h) {
  float* rgba = nullptr;
  const char* err = nullptr;
  if (LoadEXR(&rgba, w, h, p.string().c_str(), &err) != TINYEXR_SUCCESS) {
    fail(p.string() + ": cannot read (" + (err ? err : "?") + ")");
    if (err) FreeEXRErrorMessage(err);
    return {};
  }
  std::vector<float> rgb(size_t(*w) * *h * 3);
  for (size_t i = 0; i < size_t(*w) * *h; ++i)
    for (int c = 0; c < 3; ++c) rgb[3 * i + c] = rgba[4 * i + c];
  free(rgba);
  return rgb;
}

// The bound E[r^2] / E[r]^2 at width x height, recomputed from the stored
// reference (mean and per-sample sd at a multiple of that size): a study
// pixel's per-sample variance is the mean over its k x k stored pixels of
// sd^2 + mean^2, less its mean squared; r^2 the mean over channels of
// variance / (mean^2 + 0.01). NaN when the files do not fit.
double recompute_bound(const std::string& scene, int width, int height) {
  const fs::path dir = fs::path(PT_SCENES_DIR) / "reference";
  int w = 0, h = 0, ws = 0, hs = 0;
  const std::vector<float> mean = read_rgb(dir / (scene + ".exr"), &w, &h), sd = read_rgb(dir / (scene + "_sd.exr"), &ws, &hs);
  if (mean.empty() || sd.empty() || w != ws || h != hs || width <= 0 || w % width || h % height || w / width != h / height)
    return NAN;
  const int k = w / width;
  double sum_r = 0, sum_r2 = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      double r2 = 0;
      for (int c = 0; c < 3; ++c) {
        double m = 0, second = 0;
        for (int j = 0; j < k; ++j)
          for (int i = 0; i < k; ++i) {
            const size_t q = 3 * (size_t(y * k + j) * w + size_t(x * k + i)) + c;
            m += mean[q];
            second += double(sd[q]) * sd[q] + double(mean[q]) * mean[q];
          }
        m /= k * k, second /= k * k;
        r2 += std::max(0.0, second - m * m) / (m * m + 0.01) / 3;
      }
      sum_r2 += r2, sum_r += std::sqrt(r2);
    }
  const double p = double(width) * height;
  return (sum_r2 / p) / ((sum_r / p) * (sum_r / p));
}

void check_allocation(const Csv& c) {
  std::set<std::string> scenes;
  for (size_t r = 0; r < c.rows.size(); ++r) scenes.insert(c.text(r, "scene"));
  // Every library scene but the generated million-triangle one, which --quick leaves out.
  if (scenes.size() < 6) fail("allocation.csv: " + std::to_string(scenes.size()) + " scenes, expected the library's (6 or more)");
  for (const std::string& s : scenes) {
    for (const char* m : {"fixed", "bound", "budget", "budget_one_round", "course_rule"}) need_rows(c, "allocation.csv", m, 1, s);
    const auto any = c.of("budget", s);
    if (any.empty()) continue;
    const double bound = recompute_bound(s, int(c.num(any.front(), "width")), int(c.num(any.front(), "height")));
    if (!std::isfinite(bound)) {
      fail("allocation.csv: cannot recompute the bound on " + s + " from scenes/reference/");
      continue;
    }
    for (size_t r : c.of("bound", s))
      if (!(std::abs(c.num(r, "value") / bound - 1) < 1e-3))
        fail("allocation.csv: the bound on " + s + ", " + c.text(r, "value") + ", differs from the bound recomputed from the stored reference, " + std::to_string(bound));
    for (const char* method : {"budget", "budget_one_round"}) {
      const auto budget = c.of(method, s);
      if (budget.empty()) continue;
      const size_t b = budget.front();
      const double spp = c.num(b, "budget");
      if (!(std::abs(c.num(b, "samples") - spp) < 1e-9 * spp))
        fail("allocation.csv: the budgeted allocator (" + std::string(method) + ") on " + s + " took " + c.text(b, "samples") + " spp, not its budget " + c.text(b, "budget"));
      // No allocation saves more than the bound: the budget's relMSE over fixed
      // sampling's at the same count, less 3 standard errors, must not exceed it.
      for (size_t f : c.of("fixed", s)) {
        if (c.num(f, "samples") != spp) continue;
        const double fe = c.num(f, "relmse"), be = c.num(b, "relmse");
        const double ratio = fe / be, se = ratio * std::hypot(c.num(f, "relmse_se") / fe, c.num(b, "relmse_se") / be);
        if (!(ratio - 3 * se <= bound))
          fail("allocation.csv: the budgeted allocator's (" + std::string(method) + ") savings on " + s + ", " + std::to_string(ratio) + " ± " + std::to_string(se) + ", beat the bound " + std::to_string(bound) + " by more than 3 standard errors");
      }
      // The bias is reported, not judged here: with --quick's 4 seeds its
      // standard error has 3 degrees of freedom, too few for a test that
      // must not fail a correct run (test_budget.cpp tests it with known variances).
      if (!std::isfinite(c.num(b, "energy_bias")) || !std::isfinite(c.num(b, "energy_bias_se")))
        fail("allocation.csv: no energy bias for the budgeted allocator (" + std::string(method) + ") on " + s);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: pt-study-check DIR   (a folder written by pt-study)\n";
    return 2;
  }
  const fs::path dir = argv[1];
  const std::vector<std::string> names = {"bvh", "direct", "roulette", "depth", "adaptive", "allocation", "threads"};
  std::map<std::string, Csv> csv;
  for (const std::string& n : names) {
    Csv c;
    if (!read_csv(dir / (n + ".csv"), &c)) {
      fail(n + ".csv: missing or empty");
      continue;
    }
    check_rows(c, n + ".csv");
    csv[n] = c;
    for (const char* ext : {".png", ".svg", ".gp"})
      if (!fs::exists(dir / (n + ext))) fail(n + ext + ": missing");
    if (fs::exists(dir / (n + ".png"))) check_png(dir / (n + ".png"));
    if (fs::exists(dir / (n + ".svg"))) check_svg(dir / (n + ".svg"));
  }

  // 1. BVH: rows, the cow's size, agreement, work per ray.
  if (csv.count("bvh")) {
    const Csv& c = csv["bvh"];
    need_rows(c, "bvh.csv", "bvh", 5);
    need_rows(c, "bvh.csv", "brute_force", 4);
    bool cow = false;
    for (size_t r : c.of("bvh")) {
      cow |= c.num(r, "triangles") == 5808;
      if (!(c.num(r, "tests_per_ray") < 50)) fail("bvh.csv: BVH takes " + c.text(r, "tests_per_ray") + " tests per ray at " + c.text(r, "triangles") + " triangles");
      const double mm = c.num(r, "mismatches");
      if (std::isfinite(mm) && mm != 0) fail("bvh.csv: the BVH and brute force disagree on " + c.text(r, "mismatches") + " rays");
    }
    if (!cow) fail("bvh.csv: no row at the course cow's size (5808 triangles)");
    for (size_t r : c.of("brute_force")) {
      for (size_t b : c.of("bvh"))
        if (c.num(b, "triangles") == c.num(r, "triangles") && c.num(r, "triangles") >= 1000 &&
            !(c.num(b, "seconds_per_ray") < c.num(r, "seconds_per_ray")))
          fail("bvh.csv: the BVH is not faster than brute force at " + c.text(r, "triangles") + " triangles");
    }
  }

  // 2. Direct lighting: light sampling below hemisphere at equal time; the point light.
  if (csv.count("direct")) {
    const Csv& c = csv["direct"];
    for (const char* s : {"cornell_spheres", "point_light_room"}) {
      need_rows(c, "direct.csv", "hemisphere", 3, s);
      need_rows(c, "direct.csv", "light", 3, s);
    }
    need_rows(c, "direct.csv", "trade", 3);
    auto curve = [&](const std::string& m, const std::string& s, const std::string& col) {
      std::vector<std::pair<double, double>> pts;
      for (size_t r : c.of(m, s)) pts.push_back({c.num(r, "wall_seconds"), c.num(r, col)});
      std::sort(pts.begin(), pts.end());
      return pts;
    };
    const auto h = curve("hemisphere", "cornell_spheres", "relmse"), hs = curve("hemisphere", "cornell_spheres", "relmse_se");
    const auto l = curve("light", "cornell_spheres", "relmse"), ls = curve("light", "cornell_spheres", "relmse_se");
    if (!h.empty() && !l.empty()) {
      const double lo = std::max(h.front().first, l.front().first), hi = std::min(h.back().first, l.back().first);
      if (lo < hi) {
        int compared = 0;
        for (int k = 0; k <= 4; ++k) {
          const double t = lo * std::pow(hi / lo, k / 4.0);
          const double eh = interp(h, t), el = interp(l, t);
          // Standard errors at t, interpolated as the values are.
          const double seh = interp(hs, t), sel = interp(ls, t);
          if (!std::isfinite(eh) || !std::isfinite(el) || !std::isfinite(seh) || !std::isfinite(sel)) continue;
          ++compared;
          if (!(el + 3 * sel < eh - 3 * seh))
            fail("direct.csv: at equal time " + std::to_string(t) + " s light sampling's relMSE " + std::to_string(el) +
                 " is not below hemisphere sampling's " + std::to_string(eh) + " by 3 standard errors");
        }
        if (!compared) fail("direct.csv: no time at which both Cornell curves can be interpolated");
      } else if (!(l.back().first <= h.front().first && l.back().second < h.front().second)) {
        fail("direct.csv: the hemisphere and light-sampling curves share no time and light sampling does not dominate");
      }
    }
    const auto ph = curve("hemisphere", "point_light_room", "relmse"), pl = curve("light", "point_light_room", "relmse");
    if (ph.size() >= 2 && !(ph.back().second >= 0.5 * ph.front().second))
      fail("direct.csv: hemisphere sampling's error on the point light fell with time (it cannot see a point light)");
    if (pl.size() >= 2 && !(pl.back().second < 0.5 * pl.front().second))
      fail("direct.csv: light sampling's error on the point light did not fall with time");
  }

  // 3, 4. Roulette and depth.
  if (csv.count("roulette")) {
    const Csv& c = csv["roulette"];
    need_rows(c, "roulette.csv", "roulette", 10);
    need_rows(c, "roulette.csv", "hard_cut", 3);
    need_rows(c, "roulette.csv", "roulette_spp", 3);
    for (size_t r : c.of("hard_cut"))
      if (c.num(r, "max_depth") == 1 && !(c.num(r, "energy_bias") + 3 * c.num(r, "energy_bias_se") < 0))
        fail("roulette.csv: a hard cut at depth 1 does not lose energy by 3 standard errors");
  }
  if (csv.count("depth")) {
    const Csv& c = csv["depth"];
    need_rows(c, "depth.csv", "max_depth", 5);
    const auto rows = c.of("max_depth");
    if (rows.size() >= 2) {
      const double first = c.num(rows.front(), "missing_energy"), last = c.num(rows.back(), "missing_energy");
      if (!(first > last + 3 * c.num(rows.front(), "missing_energy_se")))
        fail("depth.csv: the energy missing at the smallest depth is not above that at the largest");
    }
  }

  // 5. Adaptive: fewer rays than fixed at the same cap; the failure mode's bias.
  if (csv.count("adaptive")) {
    const Csv& c = csv["adaptive"];
    need_rows(c, "adaptive.csv", "fixed", 3);
    need_rows(c, "adaptive.csv", "adaptive", 2);
    for (const char* m : {"hemisphere_adaptive", "hemisphere_fixed", "light_adaptive"}) need_rows(c, "adaptive.csv", m, 1);
    // Per scene (the scene column): the fixed render at the largest count is the cap.
    std::set<std::string> scenes;
    for (size_t r : c.of("adaptive")) scenes.insert(c.text(r, "scene"));
    for (const std::string& scene : scenes) {
      double cap = 0, cap_rays = NAN;
      for (size_t r : c.of("fixed", scene))
        if (c.num(r, "samples") > cap) cap = c.num(r, "samples"), cap_rays = c.num(r, "rays");
      for (size_t r : c.of("adaptive", scene)) {
        if (!(c.num(r, "rays") < cap_rays))
          fail("adaptive.csv: adaptive " + c.text(r, "parameter") + " on " + scene + " traced " + c.text(r, "rays") +
               " rays, not fewer than fixed sampling at its cap (" + std::to_string(cap_rays) + ")");
        if (!(c.num(r, "samples") <= cap))
          fail("adaptive.csv: adaptive " + c.text(r, "parameter") + " on " + scene + " went past the cap");
      }
    }
    for (size_t r : c.of("hemisphere_adaptive"))
      if (!(c.num(r, "energy_bias") + 3 * c.num(r, "energy_bias_se") < 0))
        fail("adaptive.csv: adaptive hemisphere sampling shows no energy lost to black first batches");
  }

  // 5b. Allocation: the bound recomputed, the budget spent, the bound not beaten, no bias.
  if (csv.count("allocation")) check_allocation(csv["allocation"]);

  // 6. Threads.
  if (csv.count("threads")) {
    const Csv& c = csv["threads"];
    need_rows(c, "threads.csv", "1_thread", 1);
    need_rows(c, "threads.csv", "2_threads", 1);
    for (size_t r = 0; r < c.rows.size(); ++r)
      if (c.num(r, "identical_image") != 1) fail("threads.csv: the image differs between thread counts");
  }

  // The page: every image it shows exists, every chart is on it.
  std::ifstream page(dir / "index.html");
  if (!page) {
    fail("index.html: missing");
  } else {
    std::stringstream ss;
    ss << page.rdbuf();
    const std::string html = ss.str();
    std::set<std::string> srcs;
    std::regex img("<img[^>]*src=\"([^\"]+)\"");
    for (auto it = std::sregex_iterator(html.begin(), html.end(), img); it != std::sregex_iterator(); ++it)
      srcs.insert((*it)[1]);
    for (const std::string& s : srcs)
      if (!fs::exists(dir / s)) fail("index.html shows " + s + ", which does not exist");
    for (const std::string& n : names)
      if (!srcs.count(n + ".png")) fail("index.html does not show " + n + ".png");
  }
  if (failures) {
    std::cout << failures << " check(s) failed in " << dir << "\n";
    return 1;
  }
  std::cout << "pt-study-check: every CSV, chart and direction check passed in " << dir << "\n";
  return 0;
}
