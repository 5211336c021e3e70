// Sunlight 89 degrees from the normal of a tilted floor of 288 triangles, away from the origin: a
// shadow ray climbs 1.7 cm per metre over the floor, so a ray offset that does not clear the
// neighbouring triangles (rounded to float, in a plane no axis lies in) shows as shadow acne,
// texels darkened in stripes. Every texel must read E cos 89 degrees.
#include <gtest/gtest.h>

#include <cmath>

#include "hard_cases/hard_case_checks.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

TEST(GrazingLight, TiltedTessellatedFloorHasNoAcne) {
  const Vec3 centre{5, 2, -3}, normal = normalize(Vec3{0.3f, 1, 0.2f});
  Vec3 u, v;
  orthonormal_basis(normal, u, v);
  // A 2 m square in the plane, 12 x 12 cells, two triangles each, front toward `normal`.
  constexpr int kCells = 12;
  std::vector<Vec3> positions;
  std::vector<uint32_t> triangles;
  for (int j = 0; j <= kCells; ++j)
    for (int i = 0; i <= kCells; ++i)
      positions.push_back(centre + u * (2.0f * i / kCells - 1) + v * (2.0f * j / kCells - 1));
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i) {
      const uint32_t a = uint32_t(j * (kCells + 1) + i), b = a + 1, c = a + kCells + 1, d = c + 1;
      triangles.insert(triangles.end(), {a, b, d, a, d, c});
    }
  ASSERT_GT(dot(cross(positions[1] - positions[0], positions[kCells + 2] - positions[0]), normal), 0);
  Scene scene;
  test::add_mesh(scene, positions, triangles, test::add_material(scene, {0, 0, 0}), "tilted floor");

  const float angle = 89 * float(M_PI) / 180;
  const Vec3 along = normalize(u * 0.8f + v * 0.6f);  // a tangent no grid line follows
  Light sun;
  sun.type = LightType::Directional;
  sun.intensity = 1000;  // lux on a surface facing it
  sun.direction = -(normal * std::cos(angle) + along * std::sin(angle));
  scene.lights.push_back(sun);
  test::Baked b = test::bake_scene(scene, {24, 128, 2}, {});
  test::expect_finite_and_non_negative(b.result);

  const double expected = sun.intensity * std::cos(89 * M_PI / 180);  // 17.45 lux
  size_t count = 0;
  const double worst = test::worst_relative_error(
      b.result, [](Vec3, Vec3) { return true; }, [&](Vec3, Vec3) { return expected; }, &count);
  RecordProperty("worst_relative_error", std::to_string(worst));
  RecordProperty("expected_lux", std::to_string(expected));
  EXPECT_GT(count, 2000u);
  // 1%: nothing shades the floor, so only float round-off separates a texel from E cos 89: each
  // triangle's normal, from corners rounded to float 6 m from the origin, is off by a few 1e-6
  // rad, 2e-4 of cos 89 (measured: 1.1e-4). A self-shadowed shadow ray costs a quarter of a
  // texel's light.
  EXPECT_LT(worst, 0.01);
}

}  // namespace
}  // namespace radbake
