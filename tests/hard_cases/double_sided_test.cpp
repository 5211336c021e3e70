// Single- and double-sided materials as glTF defines them. doubleSided false (the default): the
// back face is culled, so it neither emits nor reflects; light striking it is absorbed. true: both
// faces are drawn with the same lightmap texel, so both emit, and the back reflects the light that
// texel holds. Either kind blocks light from both sides.
#include <gtest/gtest.h>

#include <cmath>

#include "baker/material_sampler.h"
#include "hard_cases/hard_case_checks.h"
#include "support/closed_forms.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

const AtlasOptions kAtlas{24.0f, 256, 2};
constexpr float kLuminance = 1000;  // cd/m2

bool on_floor(Vec3 x, Vec3 n) { return n.y > 0.99f && std::fabs(x.y) < 1e-3f; }

// A 0.5 m lamp 1 m over a 3 m floor, its front facing down at the floor or up away from it.
BakeResult lamp_over_floor(bool facing_floor, bool double_sided) {
  Scene scene;
  int grey = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  int lamp = test::add_material(scene, {0, 0, 0}, {1, 1, 1}, kLuminance);
  scene.materials[size_t(lamp)].double_sided = double_sided;
  test::add_quad(scene, {-1.5f, 0, 1.5f}, {3, 0, 0}, {0, 0, -3}, grey, "floor");
  if (facing_floor) test::add_quad(scene, {0, 1, 0}, {0.5f, 0, 0}, {0, 0, 0.5f}, lamp, "lamp");
  else test::add_quad(scene, {0, 1, 0}, {0, 0, 0.5f}, {0.5f, 0, 0}, lamp, "lamp");
  BakeResult r = test::bake_scene(scene, kAtlas, {}).result;
  test::expect_finite_and_non_negative(r);
  return r;
}

TEST(DoubleSided, ADoubleSidedLampLightsFromItsBackAsFromItsFront) {
  BakeResult back = lamp_over_floor(false, true), front = lamp_over_floor(true, false);
  const Elements& e = back.elements;
  size_t checked = 0;
  double worst = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i) || !on_floor(e.position[i], e.normal[i])) continue;
    const Vec3 x = e.position[i];
    double expected = kExitancePerEmissiveUnit * kLuminance * test::point_to_rectangle(x.x, x.z, 0, 0.5, 0, 0.5, 1);
    worst = std::max(worst, std::fabs(back.irradiance[i].x - expected) / expected);
    ++checked;
  }
  RecordProperty("worst_relative_error", std::to_string(worst));
  EXPECT_GT(checked, 4000u);
  // A texel's value is the exact contour integral averaged over 16 points of its footprint; the
  // closed form is taken at its sample point, which on texels the floor's diagonal cuts sits off
  // the footprint's centre (measured 1.1% apart there, 0.1% elsewhere). 2% bounds that; a lamp
  // lighting only from its front would leave this floor at zero.
  EXPECT_LT(worst, 0.02);
  // Front and back are the same integrals over the same points: float rounding only.
  Rgb from_front = test::mean_irradiance(front, on_floor), from_back = test::mean_irradiance(back, on_floor);
  EXPECT_NEAR(from_back.x, from_front.x, 1e-4 * from_front.x);
}

TEST(DoubleSided, ASingleSidedLampFacingAwayLeavesTheFloorDark) {
  BakeResult r = lamp_over_floor(false, false);
  size_t checked = 0;
  Rgb floor = test::mean_irradiance(r, on_floor, &checked);
  EXPECT_GT(checked, 4000u);
  EXPECT_EQ(floor.x, 0.0f);
}

// A white 1 m panel 1 m over a black floor, its front facing up at a lamp above it. The floor
// under it is in its shadow and sees only its back.
BakeResult panel_over_floor(bool double_sided) {
  Scene scene;
  int black = test::add_material(scene, {0, 0, 0}), white = test::add_material(scene, {0.8f, 0.8f, 0.8f});
  scene.materials[size_t(white)].double_sided = double_sided;
  test::add_quad(scene, {-1.5f, 0, 1.5f}, {3, 0, 0}, {0, 0, -3}, black, "floor");
  test::add_quad(scene, {-0.5f, 1, 0.5f}, {1, 0, 0}, {0, 0, -1}, white, "panel");  // front faces up
  Light lamp;
  lamp.intensity = 200;
  lamp.position = {0, 2, 0};
  scene.lights.push_back(lamp);
  BakeResult r = test::bake_scene(scene, kAtlas, {}).result;
  test::expect_finite_and_non_negative(r);
  return r;
}

bool under_panel_centre(Vec3 x, Vec3 n) { return on_floor(x, n) && std::fabs(x.x) < 0.25f && std::fabs(x.z) < 0.25f; }

TEST(DoubleSided, ADoubleSidedPanelReflectsItsTexelsLightFromItsBack) {
  BakeResult single = panel_over_floor(false), both = panel_over_floor(true);
  size_t count = 0;
  EXPECT_EQ(test::mean_irradiance(single, under_panel_centre, &count).x, 0.0f);  // the back absorbs
  EXPECT_GT(count, 50u);
  // What the floor should get from the panel's back: the sum over the panel's texels of their
  // radiosity (reflectance times the irradiance baked on the front) times the texel-to-point form
  // factor cos cos A / (pi d^2), at each floor texel under the panel's centre.
  const Elements& e = both.elements;
  double expected = 0, area = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i) || !under_panel_centre(e.position[i], e.normal[i])) continue;
    double gathered = 0;
    for (size_t j = 0; j < e.size(); ++j) {
      if (!e.valid(j) || std::fabs(e.position[j].y - 1) > 1e-3f) continue;
      Vec3 d = e.position[j] - e.position[i];
      double d2 = dot(d, d), cosine = d.y / std::sqrt(d2);
      gathered += 0.8 * both.irradiance[j].x * cosine * cosine * e.area[j] / (M_PI * d2);
    }
    expected += gathered * e.area[i];
    area += e.area[i];
  }
  expected /= area;
  double baked = test::mean_irradiance(both, under_panel_centre).x;
  RecordProperty("expected_lux", std::to_string(expected));
  RecordProperty("baked_lux", std::to_string(baked));
  EXPECT_GT(expected, 10.0);
  // 5% bounds the final gather's noise over this patch of floor and the patch-level radiosity the
  // gather reads (a patch's mean rather than each texel's).
  EXPECT_NEAR(baked, expected, 0.05 * expected);
}

}  // namespace
}  // namespace radbake
