#pragma once
// What the viewer's BVH walk and pixel inspector answer, as JSON for the page.
// Both read the scene as the student's code built it; neither changes it.
#include <string>

#include <nlohmann/json.hpp>

#include "render/pathtracer.h"
#include "scene/scene.h"

namespace pt {

// Image position of a world point for a width x height render through
// `camera`, in pixels with row 0 at the top; false when behind the camera.
bool project(const Camera& camera, int width, int height, const Vec3& p, double* px, double* row);

// The BVH node reached from the root by `path` ("" the root, then 'l' or 'r'
// per step): its box, depth, primitive count, SAH costs, which children it
// has, and line segments [x0, y0, x1, y1] of its box and of (at most
// `max_drawn`) of its primitives projected for the page.
// Throws std::invalid_argument naming the step when the path leaves the tree.
nlohmann::json bvh_node_json(const Scene& scene, const std::string& path, const Camera& camera, int width, int height,
                             size_t max_drawn = 4000);

// One path through pixel (x, row) (row 0 at the top) traced by the viewer,
// which calls the student's task functions one at a time and records what
// each returns: the camera ray (P1T1), each hit (scene.intersect: P1T3/P1T4
// through P2T3), emission (P3T2), direct light (P3T5) and a BSDF sample
// (P3T1) per vertex, and the Russian-roulette decision (the viewer's own
// draw with settings.rr_continue_prob, as P4T2 specifies). A task that
// throws ends the path with its message in "error".
nlohmann::json pixel_path_json(const Scene& scene, const PathTracer& tracer, const Camera& camera, int x, int row);

}  // namespace pt
