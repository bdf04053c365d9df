#include "support/image_test.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "render/renderer.h"
#include "support/image_test_files.h"
#include "support/reference_image.h"
#include "support/scene_library.h"
#include "support/seed.h"
#include "support/statistics.h"

namespace pt::image_test {

namespace {

constexpr const char* kChannel[3] = {"red", "green", "blue"};
constexpr double kRounding = 1e-6;  // relative, per pixel: the stored mean is float (reference_check.h)

struct Reference {
  Image mean;      // block averages of the stored mean
  Image variance;  // the noise of that block average itself
  Image sample_variance;  // the solution's per-sample variance at this size
  Image weight;    // each pixel's weight in a region's sum: 1 / (its per-sample variance + a floor)
  Spectrum floor;  // that floor, per channel
};

// Each test pixel covers k x k stored pixels: its expected value is their
// mean, and the stored mean's noise there is mean(sd^2) / (N k^2). One sample
// of the test pixel is a sample of a uniformly chosen stored pixel, so its
// variance is mean(sd^2) + the variance of the stored means over the block
// (the law of total variance): the solution's noise at this size, which sets
// the weights. Weighting by inverse variance keeps a few noisy pixels (the
// edge of a light seen directly, fireflies) from drowning a region's sum;
// the floor, 1% of the channel's image mean per sample, keeps noise-free
// pixels from taking all the weight. The weights come from the stored image
// only, never from the render, so the sum stays one of independent
// zero-mean terms under the null hypothesis, whatever the render's noise.
Reference block_average(const library::ReferenceImage& ref, int k) {
  const int w = ref.mean.width / k, h = ref.mean.height / k;
  Reference out{Image(w, h), Image(w, h), Image(w, h), Image(w, h), Spectrum(0.0)};
  const double n = ref.model.reference_samples, kk = double(k) * k;
  Spectrum image_mean(0.0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      Spectrum sum(0.0), sum2(0.0), sd2(0.0);
      for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
          const Spectrum r = ref.mean.at(x * k + i, y * k + j), sd = ref.sd.at(x * k + i, y * k + j);
          sum += r, sum2 += r * r, sd2 += sd * sd;
        }
      const Spectrum mean = sum / kk;
      out.mean.at(x, y) = mean;
      out.variance.at(x, y) = sd2 / (kk * kk * n);
      out.sample_variance.at(x, y) = sd2 / kk + glm::max(sum2 / kk - mean * mean, Spectrum(0.0));
      image_mean += mean / double(w * h);
    }
  out.floor = 1e-4 * image_mean * image_mean + Spectrum(1e-12);
  for (size_t i = 0; i < out.weight.pixels.size(); ++i)
    out.weight.pixels[i] = Spectrum(1.0) / (out.sample_variance.pixels[i] + out.floor);
  return out;
}

Region test_region(const std::vector<Image>& renders, const Image& mean, const Reference& ref, int grid, int col,
                   int row, int c, bool weighted, int spp) {
  Region g;
  g.grid = grid, g.col = col, g.row = row, g.channel = c, g.weighted = weighted;
  g.x0 = col * mean.width / grid, g.x1 = (col + 1) * mean.width / grid;
  g.y0 = row * mean.height / grid, g.y1 = (row + 1) * mean.height / grid;
  const double k = double(renders.size());
  double diff = 0, reference = 0, weighted_diff = 0, weighted_reference = 0, var = 0, var2_over_dof = 0,
         solution_var = 0, reference_var = 0, rounding = 0;
  for (int y = g.y0; y < g.y1; ++y)
    for (int x = g.x0; x < g.x1; ++x) {
      const double r = ref.mean.at(x, y)[c], m = mean.at(x, y)[c], w = weighted ? ref.weight.at(x, y)[c] : 1.0;
      double s2 = 0;  // the sample variance of the pixel's K values
      for (const Image& img : renders) s2 += (img.at(x, y)[c] - m) * (img.at(x, y)[c] - m);
      s2 /= k - 1;
      const double v = w * w * s2 / k;
      diff += m - r;
      reference += r;
      weighted_diff += w * (m - r);
      if (ref.weight.at(x, y)[c] * ref.floor[c] < 0.5) weighted_reference += w * r;  // noisy pixels only: see relative_error
      var += v;
      solution_var += w * w * ref.sample_variance.at(x, y)[c] / (spp * k);
      reference_var += w * w * ref.variance.at(x, y)[c];
      var2_over_dof += v * v / (k - 1);  // the stored variance is known: no dof term
      rounding += w * (kRounding * std::abs(r) + 1e-12);
    }
  // A region's measured variance is never taken below the solution's: at a
  // few samples per pixel a region that drew no bright sample has both a low
  // mean and a low measured variance, and that self-normalised t has a far
  // heavier lower tail than Student's (a correct render failed at
  // p = 2e-5 in one of eight tests). The solution's variance is known: no
  // degrees of freedom are lost when it is the larger.
  const bool measured = var > solution_var;
  const double var_measured = var;
  var = std::max(var, solution_var) + reference_var;
  const double pixels = double(g.x1 - g.x0) * (g.y1 - g.y0);
  g.mean_difference = diff / pixels;
  g.mean_reference = reference / pixels;
  g.relative_error = weighted_reference > 0.0 ? std::sqrt(var) / weighted_reference : INFINITY;
  const double excess = std::max(0.0, std::abs(weighted_diff) - rounding);
  if (excess == 0.0) return g;  // t 0, p 1
  if (var <= 0.0) {
    g.t = std::copysign(INFINITY, weighted_diff), g.p = 0.0;  // noise-free on both sides: any difference is real
    return g;
  }
  g.t = std::copysign(excess / std::sqrt(var), weighted_diff);
  // Welch-Satterthwaite; at least K - 1 (one pixel's), at most unbounded (the
  // stored variance alone).
  g.dof = measured && var2_over_dof > 0.0 ? std::max(k - 1.0, var_measured * var_measured / var2_over_dof) : 1e9;
  g.p = 2.0 * stats::student_t_sf(std::abs(g.t), g.dof);
  return g;
}

}  // namespace

std::string Region::describe(int width, int height) const {
  std::ostringstream s;
  s.precision(4);
  if (grid == 1)
    s << "the whole " << width << "x" << height << " image";
  else
    s << "cell (column " << col << ", row " << row << ") of the " << grid << "x" << grid << " grid, row 0 at the top"
      << " (pixels x " << x0 << "-" << x1 - 1 << ", y " << y0 << "-" << y1 - 1 << ")";
  s << ", " << kChannel[channel] << (weighted ? " (pixels weighted by inverse variance)" : " (plain sum)")
    << ": mean difference " << mean_difference << " against a reference mean of "
    << mean_reference << " (t = " << t << ", " << dof << " degrees of freedom, p = " << p << ")";
  return s.str();
}

const Region& Result::worst() const {
  static const Region none;
  if (regions.empty()) return none;
  return *std::min_element(regions.begin(), regions.end(), [](const Region& a, const Region& b) { return a.p < b.p; });
}

double Result::detectable_change() const {
  // A change of every pixel by the same factor 1 + d moves a region's weighted
  // sum by d times its weighted reference: caught 99% of the time once that
  // is (threshold + z_0.99) standard errors, in the best-measured channel.
  const double threshold = stats::normal_quantile(1.0 - alpha_each / 2.0) + stats::normal_quantile(0.99);
  double best = INFINITY;
  for (const Region& g : regions)
    if (g.grid == 1) best = std::min(best, threshold * g.relative_error);
  return best;
}

bool Result::passed() const { return error.empty() && nonfinite == 0 && worst().p >= alpha_each; }

std::string Result::describe() const {
  std::ostringstream s;
  s.precision(4);
  s << spec.scene << " at " << width << "x" << height << ", " << spec.renders << " renders of " << spec.spp
    << " spp (seeds " << test::seed(spec.seed) << "..." << test::seed(spec.seed + spec.renders - 1) << ")";
  if (!spec.what.empty()) s << " with " << spec.what;
  if (!error.empty()) return s.str() + ": the render failed: " + error;
  const int failing = int(std::count_if(regions.begin(), regions.end(), [&](const Region& g) { return g.p < alpha_each; }));
  s << ": " << (passed() ? "matches the reference" : "DIFFERS from the reference") << "; worst region "
    << worst().describe(width, height) << "; each of the " << regions.size() << " region tests at alpha "
    << alpha_each << " (Sidak share of " << kAlphaFamily << "), " << failing << " below it";
  if (nonfinite) s << "; " << nonfinite << " NaN or infinite pixels";
  s << "; power: scaling the noisy pixels of the whole image by " << 100.0 * detectable_change()
    << "% fails with probability 0.99";
  s << " [" << seconds << " s]";
  return s.str();
}

Result run(const Spec& spec) {
  const auto start = std::chrono::steady_clock::now();
  Result out;
  out.spec = spec;
  const int tests = 6 * [] {
    int n = 0;
    for (int g : kGrids) n += g * g;
    return n;
  }();
  out.alpha_each = stats::sidak_alpha(kAlphaFamily, tests);
  try {
    const library::Library lib = library::load_library(library::default_manifest(), "");
    const library::LibraryScene& s = lib.find(spec.scene);
    const library::ReferenceImage stored = library::read_reference(lib.reference_dir, s.name);
    if (stored.mean.width % spec.downscale || stored.mean.height % spec.downscale || spec.renders < 2 || spec.spp < 2)
      throw std::invalid_argument("image test of " + s.name + ": bad size, render count or sample count");
    const Reference ref = block_average(stored, spec.downscale);
    out.width = ref.mean.width, out.height = ref.mean.height;
    out.reference = ref.mean;
    LoadedScene loaded = library::load(s);
    std::vector<Image> renders;
    for (int r = 0; r < spec.renders; ++r) {
      RenderSettings settings = s.settings(spec.spp, test::seed(spec.seed + r));
      settings.width = out.width, settings.height = out.height;
      if (spec.adjust) spec.adjust(settings);
      RenderResult result = render(PathTracer(loaded.scene, settings), 1);
      if (!result.ok()) throw std::runtime_error(result.error);
      out.nonfinite += result.nonfinite_pixels;
      renders.push_back(std::move(result.image));
    }
    out.render = Image(out.width, out.height);
    for (const Image& img : renders)
      for (size_t i = 0; i < img.pixels.size(); ++i) out.render.pixels[i] += img.pixels[i] / double(spec.renders);
    for (int grid : kGrids)
      for (int row = 0; row < grid; ++row)
        for (int col = 0; col < grid; ++col)
          for (int c = 0; c < 3; ++c)
            for (bool weighted : {false, true})
              out.regions.push_back(test_region(renders, out.render, ref, grid, col, row, c, weighted, spec.spp));
  } catch (const std::exception& e) {
    out.error = e.what();
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

::testing::AssertionResult check(const Spec& spec) {
  const Result r = run(spec);
  static const bool verbose = std::getenv("PT_STATS_VERBOSE") != nullptr;
  if (verbose) std::printf("[stats] %s\n", r.describe().c_str());
  if (r.passed()) return ::testing::AssertionSuccess() << r.describe();
  return ::testing::AssertionFailure() << r.describe() << write_failure_images(r);
}

}  // namespace pt::image_test
