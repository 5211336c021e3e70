// Single- and double-sided materials as glTF's doubleSided says: a single-sided surface has a
// front only (it emits and reflects from its front, and light striking its back is absorbed); a
// double-sided one on an open surface has two faces with texels of their own (baker/surface/back_faces.h),
// so it emits from both and each face shows the light that reaches it. Both kinds block light
// from both sides.
#include <gtest/gtest.h>

#include "baker/surface/material_sampler.h"
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
  // Like the same lamp turned toward the floor: the same form factor whichever face (the lamp's
  // front or its back-face twin) looks at the floor, and the same floor texels and random numbers
  // (its chart, the largest, is packed first either way), so equal to round-off (measured: identical).
  EXPECT_NEAR(mean_both, mean_facing, 1e-4 * mean_facing);
  // The lamp's light leaves from both faces (the twin's texels emit too): twice its area's worth,
  // all accounted for.
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

// A 2 m grey panel in the sun, its front toward it, and 1 m behind it a 1 m white plate facing
// the panel's back, wholly in its shadow. The panel's front holds the sun's light; its back sees
// only the dark plate, so a double-sided panel's back shows nothing, and lights nothing: the back
// does not show the front's light. Yet the plate sees a face, not the inside of anything.
BakeResult panel_and_plate(bool double_sided) {
  Scene scene;
  int grey = test::add_material(scene, {0.8f, 0.8f, 0.8f}, {0, 0, 0}, 1, double_sided);
  int white = test::add_material(scene, {0.8f, 0.8f, 0.8f});
  test::add_quad(scene, {-1, -1, 0}, {0, 2, 0}, {2, 0, 0}, grey, "panel, front toward -z");
  test::add_quad(scene, {-0.5f, -0.5f, 1}, {0, 1, 0}, {1, 0, 0}, white, "plate 1 m behind, facing the panel");
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
bool on_panel_back(Vec3 p, Vec3 n) { return p.z < 0.01f && n.z > 0.9f; }
bool on_panel_front(Vec3 p, Vec3 n) { return p.z < 0.01f && n.z < -0.9f; }

TEST(DoubleSided, PanelBackShowsItsOwnLightNotTheFront) {
  const BakeResult both_faces = panel_and_plate(true), front_only = panel_and_plate(false);
  size_t front_count = 0, back_count = 0, plate_count = 0, plate_single_sided = 0;
  // The front reads the sun, 1000 lux, exactly: nothing else reaches it (the plate is behind).
  const Rgb front = test::mean_irradiance(both_faces, on_panel_front, &front_count);
  EXPECT_NEAR(front.x, 1000.0f, 1.0f);
  // The back and the plate see only each other, both unlit: zero, where a back showing the front's
  // texels (0.8 x 1000 lm/m2) would light the plate by about 190 lux.
  for (size_t i = 0; i < both_faces.elements.size(); ++i) {
    if (!both_faces.elements.valid(i)) continue;
    const Vec3 p = both_faces.elements.position[i], n = both_faces.elements.normal[i];
    if (!on_panel_back(p, n) && !on_plate(p, n)) continue;
    EXPECT_EQ(both_faces.irradiance[i].x, 0.0f);
    (on_plate(p, n) ? plate_count : back_count) += 1;
  }
  EXPECT_GT(front_count, 2000u);
  EXPECT_GT(back_count, 2000u);
  // The plate faces the back's own face, so its texels count as surfaces; facing a single-sided
  // back, most count as buried inside geometry (left to dilation).
  for (size_t i = 0; i < front_only.elements.size(); ++i)
    plate_single_sided += front_only.elements.valid(i) && on_plate(front_only.elements.position[i], {});
  EXPECT_GT(plate_count, 500u);
  EXPECT_LT(plate_single_sided, plate_count / 2);
  EXPECT_LT(std::fabs(both_faces.report.balance.relative_error), 0.005);
}

}  // namespace
}  // namespace radbake
