// Experiment 6: throughput of one render on 1 and 2 threads, timed in turns
// run by run, to say how the study's wall times scale. The image must be the
// same on any number of threads (each pixel has its own random stream).
#include <algorithm>
#include <cstdio>
#include <fstream>

#include "study.h"

namespace pt::study {

Experiment run_threads(const Options& opt) {
  Experiment e;
  e.name = "threads";
  e.title = "6. Threads";
  StudyScene s = load_study_scene("cornell_spheres");
  RenderSettings r = s.settings(opt, opt.quick ? 4 : 16, 1);
  const int reps = opt.quick ? 3 : 5;
  e.scene = "cornell_spheres, -m 5 --rr 0.7 -l 1 -s " + std::to_string(r.ns_aa) + ", " + std::to_string(opt.width) +
            "×" + std::to_string(opt.height) + ", " + std::to_string(reps) + " runs on each thread count, in turns";
  const std::string load_before = load_average();
  Table t(core_columns({"threads", "mrays_per_second", "identical_image"}));
  std::vector<double> secs[2], ratios;
  double rays = 0;
  Image first;
  bool identical = true;
  for (int k = 0; k < reps; ++k) {
    for (int th = 1; th <= 2; ++th) {
      PathTracer tracer(s.loaded.scene, r);
      RenderResult res = render(tracer, th);
      if (!res.ok()) throw std::runtime_error(res.error);
      secs[th - 1].push_back(res.seconds);
      rays = double(res.work.rays);
      if (first.pixels.empty()) first = res.image;
      else identical = identical && res.image.pixels == first.pixels;
    }
    ratios.push_back(secs[0].back() / secs[1].back());
  }
  for (int th = 1; th <= 2; ++th) {
    double m = 0, v = 0;
    for (double x : secs[th - 1]) m += x / reps;
    for (double x : secs[th - 1]) v += (x - m) * (x - m) / (reps - 1);
    t.row()
        .set("method", th == 1 ? "1_thread" : "2_threads")
        .set("parameter", "-t " + std::to_string(th))
        .set("value", th)
        .set("samples", r.ns_aa)
        .set("rays", rays)
        .set("wall_seconds", m)
        .set("wall_seconds_se", std::sqrt(v / reps))
        .set("seeds", reps)
        .set("threads", th)
        .set("mrays_per_second", rays / m / 1e6)
        .set("identical_image", identical ? 1.0 : 0.0);
  }
  t.write(opt.out + "/threads.csv");
  std::sort(ratios.begin(), ratios.end());
  const double median = ratios[ratios.size() / 2];
  double rm = 0, rv = 0;
  for (double x : ratios) rm += x / reps;
  for (double x : ratios) rv += (x - rm) * (x - rm) / (reps - 1);
  const std::string speedup = pm(rm, std::sqrt(rv / reps), "×");
  const std::string load_after = load_average();
  e.headline.push_back({"threads_speedup", speedup});
  e.headline.push_back({"threads_mrays_1", fmt("%.3g", rays / secs[0][0] / 1e6)});
  e.gnuplot = R"GP(set title "Throughput on 1 and 2 threads (Cornell box, -m 5)"
set ylabel "million rays per second"
set xlabel "threads"
set xrange [0.5:2.5]
set yrange [0:*]
set xtics 1
set grid ytics
set style fill solid 0.5
set boxwidth 0.5
plot "threads.csv" using 12:13 with boxes lc rgb "#1f77b4" notitle, \
     "" using 12:13:(sprintf("%.2f", $13)) with labels offset 0,1 notitle
)GP";
  e.html = "<p>One render timed " + std::to_string(reps) + " times on each thread count, in turns: 2 threads run " +
           speedup + " as fast as one (median of the paired ratios " + fmt("%.2f", median) +
           "). The load average was " + load_before + " before and " + load_after +
           " after: on a shared machine another process takes part of the second core, and every wall time on this "
           "page carries that. The images on 1 and 2 threads are " +
           (identical ? "identical, pixel for pixel." : "<b>not identical</b> (a bug: every pixel has its own stream).") +
           "</p>";
  return e;
}

}  // namespace pt::study
