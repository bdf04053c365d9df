#include "render/budget.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include "render/limits.h"
#include "render/tiles.h"

namespace pt {

namespace {

constexpr double kRelEpsilon = 1e-2;  // relMSE's offset (compare_images)

// One camera sample of pixel (x, y), jittered uniformly inside it: what the
// fixed-count loop averages (P1T2), here drawn one at a time.
Spectrum jittered_sample(const PathTracer& t, int x, int y, Rng& rng) {
  const Vec2 u = rng.uniform2();
  const Ray r = t.camera->generate_ray((x + u.x) / t.settings.width, (y + u.y) / t.settings.height);
  return t.est_radiance_global_illumination(r, rng);
}

void add(PixelSums& p, const Spectrum& v) {
  if (!is_finite(v)) p.finite = false;
  p.sum += v;
  p.sum_sq += v * v;
  ++p.n;
}

// Stream numbers of the two passes: 0 is the fixed and adaptive renders'.
constexpr uint32_t kPilotPass = 1, kRestPass = 2;

}  // namespace

int pilot_samples(int budget) { return std::clamp(budget / 8, 2, 8); }

std::vector<double> pooled_relative_sd(const std::vector<PixelMoments>& pixels, int width, int height) {
  // The four lines through p: the two neighbours on each side of it.
  constexpr int kLines[4][2][2] = {{{-1, 0}, {1, 0}}, {{0, -1}, {0, 1}}, {{-1, -1}, {1, 1}}, {{-1, 1}, {1, -1}}};
  std::vector<double> r(pixels.size(), 0.0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      double best = 0;
      for (const auto& line : kLines) {
        Spectrum var(0.0), mean_sq(0.0);
        int used = 0;
        for (const auto& d : line) {
          const int qx = x + d[0], qy = y + d[1];
          if (qx < 0 || qy < 0 || qx >= width || qy >= height) continue;
          const PixelMoments& q = pixels[size_t(qy) * width + qx];
          if (!q.usable) continue;
          var += q.var, mean_sq += q.mean * q.mean, ++used;
        }
        if (used == 0) continue;
        double v = 0;
        for (int c = 0; c < 3; ++c) v += var[c] / (mean_sq[c] + used * kRelEpsilon) / 3;
        best = std::max(best, v);
      }
      r[size_t(y) * width + x] = std::sqrt(best);
    }
  return r;
}

std::vector<double> pooled_relative_sd(const std::vector<PixelSums>& pilot, int width, int height) {
  std::vector<PixelMoments> m(pilot.size());
  for (size_t i = 0; i < pilot.size(); ++i) {
    const PixelSums& q = pilot[i];
    if (!q.finite || q.n < 2) continue;
    m[i].mean = q.sum / double(q.n);
    m[i].var = glm::max(Spectrum(0.0), (q.sum_sq - double(q.n) * m[i].mean * m[i].mean) / double(q.n - 1));
    m[i].usable = true;
  }
  return pooled_relative_sd(m, width, height);
}

std::vector<int> allocate_counts(const std::vector<double>& r, long long total, int floor, int cap) {
  return allocate_counts(r, total, std::vector<int>(r.size(), floor), cap);
}

std::vector<int> allocate_counts(const std::vector<double>& r, long long total, const std::vector<int>& floors,
                                 int cap) {
  const size_t n = r.size();
  std::vector<int> counts = floors;
  if (n == 0) return counts;
  auto weight = [&](size_t i) { return std::isfinite(r[i]) && r[i] > 0 ? r[i] : 0.0; };
  std::vector<double> target(n);
  for (size_t i = 0; i < n; ++i) target[i] = double(floors[i]);
  double rsum = 0;
  for (size_t i = 0; i < n; ++i) rsum += weight(i);
  if (rsum == 0) {
    // What is left over the floors, shared equally.
    long long above = total;
    for (int f : floors) above -= f;
    for (size_t i = 0; i < n; ++i) target[i] = std::min(double(cap), floors[i] + double(above) / double(n));
  } else {
    // spent(lambda) = sum clamp(lambda r_i, floor, cap) rises with lambda:
    // bisect for spent(lambda) = total (60 halvings reach double precision).
    auto spent = [&](double lambda) {
      double s = 0;
      for (size_t i = 0; i < n; ++i) s += std::clamp(lambda * weight(i), double(floors[i]), double(cap));
      return s;
    };
    double smallest = rsum;
    for (size_t i = 0; i < n; ++i)
      if (weight(i) > 0) smallest = std::min(smallest, weight(i));
    double lo = 0, hi = double(cap) / smallest;  // spent(hi): every pixel with r > 0 at its cap
    for (int k = 0; k < 200 && hi - lo > 1e-12 * hi; ++k) {
      const double mid = 0.5 * (lo + hi);
      if (spent(mid) < double(total)) lo = mid;
      else hi = mid;
    }
    for (size_t i = 0; i < n; ++i) target[i] = std::clamp(hi * weight(i), double(floors[i]), double(cap));
  }
  // Round down, then hand out what is left by largest fractional part.
  long long given = 0;
  std::vector<size_t> order(n);
  for (size_t i = 0; i < n; ++i) {
    counts[i] = std::clamp(int(std::floor(target[i])), floors[i], cap);
    given += counts[i];
    order[i] = i;
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return target[a] - counts[a] > target[b] - counts[b]; });
  // Bisection leaves the targets' sum within rounding of total; walk the
  // order as often as needed so that the counts sum exactly to it.
  for (size_t k = 0; given < total && k < 4 * n; ++k)
    if (counts[order[k % n]] < cap) ++counts[order[k % n]], ++given;
  for (size_t k = n; given > total && k-- > 0;)
    if (counts[order[k]] > floors[order[k]]) --counts[order[k]], --given;
  return counts;
}

RenderResult render_budgeted(const PathTracer& tracer, int threads, const ProgressFn& progress) {
  const RenderSettings& s = tracer.settings;
  RenderResult result;
  const size_t pixels = size_t(s.width) * s.height;
  result.image = Image(s.width, s.height);
  result.sample_counts.assign(pixels, 0);
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  // Progress over all passes: the pilot, then each round, alike.
  const int rounds = std::max(1, s.adaptive_rounds);
  auto tiles_done = [&](int offset) {
    return [&, offset](int done, int total) {
      if (progress) progress(offset * total + done, (1 + rounds) * total, elapsed());
    };
  };

  const int pilot = pilot_samples(s.adaptive_budget);  // at most the budget (limits.h's minimum is 2)
  std::vector<PixelSums> sums(pixels);
  auto pilot_pixel = [&](int x, int y, size_t i) {
    Rng rng = Rng::for_pixel(s.seed, x, y, kPilotPass);
    for (int k = 0; k < pilot; ++k) add(sums[i], jittered_sample(tracer, x, y, rng));
    return true;
  };
  for_each_pixel(s.width, s.height, threads, pilot_pixel, tiles_done(0), result);
  if (!result.ok()) return result;

  // Each round spends an equal share of what the pilot left, on counts
  // re-allocated from r pooled over every sample taken so far (one round: r
  // from the pilot alone). A round never takes samples back: the counts so
  // far are its floors. Round j draws from stream pass kRestPass + j.
  const long long total = (long long)s.adaptive_budget * (long long)pixels;
  std::vector<int> before(pixels, pilot);
  for (int round = 0; round < rounds; ++round) {
    // The pooled r is indexed like the image (row 0 at the top); so is sums.
    const std::vector<double> r = pooled_relative_sd(sums, s.width, s.height);
    long long spent = 0;
    for (int c : before) spent += c;
    const long long target = spent + (total - spent) / (rounds - round);
    result.sample_counts = allocate_counts(r, target, before, kMaxSamples);
    const bool last = round + 1 == rounds;
    // The value: the mean of all the pixel's samples (budget.h: unbiased with
    // one round; what more rounds cost is measured there).
    auto more_pixel = [&](int x, int y, size_t i) {
      Rng rng = Rng::for_pixel(s.seed, x, y, kRestPass + uint32_t(round));
      PixelSums& p = sums[i];
      for (int k = before[i]; k < result.sample_counts[i]; ++k) add(p, jittered_sample(tracer, x, y, rng));
      if (!last) return true;
      const Spectrum mean = p.sum / double(p.n);
      const bool finite = p.finite && is_finite(mean);
      result.image.pixels[i] = finite ? mean : Spectrum(0.0);
      return finite;
    };
    // 4 x 4 tiles: the counts gather in a few places, and 16 x 16 tiles left
    // one thread with the last heavy tile while the other idled.
    for_each_pixel(s.width, s.height, threads, more_pixel, tiles_done(1 + round), result, 4);
    if (!result.ok()) return result;
    before = result.sample_counts;
  }
  result.seconds = elapsed();
  return result;
}

}  // namespace pt
