// An emitting surface as an area light, in radbake's unit convention: glTF emission is luminance
// in cd/m2, a Lambertian emitter of luminance L has exitance pi L, and the irradiance it gives a
// point is pi L times the point-to-surface form factor (Howell B-3 for a rectangle).
#include <gtest/gtest.h>

#include <cmath>

#include "baker/surface/material_sampler.h"
#include "support/closed_forms.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

// A 1 m square lamp 1 m above a black floor whose glTF emission, times `emission_scale`, is a
// luminance of 1000 cd/m2: the floor's irradiance against the closed form.
void expect_closed_form_under_square_lamp(float emission_in_file, float emission_scale) {
  const float luminance = emission_in_file * emission_scale;  // cd/m2
  ASSERT_FLOAT_EQ(luminance, 1000.0f);
  Scene scene;
  int black = test::add_material(scene, {0, 0, 0});
  int lamp = test::add_material(scene, {0, 0, 0}, {1, 1, 1}, emission_in_file);
  test::add_quad(scene, {-3, 0, 3}, {6, 0, 0}, {0, 0, -6}, black);              // floor, faces +y
  test::add_quad(scene, {-0.5f, 1, -0.5f}, {1, 0, 0}, {0, 0, 1}, lamp);         // 1 m square at 1 m, faces -y
  BakeOptions options;
  options.emission_scale = emission_scale;
  test::Baked b = test::bake_scene(scene, {32.0f, 512, 2}, options);
  const Elements& e = b.result.elements;
  size_t checked = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i) || e.normal[i].y < 0.9f || (i % 97) != 0) continue;
    Vec3 x = e.position[i];
    double expected = kExitancePerEmissiveUnit * luminance * test::point_to_rectangle(x.x, x.z, -0.5, 0.5, -0.5, 0.5, 1.0);
    // 1% of the value under the lamp's centre: the texel averages over its footprint.
    EXPECT_NEAR(b.result.irradiance[i].x, expected, 0.01 * kExitancePerEmissiveUnit * luminance * 0.5)
        << "at " << x.x << ", " << x.z;
    ++checked;
  }
  EXPECT_GT(checked, 200u);
}

TEST(AreaLight, EmittingSquareGivesPiTimesLuminanceTimesFormFactor) { expect_closed_form_under_square_lamp(1000, 1); }

// What the Blender add-on relies on: Blender's emission strength 1000/683 with --emission-scale 683.
TEST(AreaLight, EmissionScaleConvertsTheFilesUnitToLuminance) {
  expect_closed_form_under_square_lamp(1000.0f / 683.0f, 683.0f);
}

}  // namespace
}  // namespace radbake
