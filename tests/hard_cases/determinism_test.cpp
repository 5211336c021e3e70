// Determinism under the hardest settings: many patches, adaptive subdivision re-measuring rows
// between rounds, both form factor methods, coloured light and two kinds of source. Every random
// number is a hash of the seed and what it is for, and every parallel sum has a fixed order, so
// neither a second run nor another thread count may change a single bit.
#include <gtest/gtest.h>

#include <cstring>

#include "hard_cases/hard_case_checks.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

Scene coloured_room() {
  Scene scene = test::lit_room(0.7f, {1, 0.9f, 0.8f}, true);
  int red = test::add_material(scene, {0.7f, 0.15f, 0.1f});
  int lamp = test::add_material(scene, {0, 0, 0}, {0.8f, 0.9f, 1}, 400);
  scene.instances[1].material = red;  // the room's +x wall
  test::add_quad(scene, {1.2f, 1.999f, 1.2f}, {0, 0, 0.4f}, {0.4f, 0, 0}, lamp, "lamp");
  return scene;
}

bool same_bits(const BakeResult& a, const BakeResult& b) {
  if (a.pages.size() != b.pages.size() || a.vertex_values.size() != b.vertex_values.size()) return false;
  for (size_t p = 0; p < a.pages.size(); ++p)
    if (a.pages[p].texels.size() != b.pages[p].texels.size() ||
        std::memcmp(a.pages[p].texels.data(), b.pages[p].texels.data(), a.pages[p].texels.size() * sizeof(Rgb)))
      return false;
  for (size_t k = 0; k < a.vertex_values.size(); ++k)
    if (a.vertex_values[k].size() != b.vertex_values[k].size() ||
        std::memcmp(a.vertex_values[k].data(), b.vertex_values[k].data(), a.vertex_values[k].size() * sizeof(Rgb)))
      return false;
  return true;
}

class Determinism : public ::testing::TestWithParam<FormFactorMethod> {};

TEST_P(Determinism, SameSeedAndAnyThreadCountGiveTheSameBits) {
  const Scene scene = coloured_room();
  const Atlas atlas = test::unwrap(scene, {16.0f, 256, 2});
  BakeOptions options;
  options.form_factors.method = GetParam();
  options.form_factors.hemicube_resolution = 32;
  options.subdivision.tolerance = 0.3;
  options.subdivision.max_rounds = 2;
  options.threads = 2;
  BakeResult first = bake(scene, atlas, options), again = bake(scene, atlas, options);
  test::expect_finite_and_non_negative(first);
  ASSERT_GE(first.report.subdivision_rounds.size(), 2u);  // the rows really were re-measured
  EXPECT_TRUE(same_bits(first, again));
  options.threads = 1;
  EXPECT_TRUE(same_bits(first, bake(scene, atlas, options)));
  options.threads = 2;
  options.seed = 7;
  EXPECT_FALSE(same_bits(first, bake(scene, atlas, options)));  // the seed does drive the sampling
}

INSTANTIATE_TEST_SUITE_P(FormFactors, Determinism,
                         ::testing::Values(FormFactorMethod::RayCast, FormFactorMethod::Hemicube),
                         [](const ::testing::TestParamInfo<FormFactorMethod>& info) {
                           return info.param == FormFactorMethod::RayCast ? "RayCast" : "Hemicube";
                         });

}  // namespace
}  // namespace radbake
