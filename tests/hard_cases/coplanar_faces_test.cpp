// Coplanar faces: a floor laid twice over itself (two overlapping quads in one plane, as a level
// made of duplicated tiles has), and a zero-thickness wall, two coincident quads facing away from
// each other. Rays starting on one copy must not stop on the other, and light must not pass
// between the two faces of the wall. Everything is black, so the light is the lamp's alone and
// its closed form holds at every texel.
#include <gtest/gtest.h>

#include "hard_cases/hard_case_checks.h"
#include "support/closed_forms.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

constexpr float kWall = -0.5f;  // x of the zero-thickness wall

TEST(CoplanarFaces, DuplicatesLightLikeOneAndAZeroThicknessWallCastsAFullShadow) {
  Scene scene;
  int black = test::add_material(scene, {0, 0, 0});
  test::add_quad(scene, {-1, 0, 1}, {2, 0, 0}, {0, 0, -2}, black, "floor");
  test::add_quad(scene, {-0.3f, 0, 1}, {1.8f, 0, 0}, {0, 0, -2}, black, "floor laid again, overlapping");
  test::add_quad(scene, {kWall, 0, -1}, {0, 0, 2}, {0, 1, 0}, black, "wall, lit face");
  test::add_quad(scene, {kWall, 0, -1}, {0, 1, 0}, {0, 0, 2}, black, "wall, back face");
  Light bulb;
  bulb.intensity = 100;
  bulb.position = {0.3f, 0.8f, 0.1f};
  scene.lights.push_back(bulb);
  test::Baked b = test::bake_scene(scene, {24, 256, 2}, {});
  const BakeResult& r = b.result;
  test::expect_finite_and_non_negative(r);

  auto closed_form = [&](Vec3 x, Vec3 n) { return test::point_light_lux(bulb.intensity, bulb.position, x, n); };
  size_t lit_floor = 0, lit_wall = 0;
  const double floor_error = test::worst_relative_error(
      r, [](Vec3 p, Vec3 n) { return n.y > 0.9f && p.x > kWall; }, closed_form, &lit_floor);
  const double wall_error = test::worst_relative_error(
      r, [](Vec3, Vec3 n) { return n.x > 0.9f; }, closed_form, &lit_wall);
  RecordProperty("worst_floor_error", std::to_string(floor_error));
  RecordProperty("worst_wall_error", std::to_string(wall_error));
  EXPECT_GT(lit_floor, 3000u);  // both copies
  EXPECT_GT(lit_wall, 1000u);
  // 2%: a texel's 4 shadow rays start from 4 jittered points of its footprint, so their mean
  // misses the footprint's by up to a percent where the light changes by 10% across the 4 cm
  // texel (measured: 1.2% at worst of 4,000). A ray stopped by the other copy gives a black
  // texel: 100%.
  EXPECT_LT(floor_error, 0.02);
  EXPECT_LT(wall_error, 0.02);

  // Behind the wall, on the floor and on its back face: nothing at all (every surface is black,
  // so only light passing the wall could get there).
  size_t behind = 0;
  for (size_t i = 0; i < r.elements.size(); ++i) {
    const Vec3 p = r.elements.position[i], n = r.elements.normal[i];
    const bool floor_behind = n.y > 0.9f && p.x < kWall, back_face = n.x < -0.9f;
    if (!r.elements.valid(i) || !(floor_behind || back_face)) continue;
    EXPECT_EQ(r.irradiance[i].x, 0.0f) << "behind the wall at " << p.x << ", " << p.y << ", " << p.z;
    ++behind;
  }
  EXPECT_GT(behind, 1000u);
}

}  // namespace
}  // namespace radbake
