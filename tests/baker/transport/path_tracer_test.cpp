// The path tracer is the reference the baker is measured against, so it is checked against what
// nobody computed with it: closed forms (a point light and a square lamp over a floor, the
// furnace), and its own convergence (its stated noise is the noise two seeds really show, and
// falls as 1 / sqrt(samples)).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "baker/surface/material_sampler.h"
#include "support/closed_forms.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

BakeOptions path_tracing(uint32_t samples, uint64_t seed = 1) {
  BakeOptions options;
  options.method = Method::PathTrace;
  options.path_trace.samples = samples;
  options.seed = seed;
  return options;
}

// A 4 m grey floor; nothing else reflects, so every texel holds direct light only.
Scene floor_under(const std::function<void(Scene&)>& add_light) {
  Scene scene;
  test::add_quad(scene, {-2, 0, 2}, {4, 0, 0}, {0, 0, -4}, test::add_material(scene, {0.5f, 0.5f, 0.5f}), "floor");
  add_light(scene);
  return scene;
}

// The path-traced bake against a closed form over whole floor texels (whose sample point is their
// centre; a texel cut by the floor's edge averages a part centred elsewhere).
void expect_closed_form(const test::Baked& b, const std::function<double(Vec3)>& closed_form) {
  const Elements& e = b.result.elements;
  size_t checked = 0, beyond_four_sigma = 0;
  double sum_squares = 0, sum_expected = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i) || !(e.flags[i] & kFlatTexel) || e.normal[i].y < 0.9f) continue;
    const double expected = closed_form(e.position[i]);
    const double error = b.result.irradiance[i].x - expected;
    // The texel's own noise, plus 0.2% for its footprint mean against the value at its centre
    // (second order in texel size over distance).
    if (std::fabs(error) > 4 * b.result.standard_error[i] + 0.002 * expected) ++beyond_four_sigma;
    sum_squares += error * error;
    sum_expected += expected;
    ++checked;
  }
  ASSERT_GT(checked, 3000u);
  const double rmse = std::sqrt(sum_squares / double(checked)) / (sum_expected / double(checked));
  const double stated = b.result.report.path_relative_noise;
  ::testing::Test::RecordProperty("relative_rmse", std::to_string(rmse));
  ::testing::Test::RecordProperty("stated_noise", std::to_string(stated));
  // Each texel's error is taken from 8 batches, so error over stated error follows Student's t
  // with 7 degrees of freedom: beyond 4 for 0.5% of the texels of a correct estimate.
  EXPECT_LE(beyond_four_sigma, checked * 15 / 1000);
  // What is left against the closed form is the noise the tracer states, nothing more.
  EXPECT_LT(rmse, 1.3 * stated + 0.001);
}

TEST(PathTracer, PointLightOverAFloorGivesInverseSquareTimesCosine) {
  const Vec3 light_at{0.3f, 1.0f, -0.2f};
  Scene scene = floor_under([&](Scene& s) {
    Light bulb;
    bulb.intensity = 100;  // cd
    bulb.position = light_at;
    s.lights.push_back(bulb);
  });
  // The light is exact; the noise left is that of 16 points spread over each 6 cm texel.
  test::Baked b = test::bake_scene(scene, {16.0f, 256, 2}, path_tracing(16));
  expect_closed_form(b, [&](Vec3 x) { return test::point_light_lux(100, light_at, x, {0, 1, 0}); });
}

TEST(PathTracer, SquareLampOverAFloorGivesTheRectangleFormFactor) {
  const float luminance = 1000;  // cd/m2, exitance pi * 1000 lm/m2
  Scene scene = floor_under([&](Scene& s) {
    int lamp = test::add_material(s, {0, 0, 0}, {1, 1, 1}, luminance);
    test::add_quad(s, {-0.5f, 1, -0.5f}, {1, 0, 0}, {0, 0, 1}, lamp, "lamp");  // faces -y
  });
  test::Baked b = test::bake_scene(scene, {16.0f, 256, 2}, path_tracing(64));
  expect_closed_form(b, [&](Vec3 x) {
    return kExitancePerEmissiveUnit * luminance * test::point_to_rectangle(x.x, x.z, -0.5, 0.5, -0.5, 0.5, 1.0);
  });
}

// Every face of a closed 1 m box emits 100 cd/m2 and reflects 0.8: irradiance M / (1 - rho)
// everywhere, which takes paths of every length (rho^20 = 1% of the light arrives after 20 bounces).
constexpr float kFurnaceLuminance = 100, kFurnaceReflectance = 0.8f;
Scene furnace() {
  Scene scene;
  const float rho = kFurnaceReflectance;
  int m = test::add_material(scene, {rho, rho, rho}, {1, 1, 1}, kFurnaceLuminance);
  test::add_box(scene, {0, 0, 0}, {1, 1, 1}, true, m);
  return scene;
}

// The furnace path-traced; each texel held to M / (1 - rho), the mean over them within four of its
// standard errors. Returns the bake for what else a test looks at.
test::Baked expect_furnace_reading(const Scene& scene) {
  test::Baked b = test::bake_scene(scene, {12.0f, 256, 2}, path_tracing(64));
  const double expected = kExitancePerEmissiveUnit * kFurnaceLuminance / (1.0 - kFurnaceReflectance);
  const Elements& e = b.result.elements;
  double sum = 0;
  size_t checked = 0, beyond_four_sigma = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i)) continue;
    const double value = b.result.irradiance[i].x;
    sum += value;
    if (std::fabs(value - expected) > 4 * b.result.standard_error[i]) ++beyond_four_sigma;
    ++checked;
  }
  EXPECT_GT(checked, 500u);
  ::testing::Test::RecordProperty("mean_relative_error", std::to_string(sum / double(checked) / expected - 1));
  EXPECT_LE(beyond_four_sigma, checked * 15 / 1000);  // Student's t, as above
  EXPECT_NEAR(sum / double(checked) / expected, 1.0, 4 * b.result.report.path_relative_noise / std::sqrt(double(checked)));
  return b;
}

TEST(PathTracer, FurnaceReadsEmissionOverOneMinusReflectance) {
  const test::Baked b = expect_furnace_reading(furnace());
  RecordProperty("surface_hits_per_path", std::to_string(b.result.report.path_mean_vertices));
  // Paths end by Russian roulette on the reflectance: 1 / (1 - 0.8) = 5 surfaces on average.
  EXPECT_NEAR(b.result.report.path_mean_vertices, 1 / (1 - kFurnaceReflectance), 0.25);
}

// A file whose NORMALs point behind their faces (an exporter's fault, and what a wrongly turned
// node made of the corpus's teapots' normals): a surface is lit and seen from its winding's side,
// so the furnace reads the same. The path tracer once shaded the points its paths struck with
// such normals, found every emitter behind them and read M alone, 80% short.
TEST(PathTracer, FurnaceWhoseNormalsPointBehindItsFacesReadsTheSame) {
  Scene scene = furnace();
  for (MeshInstance& face : scene.instances) {
    const Vec3 p0 = face.positions[face.triangles[0]];
    const Vec3 front = normalize(cross(face.positions[face.triangles[1]] - p0, face.positions[face.triangles[2]] - p0));
    face.normals.assign(face.positions.size(), -front);
  }
  expect_furnace_reading(scene);
}

// A room with a block and a bulb: light in shadows comes only by bounces.
Scene room_with_block() { return test::lit_room(0.6f, {1, 1, 1}, true); }

TEST(PathTracer, StatedNoiseIsTheNoiseTwoSeedsShowAndFallsAsOneOverRootN) {
  const Scene scene = room_with_block();
  const AtlasOptions atlas{10.0f, 256, 2};
  test::Baked a = test::bake_scene(scene, atlas, path_tracing(32, 1));
  test::Baked b = test::bake_scene(scene, atlas, path_tracing(32, 2));
  test::Baked c = test::bake_scene(scene, atlas, path_tracing(128, 3));
  const Elements& e = a.result.elements;
  double sum_squares = 0, sum_values = 0;
  size_t n = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i)) continue;
    const double d = (sum(a.result.irradiance[i]) - sum(b.result.irradiance[i])) / 3;
    sum_squares += d * d;
    sum_values += (sum(a.result.irradiance[i]) + sum(b.result.irradiance[i])) / 6;
    ++n;
  }
  ASSERT_GT(n, 2000u);
  // Two independent runs differ by sqrt(2) times the noise of one.
  const double seen = std::sqrt(sum_squares / double(n) / 2) / (sum_values / double(n));
  const double stated = a.result.report.path_relative_noise;
  RecordProperty("seen_noise", std::to_string(seen));
  RecordProperty("stated_noise", std::to_string(stated));
  // 15% bounds the estimate's own sampling error over ~2,500 texels of 8 batches each.
  EXPECT_NEAR(seen / stated, 1.0, 0.15);
  // Four times the paths, half the noise (within 10%).
  EXPECT_NEAR(c.result.report.path_relative_noise / stated, 0.5, 0.05);
}

TEST(PathTracer, SameSeedSameLightWhateverTheThreads) {
  const Scene scene = room_with_block();
  BakeOptions one_thread = path_tracing(16), two_threads = path_tracing(16);
  one_thread.threads = 1;
  two_threads.threads = 2;
  test::Baked a = test::bake_scene(scene, {8.0f, 256, 2}, one_thread);
  test::Baked b = test::bake_scene(scene, {8.0f, 256, 2}, two_threads);
  EXPECT_TRUE(test::same_pages(a.result.pages, b.result.pages));
  test::Baked c = test::bake_scene(scene, {8.0f, 256, 2}, path_tracing(16, 2));
  EXPECT_FALSE(test::same_pages(a.result.pages, c.result.pages));
}

}  // namespace
}  // namespace radbake
