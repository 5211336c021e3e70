// The bitmap packer and the sliver merge (docs/atlas_packing.md): a chart goes inside another's
// hole when it fits there, and the strips of a thin rod join into one chart without stretch.
#include <gtest/gtest.h>

#include <cmath>

#include "support/scene_builders.h"

namespace radbake {
namespace {

struct Box {
  Vec2 lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
  void add(Vec2 p) { lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)}, hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)}; }
};

// Texel positions of a mesh's UVs whose source vertex satisfies `which`.
Box texel_box(const Atlas& atlas, const MeshInstance& inst, size_t mesh, bool (*which)(Vec3)) {
  const AtlasMesh& m = atlas.meshes[mesh];
  const AtlasPage& page = atlas.pages[size_t(m.page)];
  Box b;
  for (size_t v = 0; v < m.uvs.size(); ++v)
    if (which(inst.positions[m.source_vertex[v]])) b.add({m.uvs[v].x * page.width, m.uvs[v].y * page.height});
  return b;
}

TEST(ChartPacking, ASmallChartGoesInsideARingShapedOne) {
  // A flat 1 m frame round a 0.6 m hole, and a separate 0.5 m plate: at the density that fills a
  // 256 page, the frame alone spans the page, so the plate fits only in the hole. The horizon
  // packer put it beside the frame, which capped the frame at 256 - 0.5 d - padding texels.
  Scene scene;
  const int m = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  const float o = 0.2f, i = 0.8f;
  test::add_mesh(scene,
                 {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {o, o, 0}, {i, o, 0}, {i, i, 0}, {o, i, 0}},
                 {0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7}, m, "frame");
  test::add_quad(scene, {3, 0, 0}, {0.5f, 0, 0}, {0, 0.5f, 0}, m, "plate");
  AtlasOptions options;
  options.max_page_size = 256;
  options.automatic_texels = SIZE_MAX;  // the automatic density fills the page
  const Atlas atlas = test::unwrap(scene, options);
  ASSERT_EQ(atlas.pages.size(), 1u);
  EXPECT_EQ(atlas.chart_count, 2u);
  EXPECT_EQ(atlas.stats.overlapping_texels, 0u);
  EXPECT_EQ(atlas.stats.padding_violations, 0u);
  // The frame spans at least 240 of the 256 texels (beside it, the plate would leave it at most
  // 256 - 0.5 d - 2, so d < 170 texels/m).
  EXPECT_GT(atlas.texel_density, 240.0f);
  const Box hole = texel_box(atlas, scene.instances[0], 0, [](Vec3 p) { return p.x > 0.1f && p.x < 0.9f && p.y > 0.1f && p.y < 0.9f; });
  const Box plate = texel_box(atlas, scene.instances[1], 1, [](Vec3) { return true; });
  // The plate's texels lie inside the hole, at least the padding (2 texels) from its edges.
  EXPECT_GE(plate.lo.x, hole.lo.x + 2) << plate.lo.x << " " << hole.lo.x;
  EXPECT_GE(plate.lo.y, hole.lo.y + 2) << plate.lo.y << " " << hole.lo.y;
  EXPECT_LE(plate.hi.x, hole.hi.x - 2) << plate.hi.x << " " << hole.hi.x;
  EXPECT_LE(plate.hi.y, hole.hi.y - 2) << plate.hi.y << " " << hole.hi.y;
}

TEST(ChartPacking, TheStripsOfAThinRodJoinIntoOneChartWithoutStretch) {
  // An open tube 1 cm in radius and 1 m long, 12 facets round: at 100 texels/m each facet is a
  // strip 0.52 texels wide. Curved charts are capped at a twelfth of their mesh, so the growing
  // leaves 12 one-facet charts; the sliver merge unrolls them into one band of 11 facets (the
  // twelfth would close it into a ring) and the last facet: 2 charts, no stretch.
  Scene scene;
  const int m = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  const int segments = 12;
  std::vector<Vec3> positions;
  std::vector<uint32_t> triangles;
  for (int s = 0; s < segments; ++s) {
    const float a = 2 * 3.14159265f * float(s) / segments;
    positions.push_back({0.01f * std::cos(a), 0.01f * std::sin(a), 0});
    positions.push_back({0.01f * std::cos(a), 0.01f * std::sin(a), 1});
  }
  for (uint32_t s = 0; s < uint32_t(segments); ++s) {
    const uint32_t a = 2 * s, b = 2 * ((s + 1) % segments);
    triangles.insert(triangles.end(), {a, b, b + 1, a, b + 1, a + 1});
  }
  test::add_mesh(scene, positions, triangles, m, "rod");
  AtlasOptions options;
  options.texel_density = 100;
  const Atlas atlas = test::unwrap(scene, options);
  EXPECT_EQ(atlas.chart_count, 2u);
  EXPECT_LT(atlas.stats.stretch_l2, 1.001);  // the band unrolls isometrically; 0.1% bounds float rounding
  EXPECT_LT(atlas.stats.stretch_max, 1.01);
  EXPECT_EQ(atlas.stats.overlapping_texels, 0u);
  EXPECT_EQ(atlas.stats.flipped_triangles, 0u);
  EXPECT_EQ(atlas.stats.padding_violations, 0u);
}

// A wall 2 m square with a lip folded square along its top edge, at 10 texels/m. A 1 cm lip is
// a tenth of a texel: it hinges onto the wall across the fold, one chart, unfolded without
// stretch. A 30 cm lip is three texels, which a texel can tell apart from the wall: the fold
// stays a seam, two charts.
// One grey mesh, unwrapped at 10 texels/m.
Atlas unwrap_at_ten_texels_a_metre(std::vector<Vec3> positions, std::vector<uint32_t> triangles) {
  Scene scene;
  const int m = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  test::add_mesh(scene, std::move(positions), std::move(triangles), m);
  AtlasOptions options;
  options.texel_density = 10;
  return test::unwrap(scene, options);
}

Atlas wall_with_lip(float lip) {
  return unwrap_at_ten_texels_a_metre({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {2, 2, lip}, {0, 2, lip}},
                                      {0, 1, 2, 0, 2, 3, 3, 2, 4, 3, 4, 5});
}

TEST(ChartPacking, APieceThinnerThanATexelHingesOntoItsNeighbourAcrossAFold) {
  const Atlas thin = wall_with_lip(0.01f);
  EXPECT_EQ(thin.chart_count, 1u);
  EXPECT_LT(thin.stats.stretch_max, 1.01);  // unfolded, not squeezed; 1% bounds float rounding
  EXPECT_EQ(thin.stats.overlapping_texels, 0u);
  EXPECT_EQ(thin.stats.flipped_triangles, 0u);
  const Atlas wide = wall_with_lip(0.3f);
  EXPECT_EQ(wide.chart_count, 2u);
}

// A floor 2 m square and, beside its far edge, a strip 1 m long and 20 cm wide: two texels at
// 10 texels/m, less than its padding is worth. The strip shares no vertex with the floor: it meets
// the floor's edge in the middle (a T-junction, as a level's brushes and a building's slabs meet).
// Touching, it joins the floor's chart, side by side as in the room; 1 cm apart, it does not
// touch and keeps its own chart.
Atlas floor_and_strip(float gap) {
  const float y = 2 + gap;
  return unwrap_at_ten_texels_a_metre(
      {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0.5f, y, 0}, {1.5f, y, 0}, {1.5f, y + 0.2f, 0}, {0.5f, y + 0.2f, 0}},
      {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7});
}

TEST(ChartPacking, APieceTouchingAChartWithoutSharingVerticesJoinsIt) {
  const Atlas touching = floor_and_strip(0);
  EXPECT_EQ(touching.chart_count, 1u);
  EXPECT_LT(touching.stats.stretch_max, 1.01);  // laid as it lies, not squeezed; 1% bounds float rounding
  EXPECT_EQ(touching.stats.overlapping_texels, 0u);
  EXPECT_EQ(touching.stats.flipped_triangles, 0u);
  // Where the strip's edge meets the floor's, their texels are one: the strip's corner (0.5, 2)
  // lies on the floor's edge from (0, 2) to (2, 2) in the page too, a quarter of the way along.
  const AtlasMesh& mesh = touching.meshes[0];
  auto page_uv = [&](uint32_t input_vertex) {
    for (size_t v = 0; v < mesh.source_vertex.size(); ++v)
      if (mesh.source_vertex[v] == input_vertex) return mesh.uvs[v];
    return Vec2{-1, -1};
  };
  const Vec2 from = page_uv(3), to = page_uv(2), corner = page_uv(4);
  const Vec2 expected = from + (to - from) * 0.25f;
  const float texel = 1.0f / float(touching.pages[0].width);
  EXPECT_NEAR(corner.x, expected.x, 0.01f * texel);  // a hundredth of a texel: float rounding
  EXPECT_NEAR(corner.y, expected.y, 0.01f * texel);
  EXPECT_EQ(floor_and_strip(0.01f).chart_count, 2u);
}

}  // namespace
}  // namespace radbake
