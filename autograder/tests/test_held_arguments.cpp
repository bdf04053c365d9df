// The worker's side of a row (boundary/serve.h): each call of a run starts
// from the arguments as sent. A Ray's range is mutable, and a task that
// intersects the ray it was given shortens it through its const reference:
// the run's next call must still get the ray as sent, or a correct solution
// answers a run differently from the same calls made one at a time and its
// replay accuses it of randomness from elsewhere.
#include <gtest/gtest.h>

#include <cstring>

#include "core/ray.h"
#include "core/rng.h"
#include "serve.h"

namespace pt::boundary {
namespace {

// A task that reads the ray's range, then shortens it, as an intersection does.
double shortens_its_ray(const Ray& r, Rng& rng) {
  const double seen = r.max_t;
  r.max_t = seen / 2;
  return seen + rng.uniform();
}

TEST(HeldArguments, EachCallOfARunGetsTheRayAsSent) {
  const Handler handler = serve<NoObject>(&shortens_its_ray, InTag{}, GeneratorTag{});
  Ray ray(Vec3(0.0), Vec3(0, 0, 1));
  ray.max_t = 8.0;
  const Rng given(11);
  const uint32_t asked = 6;
  Writer request;
  Crossing<Ray>::put(request, ray);
  request.put(given).put(asked);
  Reader in(request.bytes());
  Writer run;
  handler(in, run);

  Reader out(run.bytes());
  const auto n = out.get<uint32_t>();
  ASSERT_EQ(n, asked);
  Rng alone = given;
  for (uint32_t i = 0; i < n; ++i) {
    Reader answer(out.get_view(1024));
    const double got = answer.get<double>();
    const double want = shortens_its_ray(Ray(ray), alone);  // the call made alone, on a fresh copy
    EXPECT_EQ(got, want) << "call " << i << " of the run, ray " << ray;
    const auto after = out.get<Rng>();
    EXPECT_EQ(std::memcmp(&after, &alone, sizeof(Rng)), 0) << "the generator after call " << i;
  }
  out.finish();
}

}  // namespace
}  // namespace pt::boundary
