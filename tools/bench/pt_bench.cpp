// pt-bench: build time and rays per second of the Part 2 BVH, its speed-up
// over brute force, and (when Embree is installed) Intel Embree's figures on
// the same triangles and the same rays, measured side by side in one run.
// Not a test: nothing here passes or fails on a time. See README.md.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench_scenes.h"
#include "core/stats.h"
#include "geometry/bvh.h"
#include "geometry/triangle.h"
#include "io/obj_loader.h"
#ifdef PT_HAVE_EMBREE
#include "embree_scene.h"
#endif
#ifdef PT_HAVE_LADDER
#include "ladder.h"
#endif

namespace pt::bench {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// --- Options ------------------------------------------------------------------
struct Options {
  bool quick = false;
  bool median = false;
  int reps = 0;            // 0: 5, or 3 with --quick
  int image = 0;           // camera rays: image x image (0: 512, or 192 with --quick)
  size_t random = 0;       // random rays (0: 262,144, or 32,768 with --quick)
  double brute_budget = 0; // primitive tests per brute-force query (0: 1e8, or 1.5e7 with --quick)
  std::vector<int> threads{1, 2};
  std::vector<std::string> scenes{"bunny", "bunny-loop3", "bumpy-sphere", "cornell-bunny"};
  std::vector<std::string> extra;  // further scene files
  bool embree = true;
  uint64_t seed = 2024;
  std::vector<std::string> queries;  // empty: all four
  int show_mismatches = 0;  // rays that disagree with Embree, printed to stderr
  bool ladder = true;       // the steps from the reference towards Embree (ladder.h), when built
};

// --- Timing -------------------------------------------------------------------
struct Timing {
  std::vector<double> runs;
  bool empty() const { return runs.empty(); }
  double best() const { return *std::min_element(runs.begin(), runs.end()); }
  double median() const {
    std::vector<double> r = runs;
    std::sort(r.begin(), r.end());
    size_t n = r.size();
    return n % 2 ? r[n / 2] : 0.5 * (r[n / 2 - 1] + r[n / 2]);
  }
  double pick(bool use_median) const { return use_median ? median() : best(); }
};

// Throughput of `ours` over `other` as the median over runs k of
// other[k] / ours[k]: run k of each was measured back to back, so a burst of
// load elsewhere on the machine tends to hit both or to spoil one pair only.
double paired_ratio(const Timing& ours, const Timing& other) {
  Timing r;
  for (size_t k = 0; k < ours.runs.size() && k < other.runs.size(); ++k) r.runs.push_back(other.runs[k] / ours.runs[k]);
  return r.median();
}

// Runs f(i) for i in [0, n) on `threads` threads (chunks handed out by an
// atomic counter), returns the wall-clock seconds; *count = sum of f's results.
template <class F>
double run_parallel(int threads, size_t n, const F& f, size_t* count) {
  constexpr size_t kChunk = 64;
  std::atomic<size_t> next{0}, total{0};
  auto worker = [&] {
    size_t c = 0;
    for (;;) {
      size_t b = next.fetch_add(kChunk, std::memory_order_relaxed);
      if (b >= n) break;
      size_t e = std::min(n, b + kChunk);
      for (size_t i = b; i < e; ++i) c += f(i);
    }
    total += c;
  };
  auto t0 = Clock::now();
  if (threads <= 1) {
    worker();
  } else {
    std::vector<std::thread> pool;
    for (int k = 0; k < threads; ++k) pool.emplace_back(worker);
    for (auto& t : pool) t.join();
  }
  double s = seconds_since(t0);
  *count = total;
  return s;
}

// How many cores this process actually gets: T threads each run the same
// fixed arithmetic loop; capacity = T x (time of one alone) / (time of T
// together). 2.0 on an idle two-core machine, 1.0 when another process holds
// the second core (then a "2T" column cannot beat "1T").
double core_capacity(int threads) {
  auto spin = [] {
    volatile double sink = 0;
    double x = 1.0;
    for (long i = 0; i < 40'000'000; ++i) x = x * 1.0000001 + 1e-9;
    sink = x;
    (void)sink;
  };
  double best1 = kInf, bestT = kInf;
  for (int rep = 0; rep < 3; ++rep) {
    auto t0 = Clock::now();
    spin();
    best1 = std::min(best1, seconds_since(t0));
    t0 = Clock::now();
    std::vector<std::thread> pool;
    for (int k = 0; k < threads; ++k) pool.emplace_back(spin);
    for (auto& t : pool) t.join();
    bestT = std::min(bestT, seconds_since(t0));
  }
  return threads * best1 / bestT;
}

// --- Results ------------------------------------------------------------------
struct Impl {  // one column group: an implementation on 1..T threads
  std::vector<Timing> by_threads;  // index: position in Options::threads
};

struct QueryResult {
  std::string rays, query;  // e.g. "camera", "closest"
  size_t n = 0, hits = 0;
  Impl ours, embree_high, embree_medium;
  double tests_per_ray = 0, nodes_per_ray = 0;
  size_t brute_n = 0;
  double brute_seconds = 0;  // for brute_n rays, one thread
  size_t brute_mismatches = 0;
  bool have_embree = false;
  size_t embree_mismatches = 0;
  size_t count_mismatch_runs = 0;  // timed runs whose hit count differed from the checked pass
  std::vector<Timing> steps;          // the ladder's steps, one thread
  std::vector<size_t> step_mismatches;  // rays on which a step's answer differs from ours
};

struct BuildResult {
  Timing ours, embree_high, embree_medium;
  size_t nodes = 0, leaves = 0, depth = 0, largest_leaf = 0;
  double ours_bytes = 0, embree_high_bytes = 0, embree_medium_bytes = 0;
};

struct SceneResult {
  std::string name, description;
  size_t triangles = 0, primitives = 0;
  double diag = 0;
  std::string embree_note;  // why Embree is missing, if it is
  std::vector<std::string> step_names;
  std::vector<double> step_bytes;
  std::string step_note;  // why steps are missing, if they are
  BuildResult build;
  std::vector<QueryResult> queries;
};

// --- BVH statistics ---------------------------------------------------------------
void tree_stats(const BVHNode* root, BuildResult* b) {
  struct Item {
    const BVHNode* n;
    size_t depth;
  };
  std::vector<Item> stack;
  if (root) stack.push_back({root, 0});
  while (!stack.empty()) {
    Item it = stack.back();
    stack.pop_back();
    ++b->nodes;
    b->depth = std::max(b->depth, it.depth);
    if (it.n->is_leaf()) {
      ++b->leaves;
      b->largest_leaf = std::max(b->largest_leaf, it.n->size());
    }
    if (it.n->l) stack.push_back({it.n->l.get(), it.depth + 1});
    if (it.n->r) stack.push_back({it.n->r.get(), it.depth + 1});
  }
}

// Whether two closest-hit answers agree to float precision (Embree and the
// ladder's float step trace float copies of the vertices and rays): the same
// hit or miss, and t within 1e-5 x (scene diagonal + t). Unused in the
// student release, which has neither.
[[maybe_unused]] bool agree_to_float_precision(double ours, double other, double diag) {
  if ((ours == kInf) != (other == kInf)) return false;
  return ours == kInf || std::abs(ours - other) <= 1e-5 * (diag + std::abs(ours));
}

// A ray in floats, as Embree takes it.
struct FRay {
  float o[3], d[3], tnear, tfar;
};
[[maybe_unused]] std::vector<FRay> to_float(const std::vector<Ray>& rays) {
  std::vector<FRay> out(rays.size());
  for (size_t i = 0; i < rays.size(); ++i) {
    const Ray& r = rays[i];
    FRay& f = out[i];
    for (int a = 0; a < 3; ++a) {
      f.o[a] = float(r.o[a]);
      f.d[a] = float(r.d[a]);
    }
    f.tnear = float(r.min_t);
    f.tfar = float(r.max_t);  // inf stays inf, 1e30 fits
  }
  return out;
}

#ifdef PT_HAVE_EMBREE
// The triangles of the scene as one float soup; false if it holds anything else.
bool float_mesh(const BenchScene& s, FloatMesh* m) {
  for (const auto& p : s.scene.primitives) {
    const auto* t = dynamic_cast<const Triangle*>(p.get());
    if (!t) return false;
    for (const Vec3* v : {&t->p1(), &t->p2(), &t->p3()}) {
      m->indices.push_back(uint32_t(m->vertices.size() / 3));
      m->vertices.push_back(float(v->x));
      m->vertices.push_back(float(v->y));
      m->vertices.push_back(float(v->z));
    }
  }
  return true;
}

// Net bytes the device allocated (its memory monitor), to size Embree's BVH.
std::atomic<long long> g_embree_bytes{0};
bool embree_monitor(void*, ssize_t bytes, bool) {
  g_embree_bytes += bytes;
  return true;
}
#endif

// --- One scene ------------------------------------------------------------------------
// What each query is run on: our BVH, and where built, Embree's two trees and
// the ladder's steps.
struct Accelerators {
  std::unique_ptr<BVHAccel> bvh;
#ifdef PT_HAVE_EMBREE
  std::unique_ptr<EmbreeDevice> device;
  std::unique_ptr<EmbreeScene> emb_high, emb_medium;
  FloatMesh fmesh;
#endif
#ifdef PT_HAVE_LADDER
  std::vector<std::unique_ptr<ladder::Step>> steps;
#endif
};

// The builds, interleaved run by run: ours, then Embree high and medium;
// then our tree's statistics and the ladder's steps.
Accelerators build_all(BenchScene& s, const std::vector<Primitive*>& prims, const Options& opt, SceneResult& res) {
  Accelerators a;
  const bool big = prims.size() > 100000;
  const int build_reps = big ? (opt.quick ? 1 : 3) : opt.reps;
#ifdef PT_HAVE_EMBREE
  if (!opt.embree) {
    res.embree_note = "Embree disabled (--no-embree)";
  } else if (!float_mesh(s, &a.fmesh)) {
    res.embree_note = "scene has non-triangle primitives: no Embree comparison";
  } else {
    a.device = std::make_unique<EmbreeDevice>("threads=1");
    rtcSetDeviceMemoryMonitorFunction(a.device->get(), embree_monitor, nullptr);
  }
#else
  res.embree_note = "built without Embree";
#endif
  std::fprintf(stderr, "[%s] building (%d runs each)...\n", s.name.c_str(), build_reps);
  for (int k = 0; k < build_reps; ++k) {
    a.bvh.reset();
    auto t0 = Clock::now();
    a.bvh = std::make_unique<BVHAccel>(prims, 4);
    res.build.ours.runs.push_back(seconds_since(t0));
#ifdef PT_HAVE_EMBREE
    if (a.device) {
      for (int q = 0; q < 2; ++q) {
        auto& slot = q == 0 ? a.emb_high : a.emb_medium;
        slot.reset();
        slot = std::make_unique<EmbreeScene>(*a.device, a.fmesh, q == 0 ? RTC_BUILD_QUALITY_HIGH : RTC_BUILD_QUALITY_MEDIUM);
        long long before = g_embree_bytes;
        double t = slot->commit();
        double bytes = double(g_embree_bytes - before);
        (q == 0 ? res.build.embree_high : res.build.embree_medium).runs.push_back(t);
        (q == 0 ? res.build.embree_high_bytes : res.build.embree_medium_bytes) = bytes;
      }
    }
#endif
  }
  tree_stats(a.bvh->root(), &res.build);
  res.build.ours_bytes = double(res.build.nodes) * sizeof(BVHNode) + double(prims.size()) * sizeof(Primitive*);
#ifdef PT_HAVE_LADDER
  if (opt.ladder) a.steps = ladder::make_steps(*a.bvh, &res.step_note);
  for (const auto& step : a.steps) {
    res.step_names.push_back(step->name());
    res.step_bytes.push_back(double(step->bytes()));
  }
#endif
  return a;
}

// A set of rays and the query asked of it.
struct Query {
  const char* rays;
  const char* query;
  const std::vector<Ray>* set;
  bool closest;
};

// Ours, one thread, once: the answers (for the agreement checks; 0 marks an
// any-hit hit) and the work counts.
std::vector<double> our_answers(const Query& q, const BVHAccel& bvh, QueryResult& qr) {
  const std::vector<Ray>& rays = *q.set;
  std::vector<double> ours_t(rays.size(), kInf);
  take_work_counters();
  for (size_t i = 0; i < rays.size(); ++i) {
    Ray r = rays[i];
    if (q.closest) {
      Intersection isect;
      if (bvh.intersect(r, &isect)) ours_t[i] = isect.t;
    } else if (bvh.has_intersection(r)) {
      ours_t[i] = 0.0;
    }
    qr.hits += ours_t[i] != kInf;
  }
  WorkCounters wc = take_work_counters();
  qr.tests_per_ray = double(wc.primitive_tests) / rays.size();
  qr.nodes_per_ray = double(wc.node_visits) / rays.size();
  return ours_t;
}

// Brute force on an evenly strided subsample (one thread, one run).
void check_brute_force(const Query& q, const std::vector<Primitive*>& prims, const std::vector<double>& ours_t,
                       const Options& opt, QueryResult& qr) {
  const std::vector<Ray>& rays = *q.set;
  const size_t n = rays.size();
  size_t want = size_t(std::clamp(opt.brute_budget / double(prims.size()), 16.0, double(n)));
  size_t stride = std::max<size_t>(1, n / want);
  std::vector<size_t> idx;
  for (size_t i = 0; i < n && idx.size() < want; i += stride) idx.push_back(i);
  std::vector<double> brute_t(idx.size(), kInf);
  auto t0 = Clock::now();
  for (size_t k = 0; k < idx.size(); ++k) {
    Ray r = rays[idx[k]];
    if (q.closest) {
      Intersection isect;
      if (brute_closest(prims, r, &isect)) brute_t[k] = isect.t;
    } else if (brute_any(prims, r)) {
      brute_t[k] = 0.0;
    }
  }
  qr.brute_seconds = seconds_since(t0);
  qr.brute_n = idx.size();
  for (size_t k = 0; k < idx.size(); ++k) {
    double a = ours_t[idx[k]], b = brute_t[k];
    bool same = (a == kInf) == (b == kInf) && (a == kInf || std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b)));
    qr.brute_mismatches += !same;
  }
}

#ifdef PT_HAVE_EMBREE
// Agreement with Embree (high quality), one pass.
void check_embree(const Query& q, const EmbreeScene& emb, const std::vector<FRay>& frays,
                  const std::vector<double>& ours_t, double diag, const Options& opt, QueryResult& qr) {
  const std::vector<Ray>& rays = *q.set;
  qr.have_embree = true;
  int shown = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    const FRay& f = frays[i];
    if (q.closest) {
      float te = emb.intersect(f.o, f.d, f.tnear, f.tfar);  // kMiss is +inf
      double a = ours_t[i];
      bool same = agree_to_float_precision(a, te, diag);
      qr.embree_mismatches += !same;
      if (!same && shown < opt.show_mismatches) {
        ++shown;
        std::cerr << "  mismatch: ray " << i << " " << rays[i] << ": ours t = " << a << ", Embree t = " << te << "\n";
      }
    } else {
      bool he = emb.occluded(f.o, f.d, f.tnear, f.tfar);
      bool same = he == (ours_t[i] != kInf);
      qr.embree_mismatches += !same;
      if (!same && shown < opt.show_mismatches) {
        ++shown;
        std::cerr << "  mismatch: ray " << i << " " << rays[i] << ": ours " << (he ? "misses" : "hits") << ", Embree "
                  << (he ? "hits" : "misses") << "\n";
      }
    }
  }
}
#endif

#ifdef PT_HAVE_LADDER
// Agreement of every step with ours: the same closest t to the bit (the
// steps test the same triangles with the same arithmetic), the same any-hit
// answers.
void check_steps(const Query& q, const std::vector<std::unique_ptr<ladder::Step>>& steps,
                 const std::vector<double>& ours_t, double diag, QueryResult& qr) {
  const std::vector<Ray>& rays = *q.set;
  qr.steps.resize(steps.size());
  qr.step_mismatches.assign(steps.size(), 0);
  for (size_t k = 0; k < steps.size(); ++k) {
    const bool exact = steps[k]->exact();
    for (size_t i = 0; i < rays.size(); ++i) {
      bool same;
      if (!q.closest) {
        same = steps[k]->any(rays[i]) == (ours_t[i] != kInf);
      } else {
        double t = steps[k]->closest(rays[i]);
        same = exact ? t == ours_t[i] : agree_to_float_precision(ours_t[i], t, diag);
      }
      qr.step_mismatches[k] += !same;
    }
  }
}
#endif

// Timed runs, interleaved so that a burst of machine load hits every
// implementation alike.
void time_query(const Query& q, const Accelerators& a, [[maybe_unused]] const std::vector<FRay>& frays,
                const Options& opt, QueryResult& qr) {
  const std::vector<Ray>& rays = *q.set;
  const size_t n = rays.size();
  const size_t nt = opt.threads.size();
  qr.ours.by_threads.resize(nt);
  qr.embree_high.by_threads.resize(nt);
  qr.embree_medium.by_threads.resize(nt);
  auto ours_closest = [&](size_t i) -> size_t {
    Ray r = rays[i];
    Intersection isect;
    return a.bvh->intersect(r, &isect);
  };
  auto ours_any = [&](size_t i) -> size_t { return a.bvh->has_intersection(rays[i]); };
  for (int rep = 0; rep < opt.reps; ++rep) {
    for (size_t ti = 0; ti < nt; ++ti) {
      int T = opt.threads[ti];
      size_t count = 0;
      double t = q.closest ? run_parallel(T, n, ours_closest, &count) : run_parallel(T, n, ours_any, &count);
      qr.ours.by_threads[ti].runs.push_back(t);
      qr.count_mismatch_runs += count != qr.hits;
#ifdef PT_HAVE_LADDER
      if (ti == 0) {  // the steps on the first thread count only
        for (size_t k = 0; k < a.steps.size(); ++k) {
          const ladder::Step& step = *a.steps[k];
          auto closest = [&](size_t i) -> size_t { return step.closest(rays[i]) != kInf; };
          auto any = [&](size_t i) -> size_t { return step.any(rays[i]); };
          size_t step_count = 0;
          double ts = q.closest ? run_parallel(T, n, closest, &step_count) : run_parallel(T, n, any, &step_count);
          qr.steps[k].runs.push_back(ts);
        }
      }
#endif
#ifdef PT_HAVE_EMBREE
      if (a.emb_high) {
        for (int quality = 0; quality < 2; ++quality) {
          const EmbreeScene& es = quality == 0 ? *a.emb_high : *a.emb_medium;
          auto e_closest = [&](size_t i) -> size_t {
            const FRay& f = frays[i];
            return es.intersect(f.o, f.d, f.tnear, f.tfar) != EmbreeScene::kMiss;
          };
          auto e_any = [&](size_t i) -> size_t {
            const FRay& f = frays[i];
            return es.occluded(f.o, f.d, f.tnear, f.tfar);
          };
          size_t ecount = 0;
          double te = q.closest ? run_parallel(T, n, e_closest, &ecount) : run_parallel(T, n, e_any, &ecount);
          (quality == 0 ? qr.embree_high : qr.embree_medium).by_threads[ti].runs.push_back(te);
        }
      }
#endif
    }
  }
}

// One query: ours answered and counted, checked against brute force (and
// Embree and the ladder's steps where built), then timed.
QueryResult run_query(const BenchScene& s, const Query& q, const std::vector<Primitive*>& prims, const Accelerators& a,
                      const Options& opt, [[maybe_unused]] double diag) {
  QueryResult qr;
  qr.rays = q.rays;
  qr.query = q.query;
  qr.n = q.set->size();
  std::fprintf(stderr, "[%s] %s rays, %s hit: checking...\n", s.name.c_str(), q.rays, q.query);
  const std::vector<double> ours_t = our_answers(q, *a.bvh, qr);
  check_brute_force(q, prims, ours_t, opt, qr);
  std::vector<FRay> frays;
#ifdef PT_HAVE_EMBREE
  if (a.emb_high) {
    frays = to_float(*q.set);
    check_embree(q, *a.emb_high, frays, ours_t, diag, opt, qr);
  }
#endif
#ifdef PT_HAVE_LADDER
  check_steps(q, a.steps, ours_t, diag, qr);
#endif
  std::fprintf(stderr, "[%s] %s rays, %s hit: timing (%d runs)...\n", s.name.c_str(), q.rays, q.query, opt.reps);
  time_query(q, a, frays, opt, qr);
  return qr;
}

SceneResult run_scene(BenchScene& s, const Options& opt) {
  SceneResult res;
  res.name = s.name;
  res.description = s.description;
  res.triangles = s.triangle_count();
  res.primitives = s.scene.primitives.size();
  const std::vector<Primitive*> prims = s.prims();
  const BBox bounds = s.bounds();
  res.diag = glm::length(bounds.extent());
  const Accelerators a = build_all(s, prims, opt, res);

  Camera cam = s.scene.camera;
  cam.set_aspect(1.0);
  const std::vector<Ray> cam_rays = camera_rays(cam, opt.image, opt.image);
  const std::vector<Ray> rnd_rays = random_rays(bounds, opt.random, opt.seed, false);
  const std::vector<Ray> shadow_rays = random_rays(bounds, opt.random, opt.seed, true);
  const Query queries[] = {{"camera", "closest", &cam_rays, true},
                           {"camera", "any", &cam_rays, false},
                           {"random", "closest", &rnd_rays, true},
                           {"shadow", "any", &shadow_rays, false}};
  for (const Query& q : queries) {
    const std::string name = std::string(q.rays) + "-" + q.query;
    if (opt.queries.empty() || std::find(opt.queries.begin(), opt.queries.end(), name) != opt.queries.end())
      res.queries.push_back(run_query(s, q, prims, a, opt, res.diag));
  }
  return res;
}

// --- Tables -----------------------------------------------------------------------------
class Table {
 public:
  explicit Table(std::vector<std::string> header) : header_(std::move(header)) {}
  void row(std::vector<std::string> cells) { rows_.push_back(std::move(cells)); }
  void print(std::ostream& os) const {
    std::vector<size_t> w(header_.size(), 0);
    auto width = [](const std::string& s) {  // UTF-8 aware enough for "×" and "µ"
      size_t n = 0;
      for (unsigned char c : s) n += (c & 0xC0) != 0x80;
      return n;
    };
    for (size_t c = 0; c < header_.size(); ++c) w[c] = width(header_[c]);
    for (const auto& r : rows_)
      for (size_t c = 0; c < r.size() && c < w.size(); ++c) w[c] = std::max(w[c], width(r[c]));
    auto line = [&](const std::vector<std::string>& cells) {
      os << "|";
      for (size_t c = 0; c < w.size(); ++c) {
        std::string s = c < cells.size() ? cells[c] : "";
        std::string pad(w[c] - width(s), ' ');
        os << " " << (c == 0 ? s + pad : pad + s) << " |";
      }
      os << "\n";
    };
    line(header_);
    os << "|";
    for (size_t c = 0; c < w.size(); ++c) os << (c == 0 ? ":" : "") << std::string(w[c] + (c == 0 ? 1 : 1), '-') << (c == 0 ? "" : ":") << "|";
    os << "\n";
    for (const auto& r : rows_) line(r);
  }

 private:
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}
std::string group(size_t v) {
  std::string s = std::to_string(v), out;
  for (size_t i = 0; i < s.size(); ++i) {
    if (i && (s.size() - i) % 3 == 0) out += ',';
    out += s[i];
  }
  return out;
}
std::string ms(double s) { return s < 0.01 ? fmt("%.2f ms", s * 1e3) : s < 1.0 ? fmt("%.1f ms", s * 1e3) : fmt("%.2f s", s); }
std::string mb(double bytes) { return fmt("%.1f MB", bytes / 1e6); }
std::string mrays(size_t n, double s) {
  double v = n / s / 1e6;
  return v >= 100 ? fmt("%.0f", v) : v >= 10 ? fmt("%.1f", v) : fmt("%.2f", v);
}
std::string ratio(double v) { return v >= 10 ? fmt("%.1f", v) : fmt("%.2f", v); }
std::string big_ratio(double v) {
  if (v >= 1000) return group(size_t(v + 0.5)) + "×";
  return v >= 10 ? fmt("%.0f×", v) : fmt("%.1f×", v);
}

std::string read_first_line(const std::string& path) {
  std::ifstream f(path);
  std::string s;
  std::getline(f, s);
  return s;
}

std::vector<std::string> ladder_descriptions() {
#ifdef PT_HAVE_LADDER
  return ladder::step_descriptions();
#else
  return {};
#endif
}

// "From the reference to Embree, one step at a time" (ladder.h): each step's
// rays per second and, where Embree ran, its paired throughput ratio to Embree.
void print_ladder(const std::vector<SceneResult>& results, const Options& opt, std::ostream& os) {
  size_t most = 0;
  for (const auto& r : results) most = std::max(most, r.step_names.size());
  if (most == 0) return;
  const std::vector<std::string>* names = nullptr;
  for (const auto& r : results)
    if (r.step_names.size() == most) names = &r.step_names;
  const std::string t0 = std::to_string(opt.threads[0]) + "T";
  os << "\n### From the reference to Embree, one step at a time (" << t0 << ")\n\n";
  std::vector<std::string> h{"scene", "rays", "query", "reference"};
  for (const auto& name : *names) h.push_back(name);
  h.push_back("Embree high");
  h.push_back("≠ reference");
  Table lt(h);
  for (const auto& r : results) {
    for (const auto& q : r.queries) {
      // Mrays/s, and the paired throughput ratio to Embree high where it ran
      // (to the reference otherwise).
      const Timing& base = q.have_embree ? q.embree_high.by_threads[0] : q.ours.by_threads[0];
      auto cell = [&](const Timing& t) {
        return mrays(q.n, t.pick(opt.median)) + " (" + ratio(paired_ratio(t, base)) + "×)";
      };
      std::vector<std::string> row{r.name, q.rays, q.query, cell(q.ours.by_threads[0])};
      size_t bad = 0;
      for (size_t k = 0; k < most; ++k) {
        row.push_back(k < q.steps.size() ? cell(q.steps[k]) : "–");
        if (k < q.step_mismatches.size()) bad += q.step_mismatches[k];
      }
      row.push_back(q.have_embree ? mrays(q.n, q.embree_high.by_threads[0].pick(opt.median)) + " (1×)" : "–");
      row.push_back(group(bad));
      lt.row(row);
    }
  }
  lt.print(os);
  bool embree = false;
  for (const auto& r : results)
    for (const auto& q : r.queries) embree |= q.have_embree;
  os << "\nMillion rays per second (" << (opt.median ? "median" : "best") << " run) and, in brackets, the throughput "
     << (embree ? "as a fraction of Embree high's" : "relative to the reference's (Embree did not run)")
     << " (the median over runs of the ratio of two runs measured back to back). Every step is built from the "
        "reference's own tree and adds one thing to the step before it (tools/bench/ladder.h):\n";
  for (const auto& d : ladder_descriptions()) os << "- " << d << "\n";
  os << "\n≠ reference: rays on which a step's any-hit answer differs from the reference's, or its closest t "
        "differs in any bit (the float step: by more than the tolerance of the Embree comparison below), summed over "
        "the steps. Memory (nodes and copied primitives): ";
  for (size_t i = 0; i < results.size(); ++i) {
    const SceneResult& r = results[i];
    os << (i ? "; " : "") << r.name << ": reference " << mb(r.build.ours_bytes);
    for (size_t k = 0; k < r.step_names.size(); ++k) os << ", " << r.step_names[k] << " " << mb(r.step_bytes[k]);
  }
  os << ".\n";
  for (const auto& r : results)
    if (!r.step_note.empty()) os << r.name << ": " << r.step_note << "\n";
}

void print_report(const std::vector<SceneResult>& results, const Options& opt, const std::string& load_before,
                  const std::string& command, double total_seconds, double capacity_before) {
  std::ostream& os = std::cout;
  const bool med = opt.median;
  const char* pick = med ? "median" : "best";
  const size_t nt = opt.threads.size();
  os << "\n## pt-bench\n\n";
  os << "command: `" << command << "`\n";
  os << "BVH: Part 2 from " << PT_BENCH_PART2 << ", build type " << PT_BENCH_BUILD_TYPE << "; leaves of at most 4\n";
#ifdef PT_HAVE_EMBREE
  {
    EmbreeDevice d("threads=1");
    os << "comparator: " << d.describe() << ", single-ray API (rtcIntersect1 / rtcOccluded1), float vertices; "
       << "builds on a device with threads=1\n";
  }
#else
  os << "comparator: none (Embree not found at configure time)\n";
#endif
  os << "machine: " << cpu_model() << ", " << std::thread::hardware_concurrency() << " hardware threads; load average "
     << load_before << " before, " << read_first_line("/proc/loadavg").substr(0, 14) << " after\n";
  const int max_threads = *std::max_element(opt.threads.begin(), opt.threads.end());
  if (max_threads > 1)
    os << "cores this process got (" << max_threads << " threads of a fixed loop, 1.0 = one core): "
       << fmt("%.2f", capacity_before) << " before, " << fmt("%.2f", core_capacity(max_threads)) << " after\n";
  os << "timings: " << pick << " of " << opt.reps << " runs (builds of >100k triangles: " << pick << " of "
     << (opt.quick ? 1 : 3) << "), implementations interleaved run by run; total " << fmt("%.0f s", total_seconds)
     << "\n";
  os << "rays: camera = " << opt.image << "x" << opt.image << " primary rays through pixel centres; random = "
     << group(opt.random) << " rays from a point uniform in the bounds (+10% margin) towards another, t in [0, inf); "
     << "shadow = the same rays ending at the second point (any hit on the segment); seed " << opt.seed << "\n";

  // Build table.
  os << "\n### Build (one thread)\n\n";
  Table bt({"scene", "triangles", "ours", "nodes", "depth", "ours memory", "Embree high", "Embree medium",
            "Embree high memory", "ours / Embree high"});
  for (const auto& r : results) {
    const BuildResult& b = r.build;
    bool e = !b.embree_high.empty();
    bt.row({r.name, group(r.triangles), ms(b.ours.pick(med)), group(b.nodes), std::to_string(b.depth),
            mb(b.ours_bytes), e ? ms(b.embree_high.pick(med)) : "–", e ? ms(b.embree_medium.pick(med)) : "–",
            e ? mb(b.embree_high_bytes) : "–", e ? ratio(1.0 / paired_ratio(b.ours, b.embree_high)) + "× the time" : "–"});
  }
  bt.print(os);
  os << "\nours / Embree high: build time ratio, median over runs measured back to back. ours memory = nodes × sizeof(BVHNode) (" << sizeof(BVHNode)
     << " B) + the primitive pointer array; Embree memory = bytes its device allocated during rtcCommitScene.\n";

  // Throughput table.
  os << "\n### Rays per second (million rays per second, " << pick << " run)\n\n";
  std::vector<std::string> h{"scene", "rays", "query"};
  for (size_t ti = 0; ti < nt; ++ti) h.push_back("ours " + std::to_string(opt.threads[ti]) + "T");
  for (size_t ti = 0; ti < nt; ++ti) h.push_back("Embree high " + std::to_string(opt.threads[ti]) + "T");
  for (size_t ti = 0; ti < nt; ++ti) h.push_back("Embree medium " + std::to_string(opt.threads[ti]) + "T");
  const std::string t0 = std::to_string(opt.threads[0]) + "T";
  h.push_back("ours / Embree high (" + t0 + ", paired)");
  h.push_back("ours / Embree medium (" + t0 + ", paired)");
  Table tt(h);
  for (const auto& r : results) {
    for (const auto& q : r.queries) {
      std::vector<std::string> row{r.name, q.rays, q.query};
      for (size_t ti = 0; ti < nt; ++ti) row.push_back(mrays(q.n, q.ours.by_threads[ti].pick(med)));
      for (const Impl* impl : {&q.embree_high, &q.embree_medium})
        for (size_t ti = 0; ti < nt; ++ti)
          row.push_back(q.have_embree ? mrays(q.n, impl->by_threads[ti].pick(med)) : "–");
      for (const Impl* impl : {&q.embree_high, &q.embree_medium})
        row.push_back(q.have_embree ? ratio(paired_ratio(q.ours.by_threads[0], impl->by_threads[0])) : "–");
      tt.row(row);
    }
  }
  tt.print(os);
  os << "\nours / Embree: throughput ratio, the median over the " << opt.reps
     << " runs of (Embree's time / ours) for runs measured back to back (robust to load bursts; the Mrays/s "
        "columns are each the "
     << pick << " run on its own).\n";

  print_ladder(results, opt, os);

  // Work table.
  os << "\n### Work per ray, brute force, agreement\n\n";
  Table wt({"scene", "rays", "query", "rays traced", "hit %", "tests / ray", "nodes / ray", "ours µs / ray (" + t0 + ")",
            "brute force µs / ray", "brute-force rays", "speed-up over brute force", "≠ brute force",
            "≠ Embree high"});
  for (const auto& r : results) {
    for (const auto& q : r.queries) {
      double ours_per_ray = q.ours.by_threads[0].pick(med) / q.n;
      double brute_per_ray = q.brute_seconds / q.brute_n;
      wt.row({r.name, q.rays, q.query, group(q.n), fmt("%.1f", 100.0 * q.hits / q.n), fmt("%.1f", q.tests_per_ray),
              fmt("%.1f", q.nodes_per_ray), fmt("%.2f", ours_per_ray * 1e6), brute_per_ray * 1e6 < 10 ? fmt("%.2f", brute_per_ray * 1e6) : fmt("%.0f", brute_per_ray * 1e6),
              group(q.brute_n), big_ratio(brute_per_ray / ours_per_ray), group(q.brute_mismatches) + " / " + group(q.brute_n),
              q.have_embree ? group(q.embree_mismatches) + " / " + group(q.n) : "–"});
    }
  }
  wt.print(os);
  os << "\ntests / ray and nodes / ray: pt::work_counters(), one thread, all rays: primitive tests as the framework "
        "counts them around every call into Part 1 (any BVH); nodes whose box was tested as the traversal counts them "
        "itself (0 for a BVH that does not). Brute force: every primitive in scene order (any hit stops at the first),"
        " one run over an evenly strided subsample of the same rays (at most "
     << fmt("%.0e", opt.brute_budget)
     << " primitive tests per row, at least 16 rays), time extrapolated per ray; speed-up = brute-force time per ray / "
        "ours (1T) per ray. ≠ brute force: closest t differs by more than 1e-9 relative, or hit/miss differs. ≠ Embree "
        "high: hit/miss differs, or closest t differs by more than 1e-5 × (scene diagonal + t) (Embree traces float "
        "copies of the vertices and rays).\n";
  for (const auto& r : results) {
    size_t bad = 0;
    for (const auto& q : r.queries) bad += q.count_mismatch_runs;
    if (!r.embree_note.empty()) os << r.name << ": " << r.embree_note << "\n";
    if (bad) os << r.name << ": WARNING " << bad << " timed runs found a different hit count than the checked pass\n";
  }
  os << "\nscenes:\n";
  for (const auto& r : results) os << "- " << r.name << ": " << r.description << "\n";
}

std::vector<std::string> split_list(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

std::unique_ptr<BenchScene> make_scene(const std::string& which) {
  auto t0 = Clock::now();
  std::unique_ptr<BenchScene> s;
  const std::string bunny = repo_path("scenes/meshes/bunny.obj");
  if (which == "bunny") {
    s = load_bench_scene(bunny);
    s->name = "bunny";
    s->description = "scenes/meshes/bunny.obj, the Stanford bunny";
  } else if (which == "bunny-loop3") {
    std::vector<std::string> warnings;
    Mesh m = loop_subdivide(load_obj(bunny, MeshTransform{}, &warnings), 3);
    s = mesh_scene("bunny-loop3", "scenes/meshes/bunny.obj after 3 levels of Loop subdivision (×64 triangles)",
                   std::move(m));
  } else if (which == "bumpy-sphere") {
    s = mesh_scene("bumpy-sphere",
                   "a cube-sphere of 6 × 289² quads (12 × 289² triangles), displaced radially by three sinusoids",
                   make_bumpy_sphere(289));
  } else if (which == "cornell-bunny") {
    s = load_bench_scene("scenes/cornell_bunny.json");
    s->name = "cornell-bunny";
    s->description = "scenes/cornell_bunny.json: the Cornell box (5 quads and the light) with the bunny, its own camera";
  } else {
    s = load_bench_scene(which);
  }
  std::fprintf(stderr, "[%s] %zu primitives, made in %.2f s\n", s->name.c_str(), s->scene.primitives.size(),
               seconds_since(t0));
  return s;
}

}  // namespace
}  // namespace pt::bench

int main(int argc, char** argv) {
  using namespace pt::bench;
  Options opt;
  CLI::App app{
      "pt-bench: the Part 2 BVH's build time, rays per second (closest and any hit, coherent camera rays and "
      "incoherent random rays, 1 and 2 threads), work per ray and speed-up over brute force, side by side with Intel "
      "Embree when it is installed. Not a test: timings are printed, never judged."};
  std::string threads = "1,2", scenes;
  app.add_flag("--quick", opt.quick, "Fewer and smaller runs (under a minute)");
  app.add_flag("--median", opt.median, "Report the median run instead of the best");
  app.add_option("--reps", opt.reps, "Timed runs per measurement (default 5, 3 with --quick)");
  app.add_option("--image", opt.image, "Camera rays: an image of N x N (default 512, 192 with --quick)");
  app.add_option("--rays", opt.random, "Random and shadow rays per scene (default 262144, 32768 with --quick)");
  app.add_option("--brute-tests", opt.brute_budget, "Primitive tests per brute-force row (default 1e8, 1.5e7 with --quick)");
  app.add_option("--threads", threads, "Thread counts, comma-separated (default 1,2)");
  app.add_option("--scenes", scenes,
                 "Scenes, comma-separated: bunny, bunny-loop3, bumpy-sphere, cornell-bunny, or a .json/.obj path "
                 "(default: the four named)");
  std::string queries;
  app.add_option("--queries", queries,
                 "Rows to measure, comma-separated: camera-closest, camera-any, random-closest, shadow-any (default all; "
                 "handy under a profiler)");
  app.add_flag("--no-embree", [&](int64_t) { opt.embree = false; }, "Skip the Embree comparator");
  app.add_flag("--no-ladder", [&](int64_t) { opt.ladder = false; },
               "Skip the steps from the reference towards Embree (instructors' checkouts only)");
  app.add_option("--seed", opt.seed, "Seed of the random rays");
  app.add_option("--show-mismatches", opt.show_mismatches, "Print up to N rays per row on which ours and Embree disagree");
  CLI11_PARSE(app, argc, argv);
  if (opt.reps <= 0) opt.reps = opt.quick ? 3 : 5;
  if (opt.image <= 0) opt.image = opt.quick ? 192 : 512;
  if (opt.random == 0) opt.random = opt.quick ? 32768 : 262144;
  if (opt.brute_budget <= 0) opt.brute_budget = opt.quick ? 1.5e7 : 1e8;
  opt.threads.clear();
  for (const auto& t : split_list(threads)) opt.threads.push_back(std::max(1, std::stoi(t)));
  if (opt.threads.empty()) opt.threads = {1};
  if (!scenes.empty()) opt.scenes = split_list(scenes);
  if (!queries.empty()) opt.queries = split_list(queries);

  std::string command;
  for (int i = 0; i < argc; ++i) {
    std::string a = argv[i];
    if (i == 0) a = a.substr(a.find_last_of('/') + 1);
    command += (i ? " " : "") + a;
  }
  std::string load_before = read_first_line("/proc/loadavg").substr(0, 14);
  const int max_threads = *std::max_element(opt.threads.begin(), opt.threads.end());
  const double capacity_before = max_threads > 1 ? core_capacity(max_threads) : 1.0;
  auto t0 = Clock::now();
  std::vector<SceneResult> results;
  try {
    for (const auto& name : opt.scenes) {
      auto s = make_scene(name);
      results.push_back(run_scene(*s, opt));
      std::fprintf(stderr, "[%s] done (%.0f s so far)\n", name.c_str(), seconds_since(t0));
    }
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  print_report(results, opt, load_before, command, seconds_since(t0), capacity_before);
  return 0;
}
