// Degenerate and sliver triangles, as exporters and CAD tessellators leave them: zero-area
// triangles (one point three times, a repeated vertex, three collinear points) in a floor's index
// buffer, a sliver of aspect ratio 10^4 along its edge, a standing needle of the same aspect, and
// a mesh of nothing but degenerate triangles. They must cost nothing but their own texels: no NaN
// from a zero normal or area, no texel of the floor around them wrong.
#include <gtest/gtest.h>

#include "hard_cases/hard_case_checks.h"
#include "support/closed_forms.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

TEST(DegenerateTriangles, CostNothingButTheirOwnTexels) {
  Scene scene;
  int black = test::add_material(scene, {0, 0, 0});
  // The floor [0, 1] x [0, 1], facing +y, fanned around M, which sits 0.1 mm off the edge z = 0:
  // triangle A M B is 1 m long and 0.1 mm high.
  const Vec3 A{0, 0, 0}, B{1, 0, 0}, C{1, 0, 1}, D{0, 0, 1}, M{0.5f, 0, 1e-4f}, N{0.5f, 0, 0};
  test::add_mesh(scene, {A, B, C, D, M, N},
                 {0, 4, 1, /* the sliver */ 0, 3, 4, 4, 3, 2, 4, 2, 1,
                  0, 0, 0, /* one point */ 0, 1, 1, /* a repeated vertex */ 0, 5, 1 /* collinear */},
                 black, "floor with a sliver and degenerate triangles");
  // A needle standing on the floor: 0.5 m tall, 0.05 mm wide, facing +x.
  test::add_mesh(scene, {{0.3f, 0, 0.5f}, {0.3f, 0.5f, 0.5f}, {0.3f, 0, 0.50005f}}, {0, 1, 2}, black, "needle");
  test::add_mesh(scene, {A, B, N}, {0, 1, 2, 2, 2, 2}, black, "nothing but degenerate triangles");
  Light bulb;
  bulb.intensity = 50;
  bulb.position = {0.6f, 0.7f, 0.4f};
  scene.lights.push_back(bulb);
  test::Baked b = test::bake_scene(scene, {24, 128, 2}, {});
  const BakeResult& r = b.result;
  test::expect_finite_and_non_negative(r);

  auto closed_form = [&](Vec3 x, Vec3 n) { return test::point_light_lux(bulb.intensity, bulb.position, x, n); };
  size_t floor_count = 0, sliver_count = 0, needle_count = 0;
  const double floor_error = test::worst_relative_error(
      r, [](Vec3, Vec3 n) { return n.y > 0.9f; }, closed_form, &floor_count);
  // The row of texels the sliver runs through.
  const double sliver_error = test::worst_relative_error(
      r, [](Vec3 p, Vec3 n) { return n.y > 0.9f && p.z < 1.0f / 24; }, closed_form, &sliver_count);
  const double needle_error = test::worst_relative_error(
      r, [](Vec3, Vec3 n) { return n.x > 0.9f; }, closed_form, &needle_count);
  RecordProperty("worst_floor_error", std::to_string(floor_error));
  RecordProperty("worst_sliver_row_error", std::to_string(sliver_error));
  RecordProperty("worst_needle_error", std::to_string(needle_error));
  EXPECT_GT(floor_count, 500u);
  EXPECT_GE(sliver_count, 24u);
  EXPECT_GE(needle_count, 10u);
  // 2%: the 4 jittered shadow rays of a 4 cm texel 0.7 m under the bulb (see the coplanar case).
  // A sliver's texel counted with a zero or wild area, or a NaN normal, is off by far more.
  EXPECT_LT(floor_error, 0.02);
  EXPECT_LT(sliver_error, 0.02);
  // The needle's texels are 4 cm tall and 0.05 mm wide: each holds one sample on the needle.
  EXPECT_LT(needle_error, 0.02);
}

}  // namespace
}  // namespace radbake
