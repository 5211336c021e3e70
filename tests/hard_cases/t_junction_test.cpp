// A T-junction: a floor made of one 2 m quad beside two 1 m quads, whose shared corner lies in the
// middle of the big quad's edge (no vertex there), as modellers leave them. No texel along the
// junction may come out dark, and no light may pass through the hairline the junction can open: a
// bulb under the floor must not reach the ceiling plate above it. All black, so each bulb's closed
// form holds where it shines.
#include <gtest/gtest.h>

#include "hard_cases/hard_case_checks.h"
#include "support/closed_forms.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

TEST(TJunction, FloorShowsNoSeamAndLetsNoLightThrough) {
  Scene scene;
  int black = test::add_material(scene, {0, 0, 0});
  test::add_quad(scene, {0, 0, 1}, {2, 0, 0}, {0, 0, -1}, black, "floor, one quad");
  test::add_quad(scene, {0, 0, 2}, {1, 0, 0}, {0, 0, -1}, black, "floor, half quad");
  test::add_quad(scene, {1, 0, 2}, {1, 0, 0}, {0, 0, -1}, black, "floor, other half quad");  // T at (1, 0, 1)
  test::add_quad(scene, {0, 1, 0}, {2, 0, 0}, {0, 0, 2}, black, "ceiling plate");
  Light above, below;
  above.intensity = 20;
  above.position = {0.7f, 0.6f, 1.2f};
  below.intensity = 1000;  // under the floor, right under the T: 50 times the bulb above
  below.position = {1, -0.5f, 1};
  scene.lights = {above, below};
  test::Baked b = test::bake_scene(scene, {24, 256, 2}, {});
  const BakeResult& r = b.result;
  test::expect_finite_and_non_negative(r);

  // Only the bulb above lights the floor and the ceiling; the one below is behind the floor.
  auto from_above = [&](Vec3 x, Vec3 n) { return test::point_light_lux(above.intensity, above.position, x, n); };
  size_t floor_count = 0, seam_count = 0, ceiling_count = 0;
  const double floor_error = test::worst_relative_error(
      r, [](Vec3, Vec3 n) { return n.y > 0.9f; }, from_above, &floor_count);
  // The texels touching the junction line z = 1, on both sides.
  const double seam_error = test::worst_relative_error(
      r, [](Vec3 p, Vec3 n) { return n.y > 0.9f && std::fabs(p.z - 1) < 1.0f / 24; }, from_above, &seam_count);
  const double ceiling_error = test::worst_relative_error(
      r, [](Vec3, Vec3 n) { return n.y < -0.9f; }, from_above, &ceiling_count);
  RecordProperty("worst_floor_error", std::to_string(floor_error));
  RecordProperty("worst_seam_error", std::to_string(seam_error));
  RecordProperty("worst_ceiling_error", std::to_string(ceiling_error));
  EXPECT_GT(floor_count, 2000u);
  EXPECT_GT(seam_count, 90u);  // the row of texels on each side of the line
  EXPECT_GT(ceiling_count, 2000u);
  // 2%: a texel's 4 shadow rays sample its footprint at 4 jittered points, off its mean by up to
  // a percent where the bulb's light changes by 10% across the 4 cm texel. A dark seam is 50% or
  // 100%; light through a crack adds a bulb 50 times brighter.
  EXPECT_LT(floor_error, 0.02);
  EXPECT_LT(seam_error, 0.02);
  EXPECT_LT(ceiling_error, 0.02);

  // The junction's vertices (the T's own, (1, 0, 1), on the half quads) carry the same light
  // (vertex values are fitted to the texels around them and extrapolated to the edge).
  double worst_vertex = 0;
  for (size_t m = 1; m <= 2; ++m) {
    const MeshInstance& half = scene.instances[m];
    const AtlasMesh& mesh = b.atlas.meshes[m];
    for (size_t v = 0; v < mesh.source_vertex.size(); ++v) {
      const Vec3 x = half.positions[mesh.source_vertex[v]];
      const double expected = from_above(x, {0, 1, 0});
      worst_vertex = std::max(worst_vertex, std::fabs(r.vertex_values[m][v].x - expected) / expected);
    }
  }
  RecordProperty("worst_vertex_error", std::to_string(worst_vertex));
  // 3%: a plane fitted to the texels within 2-6 texels and extrapolated half a texel to the corner
  // follows the bulb's falloff to a couple of percent; a seam would pull it far lower.
  EXPECT_LT(worst_vertex, 0.03);
}

}  // namespace
}  // namespace radbake
