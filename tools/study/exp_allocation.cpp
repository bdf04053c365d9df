// Experiment 5b (Part 5): how far a per-pixel allocation is from the best one
// can do. On every library scene, at equal samples per pixel: fixed sampling,
// the course's stopping rule, the budgeted allocator (--adaptive-budget,
// skeleton/render/budget.h) in its default kRounds rounds (r re-estimated
// between them) and in one (exactly unbiased), and the bound E[r^2] / E[r]^2, with r each
// pixel's relative standard deviation of one sample, from the library's
// stored 8192-spp reference and its per-sample sd image.
//
// Why the bound: relMSE's expectation at counts n_p is sum_p r_p^2 / (P n_p)
// (r_p^2 the mean over channels of sd^2 / (mean^2 + eps), eps = 1e-2, the
// weights of compare_images). For a total of nP samples it is smallest with
// n_p ∝ r_p (Lagrange), where it is E[r]^2 / n; fixed sampling reaches
// E[r^2] / n. No allocation saves more samples than their ratio.
#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "study.h"
#include "render/budget.h"
#include "support/reference_image.h"

namespace pt::study {
namespace {

constexpr double kEps = 1e-2;  // relMSE's offset
constexpr int kRounds = 4;     // the allocator's rounds (RenderSettings' default), against one

// The stored reference box-filtered to the study's resolution (a study pixel
// is k x k stored pixels; a jittered sample of it is a jittered sample of one
// of them, chosen uniformly), with its per-sample variance by the law of total
// variance, and the bound.
struct Stored {
  Reference ref;
  double bound = kNaN, a = kNaN;  // E[r^2]/E[r]^2; E[r^2] (fixed sampling's relMSE times n)
  std::vector<double> r2;                          // per pixel, row 0 at the top
  std::vector<Spectrum> mean, var;                 // per pixel: the mean and per-sample variance
};

// Expected savings (fixed sampling's expected relMSE over the allocation's)
// of the counts allocate_counts gives for weights w at `budget` spp with the
// allocator's pilot as the floor: no rendering, the stored r^2 as the truth.
double expected_savings(const Stored& st, const std::vector<double>& w, int budget) {
  const std::vector<int> n = allocate_counts(w, (long long)budget * (long long)w.size(), pilot_samples(budget), 1 << 20);
  double alloc = 0;
  for (size_t i = 0; i < n.size(); ++i) alloc += st.r2[i] / n[i];
  return st.a / budget / (alloc / double(n.size()));
}

// The allocator's own rule (render/budget.h: r pooled over the 3x3
// neighbours, the pixel itself left out) fed the true variances.
std::vector<double> neighbour_pooled(const Stored& st, int width, int height) {
  std::vector<PixelMoments> m(st.r2.size());
  for (size_t i = 0; i < m.size(); ++i) m[i] = {st.mean[i], st.var[i], true};
  return pooled_relative_sd(m, width, height);
}

Stored stored_reference(const Options& opt, const StudyScene& s) {
  const library::Library lib = library::load_library(library::default_manifest(), PT_GENERATED_SCENES_DIR);
  const library::ReferenceImage img = library::read_reference(lib.reference_dir, s.entry.name);
  const int k = img.mean.width / opt.width;
  if (k < 1 || img.mean.width != k * opt.width || img.mean.height != k * opt.height)
    throw std::runtime_error(s.entry.name + ": the stored reference (" + std::to_string(img.mean.width) + "x" +
                             std::to_string(img.mean.height) + ") is not a multiple of the study's resolution");
  const double n_ref = img.model.reference_samples, kk = double(k) * k;
  Stored st;
  st.ref.key = s.entry.name + " (stored, " + std::to_string(int(n_ref)) + " spp)";
  st.ref.spp = int(n_ref);
  st.ref.image = Image(opt.width, opt.height);
  double r_sum = 0, r2_sum = 0, own = 0, energy_var = 0;
  const Spectrum lum(0.2126, 0.7152, 0.0722);
  for (int y = 0; y < opt.height; ++y)
    for (int x = 0; x < opt.width; ++x) {
      Spectrum mean(0.0), second(0.0), mean_var(0.0);
      for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
          const size_t q = size_t(k * y + j) * img.mean.width + size_t(k * x + i);
          const Spectrum m = img.mean.pixels[q], sd = img.sd.pixels[q];
          mean += m / kk;
          second += (sd * sd + m * m) / kk;
          mean_var += sd * sd / (n_ref * kk * kk);
        }
      st.ref.image.pixels[size_t(y) * opt.width + x] = mean;
      double r2 = 0, sd_lum = 0;
      Spectrum variance(0.0);
      for (int c = 0; c < 3; ++c) {
        const double var = std::max(0.0, second[c] - mean[c] * mean[c]);
        variance[c] = var;
        r2 += var / (mean[c] * mean[c] + kEps) / 3;
        own += mean_var[c] / (mean[c] * mean[c] + kEps) / 3;
        sd_lum += lum[c] * std::sqrt(mean_var[c]);  // channels taken as fully correlated: an upper bound
      }
      r2_sum += r2, r_sum += std::sqrt(r2), energy_var += sd_lum * sd_lum;
      st.r2.push_back(r2), st.mean.push_back(mean), st.var.push_back(variance);
    }
  const double p = double(opt.width) * opt.height;
  st.a = r2_sum / p;
  st.bound = st.a / ((r_sum / p) * (r_sum / p));
  st.ref.own_relmse = own / p;
  st.ref.energy = image_energy(st.ref.image);
  st.ref.energy_se = std::sqrt(energy_var);
  return st;
}

double ratio_se(double ratio, double a, double a_se, double b, double b_se) {
  return ratio * std::hypot(a_se / a, b_se / b);
}

// Two panels per scene, relMSE against rays and against time, four panels a
// row. Columns: 1 method, 5 rays, 6 wall_seconds, 8 relmse, 9 relmse_se, 12 scene.
std::string allocation_gnuplot(const std::vector<std::string>& scenes) {
  const int rows = int(scenes.size() + 1) / 2;
  std::string g = "set multiplot layout " + std::to_string(rows) +
                  ",4 title \"Fixed sampling, the course's rule, the budgeted allocator and the bound (equal samples)\"\n"
                  "set logscale xy\nset format y \"10^{%L}\"\nset grid\nset key bottom left font \",8\"\n"
                  "set ylabel \"relMSE\"\n";
  for (const std::string& sc : scenes) {
    std::string title = sc;
    for (size_t i = title.find('_'); i != std::string::npos; i = title.find('_', i + 3)) title.replace(i, 1, "\\\\_");
    for (int axis : {5, 6}) {
      auto pick = [&](const char* m) {
        return "(strcol(1) eq \"" + std::string(m) + "\" && strcol(12) eq \"" + sc + "\" ? $" + std::to_string(axis) + " : NaN)";
      };
      g += std::string("set title \"") + title + (axis == 5 ? ": against rays" : ": against time") + "\"\n" +
           "set xlabel \"" + (axis == 5 ? "rays per render" : "wall seconds per render") + "\"\n" +
           "plot \"allocation.csv\" using " + pick("fixed") + ":8:9 with yerrorlines pt 7 lc rgb \"#1f77b4\" title \"fixed\", \\\n" +
           "     \"\" using " + pick("bound") + ":8 with lines dt 2 lc rgb \"#2ca02c\" title \"bound (best allocation)\", \\\n" +
           "     \"\" using " + pick("budget") + ":8:9 with yerrorbars pt 9 ps 1.5 lc rgb \"#d62728\" title \"budgeted (" +
           std::to_string(kRounds) + " rounds)\", \\\n" +
           "     \"\" using " + pick("budget_one_round") + ":8:9 with yerrorbars pt 11 ps 1.2 lc rgb \"#9467bd\" title \"budgeted, one round\", \\\n" +
           "     \"\" using " + pick("course_rule") + ":8:9 with yerrorbars pt 5 lc rgb \"#ff7f0e\" title \"course rule\"\n";
    }
  }
  return g + "unset multiplot\n";
}

}  // namespace

Experiment run_allocation(const Options& study_opt) {
  // Half the study's resolution each way (64 x 48; 32 x 24 with --quick):
  // seven scenes x five configurations x the seeds fit in about ten minutes
  // on the shared 2-core machine. The stored 256 x 192 references box-filter
  // exactly to it.
  Options opt = study_opt;
  opt.width /= 2, opt.height /= 2;
  Experiment e;
  e.name = "allocation";
  e.title = "5b. Allocation against the bound";
  // The budget, the fixed counts around it (their line is the chart's
  // baseline), the course's rule capped at 4x the budget. The million-triangle
  // scene is left out of --quick (loading it alone takes seconds).
  const int budget = opt.quick ? 8 : 64;
  const std::vector<int> fixed_spps = {budget / 4, budget, 2 * budget};
  const int batch = opt.quick ? 8 : 32;
  const double tol = 0.05;
  const library::Library lib = library::load_library(library::default_manifest(), PT_GENERATED_SCENES_DIR);
  Table t(core_columns({"scene", "width", "height", "budget", "bound", "savings", "savings_se", "energy_bias",
                        "energy_bias_se"}));
  std::string para, scenes;
  std::vector<std::string> names;
  for (const library::LibraryScene& entry : lib.scenes) {
    if (opt.quick && !entry.generated.empty()) continue;
    const StudyScene s = load_study_scene(entry.name);
    const Stored st = stored_reference(opt, s);
    const RenderSettings base = s.settings(opt);
    // Where the allocator's savings are lost: the same rule with the true
    // variances (pooling and floor, no pilot noise), and n ∝ the true r with
    // the same floor (no pooling, no noise).
    std::vector<double> own_r(st.r2.size());
    for (size_t i = 0; i < own_r.size(); ++i) own_r[i] = std::sqrt(st.r2[i]);
    const double exact_pooled = expected_savings(st, neighbour_pooled(st, opt.width, opt.height), budget);
    const double exact_own = expected_savings(st, own_r, budget);
    scenes += (scenes.empty() ? "" : ", ") + entry.name;
    names.push_back(entry.name);
    auto row = [&](const std::string& method, const std::string& param, double value, const Measurement& m) {
      set_row(t, method, param, value, m, &st.ref);
      t.set("scene", entry.name).set("width", opt.width).set("height", opt.height).set("budget", budget);
      t.set("bound", st.bound).set("energy_bias", m.energy_bias).set("energy_bias_se", m.energy_bias_se);
    };
    Measurement at_budget;
    for (int spp : fixed_spps) {
      RenderSettings r = base;
      r.ns_aa = spp;
      Measurement m = measure(opt, s, r, &st.ref);
      row("fixed", "s=" + std::to_string(spp), spp, m);
      // The bound's line: what the best allocation reaches with these samples.
      Measurement b = m;
      b.relmse = m.relmse / st.bound, b.relmse_se = m.relmse_se / st.bound;
      b.energy_bias = b.energy_bias_se = kNaN;
      row("bound", "s=" + std::to_string(spp), st.bound, b);
      if (spp == budget) at_budget = std::move(m);
    }
    RenderSettings br = base;
    br.adaptive_budget = budget;
    br.adaptive_rounds = kRounds;
    const Measurement bm = measure(opt, s, br, &st.ref);
    const double bs = at_budget.relmse / bm.relmse;
    const double bs_se = ratio_se(bs, at_budget.relmse, at_budget.relmse_se, bm.relmse, bm.relmse_se);
    row("budget", "--adaptive-budget " + std::to_string(budget) + " --adaptive-rounds " + std::to_string(kRounds),
        budget, bm);
    t.set("savings", bs).set("savings_se", bs_se);

    RenderSettings r1 = br;
    r1.adaptive_rounds = 1;
    const Measurement rm = measure(opt, s, r1, &st.ref);
    const double rs = at_budget.relmse / rm.relmse;
    const double rs_se = ratio_se(rs, at_budget.relmse, at_budget.relmse_se, rm.relmse, rm.relmse_se);
    row("budget_one_round", "--adaptive-budget " + std::to_string(budget) + " --adaptive-rounds 1", budget, rm);
    t.set("savings", rs).set("savings_se", rs_se);

    RenderSettings cr = base;
    cr.ns_aa = 4 * budget;
    cr.adaptive = true, cr.samples_per_batch = batch, cr.max_tolerance = tol;
    const Measurement cm = measure(opt, s, cr, &st.ref);
    // Fixed sampling's relMSE is a / n (error_model.h): at the rule's mean
    // count it is the fixed render's at the budget times budget / count.
    const double fixed_at_course = at_budget.relmse * budget / cm.samples;
    const double cs = fixed_at_course / cm.relmse;
    const double cs_se = ratio_se(cs, at_budget.relmse, at_budget.relmse_se, cm.relmse, cm.relmse_se);
    row("course_rule", "-a " + std::to_string(batch) + " " + fmt("%g", tol) + " -s " + std::to_string(4 * budget), tol, cm);
    t.set("savings", cs).set("savings_se", cs_se);

    const std::string n = entry.name + "_";
    e.headline.push_back({n + "bound", fmt("%.3f", st.bound)});
    e.headline.push_back({n + "budget_savings", pm(bs, bs_se, "×")});
    e.headline.push_back({n + "budget_share_of_bound", pm(100 * bs / st.bound, 100 * bs_se / st.bound, "%")});
    e.headline.push_back({n + "budget_one_round_savings", pm(rs, rs_se, "×")});
    e.headline.push_back({n + "budget_one_round_share_of_bound", pm(100 * rs / st.bound, 100 * rs_se / st.bound, "%")});
    e.headline.push_back({n + "course_rule_savings", pm(cs, cs_se, "×")});
    e.headline.push_back({n + "exact_r_savings", fmt("%.3f", exact_own)});
    e.headline.push_back({n + "exact_pooled_r_savings", fmt("%.3f", exact_pooled)});
    e.headline.push_back({n + "fixed_bias", pm(100 * at_budget.energy_bias, 100 * at_budget.energy_bias_se, "%")});
    e.headline.push_back({n + "budget_bias", pm(100 * bm.energy_bias, 100 * bm.energy_bias_se, "%")});
    e.headline.push_back({n + "budget_one_round_bias", pm(100 * rm.energy_bias, 100 * rm.energy_bias_se, "%")});
    e.headline.push_back({n + "course_rule_bias", pm(100 * cm.energy_bias, 100 * cm.energy_bias_se, "%")});
    std::fprintf(stderr, "  %s: with exact r %.3f, exact pooled r %.3f; one round %s (%.0f%% of the bound), bias %s\n",
                 entry.name.c_str(), exact_own, exact_pooled, pm(rs, rs_se, "x").c_str(), 100 * rs / st.bound,
                 pm(100 * rm.energy_bias, 100 * rm.energy_bias_se, "%").c_str());
    std::fprintf(stderr, "  %s: bound %.3f, budget %s (%.0f%% of the bound), course rule %s at %.1f spp; bias fixed %s, budget %s, rule %s\n",
                 entry.name.c_str(), st.bound, pm(bs, bs_se, "x").c_str(), 100 * bs / st.bound, pm(cs, cs_se, "x").c_str(),
                 cm.samples, pm(100 * at_budget.energy_bias, 100 * at_budget.energy_bias_se, "%").c_str(),
                 pm(100 * bm.energy_bias, 100 * bm.energy_bias_se, "%").c_str(),
                 pm(100 * cm.energy_bias, 100 * cm.energy_bias_se, "%").c_str());
    para += "<li>" + entry.name + ": bound " + fmt("%.3f", st.bound) + "×; the budgeted allocator (" +
            std::to_string(kRounds) + " rounds) " + pm(bs, bs_se, "×") +
            " (" + pm(100 * bs / st.bound, 100 * bs_se / st.bound, "%") + " of the bound; its rule with the true variances would reach " +
            fmt("%.3f", exact_pooled) + "×, and n ∝ the true r with the same floor " + fmt("%.3f", exact_own) + "×), bias " +
            pm(100 * bm.energy_bias, 100 * bm.energy_bias_se, "%") + "; in one round " +
            pm(rs, rs_se, "×") + ", bias " + pm(100 * rm.energy_bias, 100 * rm.energy_bias_se, "%") +
            "; the course's rule " + pm(cs, cs_se, "×") +
            " at " + fmt("%.1f", cm.samples) + " spp, bias " + pm(100 * cm.energy_bias, 100 * cm.energy_bias_se, "%") +
            "; fixed sampling's bias " + pm(100 * at_budget.energy_bias, 100 * at_budget.energy_bias_se, "%") + "</li>";
    if (entry.name == "cornell_bunny") {
      write_picture(opt, "strips/allocation_budget.png", bm.first);
      const int top = *std::max_element(bm.first_counts.begin(), bm.first_counts.end());
      write_picture(opt, "strips/allocation_rate.png", sample_rate_image(bm.first_counts, opt.width, opt.height, top));
      e.strip = {{"strips/allocation_budget.png", "Cornell bunny, --adaptive-budget " + std::to_string(budget)},
                 {"strips/allocation_rate.png", "its sample counts (blue few, red " + std::to_string(top) + ")"}};
    }
  }
  t.write(opt.out + "/allocation.csv");
  e.scene = scenes + " at " + std::to_string(opt.width) + "×" + std::to_string(opt.height) + " (library settings); " +
            "references: the library's stored images, box-filtered";
  e.gnuplot = allocation_gnuplot(names);
  e.html = "<p>relMSE (the stored reference's own share subtracted) against rays and against time, per scene: fixed "
           "sampling at " + std::to_string(fixed_spps[0]) + ", " + std::to_string(budget) + " and " +
           std::to_string(fixed_spps[2]) + " spp, the budgeted allocator (--adaptive-budget " + std::to_string(budget) +
           " in " + std::to_string(kRounds) + " rounds, and in one), the course's stopping rule (-a " + std::to_string(batch) + " 0.05, capped at " +
           std::to_string(4 * budget) + ") and the bound: the relMSE the best per-pixel allocation of the same samples "
           "would reach, fixed sampling's divided by E[r²]/E[r]² (r from the stored reference's per-sample sd). Savings "
           "are in samples at equal relMSE: fixed sampling's relMSE at the same mean count over the method's (fixed "
           "sampling's relMSE falls as 1/n, so at the rule's mean count it is scaled from the budget's). Biases are "
           "the image's summed illuminance against the reference's, over the seeds.</p><ul>" + para + "</ul>";
  return e;
}

}  // namespace pt::study
