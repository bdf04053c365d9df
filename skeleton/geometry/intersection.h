#pragma once
#include "core/vec.h"

namespace pt {

class Primitive;
class BSDF;

// What a closest-hit query reports about the nearest hit.
struct Intersection {
  double t = kInf;                  // ray parameter of the hit
  Vec3 n{0.0};                      // unit shading normal (outward for spheres)
  Vec3 barycentric{0.0};            // triangle weights of (p1, p2, p3); zero for spheres
  const Primitive* primitive = nullptr;
  const BSDF* bsdf = nullptr;
};

}  // namespace pt
