// Reflectance 0.99 in closed rooms: light bounces hundreds of times before it is absorbed. A
// bounce cap, or a stopping rule that is not a tolerance on the unshot light, leaves such a room
// visibly dark (100 bounces would give 1 - 0.99^100 = 63% of the light); the closed forms below
// show any such bias at once.
#include <gtest/gtest.h>

#include <cmath>

#include "baker/surface/material_sampler.h"
#include "hard_cases/hard_case_checks.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

constexpr float kRho = 0.99f;

// Progressive shooting always shoots the patch with the most unshot power, U_max >= U / n, and
// at most rho of it comes back (a row of form factors sums to at most 1), so every shot removes at
// least (1 - rho) U / n: U_k <= U_0 exp(-k (1 - rho) / n). It stops once U_k <= tolerance * input,
// and U_0 = rho * input, so it needs at most n ln(rho / tolerance) / (1 - rho) shots (+1 for the
// last). These rooms take about half of that (the patch shot next holds about twice the mean):
// the bound holds only if the solver shoots the brightest patch first and stops at the tolerance.
size_t shooting_bound(size_t patches, double rho, double tolerance) {
  return size_t(std::ceil(double(patches) * std::log(rho / tolerance) / (1 - rho))) + 1;
}

TEST(HighReflectance, FurnaceConvergesToEmissionOverOneMinusReflectance) {
  Scene scene;
  const float luminance = 100;  // cd/m2: exitance pi * 100 lm/m2 from every face
  int m = test::add_material(scene, {kRho, kRho, kRho}, {1, 1, 1}, luminance);
  test::add_box(scene, {0, 0, 0}, {1, 1, 1}, true, m);
  BakeOptions options;
  test::Baked b = test::bake_scene(scene, {16.0f, 128, 2}, options);
  test::expect_finite_and_non_negative(b.result);
  // Every ray in the box sees radiosity M / (1 - rho), so every texel's irradiance is that too.
  const double expected = luminance * kExitancePerEmissiveUnit / (1.0 - kRho);
  const Elements& e = b.result.elements;
  double worst = 0;
  size_t checked = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i)) continue;
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::fabs(b.result.irradiance[i][c] / expected - 1));
    ++checked;
  }
  const BakeReport& report = b.result.report;
  RecordProperty("worst_relative_error", std::to_string(worst));
  RecordProperty("iterations", std::to_string(report.solver_iterations));
  RecordProperty("iteration_bound", std::to_string(shooting_bound(report.patches, kRho, options.solve.tolerance)));
  EXPECT_GT(checked, 1000u);
  EXPECT_TRUE(report.converged);
  // 1%: the tolerance leaves 0.1% of the input unshot, which is 0.001% of the 100-fold light in
  // the box, and the ambient term stands in for even that; the rest is float round-off over
  // the tens of thousands of shots. A capped or biased solve is off by tens of percent.
  EXPECT_LT(worst, 0.01);
  EXPECT_LE(report.solver_iterations, shooting_bound(report.patches, kRho, options.solve.tolerance));
}

// A point light in a closed room of uniform reflectance: every lumen it sends out (4 pi I) is
// absorbed at last, so (1 - rho) * sum(E A) = 4 pi I, and the area-weighted mean irradiance is
// 4 pi I / (A (1 - rho)), however unevenly the first bounce lands.
TEST(HighReflectance, LitRoomsMeanIrradianceIsTheLampsFluxOverAbsorption) {
  Scene scene;
  int m = test::add_material(scene, {kRho, kRho, kRho});
  test::add_box(scene, {0, 0, 0}, {2, 1.5f, 1}, true, m);
  Light bulb;
  bulb.intensity = 10;  // cd
  bulb.position = {0.6f, 1.1f, 0.4f};
  scene.lights.push_back(bulb);
  BakeOptions options;
  test::Baked b = test::bake_scene(scene, {12.0f, 128, 2}, options);
  test::expect_finite_and_non_negative(b.result);
  const double area = 2 * (2 * 1.5 + 2 * 1 + 1.5 * 1);
  const double expected = 4 * M_PI * bulb.intensity / (area * (1 - kRho));
  const Rgb mean = test::mean_irradiance(b.result, [](Vec3, Vec3) { return true; });
  const BakeReport& report = b.result.report;
  RecordProperty("mean_relative_error", std::to_string(mean.x / expected - 1));
  RecordProperty("iterations", std::to_string(report.solver_iterations));
  RecordProperty("iteration_bound", std::to_string(shooting_bound(report.patches, kRho, options.solve.tolerance)));
  EXPECT_TRUE(report.converged);
  // 1%: the direct light's texel quadrature (well under 0.1% at 1/12 m texels, the lamp 0.4 m
  // from the nearest wall) and the 0.1% unshot tolerance, which the ambient term covers.
  EXPECT_NEAR(mean.x, expected, 0.01 * expected);
  EXPECT_LE(report.solver_iterations, shooting_bound(report.patches, kRho, options.solve.tolerance));
}

}  // namespace
}  // namespace radbake
