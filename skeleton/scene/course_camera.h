#pragma once
// The view the course's own viewer shows a scene from (measured by loading
// course files into it; scenes/README.md): `pathtracer --course-camera`, so
// that renders can be laid beside the course's images.
#include "geometry/bbox.h"
#include "scene/camera.h"

namespace pt {

// The course viewer's start-up window, to which it first fits the field of view.
constexpr int kCourseWindowWidth = 800, kCourseWindowHeight = 600;

// Re-frames `camera` as the course's viewer does for a W x H image:
//  - it looks at the centre of `bounds` along camera's view direction, from
//    1.5 x the box's diagonal, with the world's +y up (the viewer orbits
//    about +y; camera's own up when it looks straight up or down);
//  - the fov is fitted to the 800 x 600 start-up window (when camera's aspect
//    tan(hfov/2) / tan(vfov/2) is wider than 4:3, the vertical fov is
//    recomputed from the horizontal one at 4:3), and resizing to W x H keeps
//    the screen distance d = 600 / (2 tan(vfov/2)) in pixels, so the image's
//    vertical fov is 2 atan(H / 2d) (Cornell boxes with xfov 49.134 deg at
//    480 x 360: 23.25 deg) and its horizontal fov 2 atan(W / 2d).
// Near and far clips are camera's. An empty box frames the origin.
Camera course_camera(const Camera& camera, const BBox& bounds, int width, int height);

}  // namespace pt
