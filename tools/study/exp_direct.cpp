// Experiment 2: direct lighting, uniform hemisphere sampling against light
// sampling (Part 3), on the Cornell box (-m 1); the point-light room, where
// hemisphere sampling cannot converge; and the -l against -s trade at an
// equal number of shadow rays per pixel.
#include <cstdio>

#include "study.h"

namespace pt::study {
namespace {

struct Curve {
  std::vector<double> time, relmse, relmse_se, spp;
  void add(const Measurement& m) {
    time.push_back(m.seconds);
    relmse.push_back(m.relmse);
    relmse_se.push_back(m.relmse_se);
    spp.push_back(m.spp);
  }
};

}  // namespace

Experiment run_direct(const Options& opt) {
  Experiment e;
  e.name = "direct";
  e.title = "2. Direct lighting: hemisphere against light sampling";
  const std::vector<int> spps = opt.quick ? std::vector<int>{2, 4, 8, 16} : std::vector<int>{2, 4, 8, 16, 32, 64, 128};
  const int ref_spp = opt.quick ? 1024 : 8192;
  const int trade_total = opt.quick ? 16 : 64;  // shadow rays per pixel in the -l/-s trade: s * l
  e.scene = "cornell_spheres and point_light_room, -m 1 (direct light only), -l 1, " + std::to_string(opt.width) +
            "×" + std::to_string(opt.height) + "; reference: light sampling at " + std::to_string(ref_spp) + " spp";
  Table t(core_columns({"scene", "light_samples"}));

  StudyScene cornell = load_study_scene("cornell_spheres");
  StudyScene point = load_study_scene("point_light_room");
  std::map<std::string, Curve> curves;  // "<scene> <method>"
  std::map<std::string, Measurement> firsts;
  for (StudyScene* s : {&cornell, &point}) {
    RenderSettings base = s->settings(opt);
    base.max_ray_depth = 1;
    base.ns_area_light = 1;
    const Reference ref = get_reference(opt, *s, base, ref_spp);
    for (const char* method : {"hemisphere", "light"}) {
      for (int spp : spps) {
        RenderSettings r = base;
        r.ns_aa = spp;
        r.direct_hemisphere_sample = std::string(method) == "hemisphere";
        Measurement m = measure(opt, *s, r, &ref);
        set_row(t, method, "s=" + std::to_string(spp), spp, m, &ref);
        t.set("scene", s->entry.name).set("light_samples", 1.0);
        curves[s->entry.name + " " + method].add(m);
        std::fprintf(stderr, "  %s %s %3d spp: %.3g s, relMSE %.4g +- %.2g\n", s->entry.name.c_str(), method, spp,
                     m.seconds, m.relmse, m.relmse_se);
        if (spp == spps[spps.size() / 2]) firsts[s->entry.name + " " + method] = std::move(m);
      }
    }
    if (s == &cornell) {
      // The -l against -s trade: s * l shadow rays per pixel either way.
      for (int spp = 1; spp <= trade_total; spp *= 2) {
        RenderSettings r = base;
        r.ns_aa = spp;
        r.ns_area_light = trade_total / spp;
        Measurement m = measure(opt, *s, r, &ref);
        set_row(t, "trade", "s=" + std::to_string(spp) + " l=" + std::to_string(trade_total / spp), spp, m, &ref);
        t.set("scene", s->entry.name).set("light_samples", double(trade_total / spp));
        curves["trade"].add(m);
      }
      write_picture(opt, "strips/direct_reference.png", ref.image);
    } else {
      write_picture(opt, "strips/point_reference.png", ref.image);
    }
  }
  t.write(opt.out + "/direct.csv");

  // Equal time on the Cornell box: hemisphere's relMSE over light
  // sampling's, interpolated on the two measured curves (log-log) at the
  // geometric middle of the times both cover.
  const Curve& h = curves["cornell_spheres hemisphere"];
  const Curve& l = curves["cornell_spheres light"];
  const double lo = std::max(h.time.front(), l.time.front()), hi = std::min(h.time.back(), l.time.back());
  std::string equal_time;
  if (lo < hi) {
    const double at = std::sqrt(lo * hi);
    const double eh = interp_loglog(h.time, h.relmse, at), el = interp_loglog(l.time, l.relmse, at);
    equal_time = "At equal time (" + fmt("%.3g s", at) + ", interpolated on both curves) hemisphere sampling's relMSE is " +
                 fmt("%.3g", eh) + ", light sampling's " + fmt("%.3g", el) + ": <b>" + fmt("%.0f", eh / el) +
                 "× higher</b>. ";
    e.headline.push_back({"direct_equal_time_ratio", fmt("%.0f×", eh / el)});
    e.headline.push_back({"direct_equal_time_seconds", fmt("%.3g s", at)});
  }
  // Equal error: the least error hemisphere sampling reached, and when light sampling had it.
  const double eh_best = h.relmse.back(), th_best = h.time.back();
  std::string equal_error;
  if (l.relmse.front() <= eh_best) {
    equal_error = "Hemisphere sampling's best error (" + fmt("%.3g", eh_best) + " after " + fmt("%.3g s", th_best) +
                  ") is already beaten by light sampling's shortest run (" + fmt("%.3g", l.relmse.front()) + " in " +
                  fmt("%.3g s", l.time.front()) + "): light sampling needs less than " +
                  fmt("1/%.0f", th_best / l.time.front()) + " of the time for that error. ";
    e.headline.push_back({"direct_equal_error_time_ratio_at_least", fmt("%.0f×", th_best / l.time.front())});
  }
  // The strip: light sampling at the middle sample count, hemisphere sampling
  // at the sample count its curve says takes the same time.
  const int mid = spps[spps.size() / 2];
  const double budget = interp_linear(l.spp, l.time, mid);
  double hemi_spp = interp_loglog(h.time, h.spp, budget);
  if (!std::isfinite(hemi_spp)) hemi_spp = budget < h.time.front() ? h.spp.front() : h.spp.back();
  RenderSettings hs = cornell.settings(opt, std::max(2, int(std::lround(hemi_spp))), 1);
  hs.max_ray_depth = 1;
  hs.direct_hemisphere_sample = true;
  PathTracer ht(cornell.loaded.scene, hs);
  RenderResult hr = render(ht, opt.threads);
  write_picture(opt, "strips/direct_hemisphere.png", hr.image);
  write_picture(opt, "strips/direct_light.png", firsts["cornell_spheres light"].first);
  write_picture(opt, "strips/point_hemisphere.png", firsts["point_light_room hemisphere"].first);
  write_picture(opt, "strips/point_light.png", firsts["point_light_room light"].first);
  e.strip = {{"strips/direct_hemisphere.png", "hemisphere, " + std::to_string(hs.ns_aa) + " spp, " + fmt("%.2g s", hr.seconds)},
             {"strips/direct_light.png", "light sampling, " + std::to_string(mid) + " spp, " +
                                             fmt("%.2g s", firsts["cornell_spheres light"].seconds)},
             {"strips/direct_reference.png", "reference, " + std::to_string(ref_spp) + " spp"},
             {"strips/point_hemisphere.png", "point light, hemisphere, " + std::to_string(mid) + " spp"},
             {"strips/point_light.png", "point light, light sampling, " + std::to_string(mid) + " spp"},
             {"strips/point_reference.png", "point light, reference"}};

  const Curve& ph = curves["point_light_room hemisphere"];
  const Curve& pl = curves["point_light_room light"];
  const Curve& tr = curves["trade"];
  size_t best = 0;
  for (size_t i = 0; i < tr.relmse.size(); ++i)
    if (tr.relmse[i] < tr.relmse[best]) best = i;
  const int best_s = int(tr.spp[best]);
  e.headline.push_back({"point_hemisphere_relmse", fmt2("%.3g → %.3g", ph.relmse.front(), ph.relmse.back())});
  e.headline.push_back({"point_light_relmse", fmt2("%.3g → %.3g", pl.relmse.front(), pl.relmse.back())});
  e.headline.push_back({"trade_best", "-s " + std::to_string(best_s) + " -l " + std::to_string(trade_total / best_s)});

  e.gnuplot = R"GP(set multiplot layout 1,3 title "Direct lighting (-m 1): uniform hemisphere against light sampling"
set logscale xy
set format y "10^{%L}"
set grid
set key bottom left
is(m, s) = strcol(1) eq m && strcol(12) eq s
set title "Cornell box: relMSE against time"
set xlabel "wall seconds per render"
set ylabel "relMSE"
plot "direct.csv" using (is("hemisphere", "cornell_spheres") ? $6 : NaN):8:9 with yerrorlines pt 7 lc rgb "#d62728" title "hemisphere (-H)", \
     "" using (is("light", "cornell_spheres") ? $6 : NaN):8:9 with yerrorlines pt 5 lc rgb "#1f77b4" title "light sampling"
set title "point light: hemisphere cannot see it"
plot "direct.csv" using (is("hemisphere", "point_light_room") ? $6 : NaN):8:9 with yerrorlines pt 7 lc rgb "#d62728" title "hemisphere (-H)", \
     "" using (is("light", "point_light_room") ? $6 : NaN):8:9 with yerrorlines pt 5 lc rgb "#1f77b4" title "light sampling"
set title "equal shadow rays: -s against -l (s × l fixed)"
set xlabel "samples per pixel -s (-l = total / s)"
set logscale x 2
set format x "%g"
set key top right
plot "direct.csv" using (strcol(1) eq "trade" ? $4 : NaN):8:9 with yerrorlines pt 9 lc rgb "#2ca02c" title "relMSE", \
     "" using (strcol(1) eq "trade" ? $4 : NaN):($6 * 10) with linespoints pt 6 dashtype 2 lc rgb "gray40" title "wall seconds × 10"
unset multiplot
)GP";
  e.html = "<p>Left: relMSE of direct lighting on the Cornell box against the wall time of a render, one line per "
           "estimator, " + std::to_string(spps.front()) + " to " + std::to_string(spps.back()) + " spp. " + equal_time +
           equal_error +
           "Middle: the point-light room, where no uniformly sampled direction can hit a delta light: hemisphere "
           "sampling's relMSE stays at " + fmt2("%.3g → %.3g", ph.relmse.front(), ph.relmse.back()) +
           " (the image is black) however long it runs, while light sampling's falls from " +
           fmt2("%.3g to %.3g", pl.relmse.front(), pl.relmse.back()) + ". Right: " + std::to_string(trade_total) +
           " shadow rays per pixel split as -s × -l: the lowest relMSE is at -s " + std::to_string(best_s) + " -l " +
           std::to_string(trade_total / best_s) + fmt(" (%.3g)", tr.relmse[best]) +
           "; more camera samples also antialias edges and sample the pixel's area, which light samples cannot, "
           "while light samples save the camera rays (-s 1 takes the pixel centre only, so its edges keep their "
           "aliasing). The strip shows the two estimators at equal time.</p>";
  return e;
}

}  // namespace pt::study
