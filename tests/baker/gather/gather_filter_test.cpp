// The gather filter trades the final gather's noise for blur where indirect light is smooth, and
// must not blur where it is not: next to another surface. Noise is measured as two seeds'
// disagreement; blur (the filter's bias) as the filtered bake's difference from the unfiltered
// one at many rays, where the unfiltered one has little noise left.
#include <gtest/gtest.h>

#include <cmath>

#include "support/scene_builders.h"

namespace radbake {
namespace {

// A white block on a grey floor under a low sun: the block's lit face throws light on the floor,
// strongest at its foot and falling off over the block's height.
Scene block_in_the_sun() {
  Scene scene;
  int grey = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  int white = test::add_material(scene, {0.8f, 0.8f, 0.8f});
  test::add_quad(scene, {-2, 0, 2}, {4, 0, 0}, {0, 0, -4}, grey, "floor");
  test::add_box(scene, {-0.4f, 0, -0.4f}, {0.4f, 0.8f, 0.4f}, false, white, "block");
  Light sun;
  sun.type = LightType::Directional;
  sun.intensity = 10000;  // lux
  sun.direction = normalize(Vec3{-1, -0.7f, 0.2f});
  scene.lights.push_back(sun);
  return scene;
}

BakeOptions gathering(uint32_t rays, int filter_radius, uint64_t seed, float validity = GatherFilterOptions{}.validity) {
  BakeOptions options;
  options.gather.rays = rays;
  options.gather.filter.radius = filter_radius;
  options.gather.filter.validity = validity;
  options.seed = seed;
  return options;
}

const AtlasOptions kAtlas{25.0f, 512, 2};  // 4 cm texels

// Floor texels in the open on the block's sunlit side (x > 0.4): at least `from` and under `to`
// metres from the block's face.
bool floor_beside_block(Vec3 p, Vec3 n, float from, float to) {
  return n.y > 0.9f && p.x - 0.4f >= from && p.x - 0.4f < to && std::fabs(p.z) < 0.35f;
}

// RMS over the chosen floor texels of a - b, relative to their mean in a.
double relative_rms_difference(const BakeResult& a, const BakeResult& b, float from, float to) {
  double squares = 0, level = 0;
  size_t n = 0;
  for (size_t i = 0; i < a.elements.size(); ++i) {
    if (!a.elements.valid(i) || !floor_beside_block(a.elements.position[i], a.elements.normal[i], from, to)) continue;
    const double d = a.irradiance[i].x - b.irradiance[i].x;
    squares += d * d;
    level += a.irradiance[i].x;
    ++n;
  }
  EXPECT_GT(n, 50u);
  return std::sqrt(squares / double(n)) / (level / double(n));
}

double mean_lux(const BakeResult& r, float from, float to) {
  return test::mean_irradiance(r, [&](Vec3 p, Vec3 n) { return floor_beside_block(p, n, from, to); }).x;
}

TEST(GatherFilter, CutsTheNoiseOfTheGatherSeveralTimes) {
  const Scene scene = block_in_the_sun();
  // Away from the block (beyond 12 cm) the floor's indirect light is smooth: noise is all that
  // differs between two seeds.
  const double raw = relative_rms_difference(test::bake_scene(scene, kAtlas, gathering(64, 0, 1)).result,
                                             test::bake_scene(scene, kAtlas, gathering(64, 0, 2)).result, 0.12f, 1.5f);
  const double filtered = relative_rms_difference(test::bake_scene(scene, kAtlas, gathering(64, 3, 1)).result,
                                                  test::bake_scene(scene, kAtlas, gathering(64, 3, 2)).result, 0.12f, 1.5f);
  RecordProperty("raw_noise", std::to_string(raw / std::sqrt(2.0)));
  RecordProperty("filtered_noise", std::to_string(filtered / std::sqrt(2.0)));
  ASSERT_GT(raw, 0.002);  // there is noise to remove (the sun's direct light has none)
  // A 7 x 7 Gaussian of sigma 1.5 texels averages about 28 texels' worth: noise / 5 in the open
  // (measured 1.45% to 0.27%), a little less for the plane's two slopes.
  EXPECT_LT(filtered, raw / 3);
}

TEST(GatherFilter, LeavesTheLightAtTheFootOfAWallAsGathered) {
  const Scene scene = block_in_the_sun();
  const BakeResult raw = test::bake_scene(scene, kAtlas, gathering(1024, 0, 1)).result;
  const BakeResult guarded = test::bake_scene(scene, kAtlas, gathering(1024, 3, 1)).result;
  const BakeResult unguarded = test::bake_scene(scene, kAtlas, gathering(1024, 3, 1, 100.0f)).result;
  // The first two texel rows at the block's foot, where its light on the floor falls fastest.
  const double at_foot = mean_lux(raw, 0, 0.08f);
  const double guarded_bias = mean_lux(guarded, 0, 0.08f) / at_foot - 1;
  const double unguarded_bias = mean_lux(unguarded, 0, 0.08f) / at_foot - 1;
  RecordProperty("guarded_bias", std::to_string(guarded_bias));
  RecordProperty("unguarded_bias", std::to_string(unguarded_bias));
  // Reaching past the validity radius, the kernel takes in the dimmer floor further out, more
  // than its plane can follow: the foot loses 1.0% of its light (measured), 0.3% without. 0.6%:
  // the two bakes' residual gather noise (1024 rays, about 40 texels) plus what is left of the blur.
  EXPECT_LT(std::fabs(guarded_bias), 0.006);
  EXPECT_GT(std::fabs(unguarded_bias), 2 * std::fabs(guarded_bias));
  // And over the whole floor beside the block the filter moves no light: a symmetric kernel of
  // weights that sum to one.
  EXPECT_NEAR(mean_lux(guarded, 0, 1.5f) / mean_lux(raw, 0, 1.5f), 1.0, 0.003);
}

}  // namespace
}  // namespace radbake
