// A double-sided lamp hung 0.1 mm under the ceiling of a closed room. Its back-face twin emits as
// much as its front, up into the gap, where the ceiling and the lamp's white back bounce it until
// they absorb it; only what finds the slit round the lamp gets out, a few tenths of a percent. A
// baker that mixes the gap's texels with the open ceiling's beside them, in a patch or in a texel
// across the lamp's edge, shines the gap's light into the room: 26% more light in this room, 44%
// more in the Cornell box, before texels and patches were split at the edges of covers
// (baker/surface/sample_placement.cpp), and at any texel density until rays stopped crossing a thin
// gap's slit (element_for_hit). So the room must read what the lamp single-sided gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "base/scene.h"
#include "hard_cases/hard_case_checks.h"
#include "io/gltf/gltf_loader.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

constexpr float kGap = 1e-4f;  // metres between the ceiling and the lamp
// The lamp's edges, x and z. They leave 60% and 11% of the texels they cross in the gap at 64
// texels per metre, 80% and 6% at 32: at one edge those texels lie mostly in the gap, at the
// other mostly in the room, with a sliver of gap that misses every centre of their 4 x 4 cells.
constexpr float kLampLow = 0.35f, kLampHigh = 0.658f;

// A closed 1 m room of grey walls (0.75) with a block, and a white (0.78, as the Cornell box's)
// square lamp of 1000 cd/m2 under the ceiling, facing down.
Scene room_with_lamp_under_ceiling(bool double_sided) {
  Scene scene;
  int grey = test::add_material(scene, {0.75f, 0.75f, 0.75f});
  int lamp = test::add_material(scene, {0.78f, 0.78f, 0.78f}, {1, 1, 1}, 1000, double_sided);
  test::add_box(scene, {0, 0, 0}, {1, 1, 1}, true, grey, "room");
  test::add_box(scene, {0.6f, 0, 0.15f}, {0.85f, 0.5f, 0.4f}, false, grey, "block");
  const float side = kLampHigh - kLampLow;
  test::add_quad(scene, {kLampLow, 1 - kGap, kLampLow}, {side, 0, 0}, {0, 0, side}, lamp, "lamp");
  return scene;
}

// A part of the room, by sample point and normal, and how close (relative) its mean irradiance
// must come to the single-sided lamp's.
struct Part {
  const char* name;
  std::function<bool(Vec3, Vec3)> where;
  double tolerance = 0.005;  // above what a 0.1 mm gap truly lets out, a few tenths of a percent
};

// Each part's area-weighted mean irradiance with the lamp double-sided against single-sided.
void expect_same_light(const BakeResult& both, const BakeResult& front, const std::vector<Part>& parts) {
  for (const Part& part : parts) {
    size_t count = 0;
    const double with_back = test::mean_irradiance(both, part.where, &count).x;
    const double front_only = test::mean_irradiance(front, part.where).x;
    ::testing::Test::RecordProperty(std::string(part.name) + " double / single - 1",
                                    std::to_string(with_back / front_only - 1));
    EXPECT_GE(count, 50u) << part.name;
    EXPECT_NEAR(with_back, front_only, part.tolerance * front_only) << part.name;
  }
}

// Light absorbed by the valid texels `where` selects, lm, the mean of RGB as the energy balance
// counts it.
double absorbed(const BakeResult& r, const std::function<bool(Vec3, Vec3)>& where) {
  double total = 0;
  for (size_t i = 0; i < r.elements.size(); ++i)
    if (r.elements.valid(i) && where(r.elements.position[i], r.elements.normal[i]))
      total += sum((Rgb{1, 1, 1} - r.elements.reflectance[i]) * r.irradiance[i]) / 3.0 * r.elements.area[i];
  return total;
}

bool on_block(Vec3 p, Vec3) { return p.y > 1e-3f && p.y < 0.501f && p.x > 0.599f && p.x < 0.851f; }
bool over_lamp(Vec3 p) { return p.x > kLampLow && p.x < kLampHigh && p.z > kLampLow && p.z < kLampHigh; }
bool on_ceiling(Vec3 p, Vec3 n) { return n.y < -0.9f && p.y > 1 - kGap / 2; }
// The gap: the lamp's back and the ceiling over it.
bool in_gap(Vec3 p, Vec3 n) { return (n.y > 0.9f && p.y > 0.99f) || (on_ceiling(p, n) && over_lamp(p)); }

struct Case {
  const char* name;
  float density;  // texels per metre
  BakeOptions options;
};
void PrintTo(const Case& c, std::ostream* out) { *out << c.name; }

// About what `--quality production` sets (baker/pipeline/quality_presets.cpp): patches of 4
// texels (what its patch budget gives the Cornell box on a 256 page), more rays.
BakeOptions production() {
  BakeOptions options;
  options.gather.rays = 1024;
  options.form_factors.rays_per_patch = 4096;
  options.direct.area_light_rays = 64;
  options.direct.punctual_rays = 16;
  options.solve.tolerance = 1e-4;
  options.patches.block_size = 4;
  return options;
}

class GapLeak : public ::testing::TestWithParam<Case> {};

TEST_P(GapLeak, RoomGetsWhatTheLampSingleSidedGives) {
  const Case& c = GetParam();
  const test::Baked both = test::bake_scene(room_with_lamp_under_ceiling(true), {c.density, 512, 2}, c.options);
  const test::Baked front = test::bake_scene(room_with_lamp_under_ceiling(false), {c.density, 512, 2}, c.options);
  test::expect_finite_and_non_negative(both.result);
  test::expect_finite_and_non_negative(front.result);
  // Every part within 0.5%: the slit's light is a few tenths of a percent of the room's at most
  // and a face's mean moves by under 0.05% from seed to seed (measured: every part within 0.1%,
  // 24% to 40% before the split).
  expect_same_light(both.result, front.result,
                    {{"room", [](Vec3 p, Vec3 n) { return !in_gap(p, n); }},
                     {"floor", [](Vec3 p, Vec3 n) { return n.y > 0.9f && p.y < 1e-3f; }},
                     {"wall -x", [](Vec3 p, Vec3 n) { return n.x > 0.9f && p.x < 1e-3f; }},
                     {"wall +x", [](Vec3 p, Vec3 n) { return n.x < -0.9f && p.x > 1 - 1e-3f; }},
                     {"wall -z", [](Vec3 p, Vec3 n) { return n.z > 0.9f && p.z < 1e-3f; }},
                     {"wall +z", [](Vec3 p, Vec3 n) { return n.z < -0.9f && p.z > 1 - 1e-3f; }},
                     {"block", on_block},
                     {"ceiling beside the lamp", [](Vec3 p, Vec3 n) { return on_ceiling(p, n) && !over_lamp(p); }},
                     {"lamp's front", [](Vec3 p, Vec3 n) { return n.y < -0.9f && p.y > 0.99f && !on_ceiling(p, n); }}});
  // The gap keeps the back's light: its texels absorb what the back emits (measured 99.9%, 74% and
  // 64% before the split), and the balance holds.
  const double gap_absorbed = absorbed(both.result, in_gap);
  const double back_emits = front.result.report.balance.emitted;  // the same lamp, once
  RecordProperty("gap absorbs / back emits", std::to_string(gap_absorbed / back_emits));
  EXPECT_GT(gap_absorbed, 0.99 * back_emits);
  EXPECT_LT(gap_absorbed, 1.005 * back_emits);
  EXPECT_LT(std::fabs(both.result.report.balance.relative_error), 0.005);
  EXPECT_LT(std::fabs(front.result.report.balance.relative_error), 0.005);
}

INSTANTIATE_TEST_SUITE_P(Bakes, GapLeak,
                         ::testing::Values(Case{"Default", 64, {}}, Case{"Production", 32, production()}),
                         [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

// The sample itself (its 256 texel page is about 150 texels per metre): its lamp hangs 0.1 mm under
// the ceiling, single-sided; made double-sided (as Blender exports it unless backface culling is
// on), the box must get the same light at each of four densities.
class GapLeakDensity : public ::testing::TestWithParam<float> {};

TEST_P(GapLeakDensity, CornellBoxWithItsLampDoubleSided) {
  LoadedScene loaded = load_gltf(test::source_path("samples/cornell_box/cornell_box.gltf"));
  Scene& scene = loaded.scene;
  const MeshInstance* lamp = nullptr;
  float ceiling = 0;
  for (const MeshInstance& inst : scene.instances) {
    if (inst.name.rfind("light", 0) == 0) lamp = &inst;
    if (inst.name.rfind("ceiling", 0) == 0) ceiling = inst.positions[0].y;
  }
  ASSERT_NE(lamp, nullptr);
  ASSERT_FALSE(material_of(scene, lamp->material).double_sided);
  Vec3 lo = lamp->positions[0], hi = lo;
  for (Vec3 p : lamp->positions) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  ASSERT_NEAR(ceiling - lo.y, 1e-4f, 1e-5f);
  ASSERT_EQ(lo.y, hi.y);
  const float between = (ceiling + lo.y) / 2;
  // Over the lamp, edges included: at these densities texel centres fall on its edges (0.1 mm off,
  // at most), and there the gap's share of a texel split at the edge keeps the centre as its sample.
  constexpr float kEdge = 1e-4f;  // metres
  auto over = [=](Vec3 p) {
    return p.x > lo.x - kEdge && p.x < hi.x + kEdge && p.z > lo.z - kEdge && p.z < hi.z + kEdge;
  };
  auto ceiling_at = [=](Vec3 p, Vec3 n) { return n.y < -0.9f && p.y > between; };
  auto in_gap = [=](Vec3 p, Vec3 n) { return over(p) && ((n.y > 0.9f && p.y > lo.y - 1e-3f) || ceiling_at(p, n)); };
  auto on_blocks = [](Vec3 p, Vec3) { return p.y > 1e-3f && p.y < 0.331f && p.x > 0.05f && p.x < 0.5f && p.z < 0.5f; };

  // One density for both bakes, so the two differ only by the lamp's back: the automatic density of
  // each would differ with the back's chart.
  AtlasOptions atlas;
  atlas.max_page_size = 1024;
  atlas.texel_density = GetParam();
  const test::Baked front = test::bake_scene(scene, atlas, {});
  scene.materials[size_t(lamp->material)].double_sided = true;
  const test::Baked both = test::bake_scene(scene, atlas, {});
  test::expect_finite_and_non_negative(both.result);
  // The gap is sealed (element_for_hit): rays neither enter nor leave its slit, so the bakes agree
  // to their noise. Measured before the seal, room / ceiling beside the lamp: +9.5% / +62% at 100
  // texels per metre, +0.4% / +0.95% at 150, +1.1% / +4.2% at 200, +2.3% / +15% at 400; sealed,
  // every part within 0.12% but the ceiling beside the lamp (0.09%, 0.02%, 0.55%, 0.27%). That
  // one is the back's own light, reaching it straight from the slit, which direct light does not
  // seal: the strip of ceiling within a gap height or two of the edge catches M h / 4 per metre of
  // edge (0.74 lm here, 0.5% of the ceiling beside), all of it or none depending on whether any of
  // a texel's light sample points fall in that strip. The bound of 1% holds that, true light.
  expect_same_light(both.result, front.result,
                    {{"room", [=](Vec3 p, Vec3 n) { return !in_gap(p, n); }},
                     {"floor", [](Vec3 p, Vec3 n) { return n.y > 0.9f && p.y < 1e-3f; }},
                     {"back wall", [](Vec3, Vec3 n) { return n.z < -0.9f; }},
                     {"red wall", [](Vec3 p, Vec3 n) { return n.x < -0.9f && p.x > 0.5f; }},
                     {"green wall", [](Vec3 p, Vec3 n) { return n.x > 0.9f && p.x < 0.05f; }},
                     {"blocks", on_blocks},
                     {"lamp's front",
                      [=](Vec3 p, Vec3 n) { return n.y < -0.9f && p.y > lo.y - 1e-3f && !ceiling_at(p, n); }},
                     {"ceiling beside the lamp", [=](Vec3 p, Vec3 n) { return ceiling_at(p, n) && !over(p); }, 0.01}});
  RecordProperty("escaped double / single - 1",
                 std::to_string(both.result.report.balance.escaped / front.result.report.balance.escaped - 1));
  const double gap_absorbed = absorbed(both.result, in_gap), back_emits = front.result.report.balance.emitted;
  RecordProperty("gap absorbs / back emits", std::to_string(gap_absorbed / back_emits));
  EXPECT_GT(gap_absorbed, 0.99 * back_emits);
  EXPECT_LT(std::fabs(both.result.report.balance.relative_error), 0.005);
}

INSTANTIATE_TEST_SUITE_P(TexelsPerMetre, GapLeakDensity, ::testing::Values(100.0f, 150.0f, 200.0f, 400.0f),
                         [](const ::testing::TestParamInfo<float>& info) {
                           return std::to_string(int(info.param)) + "PerMetre";
                         });

}  // namespace
}  // namespace radbake
