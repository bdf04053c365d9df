#pragma once
// The albedo and directions of the Part 3 BSDF tests (P3T1).
#include <vector>

#include "core/vec.h"

namespace pt::test::part3 {

// A colour whose channels differ, so that a channel mix-up shows.
inline const Spectrum kColour(0.2, 0.5, 0.9);

inline std::vector<Vec3> some_directions() {
  return {{0, 0, 1}, glm::normalize(Vec3(1, 2, 3)), glm::normalize(Vec3(-0.3, 0.1, 0.05)),
          glm::normalize(Vec3(0.9, -0.9, 0.001)), glm::normalize(Vec3(-2, -1, 4))};
}

}  // namespace pt::test::part3
