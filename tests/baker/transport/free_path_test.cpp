// The mean free path sizes the automatic patches (patches.h): checked against Cauchy's mean chord
// of a convex room, and against a scene where no ray strikes anything.
#include <gtest/gtest.h>

#include <cmath>

#include "baker/transport/free_path.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

double room_free_path(Vec3 size, uint64_t seed) {
  Scene scene;
  test::add_box(scene, {0, 0, 0}, size, true, test::add_material(scene, {0.5f, 0.5f, 0.5f}));
  AtlasOptions atlas;
  atlas.texel_density = 8;
  const auto placed = test::placed_elements(scene, atlas);
  return mean_free_path(placed->elements, placed->surface, *placed->tracer, seed);
}

TEST(FreePath, ARoomsMeanChordIsFourTimesItsVolumeOverItsArea) {
  // Cosine-weighted rays from points spread evenly over a convex body's inside walls cross it in
  // 4 V / S on average (Cauchy): 4 x 5 x 2.5 m gives 200 / 85 = 2.35 m, a 2 m cube 1.33 m. The
  // chords spread about 0.6 of their mean, so 4,096 rays hold the mean to about 1%; 3% bounds it.
  for (uint64_t seed : {1, 2}) {
    EXPECT_NEAR(room_free_path({4, 2.5f, 5}, seed), 200.0 / 85.0, 0.03 * 200.0 / 85.0) << "seed " << seed;
    EXPECT_NEAR(room_free_path({2, 2, 2}, seed), 4.0 / 3.0, 0.03 * 4.0 / 3.0) << "seed " << seed;
  }
}

TEST(FreePath, InfiniteWhereNoRayStrikesASurface) {
  Scene scene;
  test::add_quad(scene, {0, 0, 0}, {2, 0, 0}, {0, 0, -2}, test::add_material(scene, {0.5f, 0.5f, 0.5f}));
  AtlasOptions atlas;
  atlas.texel_density = 8;
  const auto placed = test::placed_elements(scene, atlas);
  EXPECT_TRUE(std::isinf(mean_free_path(placed->elements, placed->surface, *placed->tracer, 1)));
}

}  // namespace
}  // namespace radbake
