// pt-study: speed against accuracy, charted, for the methods of the five parts
// (README.md beside this file).
//
//   pt-study --out study/                 the full study (8 minutes on a shared 2-core VM)
//   pt-study --quick --out /tmp/q         every experiment at toy size (the ctest `study` runs this)
//   pt-study --only bvh --out study/      one experiment; the page keeps the others
//   pt-study --only adaptive --out study/ Part 5's two: the stopping rule and the allocation
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <thread>

#include <CLI/CLI.hpp>

#include "bench_scenes.h"
#include "report.h"
#include "io/scene_loader.h"
#include "pt_source_dir.h"
#include "study.h"

namespace fs = std::filesystem;
using namespace pt::study;

namespace {

// The first line a shell command prints.
std::string command_output(const std::string& cmd) {
  std::string s;
  if (FILE* p = popen(cmd.c_str(), "r")) {
    char buf[256];
    if (fgets(buf, sizeof buf, p)) s = buf;
    pclose(p);
  }
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"pt-study: error against time for every method of the five parts; CSVs, gnuplot charts and index.html"};
  Options opt;
  std::vector<std::string> only;
  app.add_flag("--quick", opt.quick, "every experiment at toy size (under 90 s on 2 cores)");
  app.add_option("--only", only,
                 "run only these experiments (bvh, direct, roulette, depth, adaptive, allocation, threads; "
                 "adaptive includes allocation: Part 5's two)")
      ->delimiter(',');
  app.add_option("--out", opt.out, "output folder (created; references are cached in it)")->required();
  app.add_option("--threads,-t", opt.threads, "render threads")->check(CLI::Range(1, 64));
  app.add_option("--seeds", opt.seeds, "independent renders per configuration (default 6; 4 with --quick)")
      ->check(CLI::Range(2, 64));
  CLI11_PARSE(app, argc, argv);
  if (opt.quick) {
    if (app.count("--seeds") == 0) opt.seeds = 4;
    opt.width = 64, opt.height = 48;
  }
  for (int i = 0; i < argc; ++i) opt.command += std::string(i ? " " : "") + argv[i];

  const std::vector<std::pair<std::string, std::function<Experiment(const Options&)>>> experiments = {
      {"bvh", run_bvh},         {"direct", run_direct},     {"roulette", run_roulette},
      {"depth", run_depth},     {"adaptive", run_adaptive}, {"allocation", run_allocation},
      {"threads", run_threads}};
  std::vector<std::string> order;
  for (const auto& x : experiments) order.push_back(x.first);
  for (const std::string& n : only)
    if (std::find(order.begin(), order.end(), n) == order.end()) {
      std::cerr << "pt-study: --only: no experiment named \"" << n << "\" (bvh, direct, roulette, depth, adaptive, allocation, threads)\n";
      return 2;
    }
  // Part 5's question is one: what the stopping rule saves, and how far any
  // allocation could go (the bound, the budgeted allocator).
  if (std::find(only.begin(), only.end(), "adaptive") != only.end() &&
      std::find(only.begin(), only.end(), "allocation") == only.end())
    only.push_back("allocation");
  if (!have_gnuplot()) {
    std::cerr << "pt-study: gnuplot not found; install Debian's gnuplot-nox (./setup.sh --deps-only)\n";
    return 2;
  }
  std::error_code ec;
  fs::create_directories(opt.out, ec);
  if (ec || !fs::is_directory(opt.out)) {
    std::cerr << "pt-study: cannot create " << opt.out << ": " << ec.message() << "\n";
    return 2;
  }

  const std::string load_before = load_average();
  const double t0 = now_seconds();
  int failures = 0;
  try {
    for (const auto& [name, run] : experiments) {
      if (!only.empty() && std::find(only.begin(), only.end(), name) == only.end()) continue;
      std::fprintf(stderr, "[%s]\n", name.c_str());
      const double start = now_seconds();
      Experiment e = run(opt);
      e.seconds = now_seconds() - start;
      const std::string err = draw_chart(opt, e);
      if (!err.empty()) {
        std::fprintf(stderr, "pt-study: %s\n", err.c_str());
        ++failures;
      }
      write_fragment(opt, e);
      std::fprintf(stderr, "[%s] %.0f s\n", name.c_str(), e.seconds);
    }
  } catch (const std::exception& ex) {
    std::fprintf(stderr, "pt-study: %s\n", ex.what());
    return 1;
  }
  const double total = now_seconds() - t0;
  std::time_t now = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  std::string machine = "command: " + opt.command + "\n" + "mode: " + (opt.quick ? "quick" : "full") + ", " +
                        std::to_string(opt.width) + "x" + std::to_string(opt.height) + " renders, " +
                        std::to_string(opt.seeds) + " seeds per configuration, " + std::to_string(opt.threads) +
                        " render threads\n" + "machine: " + pt::bench::cpu_model() + ", " +
                        std::to_string(std::thread::hardware_concurrency()) + " hardware threads; load average " +
                        load_before + " before, " + load_average() + " after\n" +
                        "build: " + PT_STUDY_BUILD_TYPE + ", every part from reference/; commit " +
                        command_output("git -C '" + std::string(PT_SOURCE_DIR) + "' rev-parse --short HEAD 2>/dev/null") +
                        "\n" + "date: " + date + "; this run took " + fmt("%.0f s", total) +
                        (only.empty() ? "" : " (only some experiments; the others' sections are from earlier runs)");
  write_index(opt, order, machine);
  std::fprintf(stderr, "pt-study: %.0f s; open %s/index.html\n", total, opt.out.c_str());
  return failures ? 1 : 0;
}
