// The sky as a light source (baker/direct/sky_light.h) against closed forms in the open.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "base/errors.h"
#include "io/gltf/gltf_loader.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

TEST(SkyLight, ASkyAloneLightsAScene) {
  // No lamp and no emitting material: with a sky, "nothing emits light" must not be an error.
  Scene scene;
  const int grey = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  test::add_quad(scene, {-1, 0, 1}, {2, 0, 0}, {0, 0, -2}, grey, "ground plate");
  BakeOptions options;
  options.sky.enabled = true;
  options.sky.distribution.model = SkyModel::Uniform;
  options.sky.zenith_luminance = 1000;
  options.sky.rays = 64;
  AtlasOptions atlas;
  atlas.texel_density = 4;
  const BakeResult r = test::bake_scene(scene, atlas, options).result;
  // A plate open to a uniform sky: E = pi L everywhere, exactly (no ray can be blocked).
  for (size_t i = 0; i < r.elements.size(); ++i)
    if (r.elements.valid(i) && r.elements.normal[i].y > 0.9f) {
      EXPECT_NEAR(sum(r.irradiance[i]) / 3, M_PI * 1000, 1e-2);  // float rounding of ~3142 lx
    }
}

// The largest relative error of the texels facing +Z (south) against `expected` lux.
double worst_error_facing_south(const BakeResult& r, double expected) {
  double worst = 0;
  for (size_t i = 0; i < r.elements.size(); ++i)
    if (r.elements.valid(i) && r.elements.normal[i].z > 0.9f)
      worst = std::max(worst, std::fabs(sum(r.irradiance[i]) / 3 / expected - 1));
  return worst;
}

TEST(SkyLight, AWallInTheOpenSeesHalfSkyHalfGround) {
  // A vertical plate under a uniform sky of luminance L over a ground of reflectance rho: the
  // upper half of its view is sky (pi L / 2), the lower half ground lit by the whole sky
  // (luminance rho L, so pi rho L / 2).
  Scene scene;
  const int grey = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  test::add_quad(scene, {-1, 0, 0}, {2, 0, 0}, {0, 2, 0}, grey, "wall");  // faces +Z
  BakeOptions options;
  options.sky.enabled = true;
  options.sky.distribution.model = SkyModel::Uniform;
  options.sky.zenith_luminance = 1000;
  options.sky.ground_reflectance = 0.3;
  options.sky.rays = 4096;
  AtlasOptions atlas;
  atlas.texel_density = 4;
  const BakeResult r = test::bake_scene(scene, atlas, options).result;
  const double expected = M_PI * 1000 * (1 + 0.3) / 2;
  const double worst = worst_error_facing_south(r, expected);
  RecordProperty("worst_relative_error", std::to_string(worst));
  // Measured 1e-6: the stratified rays split at the horizon exactly in half. 1% bounds the
  // split's noise for other seeds and densities.
  EXPECT_LT(worst, 0.01);
}

// The path tracer under a sky: the same closed forms, reached by paths that leave the scene and
// by the sun's shadow rays at every vertex, with none of the bake's sky machinery.
TEST(SkyLight, ThePathTracerSeesHalfSkyHalfGroundAndTheSun) {
  Scene scene;
  const int grey = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  test::add_quad(scene, {-1, 0, 0}, {2, 0, 0}, {0, 2, 0}, grey, "wall");  // faces +Z, south
  BakeOptions options;
  options.method = Method::PathTrace;
  options.path_trace.samples = 256;
  options.sky.enabled = true;
  options.sky.distribution.model = SkyModel::Uniform;
  options.sky.zenith_luminance = 1000;
  options.sky.ground_reflectance = 0.3;
  options.sky.sun_illuminance = 20000;
  options.sky.sun_zenith = 60 * M_PI / 180;
  options.sky.sun_azimuth = M_PI;  // due south: 30 degrees up in front of the wall
  AtlasOptions atlas;
  atlas.texel_density = 4;
  const BakeResult r = test::bake_scene(scene, atlas, options).result;
  // Sky and ground as before; the ground lit by the sun too (rho E_n cos 60 / pi); the sun on the
  // wall 30 degrees from its normal.
  const double expected = M_PI * 1000 * (1 + 0.3) / 2 + 0.3 * 20000 * 0.5 / 2 + 20000 * std::cos(M_PI / 6);
  const double worst = worst_error_facing_south(r, expected);
  RecordProperty("worst_relative_error", std::to_string(worst));
  // 1% bounds 256 paths' noise (stratified first directions; the sun by one ray per path).
  EXPECT_LT(worst, 0.01);
}

// A white room (rho 0.6) lit only through a 1 m roof opening under the CIE overcast sky, glazed
// or not: every wall's and the floor's light is the sky's, direct and interreflected. Radiosity and
// the path tracer share no light transport code: the bake's sky rays, patches, solve and gather
// against paths.
void expect_radiosity_to_agree_with_the_path_tracer_in_a_roof_lit_room(float glazing) {
  Scene scene;
  const int white = test::add_material(scene, {0.6f, 0.6f, 0.6f});
  test::add_box(scene, {0, 0, 0}, {4, 3, 4}, true, white, "room");
  // The ceiling, facing down, around a 1 m opening in its middle (the box's own is taken out).
  scene.instances.erase(std::remove_if(scene.instances.begin(), scene.instances.end(),
                                       [](const MeshInstance& m) { return m.name == "room+y"; }),
                        scene.instances.end());
  test::add_quad(scene, {0, 3, 0}, {1.5f, 0, 0}, {0, 0, 4}, white, "ceiling west");
  test::add_quad(scene, {2.5f, 3, 0}, {1.5f, 0, 0}, {0, 0, 4}, white, "ceiling east");
  test::add_quad(scene, {1.5f, 3, 0}, {1, 0, 0}, {0, 0, 1.5f}, white, "ceiling north");
  test::add_quad(scene, {1.5f, 3, 2.5f}, {1, 0, 0}, {0, 0, 1.5f}, white, "ceiling south");
  if (glazing > 0) {
    const int glass = test::add_material(scene, {0.9f, 0.9f, 0.9f});
    scene.materials[size_t(glass)].transmission = 1;
    scene.materials[size_t(glass)].visible_transmittance = glazing;
    test::add_quad(scene, {1.5f, 3, 1.5f}, {1, 0, 0}, {0, 0, 1}, glass, "roof light");  // facing down
  }
  AtlasOptions atlas;
  atlas.texel_density = 6;
  BakeOptions options;
  options.sky.enabled = true;
  options.sky.distribution.model = SkyModel::CieOvercast;
  options.sky.zenith_luminance = 1000;
  options.sky.ground_reflectance = 0;
  const BakeResult baked = test::bake_scene(scene, atlas, options).result;
  options.method = Method::PathTrace;
  options.path_trace.samples = 512;
  const BakeResult traced = test::bake_scene(scene, atlas, options).result;
  auto floor = [](Vec3 p, Vec3 n) { return n.y > 0.9f && p.y < 0.01f; };
  auto walls = [](Vec3, Vec3 n) { return std::fabs(n.y) < 0.1f; };
  auto ceiling = [](Vec3 p, Vec3 n) { return n.y < -0.9f && p.y > 2.99f; };
  for (const auto& [name, where] : {std::pair<const char*, std::function<bool(Vec3, Vec3)>>{"floor", floor},
                                    {"walls", walls}, {"ceiling", ceiling}}) {
    const double b = test::mean_irradiance(baked, where).x, t = test::mean_irradiance(traced, where).x;
    testing::Test::RecordProperty(std::string(name) + "_radiosity_over_path_traced", std::to_string(b / t));
    // 3% bounds the bake's error at its default preset and the path tracer's noise (512 paths a
    // texel, about 0.3% on these means).
    EXPECT_NEAR(b / t, 1, 0.03) << name << ": radiosity " << b << " lx, path traced " << t << " lx";
  }
  // And every lumen the sky brings in is absorbed or leaves again (0.5%: the solve's tolerance and
  // the rays' sampling of what escapes).
  testing::Test::RecordProperty("balance_relative_error", std::to_string(baked.report.balance.relative_error));
  EXPECT_NEAR(baked.report.balance.relative_error, 0, 0.005);
}

TEST(SkyLight, RadiosityAndThePathTracerAgreeOnDaylightInARoom) {
  expect_radiosity_to_agree_with_the_path_tracer_in_a_roof_lit_room(0);
}

// Glazing stops 30% of the light that meets it and passes the rest: reciprocity between the room's
// patches and the pane's holds for the share that stops (3% too dark before it was weighed so).
TEST(SkyLight, RadiosityAndThePathTracerAgreeOnDaylightThroughGlazing) {
  expect_radiosity_to_agree_with_the_path_tracer_in_a_roof_lit_room(0.7f);
}

SkyLight sun_only(double zenith_degrees, double normal_lux) {
  SkyLight sky;
  sky.enabled = true;
  sky.zenith_luminance = 0;  // no sky: the sun alone
  sky.ground_reflectance = 0;
  sky.rays = 1;
  sky.sun_zenith = zenith_degrees * M_PI / 180;
  sky.sun_illuminance = normal_lux;
  sky.sun_rays = 64;
  return sky;
}

// The classroom's floor under the CIE overcast sky, baked twice with different seeds: each texel's
// difference over sqrt(2) is one bake's noise, RMS over the floor relative to its mean. A heat map
// needs under 3% at the defaults. Cosine-distributed rays alone measured 11.2%; half
// of them aimed at the panes by their area, 5.3%; three quarters aimed into the windows' solid
// angles, each window chosen by what it could bring (sky_portals.h), 2.5%. Each bake states its
// texels' sky noise (report.json).
TEST(SkyLight, TheClassroomFloorsTexelsAreQuietEnoughForAHeatMapAtTheDefaultsAndSaySo) {
  Scene scene = load_gltf(test::source_path("samples/classroom/classroom.gltf")).scene;
  BakeOptions options;
  options.sky.enabled = true;
  options.sky.distribution.model = SkyModel::CieOvercast;
  options.sky.zenith_luminance = 1000;
  const BakeResult a = test::bake_scene(scene, AtlasOptions{}, options).result;
  options.seed = 2;
  const BakeResult b = test::bake_scene(scene, AtlasOptions{}, options).result;
  ASSERT_EQ(a.elements.size(), b.elements.size());
  double squares = 0, level = 0;
  size_t n = 0;
  for (size_t i = 0; i < a.elements.size(); ++i) {
    if (!a.elements.valid(i) || !(a.elements.normal[i].y > 0.9f) || !(a.elements.position[i].y < 0.01f)) continue;
    const double x = photopic(a.irradiance[i]), y = photopic(b.irradiance[i]);
    squares += (x - y) * (x - y) / 2;
    level += x;
    ++n;
  }
  ASSERT_GT(n, 5000u);
  level /= double(n);
  const double noise = std::sqrt(squares / double(n)) / level;
  RecordProperty("floor_noise_percent_of_mean", std::to_string(100 * noise));
  RecordProperty("stated_sky_noise_percent", std::to_string(100 * a.report.sky_noise));
  EXPECT_LT(noise, 0.03);
  // Stated from each texel's interleaved eighths, it overstates (measured 8.7% to the floor's 2.5%),
  // and must not understate.
  EXPECT_GT(a.report.sky_noise, noise);
}

TEST(SkyLight, TheSunOnAnOpenFloorGivesItsNormalIlluminanceTimesCosine) {
  Scene scene;
  const int grey = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  test::add_quad(scene, {-1, 0, 1}, {2, 0, 0}, {0, 0, -2}, grey, "floor");
  BakeOptions options;
  options.sky = sun_only(60, 100000);
  AtlasOptions atlas;
  atlas.texel_density = 4;
  const BakeResult r = test::bake_scene(scene, atlas, options).result;
  for (size_t i = 0; i < r.elements.size(); ++i)
    if (r.elements.valid(i) && r.elements.normal[i].y > 0.9f) {
      // 50,000 lx: the disc's points lie 0.27 degree either side of 60, their cosines averaging
      // to cos 60 within 1e-5; 0.1% bounds that and float sums.
      EXPECT_NEAR(sum(r.irradiance[i]) / 3 / 50000, 1.0, 1e-3);
    }
}

TEST(SkyLight, TheSunsDiscCastsASoftShadowEdge) {
  // The sun overhead; a plate 2 m up covers x < 0. On the floor below, the penumbra is
  // 2 m x tan(0.2665 degree) = 9.3 mm either side of x = 0: dark before, lit after, and
  // in between neither.
  Scene scene;
  const int grey = test::add_material(scene, {0, 0, 0});
  test::add_quad(scene, {-0.2f, 0, 0.05f}, {0.4f, 0, 0}, {0, 0, -0.1f}, grey, "floor");
  test::add_quad(scene, {-1, 2, 1}, {1, 0, 0}, {0, 0, -2}, grey, "overhang");
  BakeOptions options;
  options.sky = sun_only(0, 100000);
  AtlasOptions atlas;
  atlas.texel_density = 400;  // 2.5 mm texels
  const BakeResult r = test::bake_scene(scene, atlas, options).result;
  size_t shadowed = 0, lit = 0, penumbra = 0;
  for (size_t i = 0; i < r.elements.size(); ++i) {
    if (!r.elements.valid(i) || r.elements.position[i].y > 0.01f || r.elements.normal[i].y < 0.9f) continue;
    const double x = r.elements.position[i].x, fraction = sum(r.irradiance[i]) / 3 / 100000;
    if (x < -0.012) {  // beyond the penumbra and a texel
      EXPECT_LT(fraction, 0.01) << x;
      ++shadowed;
    }
    if (x > 0.012) {
      EXPECT_GT(fraction, 0.99) << x;
      ++lit;
    }
    if (std::fabs(x) < 0.004) {
      EXPECT_GT(fraction, 0.2) << x;  // a texel on the edge sees part of the disc, not none or all
      EXPECT_LT(fraction, 0.8) << x;
      ++penumbra;
    }
  }
  EXPECT_GT(shadowed, 100u);
  EXPECT_GT(lit, 100u);
  EXPECT_GT(penumbra, 10u);
}

}  // namespace
}  // namespace radbake
