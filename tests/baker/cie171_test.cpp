// CIE 171:2006, "Test cases to assess the accuracy of lighting computer programs": the cases
// radbake's light sources already cover, each against the report's closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "support/closed_forms.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

Light point_light(Vec3 position, float candela) {
  Light bulb;
  bulb.type = LightType::Point;
  bulb.intensity = candela;
  bulb.position = position;
  return bulb;
}

// 5.2: a point source over a floor. Direct illuminance E = I cos(theta) / d^2 at every point of a
// black floor (the report's table is this formula at chosen points; here every texel's sample
// point is checked). A 1000 cd source 3 m over a 10 m x 10 m floor.
TEST(Cie171, Case5_2PointSourceOverAFloor) {
  Scene scene;
  const int black = test::add_material(scene, {0, 0, 0});
  test::add_quad(scene, {-5, 0, 5}, {10, 0, 0}, {0, 0, -10}, black, "floor");
  const Vec3 source{0, 3, 0};
  scene.lights.push_back(point_light(source, 1000));
  AtlasOptions atlas;
  atlas.texel_density = 4;  // 25 cm texels, 1,600 of them
  const BakeResult r = test::bake_scene(scene, atlas, BakeOptions{}).result;
  const Elements& e = r.elements;
  size_t checked = 0;
  double worst = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i)) continue;
    const double exact = test::point_light_lux(1000, source, e.position[i], e.normal[i]);
    // Each texel is the mean over its footprint, the formula is at its sample point: the
    // difference is the field's curvature over 25 cm, 1.4% at worst (measured), right under the
    // source; CIE 171 asks 5% pointwise.
    worst = std::max(worst, std::fabs(sum(r.irradiance[i]) / 3 / exact - 1));
    ++checked;
  }
  RecordProperty("worst_relative_error", std::to_string(worst));
  EXPECT_GT(checked, 1000u);
  EXPECT_LT(worst, 0.05);
}

// 5.8: interreflections in a closed cube. A source of flux Phi inside a room of surface S and
// uniform reflectance rho: every lumen is reflected rho, rho^2, ... times before it is absorbed,
// so the mean indirect illuminance is rho Phi / (S (1 - rho)), whatever the source's position.
class Cie171Cube : public ::testing::TestWithParam<float> {};

TEST_P(Cie171Cube, Case5_8MeanIndirectIlluminanceIsRhoPhiOverSOneMinusRho) {
  const float rho = GetParam();
  Scene scene;
  const int walls = test::add_material(scene, {rho, rho, rho});
  test::add_box(scene, {0, 0, 0}, {4, 4, 4}, true, walls, "cube");
  const float candela = 1000;
  scene.lights.push_back(point_light({1.3f, 2.9f, 2.2f}, candela));  // off centre, on purpose
  BakeOptions options;
  options.keep_direct = true;
  options.solve.tolerance = 1e-4;
  const BakeResult r = test::bake_scene(scene, AtlasOptions{}, options).result;
  const Elements& e = r.elements;
  double indirect = 0, area = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i)) continue;
    indirect += (sum(r.irradiance[i]) - sum(r.direct[i])) / 3 * e.area[i];
    area += e.area[i];
  }
  const double phi = 4 * M_PI * candela, surface = 6 * 4.0 * 4.0;
  const double expected = rho * phi / (surface * (1 - rho));
  RecordProperty("mean_indirect_lux", std::to_string(indirect / area));
  RecordProperty("expected_lux", std::to_string(expected));
  EXPECT_NEAR(area, surface, 1e-3 * surface);
  // Measured -0.005%, -0.008% and -0.019% for rho 0.5, 0.9, 0.95. 1% bounds the solve's
  // stopping point (0.01% of the light unshot, spread by its ambient term) and the form factors'
  // sampling, which reciprocity keeps conservative.
  EXPECT_NEAR(indirect / area / expected, 1.0, 0.01);
}

INSTANTIATE_TEST_SUITE_P(Reflectances, Cie171Cube, ::testing::Values(0.5f, 0.9f, 0.95f),
                         [](const auto& info) { return "rho_" + std::to_string(int(std::lround(info.param * 100))); });

// 5.9: the sky component through a roof opening. A black 4 m x 4 m x 3 m room with a 1 m square
// opening in the middle of its roof, under a uniform sky of luminance L: at a floor point the
// sky component, E / (pi L), is the view factor to the opening (Howell B-3 in closed form).
TEST(Cie171, Case5_9SkyComponentThroughARoofOpeningIsTheViewFactor) {
  Scene scene;
  const int black = test::add_material(scene, {0, 0, 0});
  test::add_quad(scene, {0, 0, 4}, {4, 0, 0}, {0, 0, -4}, black, "floor");
  test::add_quad(scene, {0, 0, 0}, {4, 0, 0}, {0, 3, 0}, black, "south wall");
  test::add_quad(scene, {4, 0, 4}, {-4, 0, 0}, {0, 3, 0}, black, "north wall");
  test::add_quad(scene, {0, 0, 4}, {0, 0, -4}, {0, 3, 0}, black, "west wall");
  test::add_quad(scene, {4, 0, 0}, {0, 0, 4}, {0, 3, 0}, black, "east wall");
  // The roof, facing down, around the opening [1.5, 2.5] x [1.5, 2.5].
  test::add_quad(scene, {0, 3, 0}, {4, 0, 0}, {0, 0, 1.5f}, black, "roof");
  test::add_quad(scene, {0, 3, 2.5f}, {4, 0, 0}, {0, 0, 1.5f}, black, "roof");
  test::add_quad(scene, {0, 3, 1.5f}, {1.5f, 0, 0}, {0, 0, 1}, black, "roof");
  test::add_quad(scene, {2.5f, 3, 1.5f}, {1.5f, 0, 0}, {0, 0, 1}, black, "roof");
  BakeOptions options;
  options.sky.enabled = true;
  options.sky.distribution.model = SkyModel::Uniform;
  options.sky.zenith_luminance = 1000;  // cd/m2
  // 0.3% (corners) to 3% (centre) of a floor texel's cosine-weighted rays reach the opening:
  // 131,072 of them keep a corner texel's noise near 1.5%.
  options.sky.rays = 131072;
  AtlasOptions atlas;
  atlas.texel_density = 3;  // 33 cm texels
  const BakeResult r = test::bake_scene(scene, atlas, options).result;
  const Elements& e = r.elements;
  size_t checked = 0;
  double worst = 0, mean_error = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i) || e.normal[i].y < 0.9f || e.position[i].y > 0.01f) continue;  // floor texels
    const Vec3 p = e.position[i];
    const double view_factor = test::point_to_rectangle(p.x, p.z, 1.5, 2.5, 1.5, 2.5, 3.0);
    const double sky_component = sum(r.irradiance[i]) / 3 / (M_PI * 1000);
    worst = std::max(worst, std::fabs(sky_component / view_factor - 1));
    mean_error += sky_component / view_factor - 1;
    ++checked;
  }
  mean_error /= double(checked);
  RecordProperty("worst_relative_error", std::to_string(worst));
  RecordProperty("mean_relative_error", std::to_string(mean_error));
  EXPECT_GT(checked, 100u);
  // CIE 171's 5% pointwise; the mean within 0.5% bounds the bias (the noise averages out).
  // Measured: 2.4% at worst, -0.02% on average over the 144 floor texels.
  EXPECT_LT(worst, 0.05);
  EXPECT_LT(std::fabs(mean_error), 0.005);
}

}  // namespace
}  // namespace radbake
