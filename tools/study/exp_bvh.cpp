// Experiment 1: the BVH against brute force over mesh size.
//
// Meshes: pt-bench's bumpy sphere (12 n^2 triangles, the library's
// million-triangle scene at n = 289), from about 100 to 1,000,000 triangles.
// Rays: the same incoherent closest-hit rays at every size (bench_scenes.h,
// random_rays), one thread. The BVH and the linear scan are timed in turns,
// run by run. The linear scan is measured while one pass over the rays is
// predicted to take at most `brute_limit` seconds (a minute in the full
// study) and extrapolated beyond, by a power law fitted to the measured sizes
// of 1,000 triangles and more; those rows say so (`extrapolated` = 1).
#include <algorithm>
#include <cstdio>
#include <memory>

#include "bench_scenes.h"
#include "core/stats.h"
#include "study.h"

namespace pt::study {
namespace {

// The course cow's size (handouts/part2.md: the write-up's 5.8k-triangle cow):
// the bumpy sphere at n = 22 has 12 * 22^2 = 5,808 triangles.
constexpr int kCowN = 22;

struct Timed {
  std::vector<double> runs;  // seconds per ray, one per run
  double mean() const {
    double s = 0;
    for (double r : runs) s += r;
    return s / runs.size();
  }
  double se() const {
    if (runs.size() < 2) return kNaN;
    double m = mean(), v = 0;
    for (double r : runs) v += (r - m) * (r - m);
    return std::sqrt(v / (runs.size() - 1) / runs.size());
  }
};

// One pass over the rays; returns seconds per ray and fills the hits' t.
template <class F>
double pass(const std::vector<Ray>& rays, std::vector<double>* t, const F& closest) {
  const double t0 = now_seconds();
  for (size_t i = 0; i < rays.size(); ++i) {
    Intersection isect;
    (*t)[i] = closest(rays[i], &isect) ? isect.t : kInf;
  }
  return (now_seconds() - t0) / double(rays.size());
}

}  // namespace

Experiment run_bvh(const Options& opt) {
  Experiment e;
  e.name = "bvh";
  e.title = "1. BVH against brute force";
  const std::vector<int> sizes = opt.quick ? std::vector<int>{3, 5, 9, 16, 22, 29, 51}
                                           : std::vector<int>{3, 5, 9, 16, 22, 29, 51, 91, 161, 289};
  const size_t nrays = opt.quick ? 2048 : 16384;
  const double brute_limit = opt.quick ? 1.0 : 60.0;  // seconds for one pass of the linear scan
  const int bvh_reps = opt.quick ? 3 : 5;
  e.scene = "pt-bench's bumpy sphere (12 n² triangles, n = 3 … " + std::to_string(sizes.back()) + "), " +
            std::to_string(nrays) +
            " incoherent closest-hit rays (origin and target uniform in the bounds + 10%), one thread";

  Table t(core_columns({"triangles", "seconds_per_ray", "seconds_per_ray_se", "tests_per_ray", "node_visits_per_ray",
                        "build_seconds", "build_seconds_se", "mismatches", "extrapolated"}));
  struct Point {
    double n, bvh, bvh_se, brute = kNaN, brute_se = kNaN;
  };
  std::vector<Point> pts;
  double cost_per_test = 0.0;  // brute force seconds per primitive test, from the last measured size
  std::vector<double> fit_x, fit_y;
  std::string cow_line;
  for (int n : sizes) {
    auto s = bench::mesh_scene("bumpy", "bumpy sphere", bench::make_bumpy_sphere(n));
    const std::vector<Primitive*> prims = s->prims();
    const double tris = double(prims.size());
    const std::vector<Ray> rays = bench::random_rays(s->bounds(), nrays, 2024, false);
    Timed build;
    std::unique_ptr<BVHAccel> bvh;
    for (int k = 0; k < (tris > 1e5 ? 2 : 3); ++k) {
      bvh.reset();
      const double t0 = now_seconds();
      bvh = std::make_unique<BVHAccel>(prims, 4);
      build.runs.push_back(now_seconds() - t0);
    }
    const double predicted = cost_per_test * tris * double(nrays);
    const bool measure_brute = cost_per_test == 0.0 || predicted <= brute_limit;
    const int brute_reps = !measure_brute ? 0 : predicted * 3 <= brute_limit / 4 ? 3 : 1;
    std::vector<double> t_bvh(rays.size()), t_brute(rays.size(), kNaN);
    Timed tb, tf;
    WorkCounters work;
    for (int k = 0; k < std::max(bvh_reps, brute_reps); ++k) {
      if (k < bvh_reps) {
        take_work_counters();
        tb.runs.push_back(pass(rays, &t_bvh, [&](const Ray& r, Intersection* i) { return bvh->intersect(r, i); }));
        work = take_work_counters();
      }
      if (k < brute_reps)
        tf.runs.push_back(pass(rays, &t_brute, [&](const Ray& r, Intersection* i) {
          return bench::brute_closest(prims, r, i);
        }));
    }
    int mismatches = 0;
    for (size_t i = 0; i < rays.size() && brute_reps; ++i)
      if (t_bvh[i] != t_brute[i]) ++mismatches;
    const double per_ray = double(nrays);
    // One row: a method's time per ray (mean and standard error over runs) at this size.
    auto row = [&](const char* method, const std::string& param, double secs, double se, double runs, double tests) {
      t.row()
          .set("method", method)
          .set("parameter", param)
          .set("value", tris)
          .set("samples", per_ray)
          .set("rays", per_ray)
          .set("wall_seconds", secs * per_ray)
          .set("wall_seconds_se", se * per_ray)
          .set("seeds", runs)
          .set("triangles", tris)
          .set("seconds_per_ray", secs)
          .set("seconds_per_ray_se", se)
          .set("tests_per_ray", tests)
          .set("extrapolated", std::string(method) == "brute_force_extrapolated" ? 1.0 : 0.0);
    };
    row("bvh", "n=" + std::to_string(n), tb.mean(), tb.se(), double(tb.runs.size()),
        double(work.primitive_tests) / per_ray);
    t.set("node_visits_per_ray", double(work.node_visits) / per_ray)
        .set("build_seconds", build.mean())
        .set("build_seconds_se", build.se())
        .set("mismatches", brute_reps ? double(mismatches) : kNaN);
    Point p{tris, tb.mean(), tb.se()};
    if (brute_reps) {
      cost_per_test = tf.mean() / tris;
      if (tris >= 1000) fit_x.push_back(std::log(tris)), fit_y.push_back(std::log(tf.mean()));
      p.brute = tf.mean();
      p.brute_se = tf.se();
      row("brute_force", "n=" + std::to_string(n), tf.mean(), tf.se(), double(tf.runs.size()), tris);
    } else {
      // log t = a + b log N, least squares over the measured sizes >= 1,000 triangles.
      const size_t m = fit_x.size();
      double sx = 0, sy = 0, sxx = 0, sxy = 0;
      for (size_t i = 0; i < m; ++i) sx += fit_x[i], sy += fit_y[i], sxx += fit_x[i] * fit_x[i], sxy += fit_x[i] * fit_y[i];
      const double b = (m * sxy - sx * sy) / (m * sxx - sx * sx), a = (sy - b * sx) / m;
      p.brute = std::exp(a + b * std::log(tris));
      row("brute_force_extrapolated", "n=" + std::to_string(n) + " fit N^" + fmt("%.3f", b), p.brute, kNaN, 0.0, tris);
    }
    std::fprintf(stderr, "  %9.0f triangles: build %.3g s, BVH %.3g us/ray (%.1f tests), brute %.3g us/ray%s\n", tris,
                 build.mean(), tb.mean() * 1e6, double(work.primitive_tests) / per_ray, p.brute * 1e6,
                 brute_reps ? "" : " (extrapolated)");
    if (n == kCowN) {
      const double ratio = p.brute / p.bvh;
      const double rel = std::sqrt(std::pow(p.brute_se / p.brute, 2) + std::pow(p.bvh_se / p.bvh, 2));
      e.headline.push_back({"bvh_speedup_at_cow", pm(ratio, ratio * rel, "×")});
      e.headline.push_back({"bvh_tests_per_ray_at_cow", fmt("%.1f", double(work.primitive_tests) / per_ray)});
      e.headline.push_back({"brute_tests_per_ray_at_cow", fmt("%.0f", tris)});
      cow_line = "At the course cow's size (" + fmt("%.0f", tris) + " triangles) the BVH traces a ray in " +
                 pm(p.bvh * 1e6, p.bvh_se * 1e6, " µs") + " against brute force's " +
                 pm(p.brute * 1e6, p.brute_se * 1e6, " µs") + ": a speed-up of <b>" + pm(ratio, ratio * rel, "×") +
                 "</b>, with " + fmt("%.1f", double(work.primitive_tests) / per_ray) + " primitive tests per ray against " +
                 fmt("%.0f", tris) + " (the write-up: 942 against 6, and 38.19 s against 0.0183 s for a whole render).";
    }
    pts.push_back(p);
  }
  const Point& last = pts.back();
  e.headline.push_back({"bvh_speedup_at_largest", fmt("%.0f×", last.brute / last.bvh)});
  e.headline.push_back({"bvh_largest_triangles", fmt("%.0f", last.n)});
  t.write(opt.out + "/bvh.csv");
  // Columns: 3 value, 12 triangles, 13 s/ray, 14 its se, 15 tests/ray, 16 nodes/ray, 17 build, 18 its se.
  e.gnuplot = R"GP(set multiplot layout 1,3 title "BVH against brute force: bumpy sphere, incoherent closest-hit rays, one thread"
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set xlabel "triangles"
set key top left
set grid
cow = 5808
set arrow 1 from cow, graph 0 to cow, graph 1 nohead dashtype 3 lc rgb "gray40"
set label 1 "course cow (5,808)" at cow, graph 0.04 left offset 0.5,0 textcolor rgb "gray40" front
is(m) = strcol(1) eq m
set title "time per ray"
set ylabel "seconds per ray"
set key at graph 0.02, graph 0.98 left top
plot "bvh.csv" using (is("bvh") ? $12 : NaN):13:14 with yerrorlines lc rgb "#1f77b4" pt 7 title "BVH", \
     "" using (is("brute_force") ? $12 : NaN):13:($14 == $14 ? $14 : 0) with yerrorlines lc rgb "#d62728" pt 5 title "brute force", \
     "" using (is("brute_force_extrapolated") ? $12 : NaN):13 with linespoints dashtype 2 lc rgb "#d62728" pt 4 title "brute force, extrapolated"
set title "primitive tests per ray"
set ylabel "tests per ray"
set key default
set key top left
plot "bvh.csv" using (is("bvh") ? $12 : NaN):15 with linespoints lc rgb "#1f77b4" pt 7 title "BVH", \
     "" using (is("brute_force") || is("brute_force_extrapolated") ? $12 : NaN):15 with linespoints lc rgb "#d62728" pt 5 title "brute force"
set title "BVH build time"
set ylabel "seconds"
set key default
set key top left
plot "bvh.csv" using (is("bvh") ? $12 : NaN):17:18 with yerrorlines lc rgb "#1f77b4" pt 7 title "BVH build (one thread)"
unset multiplot
)GP";
  e.html = "<p>Time per ray (left) and primitive tests per ray (middle) of the reference BVH and of the linear scan "
           "over every primitive, against the mesh's size; right, the BVH's build time. "
           "Brute force is measured while one pass over the rays takes at most " +
           fmt("%.0f", brute_limit) +
           " s and extrapolated beyond (dashed, open squares: a power law fitted to the measured sizes of 1,000 "
           "triangles and more). Error bars: standard error over the timed runs. " +
           cow_line + " At " + fmt("%.0f", last.n) + " triangles the speed-up is " + fmt("%.0f×", last.brute / last.bvh) +
           (std::isfinite(last.brute_se) ? "" : " (brute force extrapolated)") +
           ". The BVH's and brute force's closest hits agree on every measured ray (<code>mismatches</code> column).</p>";
  return e;
}

}  // namespace pt::study
