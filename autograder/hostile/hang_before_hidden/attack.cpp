// Not an attack: an honest student's infinite loop. generate_ray loops
// forever for one camera at the image centre, which two visible tests of
// CameraRay ask for, the suite's first visible one (CentreLooksAtTarget) and
// OriginAndClipRange; no hidden test does. GoogleTest runs the suite's hidden tests
// (SensorIsAPlane, PosedCameraMatchesLookAt) before it, in the same process,
// so the hung test's diagnosis was the verifier's last lines: the hidden
// tests' names and results, and the stack with the kit's absolute path.
namespace {
void loop_forever_at_the_centre(double x, double y, double hfov, double vfov) {
  if (x != 0.5 || y != 0.5 || hfov != 60.0 || vfov != 45.0) return;
  for (volatile unsigned long i = 0;; i = i + 1) {
  }
}
}  // namespace
