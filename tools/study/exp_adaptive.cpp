// Experiment 5 (Part 5): adaptive against fixed sampling on the Cornell bunny,
// the rays each needs for an equal relMSE, and the documented failure mode:
// adaptive sampling with uniform hemisphere sampling stops on pixels whose
// first batch saw no light (mu = 0 passes the test) and leaves them black.
#include <algorithm>
#include <cstdio>

#include "study.h"

namespace pt::study {
namespace {

// Fixed rays needed for relMSE `err`, interpolated (log-log) on the fixed
// curve; with the delta-method relative standard error of the savings ratio.
struct Savings {
  double fixed_rays = kNaN, ratio = kNaN, ratio_se = kNaN;
};
Savings savings(const std::vector<double>& f_rays, const std::vector<double>& f_err, const std::vector<double>& f_se,
                const Measurement& a) {
  Savings s;
  // The fixed curve falls with rays: walk it by error, ascending.
  std::vector<double> e(f_err.rbegin(), f_err.rend()), r(f_rays.rbegin(), f_rays.rend()), se(f_se.rbegin(), f_se.rend());
  s.fixed_rays = interp_loglog(e, r, a.relmse);
  if (!std::isfinite(s.fixed_rays)) return s;
  s.ratio = s.fixed_rays / a.rays;
  for (size_t i = 0; i + 1 < e.size(); ++i) {
    if (a.relmse < e[i] || a.relmse > e[i + 1]) continue;
    const double slope = std::log(r[i + 1] / r[i]) / std::log(e[i + 1] / e[i]);  // d log rays / d log relMSE
    const double w = std::log(a.relmse / e[i]) / std::log(e[i + 1] / e[i]);
    const double fixed_rel = (1 - w) * se[i] / e[i] + w * se[i + 1] / e[i + 1];
    s.ratio_se = s.ratio * std::abs(slope) * std::hypot(a.relmse_se / a.relmse, fixed_rel);
    break;
  }
  return s;
}

}  // namespace

namespace {

struct Config {
  int batch;
  double tol;
};

// Fixed against adaptive sampling on one scene: the rows, and what the page says.
struct Comparison {
  Measurement fixed_cap, course;
  Savings course_savings;
  std::vector<double> f_time, f_spp;
  std::string course_line, best_line;
  int cap = 0;
};

Comparison compare(const Options& opt, const StudyScene& s, const Reference& ref, const std::vector<int>& spps,
                   const std::vector<Config>& configs, const Config& course, Table& t, Experiment& e,
                   const std::string& prefix) {
  Comparison c;
  c.cap = spps.back();
  std::vector<double> f_rays, f_err, f_se;
  const RenderSettings base = s.settings(opt);
  for (int spp : spps) {
    RenderSettings r = base;
    r.ns_aa = spp;
    Measurement m = measure(opt, s, r, &ref);
    set_row(t, "fixed", "s=" + std::to_string(spp), spp, m, &ref);
    t.set("scene", s.entry.name);
    std::fprintf(stderr, "  %s fixed %3d spp: %.3g s, %.3g rays, relMSE %.4g +- %.2g\n", s.entry.name.c_str(), spp,
                 m.seconds, m.rays, m.relmse, m.relmse_se);
    f_rays.push_back(m.rays), f_err.push_back(m.relmse), f_se.push_back(m.relmse_se);
    c.f_time.push_back(m.seconds), c.f_spp.push_back(spp);
    if (spp == c.cap) c.fixed_cap = std::move(m);
  }
  double best_ratio = 0;
  for (const Config& k : configs) {
    RenderSettings r = base;
    r.ns_aa = c.cap;
    r.adaptive = true;
    r.samples_per_batch = k.batch;
    r.max_tolerance = k.tol;
    Measurement m = measure(opt, s, r, &ref);
    const Savings sv = savings(f_rays, f_err, f_se, m);
    set_row(t, "adaptive", "a=" + std::to_string(k.batch) + " " + fmt("%g", k.tol), k.tol, m, &ref);
    t.set("scene", s.entry.name).set("batch", k.batch).set("tolerance", k.tol);
    t.set("fixed_rays_at_equal_relmse", sv.fixed_rays).set("savings", sv.ratio).set("savings_se", sv.ratio_se);
    std::fprintf(stderr, "  %s adaptive -a %d %g: %.3g s, %.1f spp, %.3g rays, relMSE %.4g +- %.2g, savings %.3g +- %.2g\n",
                 s.entry.name.c_str(), k.batch, k.tol, m.seconds, m.samples, m.rays, m.relmse, m.relmse_se, sv.ratio,
                 sv.ratio_se);
    const std::string line = "-a " + std::to_string(k.batch) + " " + fmt("%g", k.tol) + " takes " +
                             fmt("%.1f", m.samples) + " spp on average (" + fmt("%.3g", m.rays / c.fixed_cap.rays) +
                             " of the fixed " + std::to_string(c.cap) + "-spp render's rays) for relMSE " +
                             pm(m.relmse, m.relmse_se) + " against the fixed render's " +
                             pm(c.fixed_cap.relmse, c.fixed_cap.relmse_se) + "; fixed sampling reaches that relMSE with " +
                             (std::isfinite(sv.ratio) ? pm(sv.ratio, sv.ratio_se, "×") + " the adaptive render's rays"
                                                      : std::string("(outside the measured fixed curve)"));
    if (k.batch == course.batch && k.tol == course.tol) {
      c.course_line = line;
      c.course_savings = sv;
      e.headline.push_back({prefix + "savings_course", pm(sv.ratio, sv.ratio_se, "×")});
      e.headline.push_back({prefix + "course_spp", fmt("%.1f", m.samples)});
      e.headline.push_back({prefix + "course_rays_saved_vs_cap", fmt("%.2f×", c.fixed_cap.rays / m.rays)});
      e.headline.push_back({prefix + "course_relmse_vs_cap", fmt("%.2f×", m.relmse / c.fixed_cap.relmse)});
      write_picture(opt, "strips/" + prefix + "adaptive.png", m.first);
      write_picture(opt, "strips/" + prefix + "rate.png", sample_rate_image(m.first_counts, opt.width, opt.height, c.cap));
      c.course = std::move(m);
    }
    if (std::isfinite(sv.ratio) && sv.ratio > best_ratio) best_ratio = sv.ratio, c.best_line = line;
  }
  return c;
}

// "reproduced" or not: the write-up's 1.238 G against 370.9 M rays (3.3x) at
// "nearly identical" quality, read as the issue's target: at least 3x fewer
// rays than the fixed render at the cap, at a relMSE within 10% of it.
std::string verdict(const Comparison& c, const std::string& scene) {
  const double rays = c.fixed_cap.rays / c.course.rays, rel = c.course.relmse / c.fixed_cap.relmse;
  return "On " + scene + ", against the fixed " + std::to_string(c.cap) + "-spp render, the course's setting traces " +
         fmt("%.2f×", rays) + " fewer rays at " + fmt("%.2f×", rel) + " its relMSE: the target (at least 3× fewer "
         "rays at a relMSE within 10%) is " + (rays >= 3 && rel <= 1.1 ? "met." : "<b>not</b> met.");
}

}  // namespace

Experiment run_adaptive(const Options& opt) {
  Experiment e;
  e.name = "adaptive";
  e.title = "5. Adaptive against fixed sampling";
  const int ref_spp = opt.quick ? 512 : 4096;
  const std::vector<int> spps = opt.quick ? std::vector<int>{4, 8, 16, 32} : std::vector<int>{4, 8, 16, 32, 64, 128, 256};
  const int cap = spps.back();
  const std::vector<Config> configs =
      opt.quick ? std::vector<Config>{{4, 0.1}, {4, 0.05}, {8, 0.1}, {8, 0.05}}
                : std::vector<Config>{{8, 0.2}, {8, 0.1}, {8, 0.05}, {16, 0.05},
                                      {32, 0.2}, {32, 0.1}, {32, 0.05}, {32, 0.025}};
  const Config course = opt.quick ? Config{8, 0.05} : Config{32, 0.05};  // the course's -a 32 0.05
  const std::vector<Config> sun_configs =
      opt.quick ? std::vector<Config>{{8, 0.05}} : std::vector<Config>{{8, 0.05}, {32, 0.1}, {32, 0.05}};
  Table t(core_columns({"scene", "batch", "tolerance", "fixed_rays_at_equal_relmse", "savings", "savings_se",
                        "energy_bias", "energy_bias_se", "first_batch_stops"}));

  StudyScene s = load_study_scene("cornell_bunny");
  const RenderSettings base = s.settings(opt);
  const Reference ref = get_reference(opt, s, base, ref_spp);
  const Comparison bunny = compare(opt, s, ref, spps, configs, course, t, e, "adaptive_");
  StudyScene sun = load_study_scene("adaptive_sun");
  const Reference sun_ref = get_reference(opt, sun, sun.settings(opt), ref_spp);
  const Comparison sunc = compare(opt, sun, sun_ref, spps, sun_configs, course, t, e, "sun_");
  e.scene = "cornell_bunny (-m 5 --rr 0.7 -l 1) and adaptive_sun (-m 1), " + std::to_string(opt.width) + "×" +
            std::to_string(opt.height) + "; references " + std::to_string(ref_spp) + " spp; adaptive capped at -s " +
            std::to_string(cap);

  // The failure mode: direct light only (-m 1), hemisphere sampling, small batches.
  RenderSettings h = base;
  h.max_ray_depth = 1;
  const Reference href = get_reference(opt, s, h, ref_spp);
  const int hbatch = 4;
  std::string failure;
  for (int k = 0; k < 3; ++k) {
    RenderSettings r = h;
    r.ns_aa = cap;
    r.direct_hemisphere_sample = k != 2;
    r.adaptive = k != 1;
    r.samples_per_batch = hbatch;
    r.max_tolerance = 0.05;
    const std::string method = k == 0 ? "hemisphere_adaptive" : k == 1 ? "hemisphere_fixed" : "light_adaptive";
    Measurement m = measure(opt, s, r, &href);
    // Pixels that stopped after one batch, black, where the reference is not.
    int stops = 0;
    for (size_t i = 0; i < m.first_counts.size(); ++i)
      if (r.adaptive && m.first_counts[i] == hbatch && illuminance(m.first.pixels[i]) == 0.0 &&
          illuminance(href.image.pixels[i]) > 0.0)
        ++stops;
    const double frac = double(stops) / double(m.first_counts.size());
    set_row(t, method, "-m 1 -a " + std::to_string(hbatch) + " 0.05", 0.05, m, &href);
    t.set("batch", hbatch).set("tolerance", 0.05).set("energy_bias", m.energy_bias).set("energy_bias_se", m.energy_bias_se);
    t.set("first_batch_stops", frac);
    std::fprintf(stderr, "  %s: %.1f spp, energy %+.4f +- %.4f, %.1f%% black after one batch\n", method.c_str(),
                 m.samples, m.energy_bias, m.energy_bias_se, 100 * frac);
    if (k == 0) {
      e.headline.push_back({"hemisphere_adaptive_bias", pm(m.energy_bias * 100, m.energy_bias_se * 100, "%")});
      e.headline.push_back({"hemisphere_adaptive_black_pixels", fmt("%.1f%%", 100 * frac)});
      failure = "With hemisphere sampling (-H -m 1 -a " + std::to_string(hbatch) + " 0.05), " + fmt("%.1f%%", 100 * frac) +
                " of the pixels (lit in the reference) saw no light in their first batch of " + std::to_string(hbatch) +
                " samples and stopped there, black (μ = 0 passes the test): the image loses " +
                pm(-m.energy_bias * 100, m.energy_bias_se * 100, "%") + " of its energy";
      write_picture(opt, "strips/adaptive_hemisphere.png", m.first);
    } else if (k == 1) {
      failure += ", where fixed hemisphere sampling at " + std::to_string(cap) + " spp is off by " +
                 pm(m.energy_bias * 100, m.energy_bias_se * 100, "%");
    } else {
      failure += " and adaptive light sampling by " + pm(m.energy_bias * 100, m.energy_bias_se * 100, "%") + ".";
    }
  }
  t.write(opt.out + "/adaptive.csv");

  // The strip at equal time: fixed sampling at the sample count its curve
  // says takes as long as the course's adaptive setting.
  const Measurement& course_m = bunny.course;
  double fspp = interp_loglog(bunny.f_time, bunny.f_spp, course_m.seconds);
  if (!std::isfinite(fspp)) fspp = course_m.seconds < bunny.f_time.front() ? bunny.f_spp.front() : bunny.f_spp.back();
  RenderSettings fr = base;
  fr.ns_aa = std::max(2, int(std::lround(fspp)));
  fr.seed = 1;
  PathTracer ft(s.loaded.scene, fr);
  RenderResult frr = render(ft, opt.threads);
  write_picture(opt, "strips/adaptive_fixed.png", frr.image);
  write_picture(opt, "strips/adaptive_reference.png", ref.image);
  e.strip = {{"strips/adaptive_fixed.png", "fixed, " + std::to_string(fr.ns_aa) + " spp, " + fmt("%.2g s", frr.seconds)},
             {"strips/adaptive_adaptive.png", "adaptive -a " + std::to_string(course.batch) + " " +
                                                  fmt("%g", course.tol) + ", " + fmt("%.1f spp, ", course_m.samples) +
                                                  fmt("%.2g s", course_m.seconds)},
             {"strips/adaptive_rate.png", "its sample rate (blue few, red " + std::to_string(cap) + ")"},
             {"strips/adaptive_reference.png", "reference, " + std::to_string(ref_spp) + " spp"},
             {"strips/adaptive_hemisphere.png", "-H -m 1 -a " + std::to_string(hbatch) + " 0.05: black pixels"}};

  e.strip.push_back({"strips/sun_adaptive.png", "adaptive_sun, -a " + std::to_string(course.batch) + " " +
                                                    fmt("%g", course.tol) + ", " + fmt("%.1f spp", sunc.course.samples)});
  e.strip.push_back({"strips/sun_rate.png", "adaptive_sun, its sample rate"});

  // relMSE against rays, one panel per scene: the fixed curve and the
  // adaptive settings by batch size.
  auto panel = [&](const std::string& scene, const std::vector<Config>& cs) {
    std::string p = "plot \"adaptive.csv\" using (strcol(1) eq \"fixed\" && strcol(12) eq \"" + scene +
                    "\" ? $5 : NaN):8:9 with yerrorlines pt 7 lc rgb \"#1f77b4\" title \"fixed, " +
                    std::to_string(spps.front()) + " … " + std::to_string(cap) + " spp\"";
    const char* colours[] = {"#d62728", "#ff7f0e", "#9467bd", "#8c564b"};
    std::vector<int> seen;
    for (const Config& c : cs)
      if (std::find(seen.begin(), seen.end(), c.batch) == seen.end()) seen.push_back(c.batch);
    for (size_t i = 0; i < seen.size(); ++i)
      p += ", \\\n     \"\" using (strcol(1) eq \"adaptive\" && strcol(12) eq \"" + scene + "\" && $13 == " +
           std::to_string(seen[i]) + " ? $5 : NaN):8:9 with yerrorbars pt " + std::to_string(5 + 4 * int(i)) +
           " lc rgb \"" + colours[i % 4] + "\" title \"adaptive, batch " + std::to_string(seen[i]) + "\"";
    return p + "\n";
  };
  e.gnuplot = R"GP(set multiplot layout 1,3 title "Adaptive against fixed sampling (adaptive capped at the fixed curve's largest count)"
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set grid
set key bottom left
set xlabel "rays traced per render"
set ylabel "relMSE"
set title "Cornell bunny (-m 5): relMSE against rays"
)GP" + panel("cornell_bunny", configs) +
              "set title \"adaptive\\\\_sun (-m 1): relMSE against rays\"\n" + panel("adaptive_sun", sun_configs) +
              R"GP(set title "relMSE against time"
set xlabel "wall seconds per render"
plot "adaptive.csv" using (strcol(1) eq "fixed" && strcol(12) eq "cornell_bunny" ? $6 : NaN):8:9 with yerrorlines pt 7 lc rgb "#1f77b4" title "Cornell bunny, fixed", \
     "" using (strcol(1) eq "adaptive" && strcol(12) eq "cornell_bunny" ? $6 : NaN):8:9 with yerrorbars pt 5 lc rgb "#d62728" title "Cornell bunny, adaptive", \
     "" using (strcol(1) eq "fixed" && strcol(12) eq "adaptive_sun" ? $6 : NaN):8:9 with yerrorlines pt 6 lc rgb "#2ca02c" title "adaptive\\_sun, fixed", \
     "" using (strcol(1) eq "adaptive" && strcol(12) eq "adaptive_sun" ? $6 : NaN):8:9 with yerrorbars pt 4 lc rgb "#ff7f0e" title "adaptive\\_sun, adaptive"
unset multiplot
)GP";
  e.html = "<p>relMSE against rays for fixed sampling at " + std::to_string(spps.front()) + " to " +
           std::to_string(cap) + " spp and adaptive sampling capped at " + std::to_string(cap) +
           " spp, several batch sizes and tolerances, on the Cornell bunny (left) and on adaptive_sun (middle), the "
           "library's scene made for adaptive sampling (sunlit and sun-shadowed regions are noise-free after one "
           "sample); right, against wall time. The savings ratio is the fixed rays needed for the adaptive render's "
           "relMSE (interpolated on the fixed curve, log-log) over the adaptive render's rays; its error bar "
           "propagates both relMSEs' standard errors through the curve's slope. Cornell bunny, the course's "
           "setting: " + bunny.course_line + "; the largest saving: " + bunny.best_line + ". adaptive_sun, the "
           "course's setting: " + sunc.course_line + ". " + verdict(bunny, "the Cornell bunny") + " " +
           verdict(sunc, "adaptive_sun") + " One reason: the stopping rule gives a pixel samples in proportion to its relative variance (σ/μ)², "
           "while the counts that minimise relMSE for a given total are in proportion to its relative standard "
           "deviation σ/μ; where nearly every pixel is noisy (indirect light everywhere in a closed box) the rule "
           "over-spends on the noisiest and the cap stops it, and where much of the image is noise-free after a "
           "batch (a sunlit floor) it saves whole pixels. " + failure +
           "</p>";
  return e;
}

}  // namespace pt::study
