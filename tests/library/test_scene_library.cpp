// The scene library against its stored reference images (scenes/reference/).
//
// Each library scene is rendered at its manifest's check sample count (16 spp,
// a second or two on one thread) with a seed the reference did not use, and
// compared with its stored image by support/reference_check.h: relMSE within
// what 16 spp explains (the bound E[S] + z sd[S] from the reference's
// measured per-pixel variance, error_model.h) and no region's mean difference
// beyond |z| <= 5.2 (whole image and a 4 x 4 grid, per channel). The checks
// share alpha = 1e-5 (Sidak), ten times below the 1e-4 false-failure budget.
// The same renders scaled by 1.05 and by 0.95 (a 5% brightness change in the
// reference, either way) must fail the same check: that shows the check is
// strong enough to catch such a change. CMakeLists.txt also builds this test
// with mutants of the reference (a missing cosine factor in light sampling
// and in the indirect bounce) and expects it to fail.
//
// A failure here after a change to reference/ or skeleton/ means the renders
// no longer match the stored images: if the change is meant, regenerate them
// (cmake --build --preset default --target reference-images) and commit them
// with it.
#include <gtest/gtest.h>

#include "app/viewer_library.h"
#include "support/reference_check.h"
#include "support/reference_image.h"
#include "support/scene_library.h"

namespace pt::library {
namespace {

constexpr double kAlpha = 1e-5;

Library the_library() { return load_library(default_manifest(), PT_GENERATED_SCENES_DIR); }

std::vector<std::string> scene_names() {
  std::vector<std::string> names;
  try {
    for (const auto& s : the_library().scenes) names.push_back(s.name);
  } catch (const std::exception&) {
    names.push_back("unreadable_manifest");  // the test below reports why
  }
  return names;
}

Image scaled(const Image& img, double k) {
  Image out = img;
  for (Spectrum& p : out.pixels) p *= k;
  return out;
}

// The viewer (pathtracer --view) draws this test's bound for the scene in
// view, with its z as a constant (it has no statistics library): the two must
// agree to the two decimals the constant keeps.
TEST(SceneLibraryBound, TheViewerDrawsTheSameBound) {
  const Library lib = the_library();
  const ReferenceImage ref = read_reference(lib.reference_dir, lib.scenes.front().name);
  const double z = check_render(ref.mean, 16, ref, kAlpha).z_relmse;
  EXPECT_NEAR(kLibraryCheckZ, z, 0.005) << "skeleton/app/viewer_library.h's kLibraryCheckZ against the library "
                                        << "test's z (alpha " << kAlpha << " shared by its checks, Sidak)";
}

class SceneLibrary : public testing::TestWithParam<std::string> {};

TEST_P(SceneLibrary, MatchesStoredReference) {
  const Library lib = the_library();
  const LibraryScene& s = lib.find(GetParam());
  const ReferenceImage ref = read_reference(lib.reference_dir, s.name);
  ASSERT_EQ(ref.mean.width, s.width) << s.name << ": the stored image does not have the manifest's size";
  ASSERT_EQ(ref.mean.height, s.height) << s.name << ": the stored image does not have the manifest's size";
  LoadedScene loaded = load(s);
  RenderResult r = render(s, loaded.scene, s.check_samples, s.check_seed, /*threads=*/1);
  ASSERT_TRUE(r.ok()) << s.name << ": " << r.error;

  EXPECT_TRUE(check(check_render(r.image, s.check_samples, ref, kAlpha)))
      << s.name << ": " << s.check_samples << " spp, seed " << s.check_seed << ", against "
      << reference_paths(lib.reference_dir, s.name).mean;
  for (double k : {1.05, 0.95})
    EXPECT_FALSE(check(check_render(scaled(r.image, k), s.check_samples, ref, kAlpha)))
        << s.name << ": the render scaled by " << k << " passes the check: it would not catch a "
        << (k > 1 ? "brighter" : "darker") << " reference";
}

INSTANTIATE_TEST_SUITE_P(Library, SceneLibrary, testing::ValuesIn(scene_names()),
                         [](const testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace pt::library
