#include "geometry/triangle.h"

namespace pt {

BBox Triangle::get_bbox() const {
  BBox b(p1());
  b.expand(p2());
  b.expand(p3());
  return b;
}

}  // namespace pt
