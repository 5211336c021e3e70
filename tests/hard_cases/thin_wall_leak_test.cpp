// Light leaks through a 1 cm wall, four times thinner than a texel. A lit room (white walls,
// reflectance 0.8, so light reaches every corner many times over) and a closed dark room side by
// side; the dark room must stay dark: under 0.1% of the lit room's mean irradiance.
#include <gtest/gtest.h>

#include "hard_cases/hard_case_checks.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

constexpr float kWallLo = 2.0f, kWallHi = 2.01f;  // the wall's two faces: 1 cm apart

Light lamp() {
  Light light;
  light.intensity = 100;
  light.position = {1.0f, 1.6f, 1.0f};
  return light;
}

// Floor and ceiling run under and over the wall from one room into the other; the wall is a 1 cm
// box standing on the floor and touching the ceiling, with no gap at either.
Scene shared_floor() {
  Scene scene;
  int white = test::add_material(scene, {0.8f, 0.8f, 0.8f});
  test::add_quad(scene, {0, 0, 2}, {4.01f, 0, 0}, {0, 0, -2}, white, "floor");
  test::add_quad(scene, {0, 2, 0}, {4.01f, 0, 0}, {0, 0, 2}, white, "ceiling");
  test::add_quad(scene, {0, 0, 0}, {4.01f, 0, 0}, {0, 2, 0}, white, "front");
  test::add_quad(scene, {0, 0, 2}, {0, 2, 0}, {4.01f, 0, 0}, white, "back");
  test::add_quad(scene, {0, 0, 0}, {0, 2, 0}, {0, 0, 2}, white, "left");
  test::add_quad(scene, {4.01f, 0, 0}, {0, 0, 2}, {0, 2, 0}, white, "right");
  test::add_box(scene, {kWallLo, 0, 0}, {kWallHi, 2, 2}, false, white, "wall");
  return scene;
}

// Two closed rooms, each a box of its own, 1 cm apart.
Scene two_boxes() {
  Scene scene;
  int white = test::add_material(scene, {0.8f, 0.8f, 0.8f});
  test::add_box(scene, {0, 0, 0}, {kWallLo, 2, 2}, true, white, "lit room");
  test::add_box(scene, {kWallHi, 0, 0}, {4.01f, 2, 2}, true, white, "dark room");
  return scene;
}

struct Case {
  const char* name;
  Scene (*build)();
  float density;  // texels per metre
};

class ThinWall : public ::testing::TestWithParam<Case> {};

TEST_P(ThinWall, DarkRoomGetsUnderAThousandthOfTheLitRoomsLight) {
  Scene scene = GetParam().build();
  scene.lights.push_back(lamp());
  BakeResult r = test::bake_scene(scene, {GetParam().density, 512, 2}, {}).result;
  test::expect_finite_and_non_negative(r);
  size_t lit_count = 0, dark_count = 0;
  Rgb lit = test::mean_irradiance(r, [](Vec3 x, Vec3) { return x.x < kWallLo - 1e-3f; }, &lit_count);
  Rgb dark = test::mean_irradiance(r, [](Vec3 x, Vec3) { return x.x > kWallHi + 1e-3f; }, &dark_count);
  RecordProperty("lit_mean_lux", std::to_string(lit.x));
  RecordProperty("dark_mean_lux", std::to_string(dark.x));
  EXPECT_GT(lit_count, 1000u);
  EXPECT_GT(dark_count, 1000u);
  EXPECT_GT(lit.x, 20.0f);  // the lamp alone gives 100 / 1.6^2 = 39 lux under it
  EXPECT_LT(dark.x, 1e-3f * lit.x);
}

const Case kCases[] = {{"SharedFloorAndCeiling", shared_floor, 24.0f},
                       {"SharedFloorAndCeilingOtherTexels", shared_floor, 29.3f},
                       {"TwoClosedBoxes", two_boxes, 24.0f}};

INSTANTIATE_TEST_SUITE_P(Scenes, ThinWall, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace radbake
