// The bake as a whole: determinism, thread counts, cancellation, solver agreement, stored quantity.
#include <gtest/gtest.h>

#include "baker/pipeline/bake.h"
#include "base/errors.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

// A small lit room with a coloured block: enough to exercise every stage quickly.
Scene small_room() {
  Scene scene;
  int white = test::add_material(scene, {0.75f, 0.75f, 0.75f});
  int red = test::add_material(scene, {0.7f, 0.1f, 0.1f});
  int lamp = test::add_material(scene, {0, 0, 0}, {1, 1, 1}, 3000);
  test::add_box(scene, {0, 0, 0}, {2, 2, 2}, true, white, "room");
  test::add_box(scene, {0.4f, 0, 0.4f}, {0.9f, 0.7f, 0.9f}, false, red, "block");
  test::add_quad(scene, {0.8f, 1.999f, 0.8f}, {0, 0, 0.4f}, {0.4f, 0, 0}, lamp, "lamp");
  Light bulb;
  bulb.intensity = 20;
  bulb.position = {1.5f, 1.2f, 1.5f};
  scene.lights.push_back(bulb);
  return scene;
}

const AtlasOptions kAtlas{24.0f, 256, 2};

TEST(Pipeline, SameSeedGivesBitIdenticalLightmaps) {
  BakeResult a = test::bake_scene(small_room(), kAtlas, {}).result;
  BakeResult b = test::bake_scene(small_room(), kAtlas, {}).result;
  EXPECT_TRUE(test::same_pages(a.pages, b.pages));
  BakeOptions other_seed;
  other_seed.seed = 2;
  BakeResult c = test::bake_scene(small_room(), kAtlas, other_seed).result;
  EXPECT_FALSE(test::same_pages(a.pages, c.pages));  // the seed really drives the sampling
}

TEST(Pipeline, ThreadCountDoesNotChangeTheResult) {
  BakeOptions one, two;
  one.threads = 1;
  two.threads = 2;
  BakeResult a = test::bake_scene(small_room(), kAtlas, one).result;
  BakeResult b = test::bake_scene(small_room(), kAtlas, two).result;
  EXPECT_TRUE(test::same_pages(a.pages, b.pages));
}

TEST(Pipeline, ProgressCanCancelTheBake) {
  Scene scene = small_room();
  Atlas atlas = test::unwrap(scene, kAtlas);
  std::vector<std::string> stages;
  auto stop_at_gather = [&](const std::string& stage, double) {
    if (stages.empty() || stages.back() != stage) stages.push_back(stage);
    return stage != "final gather";
  };
  EXPECT_THROW(bake(scene, atlas, {}, stop_at_gather), Cancelled);
  EXPECT_EQ(stages.back(), "final gather");
  EXPECT_GE(stages.size(), 5u);  // elements, sample placement, lights, form factors, radiosity...
}

TEST(Pipeline, SolversAgree) {
  Rgb means[3];
  const Solver solvers[3] = {Solver::Shooting, Solver::GaussSeidel, Solver::Jacobi};
  for (int s = 0; s < 3; ++s) {
    BakeOptions o;
    o.solve.solver = solvers[s];
    o.solve.tolerance = 1e-4;
    BakeResult r = test::bake_scene(small_room(), kAtlas, o).result;
    EXPECT_TRUE(r.report.converged);
    means[s] = test::mean_irradiance(r, [](Vec3, Vec3) { return true; });
  }
  for (int s = 1; s < 3; ++s)
    for (int c = 0; c < 3; ++c)
      // Same transport, same tolerance: the mean irradiance agrees to the tolerance's order.
      EXPECT_NEAR(means[s][c], means[0][c], 1e-3 * means[0][c]) << "solver " << s << " channel " << c;
}

TEST(Pipeline, TighterToleranceIteratesLongerAndChangesLittle) {
  BakeOptions loose, tight;
  loose.solve.tolerance = 1e-2;
  tight.solve.tolerance = 1e-5;
  BakeResult a = test::bake_scene(small_room(), kAtlas, loose).result;
  BakeResult b = test::bake_scene(small_room(), kAtlas, tight).result;
  EXPECT_LT(a.report.solver_iterations, b.report.solver_iterations);
  EXPECT_LE(b.report.unshot_relative, 1e-5);
  Rgb ma = test::mean_irradiance(a, [](Vec3, Vec3) { return true; });
  Rgb mb = test::mean_irradiance(b, [](Vec3, Vec3) { return true; });
  // The ambient term stands in for the unshot 1%: the mean moves by well under that.
  EXPECT_NEAR(ma.x, mb.x, 0.01 * mb.x);
}

TEST(Pipeline, RadiosityStoreIsEmissionPlusReflectedIrradiance) {
  BakeOptions o;
  o.store = StoredQuantity::Radiosity;
  BakeResult r = test::bake_scene(small_room(), kAtlas, o).result;
  const Elements& e = r.elements;
  size_t checked = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i)) continue;
    Rgb expected = e.emission[i] + e.reflectance[i] * r.irradiance[i];
    const LightmapPage& page = r.pages[e.page[i]];
    EXPECT_EQ(page.texels[e.texel[i]].x, expected.x);
    ++checked;
  }
  EXPECT_GT(checked, 1000u);
}

TEST(Pipeline, NothingEmittingIsAnInputError) {
  Scene scene;
  test::add_box(scene, {0, 0, 0}, {1, 1, 1}, true, test::add_material(scene, {0.5f, 0.5f, 0.5f}));
  Atlas atlas = test::unwrap(scene, kAtlas);
  EXPECT_THROW(bake(scene, atlas, {}), InputError);
}

}  // namespace
}  // namespace radbake
