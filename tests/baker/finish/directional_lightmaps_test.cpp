// Directional lightmaps (baker/finish/directional_lightmaps.h): the L1 pages reconstruct the
// irradiance for normals other than the surface's, from the same bake.
#include <gtest/gtest.h>

#include <cmath>

#include "baker/finish/directional_lightmaps.h"
#include "io/gltf/gltf_loader.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

// The SH coefficients the pages hold at element i's texel.
IrradianceSh sh_at(const BakeResult& r, size_t i) {
  const size_t page = r.elements.page[i], texel = r.elements.texel[i];
  return {r.directional[0][page].texels[texel], r.directional[1][page].texels[texel],
          r.directional[2][page].texels[texel], r.directional[3][page].texels[texel]};
}

// Normals over the floor's upper hemisphere (+Y), stratified, out to 85 degrees from it.
std::vector<Vec3> upper_normals() {
  std::vector<Vec3> out;
  for (int a = 0; a <= 17; ++a)
    for (int b = 0; b < 24; ++b) {
      const float tilt = float(a) * 5 * float(M_PI) / 180, turn = float(b) * 15 * float(M_PI) / 180;
      out.push_back({std::sin(tilt) * std::cos(turn), std::cos(tilt), std::sin(tilt) * std::sin(turn)});
    }
  return out;
}

Scene floor_under(const Light& light) {
  Scene scene;
  test::add_quad(scene, {-1, 0, 1}, {2, 0, 0}, {0, 0, -2}, test::add_material(scene, {0.5f, 0.5f, 0.5f}), "floor");
  scene.lights.push_back(light);
  return scene;
}

TEST(DirectionalLightmaps, OneDirectionalLightIsReconstructedForEveryNormalOfTheHemisphere) {
  // 1000 lx on a plane facing the light, arriving 50 degrees from the zenith.
  Light sun;
  sun.type = LightType::Directional;
  sun.intensity = 1000;
  const Vec3 toward = normalize(Vec3{std::sin(0.8727f) * 0.6f, std::cos(0.8727f), std::sin(0.8727f) * 0.8f});
  sun.direction = -toward;
  BakeOptions options;
  options.directional = Directional::SphericalHarmonics;
  AtlasOptions atlas;
  atlas.texel_density = 8;
  const BakeResult r = test::bake_scene(floor_under(sun), atlas, options).result;
  ASSERT_EQ(r.directional.size(), 4u);
  size_t checked = 0;
  double worst = 0;
  for (size_t i = 0; i < r.elements.size(); ++i) {
    if (!r.elements.valid(i)) continue;
    const IrradianceSh sh = sh_at(r, i);
    for (Vec3 n : upper_normals()) {
      // Closed form: E_perp max(0, n . d). Light from one direction is what the fit reproduces
      // exactly; the 2% of E_perp bounds float rounding of the four coefficients.
      const double expected = 1000.0 * std::max(0.0f, dot(n, toward));
      const double error = std::fabs(double(sh.at(n).y) - expected) / 1000.0;
      worst = std::max(worst, error);
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000u);
  EXPECT_LT(worst, 0.02);

  // The dominant direction is the light's.
  options.directional = Directional::Dominant;
  const BakeResult d = test::bake_scene(floor_under(sun), atlas, options).result;
  ASSERT_EQ(d.directional.size(), 1u);
  for (size_t i = 0; i < d.elements.size(); ++i)
    if (d.elements.valid(i)) {
      const Vec3 dir = d.directional[0][d.elements.page[i]].texels[d.elements.texel[i]];
      EXPECT_GT(dot(dir, toward), std::cos(0.5 * M_PI / 180));  // within half a degree, length 1
    }
}

TEST(DirectionalLightmaps, AnEvenSkyGivesHalfTheLightToANormalLyingOnTheFloor) {
  // A uniform sky over an open floor: for a normal tilted by t from the floor's, the light of
  // the floor's hemisphere is E (1 + cos t) / 2 (the fit's other exact case). The 3% bounds the
  // sky rays' noise in how directional the light looks (256 rays per texel).
  Scene scene;
  test::add_quad(scene, {-1, 0, 1}, {2, 0, 0}, {0, 0, -2}, test::add_material(scene, {0.5f, 0.5f, 0.5f}), "floor");
  BakeOptions options;
  options.directional = Directional::SphericalHarmonics;
  options.sky.enabled = true;
  options.sky.distribution.model = SkyModel::Uniform;
  options.sky.zenith_luminance = 1000;
  AtlasOptions atlas;
  atlas.texel_density = 4;
  const BakeResult r = test::bake_scene(scene, atlas, options).result;
  for (size_t i = 0; i < r.elements.size(); ++i) {
    if (!r.elements.valid(i)) continue;
    const IrradianceSh sh = sh_at(r, i);
    const double e = M_PI * 1000;
    for (float tilt : {0.0f, 0.5f, 1.0f, 1.5f}) {
      const Vec3 n{std::sin(tilt), std::cos(tilt), 0};
      EXPECT_NEAR(sh.at(n).y, e * (1 + std::cos(tilt)) / 2, 0.03 * e) << "tilt " << tilt;
    }
  }
}

TEST(DirectionalLightmaps, TheCornellBoxPagesGiveBackTheIrradianceAtTheSurfaceNormal) {
  LoadedScene loaded = load_gltf(test::source_path("samples/cornell_box/cornell_box.gltf"));
  BakeOptions options;
  options.directional = Directional::SphericalHarmonics;
  AtlasOptions atlas;
  atlas.max_page_size = 128;
  const test::Baked b = test::bake_scene(loaded.scene, atlas, options);
  const BakeResult& r = b.result;
  double mean = 0;
  size_t valid = 0;
  for (size_t i = 0; i < r.elements.size(); ++i)
    if (r.elements.valid(i)) mean += sum(r.irradiance[i]) / 3, ++valid;
  mean /= double(valid);
  size_t checked = 0;
  for (size_t i = 0; i < r.elements.size(); ++i) {
    if (!r.elements.valid(i) || sum(r.irradiance[i]) / 3 < 0.01 * mean) continue;
    const Rgb page = r.pages[r.elements.page[i]].texels[r.elements.texel[i]];
    const Rgb again = sh_at(r, i).at(r.elements.normal[i]);
    // Within 1% of the plain page, per channel (the fit makes them equal up to float rounding).
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(again[c], page[c], 0.01 * page[c] + 1e-3) << "element " << i;
    ++checked;
  }
  EXPECT_GT(checked, 1000u);
}

}  // namespace
}  // namespace radbake
