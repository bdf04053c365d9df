#include "geometry/bvh.h"

namespace pt {

BVHAccel::BVHAccel(std::vector<Primitive*> primitives, size_t max_leaf_size) : primitives_(std::move(primitives)) {
  if (!primitives_.empty()) root_ = construct_bvh(primitives_.begin(), primitives_.end(), max_leaf_size);
}

BVHAccel::~BVHAccel() = default;

}  // namespace pt
