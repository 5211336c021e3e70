// Two boxes pushed into each other, as blocks and props are placed in levels: each has faces
// inside the other. Texels inside a box must be left to dilation (buried) or stay dark, the light
// must not leak into the boxes through the lines where their faces cross, and texels outside keep
// their light.
#include <gtest/gtest.h>

#include "hard_cases/hard_case_checks.h"
#include "support/closed_forms.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

bool inside(Vec3 p, Vec3 lo, Vec3 hi, float margin) {
  return p.x > lo.x + margin && p.x < hi.x - margin && p.y > lo.y + margin && p.y < hi.y - margin &&
         p.z > lo.z + margin && p.z < hi.z - margin;
}

TEST(IntersectingBoxes, InsidesStayDarkAndOutsidesKeepTheirLight) {
  const Vec3 a_lo{0, 0, 0}, a_hi{1, 1, 1}, b_lo{0.5f, 0.3f, 0.25f}, b_hi{1.5f, 1.5f, 0.75f};
  Scene scene;
  int grey = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  test::add_box(scene, a_lo, a_hi, false, grey, "box A");
  test::add_box(scene, b_lo, b_hi, false, grey, "box B, half inside A");
  Light bulb;
  bulb.intensity = 100;
  bulb.position = {0.2f, 3, 0.5f};  // west of B: B's shadow falls east, away from A's open top
  scene.lights.push_back(bulb);
  test::Baked b = test::bake_scene(scene, {32, 256, 2}, {});
  const BakeResult& r = b.result;
  test::expect_finite_and_non_negative(r);

  const Rgb mean = test::mean_irradiance(r, [](Vec3, Vec3) { return true; });
  size_t inside_valid = 0, inside_buried = 0;
  float brightest_inside = 0;
  for (size_t i = 0; i < r.elements.size(); ++i) {
    // Inside the other box by more than the ray offset: A's faces in B, B's faces in A.
    const Vec3 p = r.elements.position[i];
    if (!inside(p, a_lo, a_hi, 1e-3f) && !inside(p, b_lo, b_hi, 1e-3f)) continue;
    if (!r.elements.valid(i)) {
      ++inside_buried;
      continue;
    }
    ++inside_valid;
    brightest_inside = std::max(brightest_inside, r.irradiance[i].x);
  }
  RecordProperty("inside_buried", std::to_string(inside_buried));
  RecordProperty("inside_valid", std::to_string(inside_valid));
  RecordProperty("brightest_inside_lux", std::to_string(brightest_inside));
  EXPECT_GT(inside_buried, 500u);
  // Whatever the burial test leaves valid inside sees only the insides of the boxes, which are
  // back faces: black. A thousandth of the mean allows nothing but round-off.
  EXPECT_LT(brightest_inside, 0.001f * mean.x);

  // Outside: B's top is the highest face and sees only the sky, so its light is the bulb's alone.
  size_t top_count = 0;
  const double top_error = test::worst_relative_error(
      r, [&](Vec3 p, Vec3 n) { return n.y > 0.9f && p.y > b_hi.y - 1e-3f; },
      [&](Vec3 x, Vec3 n) { return test::point_light_lux(bulb.intensity, bulb.position, x, n); }, &top_count);
  RecordProperty("worst_top_error", std::to_string(top_error));
  EXPECT_GT(top_count, 400u);
  // 1%: the bulb is 1.5 m above 3 cm texels; their 4 jittered shadow rays average the light
  // over the footprint to a few tenths of a percent.
  EXPECT_LT(top_error, 0.01);
  // A's top west of B, up to the line where B's west face goes into it: lit by the bulb (B's
  // shadow falls east), plus what B's lit face reflects, never less: no dark seam at the line.
  size_t a_top = 0;
  for (size_t i = 0; i < r.elements.size(); ++i) {
    const Vec3 p = r.elements.position[i];
    if (!r.elements.valid(i) || r.elements.normal[i].y < 0.9f || std::fabs(p.y - a_hi.y) > 1e-3f || p.x > b_lo.x)
      continue;
    const double direct = test::point_light_lux(bulb.intensity, bulb.position, p, {0, 1, 0});
    // 2%: the 4 jittered shadow rays' error (see above), with room to spare.
    EXPECT_GT(r.irradiance[i].x, 0.98 * direct) << "on A's top at " << p.x << ", " << p.z;
    ++a_top;
  }
  EXPECT_GT(a_top, 400u);
}

}  // namespace
}  // namespace radbake
