// A chart that gets a single texel: a 1 cm square tile 0.5 m over a floor, at 4 cm texels. Its one
// element must carry the light at the tile (not the dilated gutter's, not a fraction for the part
// of the texel it does not cover), and so must its page texel and its four vertices.
#include <gtest/gtest.h>

#include "hard_cases/hard_case_checks.h"
#include "support/closed_forms.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

TEST(OneTexelChart, TinyTileCarriesTheLightAtItsPlace) {
  Scene scene;
  int black = test::add_material(scene, {0, 0, 0});
  test::add_quad(scene, {-1, 0, 1}, {2, 0, 0}, {0, 0, -2}, black, "floor");
  const Vec3 tile_centre{0.3f, 0.5f, -0.2f};
  test::add_quad(scene, tile_centre + Vec3{-0.005f, 0, 0.005f}, {0.01f, 0, 0}, {0, 0, -0.01f}, black, "1 cm tile");
  Light bulb;
  bulb.intensity = 20;
  bulb.position = {-0.2f, 1.3f, 0.1f};
  scene.lights.push_back(bulb);
  test::Baked b = test::bake_scene(scene, {24, 128, 2}, {});
  const BakeResult& r = b.result;
  test::expect_finite_and_non_negative(r);

  const double expected = test::point_light_lux(bulb.intensity, bulb.position, tile_centre, {0, 1, 0});
  const uint32_t tile = 1;  // instance
  size_t elements = 0;
  double worst = 0;
  for (size_t i = 0; i < r.elements.size(); ++i) {
    if (!r.elements.valid(i) || b.atlas.meshes[tile].page != int(r.elements.page[i]) ||
        length(r.elements.position[i] - tile_centre) > 0.01f)
      continue;
    ++elements;
    worst = std::max(worst, std::fabs(r.irradiance[i].x - expected) / expected);
    // The page texel holds the element's value, not a dilated neighbour's.
    EXPECT_EQ(r.pages[r.elements.page[i]].texels[r.elements.texel[i]].x, r.irradiance[i].x);
  }
  for (const Rgb& v : r.vertex_values[tile]) worst = std::max(worst, std::fabs(v.x - expected) / expected);
  RecordProperty("tile_elements", std::to_string(elements));
  RecordProperty("worst_relative_error", std::to_string(worst));
  EXPECT_EQ(elements, 1u);
  EXPECT_EQ(r.vertex_values[tile].size(), 4u);
  // 1%: the light changes by 0.1% across the tile, and a vertex takes the single texel's value.
  EXPECT_LT(worst, 0.01);
}

}  // namespace
}  // namespace radbake
