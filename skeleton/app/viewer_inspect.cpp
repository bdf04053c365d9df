#include "app/viewer_inspect.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <stdexcept>

#include "core/frame.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"

namespace pt {

using json = nlohmann::json;

namespace {

json vec(const Vec3& v) { return {v.x, v.y, v.z}; }

Vec3 to_camera(const Camera& c, const Vec3& p) { return glm::transpose(c.c2w) * (p - c.pos); }

// Camera-space point to pixels (row 0 at the top); z must be negative.
void to_pixels(const Camera& c, int w, int h, const Vec3& q, double* px, double* row) {
  const double sx = (q.x / -q.z) / std::tan(glm::radians(c.hfov) / 2), sy = (q.y / -q.z) / std::tan(glm::radians(c.vfov) / 2);
  *px = (sx + 1) / 2 * w;
  *row = (1 - sy) / 2 * h;
}

// Adds the segment a-b, clipped to the part in front of the camera.
void add_segment(json& out, const Camera& c, int w, int h, const Vec3& a, const Vec3& b) {
  Vec3 qa = to_camera(c, a), qb = to_camera(c, b);
  const double z_max = -1e-6;
  if (qa.z > z_max && qb.z > z_max) return;
  if (qa.z > z_max) qa = qb + (qa - qb) * ((z_max - qb.z) / (qa.z - qb.z));
  if (qb.z > z_max) qb = qa + (qb - qa) * ((z_max - qa.z) / (qb.z - qa.z));
  double x0, y0, x1, y1;
  to_pixels(c, w, h, qa, &x0, &y0);
  to_pixels(c, w, h, qb, &x1, &y1);
  const double r[] = {x0, y0, x1, y1};
  for (double v : r)
    if (!std::isfinite(v) || std::abs(v) > 1e6) return;  // far off screen: not worth drawing
  out.push_back({std::round(x0 * 10) / 10, std::round(y0 * 10) / 10, std::round(x1 * 10) / 10, std::round(y1 * 10) / 10});
}

void add_box(json& out, const Camera& c, int w, int h, const BBox& b) {
  auto corner = [&](int i) { return Vec3(i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z); };
  for (int i = 0; i < 8; ++i)
    for (int bit = 1; bit < 8; bit <<= 1)
      if (!(i & bit)) add_segment(out, c, w, h, corner(i), corner(i | bit));
}

void add_primitive(json& out, const Camera& c, int w, int h, const Primitive* p) {
  if (auto* t = dynamic_cast<const Triangle*>(p)) {
    add_segment(out, c, w, h, t->p1(), t->p2());
    add_segment(out, c, w, h, t->p2(), t->p3());
    add_segment(out, c, w, h, t->p3(), t->p1());
  } else {
    add_box(out, c, w, h, p->get_bbox());
  }
}

// The subtree's SAH cost relative to `node`: expected node visits plus
// primitive tests of a line through node's box (tests/support/bvh_checks.h
// uses the same sum, over tight boxes, for the whole tree).
double subtree_cost(const BVHNode* n, double root_area) {
  const double ratio = root_area > 0 ? n->bb.surface_area() / root_area : 1.0;
  if (n->is_leaf()) return ratio * double(n->size());
  return ratio + (n->l ? subtree_cost(n->l.get(), root_area) : 0) + (n->r ? subtree_cost(n->r.get(), root_area) : 0);
}

// A secondary ray leaving surface point p, kRayEpsilon along (Part 3's
// handout, section 7), as the estimators' own rays do.
Ray leaving(const Vec3& p, const Vec3& d, double max_t, int depth = 0) {
  Ray out(p, d, max_t, depth);
  out.min_t = kRayEpsilon;
  return out;
}

std::string primitive_kind(const Primitive* p) {
  if (dynamic_cast<const Triangle*>(p)) return "triangle";
  if (dynamic_cast<const Sphere*>(p)) return "sphere";
  return "primitive";
}

}  // namespace

bool project(const Camera& camera, int width, int height, const Vec3& p, double* px, double* row) {
  const Vec3 q = to_camera(camera, p);
  if (!(q.z < 0)) return false;
  to_pixels(camera, width, height, q, px, row);
  return std::isfinite(*px) && std::isfinite(*row);
}

json bvh_node_json(const Scene& scene, const std::string& path, const Camera& camera, int width, int height,
                   size_t max_drawn) {
  if (!scene.bvh) throw std::invalid_argument("the scene has no BVH (building it failed: the status says why)");
  if (!scene.bvh->root()) throw std::invalid_argument("the BVH has no root (construct_bvh returned none)");
  for (size_t i = 0; i < path.size(); ++i)
    if (path[i] != 'l' && path[i] != 'r')
      throw std::invalid_argument("path: step " + std::to_string(i + 1) + " is '" + path.substr(i, 1) + "', expected l or r");
  const BVHNode* node = scene.bvh->root();
  for (size_t i = 0; i < path.size(); ++i) {
    const BVHNode* next = path[i] == 'l' ? node->l.get() : node->r.get();
    if (!next)
      throw std::invalid_argument("path: step " + std::to_string(i + 1) + " (" + path[i] + ") leaves the tree: the node " +
                                  (path.substr(0, i).empty() ? "(root)" : path.substr(0, i)) + " has no " +
                                  (path[i] == 'l' ? "left" : "right") + " child");
    node = next;
  }
  json j;
  j["path"] = path;
  j["depth"] = path.size();
  j["count"] = node->size();
  j["start"] = node->start;
  j["end"] = node->end;
  j["leaf"] = node->is_leaf();
  j["has_left"] = bool(node->l);
  j["has_right"] = bool(node->r);
  j["bbox"] = {{"min", vec(node->bb.min)}, {"max", vec(node->bb.max)}};
  const double area = node->bb.surface_area();
  j["sah"]["leaf_cost"] = double(node->size());  // every primitive tested
  j["sah"]["subtree_cost"] = subtree_cost(node, area);
  if (node->l && node->r && area > 0)
    j["sah"]["split_cost"] = (node->l->bb.surface_area() * double(node->l->size()) +
                              node->r->bb.surface_area() * double(node->r->size())) / area;
  j["box_segments"] = json::array();
  add_box(j["box_segments"], camera, width, height, node->bb);
  json prims = json::array();
  const auto& order = scene.bvh->primitives();
  const size_t end = std::min(node->end, order.size());
  size_t drawn = 0;
  for (size_t i = node->start; i < end && drawn < max_drawn; ++i, ++drawn) add_primitive(prims, camera, width, height, order[i]);
  j["primitive_segments"] = prims;
  j["primitives_drawn"] = drawn;
  return j;
}

json pixel_path_json(const Scene& scene, const PathTracer& tracer, const Camera& camera, int x, int row) {
  const RenderSettings& s = tracer.settings;
  const int y = s.height - 1 - row;  // the tasks count rows from the bottom
  Rng rng = Rng::for_pixel(s.seed ^ 0x5eed1e55u, uint32_t(x), uint32_t(y));
  json out{{"x", x}, {"row", row}, {"vertices", json::array()}, {"warnings", json::array()}};
  auto warn_if_bad = [&](const std::string& what, const Vec3& v) {
    if (!is_finite(v)) out["warnings"].push_back(what + " is NaN or infinite");
    else if (v.x < 0 || v.y < 0 || v.z < 0) out["warnings"].push_back(what + " is negative");
  };
  const char* task = "P1T1 Camera::generate_ray";
  try {
    Ray r = camera.generate_ray((x + 0.5) / s.width, (y + 0.5) / s.height);
    out["camera_ray"] = {{"origin", vec(r.o)}, {"direction", vec(r.d)}};
    for (int depth = s.max_ray_depth, k = 0; k <= s.max_ray_depth; ++k, --depth) {
      json v{{"index", k}};
      Intersection isect;
      task = "the scene's intersect (P1T3/P1T4 through P2T3)";
      if (!scene.intersect(r, &isect)) {
        v["escaped"] = true;
        v["background"] = vec(scene.background(r.d));
        out["vertices"].push_back(v);
        break;
      }
      const Vec3 p = r.at(isect.t);
      const std::string at = "vertex " + std::to_string(k);
      v["point"] = vec(p);
      v["t"] = isect.t;
      v["normal"] = vec(isect.n);
      if (!is_finite(p)) out["warnings"].push_back(at + " point is NaN or infinite");
      const auto& prims = scene.primitives;
      auto it = std::find_if(prims.begin(), prims.end(), [&](const auto& q) { return q.get() == isect.primitive; });
      v["primitive"] = it == prims.end() ? -1 : long(it - prims.begin());
      v["primitive_kind"] = isect.primitive ? primitive_kind(isect.primitive) : "none";
      double px, prow;
      if (project(camera, s.width, s.height, p, &px, &prow)) v["pixel"] = {px, prow};
      if (!isect.bsdf) {
        v["error"] = "the hit has no BSDF (Intersection::bsdf not set)";
        out["vertices"].push_back(v);
        break;
      }
      if (k == 0) {
        task = "P3T2 zero_bounce_radiance";
        const Spectrum e = tracer.zero_bounce_radiance(r, isect);
        v["emitted"] = vec(e);
        warn_if_bad(at + " emission", e);
      }
      // What the framework's light sampling offers here (one sample per light).
      json lights = json::array();
      for (size_t li = 0; li < scene.lights.size(); ++li) {
        Vec3 wi;
        double dist, pdf;
        const Spectrum L = scene.lights[li]->sample_L(p, &wi, &dist, &pdf, rng);
        lights.push_back({{"light", li}, {"direction", vec(wi)}, {"radiance", vec(L)}, {"pdf", pdf},
                          {"visible", !scene.has_intersection(leaving(p, wi, dist - kRayEpsilon))}, {"cos", glm::dot(wi, isect.n)}});
      }
      v["light_samples"] = lights;
      task = "P3T5 one_bounce_radiance";
      const Spectrum direct = depth >= 1 ? tracer.one_bounce_radiance(r, isect, rng) : Spectrum(0.0);
      // This vertex's own contribution, as the task returns it; the path's
      // throughput is left to the student (it is Part 4's weight).
      v["direct"] = vec(direct);
      warn_if_bad(at + " direct light", direct);
      if (depth <= 1) {
        v["end"] = "maximum depth reached";
        out["vertices"].push_back(v);
        break;
      }
      task = "P3T1 BSDF::sample_f";
      const Frame local = Frame::from_normal(isect.n);
      Vec3 w_in;
      double pdf = 0;
      const Spectrum f = isect.bsdf->sample_f(local.to_local(-r.d), &w_in, &pdf, rng);
      const Vec3 wi = local.to_world(w_in);
      v["bsdf_sample"] = {{"direction", vec(wi)}, {"f", vec(f)}, {"pdf", pdf}, {"cos", w_in.z}};
      warn_if_bad(at + " BSDF value", f);
      if (!(pdf > 0)) out["warnings"].push_back(at + " BSDF pdf is " + (std::isnan(pdf) ? "NaN" : "not positive"));
      // Russian roulette as P4T2 specifies: never on the first bounce.
      const bool first_bounce = depth == s.max_ray_depth;
      const double p_continue = first_bounce ? 1.0 : s.rr_continue_prob;
      const double draw = rng.uniform();
      const bool survives = draw < p_continue;
      v["russian_roulette"] = {{"p", p_continue}, {"draw", draw}, {"survives", survives}};
      out["vertices"].push_back(v);
      if (!survives || !(pdf > 0)) break;
      r = leaving(p, wi, kInf, depth - 1);
    }
  } catch (const std::exception& e) {
    out["error"] = std::string(e.what()) + " (in " + task + ")";
  }
  return out;
}

}  // namespace pt
