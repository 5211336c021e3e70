// Illuminance at points in the air (baker/readings/sensor_points.h) and per-surface statistics,
// against closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "support/closed_forms.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

TEST(Sensors, InTheOpenTheyReadTheSkyAndALampExactly) {
  Scene scene;
  const int grey = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  test::add_quad(scene, {0, 0, 4}, {4, 0, 0}, {0, 0, -4}, grey, "floor");
  Light lamp;
  lamp.intensity = 500;
  lamp.position = {2, 3, 2};
  scene.lights.push_back(lamp);
  BakeOptions options = test::under_a_uniform_sky(1000);
  options.sky.ground_reflectance = 0;
  // Over the floor facing up, and beyond its edge facing back at it.
  const Vec3 up_at{2.5f, 1, 2}, side_at{6, 1, 2};
  options.sensors = {{up_at, {0, 1, 0}}, {side_at, {-1, 0, 0}}};
  const BakeResult r = test::bake_scene(scene, test::coarse_atlas(), options).result;
  ASSERT_EQ(r.sensor_lux.size(), 2u);
  // Up: pi L from the sky, I cos / d^2 from the lamp; the floor is below it. 1e-4 bounds float
  // rounding: the sky rays are unobstructed and the lamp's one ray is exact.
  const double up = M_PI * 1000 + test::point_light_lux(500, lamp.position, up_at, {0, 1, 0});
  EXPECT_NEAR(r.sensor_lux[0], up, 1e-4 * up);
  // Sideways: the sky's upper half, pi L / 2, and the lamp, plus the lit floor seen below the
  // horizon, which is less than a whole lower half of its exitance (rho (pi L + lamp) <= 0.5 x
  // 3,200 lm/m2, half of that).
  const double sky_and_lamp = M_PI * 1000 / 2 + test::point_light_lux(500, lamp.position, side_at, {-1, 0, 0});
  EXPECT_GT(r.sensor_lux[1], sky_and_lamp + 10);
  EXPECT_LT(r.sensor_lux[1], sky_and_lamp + 0.5 * 3200 / 2);
}

TEST(Sensors, AnEmittingSquareGivesPiLTimesTheFormFactorThroughTheGather) {
  // CIE 171 5.3's room: a 1 m square of 1000 cd/m2 in a black 4 x 4 x 3 m room's ceiling. In the
  // air the sensors see it through their cosine-distributed rays only.
  Scene scene;
  const int black = test::add_material(scene, {0, 0, 0});
  const int source = test::add_material(scene, {0, 0, 0}, {1, 1, 1}, 1000);
  test::add_box(scene, {0, 0, 0}, {4, 3, 4}, true, black, "room");
  test::add_quad(scene, {1.5f, 2.999f, 1.5f}, {1, 0, 0}, {0, 0, 1}, source, "source");  // facing down
  const std::vector<Vec3> corners = {{1.5f, 2.999f, 1.5f}, {2.5f, 2.999f, 1.5f}, {2.5f, 2.999f, 2.5f}, {1.5f, 2.999f, 2.5f}};
  BakeOptions options;
  options.sensor.rays = 65536;
  for (float x : {0.5f, 1.25f, 2.0f, 3.0f}) options.sensors.push_back({{x, 0.8f, 2}, {0, 1, 0}});
  const BakeResult r = test::bake_scene(scene, test::coarse_atlas(), options).result;
  double worst = 0;
  for (size_t k = 0; k < options.sensors.size(); ++k) {
    const double expected = M_PI * 1000 * test::point_to_polygon(options.sensors[k].position, {0, 1, 0}, corners);
    worst = std::max(worst, std::fabs(r.sensor_lux[k] / expected - 1));
    // 3% bounds the gather's noise: 65,536 stratified rays, of which 1-10% strike the source.
    EXPECT_NEAR(r.sensor_lux[k], expected, 0.03 * expected) << "at x = " << options.sensors[k].position.x;
  }
  RecordProperty("worst_relative_error", std::to_string(worst));
}

TEST(Sensors, JustAboveAFloorTheyReadWhatTheFloorsTexelsReceive) {
  // The lit room: a sensor 1 mm over the floor sees what the floor does; the floor's texels there
  // got their light from the bake's own gather, the sensor from its rays on the finished bake.
  Scene scene = test::lit_room(0.6f, {1, 1, 1}, false);
  BakeOptions options;
  options.sensor.rays = 16384;
  const Vec3 at{0.6f, 0.001f, 1.3f};
  options.sensors = {{at, {0, 1, 0}}};
  const BakeResult r = test::bake_scene(scene, test::coarse_atlas(), options).result;
  const Rgb floor = test::mean_irradiance(r, [&](Vec3 p, Vec3 n) {
    return n.y > 0.9f && p.y < 0.01f && std::fabs(p.x - at.x) < 0.07f && std::fabs(p.z - at.z) < 0.07f;
  });
  RecordProperty("sensor_over_floor", std::to_string(r.sensor_lux[0] / floor.x));
  // 2% bounds both gathers' noise and the texels' footprint (12.5 cm) against one point.
  EXPECT_NEAR(r.sensor_lux[0], floor.x, 0.02 * floor.x);
}

// A meter reads the photopic part of coloured light: a lamp of 100 cd whose colour is
// pure red, green or blue in linear sRGB gives E = Y(colour) x I / d^2, Y = 0.2126, 0.7152,
// 0.0722 (IEC 61966-2-1's primaries, CIE 1931 Y), not a third of it each. Over a black floor, so
// only the lamp counts; the floor's own statistics read the same.
TEST(Sensors, ColouredLightIsReadAsItsPhotopicLuminance) {
  const Rgb colours[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const double weight[3] = {0.2126, 0.7152, 0.0722};
  for (int c = 0; c < 3; ++c) {
    Scene scene;
    const int black = test::add_material(scene, {0, 0, 0});
    test::add_quad(scene, {0, 0, 2}, {2, 0, 0}, {0, 0, -2}, black, "floor");
    Light lamp;
    lamp.intensity = 100;
    lamp.color = colours[c];
    lamp.position = {1, 2, 1};
    scene.lights.push_back(lamp);
    BakeOptions options;
    options.sensors = {{{1, 0.5f, 1}, {0, 1, 0}}};
    const BakeResult r = test::bake_scene(scene, test::coarse_atlas(), options).result;
    ASSERT_EQ(r.sensor_lux.size(), 1u);
    // 1.5 m under it: 100 / 1.5^2 = 44.4 lx of white light. 1e-5 bounds float rounding (one
    // shadow ray, nothing in the way).
    const double expected = weight[c] * 100 / (1.5 * 1.5);
    EXPECT_NEAR(r.sensor_lux[0], expected, 1e-5 * expected) << "colour " << c;
    // The floor, 2 m under it: its mean over the 2 m square is below I / d^2 at the centre, and
    // at least Y x what its corners get (I h / r^3, r = 2.45 m), as it is a photopic reading too.
    ASSERT_EQ(r.report.surfaces.size(), 1u);
    EXPECT_LT(r.report.surfaces[0].mean, weight[c] * 100 / 4.0);
    EXPECT_GT(r.report.surfaces[0].mean, weight[c] * 100 * 2 / std::pow(std::sqrt(6.0), 3));
  }
}

TEST(SurfaceStatistics, PerInstanceAreaMeanAndUniformity) {
  Scene scene;
  const int grey = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  test::add_quad(scene, {0, 0, 2}, {2, 0, 0}, {0, 0, -2}, grey, "terrace");
  BakeOptions options = test::under_a_uniform_sky(1000);
  options.sky.rays = 16;
  const BakeResult r = test::bake_scene(scene, test::coarse_atlas(), options).result;
  ASSERT_EQ(r.report.surfaces.size(), 1u);
  const SurfaceStatistics& s = r.report.surfaces[0];
  EXPECT_EQ(s.name, "terrace");
  EXPECT_NEAR(s.area, 4, 1e-3);
  // Open to a uniform sky: pi L everywhere, so uniformity 1 (1e-5: float rounding).
  EXPECT_NEAR(s.mean, M_PI * 1000, 1e-5 * M_PI * 1000);
  EXPECT_NEAR(s.min, s.max, 1e-5 * s.max);
  EXPECT_NEAR(s.uniformity, 1, 1e-5);
}

}  // namespace
}  // namespace radbake
