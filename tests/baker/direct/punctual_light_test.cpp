// KHR_lights_punctual against closed forms: inverse square and cosine for a point light, the
// extension's cone falloff for a spot, lux on a tilted plane for a directional light. The plane is
// black, so only direct light arrives.
#include <gtest/gtest.h>

#include <cmath>

#include "support/scene_builders.h"

namespace radbake {
namespace {

Scene black_plane() {
  Scene scene;
  int black = test::add_material(scene, {0, 0, 0});
  test::add_quad(scene, {-2, 0, 2}, {4, 0, 0}, {0, 0, -4}, black);  // faces +y
  return scene;
}

// Irradiance of the valid element whose sample point is nearest to p.
Rgb irradiance_near(const BakeResult& r, Vec3 p, Vec3* where) {
  const Elements& e = r.elements;
  size_t best = 0;
  float best_d = INFINITY;
  for (size_t i = 0; i < e.size(); ++i) {
    float d = length(e.position[i] - p);
    if (e.valid(i) && d < best_d) best_d = d, best = i;
  }
  *where = e.position[best];
  return r.irradiance[best];
}

TEST(PunctualLight, PointLightIsIntensityTimesCosineOverDistanceSquared) {
  Scene scene = black_plane();
  Light light;
  light.type = LightType::Point;
  light.intensity = 100;  // cd
  light.position = {0.2f, 1.0f, -0.1f};
  scene.lights.push_back(light);
  test::Baked b = test::bake_scene(scene, {64.0f, 512, 2}, {});
  for (Vec3 target : {Vec3{0.2f, 0, -0.1f}, Vec3{0.7f, 0, 0.4f}, Vec3{-1.0f, 0, 1.0f}, Vec3{1.7f, 0, -1.5f}}) {
    Vec3 x;
    Rgb e = irradiance_near(b.result, target, &x);
    Vec3 d = light.position - x;
    double dist = length(d);
    double expected = light.intensity * (d.y / dist) / (dist * dist);
    // 1%: the texel (1/64 m) averages the field over its footprint; at these distances that
    // changes the value by well under 0.1%.
    EXPECT_NEAR(e.x, expected, 0.01 * expected) << "at " << x.x << ", " << x.z;
    EXPECT_FLOAT_EQ(e.x, e.y);
  }
}

TEST(PunctualLight, SpotLightFollowsTheExtensionsConeFalloff) {
  Scene scene = black_plane();
  Light spot;
  spot.type = LightType::Spot;
  spot.intensity = 100;
  spot.position = {0, 1, 0};
  spot.direction = {0, -1, 0};
  spot.inner_cone_angle = 0.3490659f;  // 20 degrees
  spot.outer_cone_angle = 0.5235988f;  // 30 degrees
  scene.lights.push_back(spot);
  test::Baked b = test::bake_scene(scene, {64.0f, 512, 2}, {});
  const double cos_inner = std::cos(spot.inner_cone_angle), cos_outer = std::cos(spot.outer_cone_angle);
  for (double degrees : {0.0, 10.0, 24.0, 27.0, 35.0, 50.0}) {
    double angle = degrees * M_PI / 180;
    Vec3 x;
    Rgb e = irradiance_near(b.result, {float(std::tan(angle)), 0, 0}, &x);
    double dist = length(spot.position - x), cd = 1.0 / dist;  // cosine to the axis = height / distance
    double t = std::clamp((cd - cos_outer) / (cos_inner - cos_outer), 0.0, 1.0);
    double expected = spot.intensity * t * t * cd / (dist * dist);
    // 1% of the on-axis value: inside the cone that is the inverse-square check; at the cone's
    // edge the falloff changes by a few percent across one texel, so this bounds the averaging.
    EXPECT_NEAR(e.x, expected, 0.01 * spot.intensity) << degrees << " degrees";
  }
}

TEST(PunctualLight, DirectionalLightGivesItsLuxTimesCosineOnATiltedPlane) {
  Scene scene;
  int black = test::add_material(scene, {0, 0, 0});
  const float tilt = 0.5235988f;  // 30 degrees about z
  test::add_quad(scene, {0, 0, 1}, {std::cos(tilt), std::sin(tilt), 0}, {0, 0, -1}, black);
  Light sun;
  sun.type = LightType::Directional;
  sun.intensity = 1000;  // lux
  sun.direction = {0, -1, 0};
  scene.lights.push_back(sun);
  test::Baked b = test::bake_scene(scene, {32.0f, 256, 2}, {});
  const Elements& e = b.result.elements;
  size_t n = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i)) continue;
    // Exact up to float round-off (1e-4 relative): nothing shadows a lone plane.
    EXPECT_NEAR(b.result.irradiance[i].x, 1000 * std::cos(tilt), 0.1);
    ++n;
  }
  EXPECT_GT(n, 500u);
}

TEST(PunctualLight, AnOccluderCastsAShadow) {
  Scene scene = black_plane();
  int black = test::add_material(scene, {0, 0, 0});
  test::add_quad(scene, {-0.25f, 0.5f, 0.25f}, {0.5f, 0, 0}, {0, 0, -0.5f}, black);  // a card at half height
  Light light;
  light.intensity = 100;
  light.position = {0, 1, 0};
  scene.lights.push_back(light);
  test::Baked b = test::bake_scene(scene, {64.0f, 512, 2}, {});
  Vec3 x;
  // Straight under the card: fully shadowed (0 lux, no light leaks through it).
  EXPECT_EQ(irradiance_near(b.result, {0, 0, 0}, &x).x, 0.0f);
  // Outside its shadow (the shadow reaches 0.5 m out): lit.
  EXPECT_GT(irradiance_near(b.result, {0.9f, 0, 0}, &x).x, 10.0f);
}

}  // namespace
}  // namespace radbake
