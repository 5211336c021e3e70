// The same room modelled in millimetres and in kilometres: geometry scaled by 1e3 and 1e-3, the
// texel density by the inverse (so the lightmap layout is the same), a point light's candela by
// s^2 (so it gives the same lux) and emitting surfaces unchanged (exitance does not depend on
// size). Every ray offset and epsilon must scale with the scene: an absolute one makes the small
// room leak or self-shadow, or the large one show acne.
#include <gtest/gtest.h>

#include <cmath>

#include "baker/pipeline/bake.h"
#include "hard_cases/hard_case_checks.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

constexpr float kDensity = 12;  // texels per metre at scale 1

// A 2 m grey room with a block on the floor, a ceiling lamp and a point light, away from the
// origin (where float spacing is finest), every length times s.
Scene room(float s) {
  const Vec3 at{10, 1, 5};
  Scene scene;
  int grey = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  int lamp = test::add_material(scene, {0, 0, 0}, {1, 1, 1}, 500);
  test::add_box(scene, at * s, (at + Vec3{2, 2, 2}) * s, true, grey, "room");
  test::add_box(scene, (at + Vec3{0.5f, 0, 0.6f}) * s, (at + Vec3{1.1f, 0.7f, 1.2f}) * s, false, grey, "block");
  test::add_quad(scene, (at + Vec3{0.7f, 1.9f, 0.7f}) * s, Vec3{0.6f, 0, 0} * s, Vec3{0, 0, 0.6f} * s, lamp, "lamp");
  Light bulb;
  bulb.intensity = 30 * s * s;  // cd
  bulb.position = (at + Vec3{1.5f, 1.4f, 1.5f}) * s;
  scene.lights.push_back(bulb);
  return scene;
}

const AtlasOptions kAtlasInMetres{kDensity, 128, 2};

BakeResult bake_with(const Scene& scene, const Atlas& atlas) {
  BakeResult r = bake(scene, atlas, {});
  test::expect_finite_and_non_negative(r);
  return r;
}

// The room in metres, unwrapped and baked once for all the cases.
struct Reference {
  Atlas atlas = test::unwrap(room(1), kAtlasInMetres);
  BakeResult result = bake_with(room(1), atlas);
};
const Reference& metres() {
  static const Reference reference;
  return reference;
}

// Area-weighted mean irradiance over the faces facing each of the six axis directions.
std::vector<double> face_means(const BakeResult& r) {
  std::vector<double> means;
  for (int axis = 0; axis < 3; ++axis)
    for (float side : {-1.0f, 1.0f})
      means.push_back(test::mean_irradiance(r, [&](Vec3, Vec3 n) { return n[axis] * side > 0.9f; }).x);
  return means;
}

class ScaleInvariance : public ::testing::TestWithParam<float> {};

// The baker alone: the metre room's atlas (its UVs are page coordinates, whatever the size), so
// texel i is the same piece of surface with the same random numbers at every scale.
TEST_P(ScaleInvariance, TexelsMatchTheRoomInMetres) {
  const float s = GetParam();
  const BakeResult& reference = metres().result;
  const BakeResult scaled = bake_with(room(s), metres().atlas);
  ASSERT_EQ(scaled.elements.size(), reference.elements.size());
  const double mean = test::mean_irradiance(reference, [](Vec3, Vec3) { return true; }).x;
  double worst = 0;
  size_t compared = 0, differing = 0, validity_changes = 0;
  for (size_t i = 0; i < reference.elements.size(); ++i) {
    validity_changes += reference.elements.valid(i) != scaled.elements.valid(i);
    if (!reference.elements.valid(i) || !scaled.elements.valid(i)) continue;
    // Relative to the texel's own value, or to a tenth of the mean in deep shadow.
    const double value = reference.irradiance[i].x, floor = std::max(value, 0.1 * mean);
    const double difference = std::fabs(scaled.irradiance[i].x - value) / floor;
    worst = std::max(worst, difference);
    ++compared;
    differing += difference > 0.01;
  }
  RecordProperty("worst_texel_relative_difference", std::to_string(worst));
  RecordProperty("texels_over_1_percent", std::to_string(differing));
  EXPECT_EQ(validity_changes, 0u);
  // Every texel within 1%, but for one in a thousand: round-off at another magnitude moves a ray
  // by an ulp, and a shadow ray passing exactly through a block's edge may then be stopped in
  // one bake and not the other (a quarter of that texel's bulb light). A ray offset or epsilon
  // that does not scale leaks light into shadow or self-shadows whole rows of texels.
  EXPECT_LE(differing, compared / 1000);
  const double scaled_mean = test::mean_irradiance(scaled, [](Vec3, Vec3) { return true; }).x;
  EXPECT_NEAR(scaled_mean, mean, 0.001 * mean);  // the room's mean: 0.1%
  EXPECT_NEAR(scaled.report.balance.relative_error, reference.report.balance.relative_error, 0.001);
}

// uv/ too: unwrapped at density / s, the atlas has the same pages, charts and covered texels
// (the charts may be packed in another order: equal sizes tie differently after rounding), and
// the bake gives every face the same light.
TEST_P(ScaleInvariance, AtlasAndFacesMatchTheRoomInMetres) {
  const float s = GetParam();
  const Atlas& reference = metres().atlas;
  const Atlas atlas = test::unwrap(room(s), {kDensity / s, 128, 2});
  ASSERT_EQ(atlas.pages.size(), reference.pages.size());
  EXPECT_EQ(atlas.pages[0].width, reference.pages[0].width);
  EXPECT_EQ(atlas.pages[0].height, reference.pages[0].height);
  EXPECT_EQ(atlas.chart_count, reference.chart_count);
  EXPECT_EQ(atlas.stats.covered_texels, reference.stats.covered_texels);
  const std::vector<double> expected = face_means(metres().result), got = face_means(bake_with(room(s), atlas));
  double worst = 0;
  for (size_t f = 0; f < expected.size(); ++f) {
    worst = std::max(worst, std::fabs(got[f] / expected[f] - 1));
    // 1%: charts packed in another order take other random numbers; a face's mean moves by
    // a few tenths of a percent with them.
    EXPECT_NEAR(got[f], expected[f], 0.01 * expected[f]) << "face " << f;
  }
  RecordProperty("worst_face_relative_difference", std::to_string(worst));
}

std::string scale_name(const ::testing::TestParamInfo<float>& info) {
  return info.param > 1 ? "Millimetres" : "Kilometres";
}

INSTANTIATE_TEST_SUITE_P(Units, ScaleInvariance, ::testing::Values(1e3f, 1e-3f), scale_name);

}  // namespace
}  // namespace radbake
