// Single- and double-sided materials as glTF's doubleSided says: a single-sided surface has a
// front only (it emits and reflects from its front, and light striking its back is absorbed); a
// double-sided one shows the same lightmap texel on both faces, so it emits from both and its back
// sends out its texel's light as the front does. Both kinds block light from both sides.
#include <gtest/gtest.h>

#include "baker/material_sampler.h"
#include "hard_cases/hard_case_checks.h"
#include "support/closed_forms.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

constexpr float kLuminance = 1000;  // cd/m2

// A 1 m square lamp 1 m over a 4 m grey floor, its front facing up (away from the floor) or down.
// The floor sees nothing that reflects, so the lamp's closed form is its whole light; being grey,
// it keeps the interreflection solve (and with it the energy balance) in the plan.
BakeResult lamp_over_floor(bool double_sided, bool facing_the_floor) {
  Scene scene;
  int grey = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  int lamp = test::add_material(scene, {0, 0, 0}, {1, 1, 1}, kLuminance, double_sided);
  test::add_quad(scene, {-2, 0, 2}, {4, 0, 0}, {0, 0, -4}, grey, "floor");
  if (facing_the_floor) test::add_quad(scene, {-0.5f, 1, -0.5f}, {1, 0, 0}, {0, 0, 1}, lamp, "lamp facing down");
  else test::add_quad(scene, {-0.5f, 1, -0.5f}, {0, 0, 1}, {1, 0, 0}, lamp, "lamp facing up");
  test::Baked b = test::bake_scene(scene, {16, 128, 2}, {});
  test::expect_finite_and_non_negative(b.result);
  return std::move(b.result);
}

bool on_floor(Vec3 p, Vec3 n) { return n.y > 0.9f && p.y < 0.01f; }

TEST(DoubleSided, EmitterFacingAwayLightsTheFloorFromItsBack) {
  const BakeResult both_faces = lamp_over_floor(true, false), front_only = lamp_over_floor(false, false);
  const BakeResult facing = lamp_over_floor(false, true);
  auto closed_form = [](Vec3 x, Vec3) {
    return kExitancePerEmissiveUnit * kLuminance * test::point_to_rectangle(x.x, x.z, -0.5, 0.5, -0.5, 0.5, 1.0);
  };
  size_t count = 0;
  const double worst = test::worst_relative_error(both_faces, on_floor, closed_form, &count);
  const double mean_both = test::mean_irradiance(both_faces, on_floor).x;
  const double mean_facing = test::mean_irradiance(facing, on_floor).x;
  RecordProperty("worst_relative_error", std::to_string(worst));
  RecordProperty("mean_vs_facing_lamp", std::to_string(mean_both / mean_facing - 1));
  RecordProperty("energy_balance", std::to_string(both_faces.report.balance.relative_error));
  EXPECT_GT(count, 3000u);
  // 0.5%: the form factor is exact, averaged over 16 points of each 6 cm texel (see the tiny
  // emitter case); an emitter dark at the back is 100% off.
  EXPECT_LT(worst, 0.005);
  // Like the same lamp turned toward the floor: the same texels and random numbers, and the same
  // form factor whichever face looks at the floor, so equal to round-off (measured: identical).
  EXPECT_NEAR(mean_both, mean_facing, 1e-4 * mean_facing);
  // The lamp's light leaves from both faces: twice its area's worth, all accounted for.
  EXPECT_NEAR(both_faces.report.balance.emitted, 2 * kExitancePerEmissiveUnit * kLuminance * 1.0, 1.0);
  EXPECT_LT(std::fabs(both_faces.report.balance.relative_error), 0.005);

  // Single-sided, facing away: nothing reaches the floor.
  size_t dark = 0;
  for (size_t i = 0; i < front_only.elements.size(); ++i)
    if (front_only.elements.valid(i) && on_floor(front_only.elements.position[i], front_only.elements.normal[i])) {
      EXPECT_EQ(front_only.irradiance[i].x, 0.0f);
      ++dark;
    }
  EXPECT_GT(dark, 3000u);
}

// A 2 m grey panel in the sun, its front toward it, and 1 m behind it a 1 m black plate facing
// the panel's back, wholly in its shadow: the panel's texels hold B = rho E, and a double-sided
// panel shows them from its back too, which lights the plate by B times the form factor from the
// plate to the panel (Howell B-3, parallel rectangles); a single-sided one leaves it dark.
BakeResult panel_and_plate(bool double_sided) {
  Scene scene;
  int grey = test::add_material(scene, {0.8f, 0.8f, 0.8f}, {0, 0, 0}, 1, double_sided);
  int black = test::add_material(scene, {0, 0, 0});
  test::add_quad(scene, {-1, -1, 0}, {0, 2, 0}, {2, 0, 0}, grey, "panel, front toward -z");
  test::add_quad(scene, {-0.5f, -0.5f, 1}, {0, 1, 0}, {1, 0, 0}, black, "plate 1 m behind, facing the panel");
  Light sun;
  sun.type = LightType::Directional;
  sun.intensity = 1000;
  sun.direction = {0, 0, 1};
  scene.lights.push_back(sun);
  test::Baked b = test::bake_scene(scene, {24, 128, 2}, {});
  test::expect_finite_and_non_negative(b.result);
  return std::move(b.result);
}

bool on_plate(Vec3 p, Vec3) { return p.z > 0.99f; }

TEST(DoubleSided, PanelSeenFromBehindReflectsItsLight) {
  const BakeResult both_faces = panel_and_plate(true), front_only = panel_and_plate(false);
  const double radiosity = 0.8 * 1000;  // lm/m2 leaving the panel, front and back
  auto closed_form = [&](Vec3 x, Vec3) { return radiosity * test::point_to_rectangle(x.x, x.y, -1, 1, -1, 1, 1.0); };
  size_t count = 0;
  const double worst = test::worst_relative_error(both_faces, on_plate, closed_form, &count);
  const double mean = test::mean_irradiance(both_faces, on_plate).x;
  double expected_mean = 0, area = 0;
  for (size_t i = 0; i < both_faces.elements.size(); ++i)
    if (both_faces.elements.valid(i) && on_plate(both_faces.elements.position[i], {})) {
      expected_mean += closed_form(both_faces.elements.position[i], {}) * both_faces.elements.area[i];
      area += both_faces.elements.area[i];
    }
  expected_mean /= area;
  const EnergyBalance& balance = both_faces.report.balance;
  RecordProperty("worst_texel_error", std::to_string(worst));
  RecordProperty("mean_error", std::to_string(mean / expected_mean - 1));
  RecordProperty("energy_balance", std::to_string(balance.relative_error));
  EXPECT_GT(count, 500u);
  // Per texel 5%: 256 gather rays, cosine-distributed and stratified, estimate the panel's share
  // of each texel's hemisphere (about half of it) to 1-2%, 4% at worst of the 576. Their noise
  // averages out over the plate: the mean to 1%. A back face that swallows the light reads 0.
  EXPECT_LT(worst, 0.05);
  EXPECT_NEAR(mean, expected_mean, 0.01 * expected_mean);
  // The back's light is the front's texels shown again: a source of its own in the balance.
  EXPECT_NEAR(balance.back_faces, radiosity * 4, 0.01 * radiosity * 4);
  EXPECT_LT(std::fabs(balance.relative_error), 0.005);

  // Single-sided: the plate sees the panel's black back. Its texels facing mostly that back count
  // as buried (left to dilation); every one that is not, and its vertices, read nothing.
  size_t dark = 0;
  for (size_t i = 0; i < front_only.elements.size(); ++i)
    if (front_only.elements.valid(i) && on_plate(front_only.elements.position[i], {})) {
      EXPECT_EQ(front_only.irradiance[i].x, 0.0f);
      ++dark;
    }
  EXPECT_GT(dark, 50u);
  for (const Rgb& v : front_only.vertex_values[1]) EXPECT_EQ(v.x, 0.0f);
  EXPECT_EQ(front_only.report.balance.back_faces, 0.0);
}

}  // namespace
}  // namespace radbake
