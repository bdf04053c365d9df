// The study's outputs beyond the CSVs: the gnuplot scripts and their charts,
// each experiment's fragment of the page, and index.html assembled from the
// fragments present in the folder (so `--only NAME` redoes one and keeps the rest).
#include "report.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace pt::study {
namespace {

std::string html_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '<') o += "&lt;";
    else if (c == '>') o += "&gt;";
    else if (c == '&') o += "&amp;";
    else if (c == '"') o += "&quot;";
    else o += c;
  }
  return o;
}

std::string read_text(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

}  // namespace

// The CSVs: comma-separated, a header row, "nan" where a column does not
// apply (read as NaN: a point with NaN is not drawn, and ($k == $k ? $k : 0)
// turns a missing error bar into none).
constexpr const char* kCsv = "set datafile separator comma\n";

bool have_gnuplot() { return std::system("gnuplot --version > /dev/null 2>&1") == 0; }

std::string draw_chart(const Options& opt, const Experiment& e) {
  // Wide enough for the panels of a multiplot.
  int rows = 1, panels = 1;
  if (auto p = e.gnuplot.find("multiplot layout "); p != std::string::npos)
    std::sscanf(e.gnuplot.c_str() + p + 17, "%d,%d", &rows, &panels);
  const int w = 120 + 470 * panels, h = rows == 1 ? 470 : 60 + 380 * rows;
  std::ostringstream gp;
  gp << "# " << e.title << "\n"
     << "# Drawn from " << e.name << ".csv alone: run `gnuplot " << e.name << ".gp` in this folder (gnuplot 5.4,\n"
     << "# Debian's gnuplot-nox). Writes " << e.name << ".png and " << e.name << ".svg. Written by pt-study.\n"
     << "set terminal pngcairo size " << w << "," << h << " font \"sans,10\"\n"
     << "set output \"" << e.name << ".png\"\n"
     << kCsv << e.gnuplot << "set output\nreset\n"
     << "set terminal svg size " << w << "," << h << " font \"sans,10\" background \"white\"\n"
     << "set output \"" << e.name << ".svg\"\n"
     << kCsv << e.gnuplot << "set output\n";
  const fs::path script = fs::path(opt.out) / (e.name + ".gp");
  std::ofstream(script) << gp.str();
  const std::string cmd = "cd '" + opt.out + "' && gnuplot " + e.name + ".gp > " + e.name + ".gnuplot.log 2>&1";
  if (std::system(cmd.c_str()) != 0)
    return "gnuplot failed on " + script.string() + " (see " + e.name + ".gnuplot.log)";
  for (const char* ext : {".png", ".svg"})
    if (!fs::exists(fs::path(opt.out) / (e.name + ext)) || fs::file_size(fs::path(opt.out) / (e.name + ext)) == 0)
      return "gnuplot wrote no " + e.name + ext;
  // A warning in the log is a chart that may be wrong (an empty plot, a bad column).
  std::string log = read_text(fs::path(opt.out) / (e.name + ".gnuplot.log"));
  if (!log.empty()) std::fprintf(stderr, "  gnuplot said, on %s.gp:\n%s", e.name.c_str(), log.c_str());
  return "";
}

void write_fragment(const Options& opt, const Experiment& e) {
  std::ostringstream h;
  h << "<section id=\"" << e.name << "\">\n<h2>" << html_escape(e.title) << "</h2>\n"
    << "<p class=\"scene\">" << html_escape(e.scene) << ". Took " << fmt("%.0f s", e.seconds) << ".</p>\n"
    << "<a href=\"" << e.name << ".svg\"><img class=\"chart\" src=\"" << e.name << ".png\" alt=\"" << html_escape(e.title)
    << "\"></a>\n";
  if (!e.strip.empty()) {
    h << "<div class=\"strip\">\n";
    for (const Picture& p : e.strip)
      h << "<figure><img src=\"" << p.file << "\" alt=\"" << html_escape(p.caption) << "\"><figcaption>"
        << html_escape(p.caption) << "</figcaption></figure>\n";
    h << "</div>\n";
  }
  h << e.html << "\n<p class=\"files\">Data: <a href=\"" << e.name << ".csv\">" << e.name << ".csv</a>, chart: <a href=\""
    << e.name << ".gp\">" << e.name << ".gp</a> (<a href=\"" << e.name << ".svg\">SVG</a>).</p>\n</section>\n";
  std::ofstream(fs::path(opt.out) / (e.name + ".html")) << h.str();
  nlohmann::ordered_json j;
  j["title"] = e.title;
  j["scene"] = e.scene;
  j["seconds"] = e.seconds;
  for (const auto& [k, v] : e.headline) j["headline"][k] = v;
  std::ofstream(fs::path(opt.out) / (e.name + ".json")) << j.dump(2) << "\n";
}

void write_index(const Options& opt, const std::vector<std::string>& order, const std::string& machine) {
  std::ostringstream h;
  h << R"(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>pt-study: speed against accuracy</title>
<style>
body { font-family: sans-serif; max-width: 1600px; margin: 1em auto; padding: 0 1em; color: #222; }
img.chart { max-width: 100%; border: 1px solid #ddd; }
.strip { display: flex; flex-wrap: wrap; gap: 8px; }
.strip figure { margin: 0; }
.strip img { width: 256px; image-rendering: pixelated; border: 1px solid #ccc; }
figcaption { font-size: 80%; max-width: 256px; }
.scene, .files { color: #555; font-size: 90%; }
pre { background: #f4f4f4; padding: 0.5em; white-space: pre-wrap; }
</style></head>
<body>
<h1>Speed against accuracy: the path tracer's methods, measured</h1>
)";
  // Every run into this folder, newest last: an --only run keeps the facts
  // of the runs that made the other sections.
  {
    std::ofstream(fs::path(opt.out) / "runs.log", std::ios::app) << machine << "\n\n";
  }
  h << "<pre>" << html_escape(read_text(fs::path(opt.out) / "runs.log")) << "</pre>\n";
  h << "<p>Every relMSE is measured against a converged reference rendered by the same code (reference solution) at "
       "the sample count stated per experiment, cached in <code>references/</code> with a sidecar; the reference's "
       "own expected contribution, a/N (a: the relative variance of one of its samples, measured from 32 "
       "independent passes; N: its sample count), is subtracted from each relMSE. Error bars are one standard "
       "error of the mean over independent seeds (or timed runs). Equal-time and equal-error figures are "
       "interpolated on the measured curves (linear in log-log between neighbouring points), never read off one "
       "run. Each chart is drawn by the gnuplot script beside its CSV, from the CSV alone.</p>\n<ul>\n";
  std::vector<std::string> present;
  for (const std::string& n : order)
    if (fs::exists(fs::path(opt.out) / (n + ".html"))) present.push_back(n);
  for (const std::string& n : present) {
    std::string title = n;
    try {
      title = nlohmann::json::parse(read_text(fs::path(opt.out) / (n + ".json"))).at("title");
    } catch (...) {
    }
    h << "<li><a href=\"#" << n << "\">" << html_escape(title) << "</a></li>\n";
  }
  h << "</ul>\n";
  for (const std::string& n : present) h << read_text(fs::path(opt.out) / (n + ".html"));
  // For the headless-browser check: how many images loaded.
  h << R"(<script>
window.addEventListener("load", function () {
  var imgs = document.images, ok = 0;
  for (var i = 0; i < imgs.length; ++i) if (imgs[i].complete && imgs[i].naturalWidth > 0) ++ok;
  document.body.setAttribute("data-images", ok + "/" + imgs.length);
});
</script>
</body></html>
)";
  std::ofstream(fs::path(opt.out) / "index.html") << h.str();
  // Every headline number in one file, for the handouts.
  nlohmann::ordered_json all;
  for (const std::string& n : present) {
    try {
      all[n] = nlohmann::json::parse(read_text(fs::path(opt.out) / (n + ".json")));
    } catch (...) {
    }
  }
  std::ofstream(fs::path(opt.out) / "headline.json") << all.dump(2) << "\n";
}

}  // namespace pt::study
