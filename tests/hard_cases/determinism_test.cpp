// Determinism on a hard bake: many small patches, adaptive subdivision (rows carried between
// rounds), a double-sided card (a back-face twin, reached through its front by the ray tracer),
// by ray casting and by hemicubes. The same seed must give bit-identical lightmap pages, and so
// must one thread and two: every random number is a hash of the seed and what it is for, and no
// sum depends on how the work is split.
#include <gtest/gtest.h>

#include "baker/pipeline/bake.h"
#include "baker/surface/back_faces.h"
#include "hard_cases/hard_case_checks.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

Scene cluttered_room() {
  Scene scene;
  int white = test::add_material(scene, {0.75f, 0.75f, 0.75f});
  int red = test::add_material(scene, {0.7f, 0.15f, 0.1f});
  int card = test::add_material(scene, {0.6f, 0.6f, 0.8f}, {0, 0, 0}, 1, true);
  int lamp = test::add_material(scene, {0, 0, 0}, {1, 1, 1}, 2000);
  test::add_box(scene, {0, 0, 0}, {2, 1.5f, 2}, true, white, "room");
  test::add_box(scene, {0.3f, 0, 0.3f}, {0.8f, 0.6f, 0.7f}, false, red, "block");
  test::add_box(scene, {1.2f, 0, 1.1f}, {1.6f, 1.0f, 1.5f}, false, white, "tall block");
  test::add_quad(scene, {1.0f, 0.2f, 0.2f}, {0.6f, 0, 0}, {0, 0.6f, 0.3f}, card, "double-sided card");
  test::add_quad(scene, {0.8f, 1.49f, 0.8f}, {0.4f, 0, 0}, {0, 0, 0.4f}, lamp, "lamp");
  Light bulb;
  bulb.intensity = 15;
  bulb.position = {0.5f, 1.2f, 1.5f};
  scene.lights.push_back(bulb);
  return scene;
}

class Determinism : public ::testing::TestWithParam<FormFactorMethod> {};

TEST_P(Determinism, SameSeedAndAnyThreadCountGiveBitIdenticalPages) {
  Scene scene = cluttered_room();
  add_back_faces(scene);
  const Atlas atlas = test::unwrap(scene, {12, 128, 2});
  BakeOptions options;
  options.patches.block_size = 2;
  options.subdivision.tolerance = 0.2;
  options.form_factors.method = GetParam();
  // Few rays: this case is about which numbers come out, not how good they are.
  options.form_factors.rays_per_patch = 256;
  options.form_factors.hemicube_resolution = 16;
  options.gather.rays = 32;
  options.threads = 2;
  const BakeResult first = bake(scene, atlas, options);
  test::expect_finite_and_non_negative(first);
  RecordProperty("patches", std::to_string(first.report.patches));
  RecordProperty("subdivision_rounds", std::to_string(first.report.subdivision_rounds.size()));
  ASSERT_GT(first.report.subdivision_rounds.size(), 1u);  // rows really were carried
  ASSERT_GT(first.report.patches, 500u);

  EXPECT_TRUE(test::same_pages(first.pages, bake(scene, atlas, options).pages)) << "same seed, two threads, again";
  BakeOptions one_thread = options;
  one_thread.threads = 1;
  EXPECT_TRUE(test::same_pages(first.pages, bake(scene, atlas, one_thread).pages)) << "one thread";
  BakeOptions other_seed = options;
  other_seed.seed = 2;
  EXPECT_FALSE(test::same_pages(first.pages, bake(scene, atlas, other_seed).pages)) << "the seed drives the sampling";
}

INSTANTIATE_TEST_SUITE_P(FormFactors, Determinism, ::testing::Values(FormFactorMethod::RayCast, FormFactorMethod::Hemicube),
                         [](const ::testing::TestParamInfo<FormFactorMethod>& info) {
                           return info.param == FormFactorMethod::RayCast ? "RayCast" : "Hemicube";
                         });

}  // namespace
}  // namespace radbake
