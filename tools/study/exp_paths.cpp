// Experiments 3 and 4 (Part 4): Russian roulette's efficiency against its
// continuation probability, the bias of a hard depth cut without roulette,
// and the energy missing at each maximum depth. One deep reference for both:
// the Cornell box with roulette (p = 0.7) and -m 64, where what 64 bounces
// leave out (albedo 0.75, an open box) is far below the noise.
#include <cstdio>

#include "study.h"

namespace pt::study {
namespace {

constexpr int kDeep = 64;

struct Setup {
  StudyScene scene;
  RenderSettings base;
  Reference ref;
};

Setup deep_setup(const Options& opt) {
  Setup s{load_study_scene("cornell_spheres"), {}, {}};
  s.base = s.scene.settings(opt);
  s.base.max_ray_depth = kDeep;
  s.base.rr_continue_prob = 0.7;
  s.ref = get_reference(opt, s.scene, s.base, opt.quick ? 512 : 4096);
  return s;
}

std::string scene_text(const Options& opt, const Setup& s) {
  return "cornell_spheres, -l 1, " + std::to_string(opt.width) + "×" + std::to_string(opt.height) +
         "; reference: --rr 0.7 -m " + std::to_string(kDeep) + " at " + std::to_string(s.ref.spp) + " spp";
}

}  // namespace

Experiment run_roulette(const Options& opt) {
  Experiment e;
  e.name = "roulette";
  e.title = "3. Russian roulette: efficiency and the bias of a hard cut";
  Setup s = deep_setup(opt);
  const int spp = opt.quick ? 4 : 16;
  e.scene = scene_text(opt, s);
  Table t(core_columns({"max_depth", "rr", "relmse_times_seconds", "relmse_times_seconds_se", "energy_bias",
                        "energy_bias_se"}));
  auto row = [&](const std::string& method, const std::string& param, double value, const RenderSettings& r) {
    Measurement m = measure(opt, s.scene, r, &s.ref);
    set_row(t, method, param, value, m, &s.ref);
    t.set("max_depth", r.max_ray_depth)
        .set("rr", r.rr_continue_prob)
        .set("relmse_times_seconds", m.relmse * m.seconds)
        .set("relmse_times_seconds_se", m.relmse * m.seconds * std::hypot(m.relmse_se / m.relmse, m.seconds_se / m.seconds))
        .set("energy_bias", m.energy_bias)
        .set("energy_bias_se", m.energy_bias_se);
    std::fprintf(stderr, "  %s %s: %.3g s, relMSE %.4g +- %.2g, energy %+.4f +- %.4f\n", method.c_str(), param.c_str(),
                 m.seconds, m.relmse, m.relmse_se, m.energy_bias, m.energy_bias_se);
    return m;
  };
  // Efficiency against p at equal samples (-m 64 throughout).
  double best_eff = kInf, best_p = 0, err_p1 = 0, eff_1 = 0, eff_07 = 0, eff_07_se = 0, eff_1_se = 0;
  for (int k = 1; k <= 10; ++k) {
    RenderSettings r = s.base;
    r.ns_aa = spp;
    r.rr_continue_prob = k / 10.0;
    Measurement m = row("roulette", fmt("p=%.1f", r.rr_continue_prob), r.rr_continue_prob, r);
    const double eff = m.relmse * m.seconds;
    // Its standard error: relMSE's and the time's, relative, in quadrature.
    const double eff_se = eff * std::hypot(m.relmse_se / m.relmse, m.seconds_se / m.seconds);
    if (eff < best_eff) best_eff = eff, best_p = r.rr_continue_prob;
    if (k == 10) eff_1 = eff, eff_1_se = eff_se, err_p1 = m.relmse;
    if (k == 7) eff_07 = eff, eff_07_se = eff_se;
  }
  // Error against time: a hard cut without roulette (p = 1) at depth m,
  // against roulette (p = 0.7, -m 64) at growing sample counts.
  std::vector<double> cut_time, cut_bias, cut_bias_se;
  double cut_err5 = kNaN;
  const std::vector<int> depths = opt.quick ? std::vector<int>{1, 2, 3, 5, 8} : std::vector<int>{1, 2, 3, 4, 5, 6, 8, 10};
  for (int d : depths) {
    RenderSettings r = s.base;
    r.ns_aa = spp;
    r.max_ray_depth = d;
    r.rr_continue_prob = 1.0;
    Measurement m = row("hard_cut", "m=" + std::to_string(d), d, r);
    cut_time.push_back(m.seconds), cut_bias.push_back(m.energy_bias), cut_bias_se.push_back(m.energy_bias_se);
    if (d == 5) cut_err5 = m.relmse;
  }
  std::vector<double> rr_bias, rr_bias_se;
  for (int n = 2; n <= (opt.quick ? 16 : 64); n *= 2) {
    RenderSettings r = s.base;
    r.ns_aa = n;
    Measurement m = row("roulette_spp", "s=" + std::to_string(n), n, r);
    rr_bias.push_back(m.energy_bias), rr_bias_se.push_back(m.energy_bias_se);
  }
  t.write(opt.out + "/roulette.csv");
  e.headline.push_back({"rr_best_p", fmt("%.1f", best_p)});
  e.headline.push_back({"rr_efficiency_gain_07_vs_1", pm(eff_1 / eff_07, eff_1 / eff_07 *
                                                                                 std::hypot(eff_1_se / eff_1, eff_07_se / eff_07),
                                                         "×")});
  // The cut's bias, depth by depth; roulette's, in standard errors.
  std::string cuts;
  for (size_t i = 0; i < depths.size(); ++i) {
    if (depths[i] != 1 && depths[i] != 3 && depths[i] != 5 && depths[i] != 8) continue;
    cuts += std::string(cuts.empty() ? "" : ", ") + "-m " + std::to_string(depths[i]) + ": " +
            pm(cut_bias[i] * 100, cut_bias_se[i] * 100, "%") + " in " + fmt("%.2g s", cut_time[i]);
    if (depths[i] == 5) e.headline.push_back({"cut5_energy_bias", pm(cut_bias[i] * 100, cut_bias_se[i] * 100, "%")});
  }
  double worst_z = 0;
  for (size_t i = 0; i < rr_bias.size(); ++i) worst_z = std::max(worst_z, std::abs(rr_bias[i]) / rr_bias_se[i]);
  const std::string cross = "A hard cut without roulette leaves out energy (" + cuts +
                            "); roulette with -m " + std::to_string(kDeep) + " is unbiased at every cost (its " +
                            std::to_string(rr_bias.size()) + " renders lie within " + fmt("%.1f", worst_z) +
                            " standard errors of the reference's energy). At " + std::to_string(spp) +
                            " spp a cut's bias hides under its noise in relMSE (at -m 5: " + fmt("%.4f", cut_err5) +
                            ", no roulette at -m " + std::to_string(kDeep) + ": " + fmt("%.4f", err_p1) +
                            "); it shows in the image's mean, and it does not fall with more samples. ";
  e.gnuplot = R"GP(set multiplot layout 1,2 title "Russian roulette on the Cornell box"
set grid
set title "efficiency at equal samples (-m 64): relMSE × time, lower is better"
set xlabel "continuation probability p"
set ylabel "relMSE × wall seconds"
set logscale y
set format y "10^{%L}"
set key top right
plot "roulette.csv" using (strcol(1) eq "roulette" ? $3 : NaN):14:15 with yerrorlines pt 7 lc rgb "#1f77b4" title "roulette, -m 64"
set title "bias against time: a hard cut (no roulette) against roulette"
set xlabel "wall seconds per render"
set ylabel "energy bias, % of the reference's"
set logscale x
unset logscale y
set format y "%g"
set format x "%g"
set key bottom right
plot 0 with lines lc rgb "gray60" notitle, \
     "roulette.csv" using (strcol(1) eq "hard_cut" ? $6 : NaN):($16 * 100):($17 * 100) with yerrorlines pt 5 lc rgb "#d62728" title "p = 1, cut at -m 1, 2, 3, …", \
     "" using (strcol(1) eq "hard_cut" ? $6 : NaN):($16 * 100):(sprintf("m=%d", $12)) with labels offset 0,-1 font ",8" notitle, \
     "" using (strcol(1) eq "roulette_spp" ? $6 : NaN):($16 * 100):($17 * 100) with yerrorlines pt 7 lc rgb "#1f77b4" title "p = 0.7, -m 64, 2, 4, 8, … spp"
unset multiplot
)GP";
  e.html = "<p>Left: relMSE × wall time (inverse efficiency) at " + std::to_string(spp) +
           " spp for continuation probabilities 0.1 to 1.0, paths cut at depth " + std::to_string(kDeep) +
           ". The best is p = " + fmt("%.1f", best_p) + "; p = 0.7 (the default) is " +
           pm(eff_1 / eff_07, eff_1 / eff_07 * std::hypot(eff_1_se / eff_1, eff_07_se / eff_07), "×") +
           " as efficient as no roulette (p = 1). Small p kills paths early: cheap, but the survivors' weights 1/p "
           "make fireflies. Right: the energy bias (summed illuminance against the reference's) against time, for "
           "a hard cut without roulette at depth m (" + std::to_string(spp) +
           " spp each) and for roulette at growing sample counts. " + cross +
           "Every relMSE has the reference's own share subtracted.</p>";
  return e;
}

Experiment run_depth(const Options& opt) {
  Experiment e;
  e.name = "depth";
  e.title = "4. Maximum depth: the energy left out";
  Setup s = deep_setup(opt);
  const int spp = opt.quick ? 4 : 16;
  e.scene = scene_text(opt, s) + "; renders at --rr 0.7 (the default) and " + std::to_string(spp) + " spp";
  Table t(core_columns({"max_depth", "missing_energy", "missing_energy_se"}));
  std::string list;
  for (int d = 0; d <= (opt.quick ? 6 : 10); ++d) {
    RenderSettings r = s.base;
    r.ns_aa = spp;
    r.max_ray_depth = d;
    Measurement m = measure(opt, s.scene, r, &s.ref);
    set_row(t, "max_depth", "m=" + std::to_string(d), d, m, &s.ref);
    t.set("max_depth", d).set("missing_energy", -m.energy_bias).set("missing_energy_se", m.energy_bias_se);
    std::fprintf(stderr, "  -m %d: %.3g s, missing %.4f +- %.4f\n", d, m.seconds, -m.energy_bias, m.energy_bias_se);
    if (d == 1 || d == 2 || d == 3 || d == 5 || d == 8)
      list += std::string(list.empty() ? "" : ", ") + "-m " + std::to_string(d) + ": " +
              pm(-m.energy_bias * 100, m.energy_bias_se * 100, "%") + " in " + fmt("%.2g s", m.seconds);
    if (d == 1 || d == 3 || d == 5)
      e.headline.push_back({"missing_energy_m" + std::to_string(d), pm(-m.energy_bias * 100, m.energy_bias_se * 100, "%")});
  }
  t.write(opt.out + "/depth.csv");
  e.gnuplot = R"GP(set title "Energy missing at maximum depth m, against render time (Cornell box, --rr 0.7)"
set xlabel "wall seconds per render"
set ylabel "missing energy (fraction of the deep reference's)"
set logscale y
set format y "10^{%L}"
set grid
set key top right
plot "depth.csv" using 6:13:14 with yerrorlines pt 7 lc rgb "#1f77b4" title "1 - E[image] / reference", \
     "" using 6:13:(sprintf("m=%d", $12)) with labels offset 1.5,0.6 font ",8" notitle
)GP";
  e.html = "<p>The share of the deep reference's energy (summed illuminance) that a render cut at maximum depth m "
           "leaves out, against its wall time (" + std::to_string(spp) +
           " spp, standard error over seeds with the reference's own in quadrature): " + list +
           ". Each further bounce costs less time than the one before (roulette ends paths, the open box lets "
           "rays escape), while the missing energy falls by about the box's average albedo per bounce.</p>";
  return e;
}

}  // namespace pt::study
