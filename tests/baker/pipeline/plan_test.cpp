// Effect planning: each skip the plan makes is held to the full simulation of the same scene
// (the same bake with that one choice undone, or with simulate_everything), and each decision
// says why. bench/plan_bench measures what the skips save.
#include <gtest/gtest.h>

#include <cstring>

#include "baker/pipeline/bake.h"
#include "baker/pipeline/plan.h"
#include "base/errors.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

const AtlasOptions kAtlas{16.0f, 256, 2};

BakeResult bake_with(const Scene& scene, const EffectPlan& plan, BakeOptions options = {}) {
  return bake(scene, test::unwrap(scene, kAtlas), options, plan);
}

BakeResult bake_everything(const Scene& scene, BakeOptions options = {}) {
  options.plan.simulate_everything = true;
  return test::bake_scene(scene, kAtlas, options).result;
}

// Largest relative difference between two bakes' irradiance over valid elements, with values
// under `floor` lux compared against the floor (dark texels' noise is not relative error).
double worst_relative_difference(const BakeResult& a, const BakeResult& b, double floor = 1e-3) {
  EXPECT_EQ(a.elements.size(), b.elements.size());
  double worst = 0;
  for (size_t i = 0; i < a.elements.size() && i < b.elements.size(); ++i) {
    if (!a.elements.valid(i)) continue;
    for (int c = 0; c < 3; ++c) {
      double x = a.irradiance[i][c], y = b.irradiance[i][c];
      worst = std::max(worst, std::fabs(x - y) / std::max({std::fabs(x), std::fabs(y), floor}));
    }
  }
  return worst;
}

bool same_irradiance(const BakeResult& a, const BakeResult& b) {
  return a.irradiance.size() == b.irradiance.size() &&
         std::memcmp(a.irradiance.data(), b.irradiance.data(), a.irradiance.size() * sizeof(Rgb)) == 0;
}

const PlanDecision* decision(const std::vector<PlanDecision>& plan, const std::string& effect) {
  for (const PlanDecision& d : plan)
    if (d.effect == effect) return &d;
  return nullptr;
}

Scene lit_room(float reflectance = 0.6f, Rgb light_colour = {1, 1, 1}) { return test::lit_room(reflectance, light_colour, false); }
Scene room_with_block(float reflectance = 0.6f, Rgb light_colour = {1, 1, 1}) { return test::lit_room(reflectance, light_colour, true); }

TEST(Plan, NothingEmittingIsAnInputError) {
  Scene scene = lit_room();
  scene.lights.clear();
  try {
    plan_effects(scene);
    FAIL() << "planned a scene with no light";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("nothing in the scene emits light"), std::string::npos) << e.what();
  }
}

TEST(Plan, LightsThatReachNothingAreAnInputErrorWhenNothingElseLights) {
  Scene scene;
  test::add_quad(scene, {0, 0, 1}, {1, 0, 0}, {0, 0, -1}, test::add_material(scene, {0.5f, 0.5f, 0.5f}), "floor");
  Light below;  // under a floor that faces up
  below.position = {0.5f, -1, 0.5f};
  scene.lights.push_back(below);
  EXPECT_THROW(plan_effects(scene), InputError);
}

TEST(Plan, NoReflectanceSkipsInterreflectionAndMatchesTheFullSimulation) {
  Scene scene = room_with_block(0.0f);
  EffectPlan plan = plan_effects(scene);
  EXPECT_FALSE(plan.interreflection);
  ASSERT_NE(decision(plan.decisions, "interreflection"), nullptr);
  EXPECT_EQ(decision(plan.decisions, "interreflection")->choice, "skipped");
  BakeResult planned = bake_with(scene, plan), full = bake_everything(scene);
  // Black surfaces send nothing on: the full solve adds exactly zero to every texel.
  EXPECT_TRUE(same_irradiance(planned, full));
  EXPECT_EQ(planned.report.patches, 0u);
  EXPECT_FALSE(planned.report.balance.measured);
  RecordProperty("rays_planned", std::to_string(planned.report.rays));
  RecordProperty("rays_full", std::to_string(full.report.rays));
  // No form factor or gather rays at all, where the full simulation casts millions.
  EXPECT_EQ(planned.report.form_factor_rays.total(), 0u);
  EXPECT_EQ(planned.report.gather_rays.total(), 0u);
  EXPECT_GT(full.report.form_factor_rays.total() + full.report.gather_rays.total(), 1000000u);
  EXPECT_LT(planned.report.rays * 5, full.report.rays);
}

TEST(Plan, DirectOnlyIsTheFullBakesDirectLight) {
  Scene scene = room_with_block();
  BakeOptions options;
  options.keep_direct = true;
  BakeResult full = test::bake_scene(scene, kAtlas, options).result;
  options.plan.direct_only = true;
  BakeResult direct = test::bake_scene(scene, kAtlas, options).result;
  EXPECT_EQ(decision(direct.report.plan, "interreflection")->reason, "asked for direct light only");
  ASSERT_EQ(direct.irradiance.size(), full.direct.size());
  EXPECT_EQ(std::memcmp(direct.irradiance.data(), full.direct.data(), full.direct.size() * sizeof(Rgb)), 0);
}

TEST(Plan, GreyMaterialsUnderWhiteLightSolveOneChannelWithTheSameResult) {
  Scene scene = room_with_block();
  EffectPlan plan = plan_effects(scene);
  ASSERT_TRUE(plan.one_channel);
  EXPECT_EQ(plan.light_colour.y, 1.0f);
  EffectPlan three = plan;
  three.one_channel = false;
  BakeResult one_channel = bake_with(scene, plan), three_channels = bake_with(scene, three);
  // A grey solve in Rgb does the same float operations in each channel as the one-channel solve.
  EXPECT_TRUE(same_irradiance(one_channel, three_channels));
  EXPECT_EQ(one_channel.report.solver_iterations, three_channels.report.solver_iterations);
  EXPECT_EQ(one_channel.report.solved_channels, 1);
  EXPECT_EQ(three_channels.report.solved_channels, 3);
}

TEST(Plan, OneLightColourScalesTheOneChannelSolve) {
  const Rgb warm{1.0f, 0.8f, 0.55f};
  Scene scene = room_with_block(0.6f, warm);
  EffectPlan plan = plan_effects(scene);
  ASSERT_TRUE(plan.one_channel);
  EXPECT_FLOAT_EQ(plan.light_colour.z, 0.55f);
  EffectPlan three = plan;
  three.one_channel = false;
  BakeResult one_channel = bake_with(scene, plan), three_channels = bake_with(scene, three);
  EXPECT_EQ(one_channel.report.solved_channels, 1);
  // Scaling the solved channel by the colour instead of solving each: float rounding, a few ulps
  // (measured 3e-6).
  double worst = worst_relative_difference(one_channel, three_channels);
  RecordProperty("worst_relative_difference", std::to_string(worst));
  EXPECT_LT(worst, 1e-5);
}

TEST(Plan, ColouredMaterialsOrLightsOfTwoColoursSolveThreeChannels) {
  Scene coloured = room_with_block();
  coloured.materials[0].base_color = {0.6f, 0.5f, 0.5f};
  EXPECT_FALSE(plan_effects(coloured).one_channel);
  Scene two_colours = room_with_block();
  Light blue = two_colours.lights[0];
  blue.color = {0.5f, 0.5f, 1};
  two_colours.lights.push_back(blue);
  EffectPlan plan = plan_effects(two_colours);
  EXPECT_FALSE(plan.one_channel);
  EXPECT_EQ(decision(plan.decisions, "colour channels")->reason, "every material is grey, but the lights differ in colour");
}

TEST(Plan, UntexturedScenesReadEachMaterialOnceAndMatchTheBoxFilter) {
  Scene scene = room_with_block();
  test::add_quad(scene, {0.9f, 1.999f, 0.9f}, {0, 0, 0.3f}, {0.3f, 0, 0}, test::add_material(scene, {0, 0, 0}, {1, 1, 1}, 500),
                 "lamp");
  scene.instances[6].material = test::add_material(scene, {0.2f, 0.5f, 0.3f});  // one face of the block green
  EffectPlan plan = plan_effects(scene);
  EXPECT_FALSE(plan.texture_sampling);
  BakeResult planned = bake_with(scene, plan), full = bake_everything(scene);
  // Only texels holding two materials (the block's green face meets grey ones) are filtered.
  RecordProperty("filtered_texels_planned", std::to_string(planned.report.filtered_texels));
  EXPECT_LT(planned.report.filtered_texels * 20, planned.report.valid_elements);
  EXPECT_GE(full.report.filtered_texels, full.report.valid_elements);
  // The box filter averages 16 samples of the same constant: equal up to float rounding of that
  // mean (a few ulps), which the solve and the gather carry through unchanged in size.
  double worst = worst_relative_difference(planned, full);
  RecordProperty("worst_relative_difference", std::to_string(worst));
  EXPECT_LT(worst, 1e-5);
}

TEST(Plan, LightsThatCannotReachASurfaceAreCulledBeforeShadowRays) {
  Scene scene = test::floor_with_lights_out_of_reach();
  EffectPlan plan = plan_effects(scene);
  EXPECT_EQ(plan.light_traced, (std::vector<uint8_t>{1, 0, 0}));
  ASSERT_NE(decision(plan.decisions, "light #1"), nullptr);
  EXPECT_NE(decision(plan.decisions, "light #1")->reason.find("range of 1 m"), std::string::npos);
  EXPECT_NE(decision(plan.decisions, "light #2")->reason.find("cone"), std::string::npos);
  BakeResult planned = bake_with(scene, plan), full = bake_everything(scene);
  // The culled lights add exactly zero wherever the full simulation traces them.
  EXPECT_TRUE(same_irradiance(planned, full));
  RecordProperty("rays_planned", std::to_string(planned.report.rays));
  RecordProperty("rays_full", std::to_string(full.report.rays));
  EXPECT_LT(planned.report.rays, full.report.rays);
}

TEST(Plan, ConvexEnclosureSkipsShadowRaysAndMatchesTheTracedBake) {
  Scene scene = test::glowing_ceiling_room();
  EffectPlan plan = plan_effects(scene);
  EXPECT_FALSE(plan.shadow_rays);
  EffectPlan traced = plan;
  traced.shadow_rays = true;
  BakeResult skipped = bake_with(scene, plan), with_rays = bake_with(scene, traced);
  // Nothing can occlude anything: the traced bake differs only by float rounding where its rays
  // sum the same unoccluded values in another order (measured 2e-6).
  double worst = worst_relative_difference(skipped, with_rays);
  RecordProperty("worst_relative_difference", std::to_string(worst));
  EXPECT_LT(worst, 1e-4);
  RecordProperty("rays_skipped", std::to_string(skipped.report.rays));
  RecordProperty("rays_traced", std::to_string(with_rays.report.rays));
  EXPECT_LT(skipped.report.rays, with_rays.report.rays);
}

TEST(Plan, ShadowsAreTracedWhenSomethingCanHideOrALightIsOutside) {
  EXPECT_EQ(decision(plan_effects(room_with_block()).decisions, "shadows")->reason, "some surface can hide another");
  Scene outside = lit_room();
  outside.lights[0].position = {1, 3, 1};  // above the ceiling
  Light inside = outside.lights[0];
  inside.position = {1, 1, 1};
  outside.lights.push_back(inside);
  EffectPlan plan = plan_effects(outside);
  EXPECT_TRUE(plan.shadow_rays);
  EXPECT_EQ(decision(plan.decisions, "shadows")->reason, "light #0 is outside the enclosure");
}

TEST(Plan, InterreflectionStopsOnTheToleranceAndSaysAfterHowManyShots) {
  Scene scene = room_with_block();
  BakeResult converged = test::bake_scene(scene, kAtlas, {}).result;
  const PlanDecision& end = converged.report.plan.back();
  EXPECT_EQ(end.effect, "interreflection");
  EXPECT_EQ(end.choice, "stopped after " + std::to_string(converged.report.solver_iterations) + " shots");
  EXPECT_NE(end.reason.find("every patch's within the tolerance of 0.1%"), std::string::npos) << end.reason;
  BakeOptions guarded;
  guarded.solve.max_iterations = 5;
  BakeResult cut = test::bake_scene(scene, kAtlas, guarded).result;
  EXPECT_EQ(cut.report.plan.back().choice, "stopped after 5 shots by the iteration guard");
  EXPECT_FALSE(cut.report.converged);
}

TEST(Plan, MaterialFeaturesLeftOutAreNamedInAWarning) {
  Scene scene = room_with_block();
  scene.materials[0].name = "Glass";
  scene.materials[0].unsimulated = {"transmission (KHR_materials_transmission)"};
  scene.instances[6].material = test::add_material(scene, {0.9f, 0.7f, 0.3f});
  scene.materials.back().name = "Brass";
  scene.materials.back().metallic = 0.8f;
  EffectPlan plan = plan_effects(scene);
  ASSERT_EQ(plan.warnings.size(), 2u);
  EXPECT_EQ(plan.warnings[0].find("metallic reflection is not simulated ('Brass')"), 0u) << plan.warnings[0];
  EXPECT_EQ(plan.warnings[1].find("transmission (KHR_materials_transmission) is not simulated ('Glass')"), 0u)
      << plan.warnings[1];
  BakeResult r = test::bake_scene(scene, kAtlas, {}).result;
  EXPECT_EQ(r.report.warnings, plan.warnings);  // reported with the bake, not only planned
  EXPECT_TRUE(plan_effects(room_with_block()).warnings.empty());
}

}  // namespace
}  // namespace radbake
