// Geometry that breaks bakers: coplanar duplicates, T-junctions, interpenetrating boxes,
// degenerate and sliver triangles, a chart smaller than a texel, and light at 89 degrees to the
// normal. Each scene is lit by one light whose unoccluded closed form is known, and surfaces are
// arranged (open floors, black rooms) so that the closed form is the whole answer.
#include <gtest/gtest.h>

#include <cmath>

#include "hard_cases/hard_case_checks.h"
#include "support/closed_forms.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

Light point_light(Vec3 position, float candela) {
  Light light;
  light.position = position;
  light.intensity = candela;
  return light;
}

// Worst relative error, over valid elements passing `where`, of the irradiance against the point
// light's unoccluded closed form; `count` gets how many were checked.
double worst_against_point_light(const BakeResult& r, const Light& light,
                                 const std::function<bool(Vec3 position, Vec3 normal)>& where, size_t* count) {
  const Elements& e = r.elements;
  double worst = 0;
  *count = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i) || !where(e.position[i], e.normal[i])) continue;
    double expected = test::point_light_lux(light.intensity, light.position, e.position[i], e.normal[i]);
    worst = std::max(worst, std::fabs(r.irradiance[i].x - expected) / expected);
    ++*count;
  }
  return worst;
}

bool on_floor(Vec3 x, Vec3 n) { return n.y > 0.99f && std::fabs(x.y) < 1e-3f; }

// A texel's four shadow rays start from stratified points of its footprint whose mean is not
// exactly the sample point the closed form is taken at: the irradiance gradient times that
// offset, measured up to 1.05% on walls 1 m from the lamp. 2% bounds it and still catches a texel
// that lost one of its four shadow rays (25%) or saw a light through a crack (thousands of %).
constexpr double kDirectTolerance = 0.02;

TEST(AwkwardGeometry, CoplanarOverlappingFacesLightLikeOne) {
  Scene scene;
  int grey = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  test::add_quad(scene, {0, 0, 2}, {2, 0, 0}, {0, 0, -2}, grey, "floor");
  test::add_quad(scene, {0.5f, 0, 1.5f}, {1.2f, 0, 0}, {0, 0, -1.2f}, grey, "floor's twin");  // same plane
  scene.lights.push_back(point_light({1, 1.5f, 1}, 30));
  BakeResult r = test::bake_scene(scene, {24.0f, 256, 2}, {}).result;
  test::expect_finite_and_non_negative(r);
  // A shadow ray that struck the twin lying in the same plane would leave its texel black.
  size_t checked = 0;
  double worst = worst_against_point_light(r, scene.lights[0], on_floor, &checked);
  RecordProperty("worst_relative_error", std::to_string(worst));
  EXPECT_GT(checked, 2000u);
  EXPECT_LT(worst, kDirectTolerance);
}

TEST(AwkwardGeometry, TJunctionsLeaveNoCrackForLightOrShadow) {
  // A black closed room whose floor is one 1 x 2 m quad beside two 1 x 1 m quads: the middle
  // vertex of the right side lies on the long quad's edge, a T-junction. A lamp under the floor
  // must not shine through the crack, and the lamp inside must light the floor along it evenly.
  Scene scene;
  int black = test::add_material(scene, {0, 0, 0});
  test::add_quad(scene, {0, 0, 2}, {1, 0, 0}, {0, 0, -2}, black, "floor, long");
  test::add_quad(scene, {1, 0, 1}, {1, 0, 0}, {0, 0, -1}, black, "floor, near");
  test::add_quad(scene, {1, 0, 2}, {1, 0, 0}, {0, 0, -1}, black, "floor, far");
  test::add_quad(scene, {0, 2, 0}, {2, 0, 0}, {0, 0, 2}, black, "ceiling");
  test::add_quad(scene, {0, 0, 0}, {2, 0, 0}, {0, 2, 0}, black, "front");
  test::add_quad(scene, {0, 0, 2}, {0, 2, 0}, {2, 0, 0}, black, "back");
  test::add_quad(scene, {0, 0, 0}, {0, 2, 0}, {0, 0, 2}, black, "left");
  test::add_quad(scene, {2, 0, 0}, {0, 0, 2}, {0, 2, 0}, black, "right");
  const Light inside = point_light({1, 1.2f, 1}, 20);
  scene.lights = {inside, point_light({1, -0.5f, 1}, 1e6f)};  // the one below is 50,000 times brighter
  BakeResult r = test::bake_scene(scene, {24.0f, 256, 2}, {}).result;
  test::expect_finite_and_non_negative(r);
  size_t checked = 0, near_junction = 0;
  double worst = worst_against_point_light(r, inside, [](Vec3, Vec3) { return true; }, &checked);
  worst_against_point_light(r, inside, [](Vec3 x, Vec3 n) { return on_floor(x, n) && std::fabs(x.x - 1) < 0.1f; },
                            &near_junction);
  RecordProperty("worst_relative_error", std::to_string(worst));
  EXPECT_GT(checked, 8000u);
  EXPECT_GT(near_junction, 100u);
  // A ray slipping through the crack would add 50,000 times the light inside to its texel.
  EXPECT_LT(worst, kDirectTolerance);
}

TEST(AwkwardGeometry, InterpenetratingBoxesKeepTheirInsidesOutOfTheBake) {
  Scene scene;
  int black = test::add_material(scene, {0, 0, 0});
  const Vec3 a_lo{0, 0, 0}, a_hi{1, 1, 1}, b_lo{0.5f, 0, 0.5f}, b_hi{1.5f, 0.6f, 1.5f};
  test::add_quad(scene, {-1, 0, 3}, {4, 0, 0}, {0, 0, -4}, black, "floor");
  test::add_box(scene, a_lo, a_hi, false, black, "tall box");
  test::add_box(scene, b_lo, b_hi, false, black, "low box");  // a quarter of it inside the tall one
  const Light lamp = point_light({2.5f, 4, 2.5f}, 200);
  scene.lights.push_back(lamp);
  BakeResult r = test::bake_scene(scene, {24.0f, 512, 2}, {}).result;
  test::expect_finite_and_non_negative(r);
  auto strictly_inside = [](Vec3 x, Vec3 lo, Vec3 hi) {
    const float margin = 0.03f;  // about one texel: texels straddling the other box's face may go either way
    return x.x > lo.x + margin && x.x < hi.x - margin && x.y > lo.y + margin && x.y < hi.y - margin &&
           x.z > lo.z + margin && x.z < hi.z - margin;
  };
  const Elements& e = r.elements;
  size_t buried_inside = 0, valid_inside = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    bool inside = strictly_inside(e.position[i], a_lo, a_hi) || strictly_inside(e.position[i], b_lo, b_hi);
    if (!inside) continue;
    (e.valid(i) ? valid_inside : buried_inside) += 1;
  }
  // Faces running through the other box: their texels there are sealed off, valued by dilation.
  EXPECT_GT(buried_inside, 100u);
  EXPECT_EQ(valid_inside, 0u);
  // The low box's top outside the tall box faces the lamp with nothing between: the closed form.
  size_t checked = 0;
  double worst = worst_against_point_light(
      r, lamp,
      [&](Vec3 x, Vec3 n) {
        return n.y > 0.99f && std::fabs(x.y - b_hi.y) < 1e-3f && (x.x > a_hi.x + 0.03f || x.z > a_hi.z + 0.03f);
      },
      &checked);
  RecordProperty("worst_relative_error", std::to_string(worst));
  EXPECT_GT(checked, 200u);
  EXPECT_LT(worst, kDirectTolerance);
}

TEST(AwkwardGeometry, DegenerateAndSliverTrianglesBakeAroundThem) {
  Scene scene;
  int grey = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  test::add_quad(scene, {0, 0, 1}, {2, 0, 0}, {0, 0, -1}, grey, "floor");
  // A strip beside it, 2 m by 0.2 mm, fanned into slivers of aspect ratio up to 10^4, with a
  // zero-area triangle (a repeated index) and a collinear one among them.
  MeshInstance strip;
  strip.name = "slivers";
  strip.node = strip.mesh = int(scene.instances.size());
  strip.primitive = 0;
  strip.material = grey;
  const float width = 2e-4f;
  for (int k = 0; k <= 4; ++k) {
    strip.positions.push_back({0.5f * k, 0, 1 + width});
    strip.positions.push_back({0.5f * k, 0, 1});
  }
  for (uint32_t k = 0; k < 4; ++k) {
    uint32_t a = 2 * k, b = 2 * k + 1, c = 2 * k + 2, d = 2 * k + 3;
    strip.triangles.insert(strip.triangles.end(), {a, b, d, a, d, c});
  }
  strip.triangles.insert(strip.triangles.end(), {1, 1, 3});  // zero area: a repeated index
  strip.triangles.insert(strip.triangles.end(), {1, 3, 5});  // zero area: three points on a line
  strip.triangles.insert(strip.triangles.end(), {0, 1, 9});  // 2 m long, 0.2 mm wide: aspect 10^4
  scene.summary.triangles += strip.triangle_count();
  scene.instances.push_back(strip);
  scene.lights.push_back(point_light({1, 1.5f, 0.5f}, 30));
  BakeResult r = test::bake_scene(scene, {24.0f, 256, 2}, {}).result;
  test::expect_finite_and_non_negative(r);
  size_t checked = 0;
  double worst = worst_against_point_light(r, scene.lights[0], on_floor, &checked);
  RecordProperty("worst_relative_error", std::to_string(worst));
  EXPECT_GT(checked, 1000u);
  EXPECT_LT(worst, kDirectTolerance);
}

TEST(AwkwardGeometry, AChartSmallerThanATexelGetsOneSaneTexel) {
  Scene scene;
  int grey = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  test::add_quad(scene, {0, 0, 2}, {2, 0, 0}, {0, 0, -2}, grey, "floor");
  test::add_quad(scene, {1, 0.5f, 1.01f}, {0.01f, 0, 0}, {0, 0, -0.01f}, grey, "chip");  // 1 cm, texels are 4 cm
  const Light lamp = point_light({1, 1.5f, 1}, 30);
  scene.lights.push_back(lamp);
  BakeResult r = test::bake_scene(scene, {24.0f, 256, 2}, {}).result;
  test::expect_finite_and_non_negative(r);
  const Elements& e = r.elements;
  size_t chip_texels = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i) || std::fabs(e.position[i].y - 0.5f) > 1e-3f) continue;
    ++chip_texels;
    double expected = test::point_light_lux(lamp.intensity, lamp.position, e.position[i], e.normal[i]);
    // 30 lux a metre below the lamp; the chip's own size makes no difference at 1%.
    EXPECT_NEAR(r.irradiance[i].x, expected, 0.01 * expected);
    EXPECT_NEAR(e.area[i], 1e-4f, 1e-6f);  // the texel stands for the whole chip, 1 cm^2
  }
  EXPECT_GE(chip_texels, 1u);
}

TEST(AwkwardGeometry, LightAt89DegreesGivesItsCosineWithoutAcne) {
  Scene scene;
  test::add_quad(scene, {0, 0, 2}, {2, 0, 0}, {0, 0, -2}, test::add_material(scene, {0.5f, 0.5f, 0.5f}), "floor");
  Light sun;
  sun.type = LightType::Directional;
  sun.intensity = 100000;  // lux, facing the light
  const float grazing = 89.0f * float(M_PI) / 180.0f;
  sun.direction = {std::sin(grazing), -std::cos(grazing), 0};
  scene.lights.push_back(sun);
  BakeResult r = test::bake_scene(scene, {24.0f, 256, 2}, {}).result;
  test::expect_finite_and_non_negative(r);
  // 100,000 cos 89 = 1745 lux everywhere. A ray offset that does not scale with the angle lets
  // shadow rays from texel footprints strike the floor itself: dark speckles (acne).
  const double expected = 100000.0 * std::cos(double(grazing));
  const Elements& e = r.elements;
  size_t checked = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i)) continue;
    EXPECT_NEAR(r.irradiance[i].x, expected, 0.01 * expected) << "at " << e.position[i].x << ", " << e.position[i].z;
    ++checked;
  }
  EXPECT_GT(checked, 2000u);
}

}  // namespace
}  // namespace radbake
