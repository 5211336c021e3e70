// No light may reach a space closed off from every lamp. Rays that strike a visible surface take
// the light of the element standing for the point they hit, even where its own sample lies across
// the surface's steps (element_for_hit looks past the steps of its own chart); a closed hollow
// box's inside and a room behind a closed door must stay black. Looking for the nearest lit
// element with no test of sight lit 5.3 m2 inside the FZK-Haus's closed cavities.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "baker/pipeline/bake.h"
#include "hard_cases/hard_case_checks.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

struct Case {
  const char* name;
  float shell;  // metres: the hollow box's wall, or the door leaf's thickness
  float texels_per_metre;
};

// The brightest valid texel that `inside` holds, lux, and how many it holds.
float brightest(const BakeResult& r, bool (*inside)(Vec3), size_t& count) {
  float most = 0;
  count = 0;
  for (size_t i = 0; i < r.elements.size(); ++i)
    if (r.elements.valid(i) && inside(r.elements.position[i])) {
      ++count;
      most = std::max({most, r.irradiance[i].x, r.irradiance[i].y, r.irradiance[i].z});
    }
  return most;
}

constexpr float kShellLow = 1.0f, kShellHigh = 2.0f;  // the hollow box's outside, metres
float g_inset = 0;                                    // its wall's thickness, for `in_the_hollow`
bool in_the_hollow(Vec3 p) {
  const float lo = kShellLow + g_inset * 0.5f, hi = kShellHigh - g_inset * 0.5f;
  return p.x > lo && p.x < hi && p.y > lo && p.y < hi && p.z > lo && p.z < hi;
}

class ClosedCavity : public ::testing::TestWithParam<Case> {};

// A 3 m room lit by a bulb, with a hollow box floating in it: a 1 m cube whose wall, thinner
// than a texel, has its outside facing the room and its inside facing the hollow.
TEST_P(ClosedCavity, AHollowBoxsInsideStaysBlack) {
  const Case c = GetParam();
  Scene scene;
  const int grey = test::add_material(scene, {0.8f, 0.8f, 0.8f});
  test::add_box(scene, {0, 0, 0}, {3, 3, 3}, true, grey, "room");
  test::add_box(scene, {kShellLow, kShellLow, kShellLow}, {kShellHigh, kShellHigh, kShellHigh}, false, grey, "outside");
  const float in_low = kShellLow + c.shell, in_high = kShellHigh - c.shell;
  test::add_box(scene, {in_low, in_low, in_low}, {in_high, in_high, in_high}, true, grey, "hollow");
  Light bulb;
  bulb.intensity = 100;
  bulb.position = {0.5f, 2.5f, 0.6f};
  scene.lights.push_back(bulb);
  test::Baked b = test::bake_scene(scene, {c.texels_per_metre, 512, 2}, {});
  test::expect_finite_and_non_negative(b.result);
  g_inset = c.shell;
  size_t inside = 0;
  const float most = brightest(b.result, in_the_hollow, inside);
  size_t lit = 0;
  const Rgb room = test::mean_irradiance(b.result, [](Vec3 p, Vec3) { return !in_the_hollow(p); }, &lit);
  RecordProperty("room_mean_lux", std::to_string(room.x));
  RecordProperty("hollow_brightest_lux", std::to_string(most));
  EXPECT_GT(inside, 100u);
  EXPECT_GT(room.x, 1.0f);
  EXPECT_EQ(most, 0.0f);  // not a photon: no path of light leads inside
}

// A 4.2 x 2 x 2 m room split in two by a 20 cm partition (x from 2 to 2.2) whose doorway (z from
// 0.6 to 1.4, up to 1.8 m) a closed door leaf fills, a slab thinner than a texel; a bulb lights the
// first half. The leaf's faces are made one chart, as the atlas makes a thin part's faces when it
// hinges its edges (the FZK-Haus's doors, tables and cabinets: 827 charts hold faces turned
// against each other): past its own chart's steps a hit on the dark face would see the lit face's
// samples through the leaf.
TEST_P(ClosedCavity, ARoomBehindAClosedDoorStaysBlack) {
  const Case c = GetParam();
  Scene scene;
  const int grey = test::add_material(scene, {0.8f, 0.8f, 0.8f});
  test::add_box(scene, {0, 0, 0}, {4.2f, 2, 2}, true, grey, "rooms");
  test::add_box(scene, {2.0f, 0, 0}, {2.2f, 2, 0.6f}, false, grey, "partition, near");
  test::add_box(scene, {2.0f, 0, 1.4f}, {2.2f, 2, 2}, false, grey, "partition, far");
  test::add_box(scene, {2.0f, 1.8f, 0.6f}, {2.2f, 2, 1.4f}, false, grey, "lintel");
  test::add_box(scene, {2.1f - c.shell * 0.5f, 0, 0.6f}, {2.1f + c.shell * 0.5f, 1.8f, 1.4f}, false, grey, "door leaf");
  Light bulb;
  bulb.intensity = 100;
  bulb.position = {1.0f, 1.5f, 1.0f};
  scene.lights.push_back(bulb);
  test::Baked b;
  b.atlas = test::unwrap(scene, {c.texels_per_metre, 512, 2});
  AtlasMesh& leaf = b.atlas.meshes.back();
  for (uint32_t& chart : leaf.triangle_chart) chart = leaf.triangle_chart[0];
  b.result = bake(scene, b.atlas, {});
  test::expect_finite_and_non_negative(b.result);
  size_t dark = 0;
  const float most = brightest(b.result, [](Vec3 p) { return p.x > 2.1f + 1e-3f; }, dark);  // the leaf's dark face and the reveals behind it too
  size_t lit = 0;
  const Rgb room = test::mean_irradiance(b.result, [](Vec3 p, Vec3) { return p.x < 2.0f; }, &lit);
  RecordProperty("lit_room_mean_lux", std::to_string(room.x));
  RecordProperty("dark_room_brightest_lux", std::to_string(most));
  EXPECT_GT(dark, 300u);
  EXPECT_GT(room.x, 1.0f);
  EXPECT_EQ(most, 0.0f);
}

INSTANTIATE_TEST_SUITE_P(Shells, ClosedCavity,
                         ::testing::Values(Case{"Shell1cm_8PerMetre", 0.01f, 8}, Case{"Shell3cm_8PerMetre", 0.03f, 8},
                                           Case{"Shell1cm_20PerMetre", 0.01f, 20}, Case{"Shell4cm_5PerMetre", 0.04f, 5.2f}),
                         [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace radbake
