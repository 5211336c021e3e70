// The furnace: a closed box whose every face emits exitance M with reflectance rho has radiosity
// B = M / (1 - rho) everywhere. Checks the direct light, the patch transport, each solver and the
// final gather together, with no noise to hide behind: every ray sees the same radiosity.
#include <gtest/gtest.h>

#include "baker/surface/material_sampler.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

struct Case {
  float reflectance;
  Solver solver;
};

class Furnace : public ::testing::TestWithParam<Case> {};

TEST_P(Furnace, RadiosityIsEmissionOverOneMinusReflectanceEverywhere) {
  const Case c = GetParam();
  Scene scene;
  const float luminance = 100;  // cd/m2: exitance pi * 100 lm/m2
  int m = test::add_material(scene, {c.reflectance, c.reflectance, c.reflectance}, {1, 1, 1}, luminance);
  test::add_box(scene, {0, 0, 0}, {1, 1, 1}, true, m);
  BakeOptions options;
  options.solve.solver = c.solver;
  options.store = StoredQuantity::Radiosity;
  test::Baked b = test::bake_scene(scene, {24.0f, 256, 2}, options);
  const float exitance = luminance * kExitancePerEmissiveUnit;
  const double expected = exitance / (1.0 - c.reflectance);
  const Elements& e = b.result.elements;
  size_t checked = 0;
  double worst = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i)) continue;
    Rgb radiosity = e.emission[i] + e.reflectance[i] * b.result.irradiance[i];
    for (int ch = 0; ch < 3; ++ch) worst = std::max(worst, std::fabs(radiosity[ch] / expected - 1.0));
    ++checked;
  }
  RecordProperty("worst_relative_error", std::to_string(worst));
  RecordProperty("iterations", std::to_string(b.result.report.solver_iterations));
  EXPECT_GT(checked, 3000u);
  EXPECT_TRUE(b.result.report.converged);
  // 1% bounds everything at once: the default tolerance (0.1% unshot) and ray-count noise.
  EXPECT_LT(worst, 0.01);
}

const Case kCases[] = {{0.5f, Solver::Shooting},    {0.9f, Solver::Shooting}, {0.5f, Solver::GaussSeidel},
                       {0.9f, Solver::GaussSeidel}, {0.5f, Solver::Jacobi},   {0.9f, Solver::Jacobi}};

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  const char* names[] = {"Shooting", "GaussSeidel", "Jacobi"};
  return std::string(names[int(info.param.solver)]) + "_rho" + std::to_string(int(info.param.reflectance * 100));
}

INSTANTIATE_TEST_SUITE_P(ReflectanceAndSolver, Furnace, ::testing::ValuesIn(kCases), case_name);

}  // namespace
}  // namespace radbake
