// A room whose ceiling and one wall are single double-sided faces, as Blender's
// Archimesh builds them (the ceiling one face, its normal up toward the roof), with the sun outside
// shining in through a window and a lamp inside. Each face of a double-sided wall has texels of
// its own (baker/surface/back_faces.h), so inside, the room must read what the same room built of
// inward-facing single-sided faces reads: the inside of the ceiling shows the lamp, not the
// sunlit roof.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "hard_cases/hard_case_checks.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

constexpr float kW = 4, kH = 2.5f, kD = 3;  // room width (x), height (y), depth (z), metres
const Vec3 kLamp{2.8f, kH - 0.3f, 1.8f};
constexpr float kLampCandela = 150, kSunLux = 1000;
const Vec3 kSunDirection = normalize(Vec3{-0.35f, -0.6f, 0.72f});  // down, toward +z and -x

// The room; `one_face` builds the ceiling and the +x wall as double-sided faces whose fronts face
// out (the roof up, the wall outward), else as inward single-sided faces like the rest. A 1 m
// window in the z = 0 wall lets the sun in onto the floor.
Scene room(bool one_face) {
  Scene scene;
  const int white = test::add_material(scene, {0.7f, 0.7f, 0.7f});
  const int two_sided = test::add_material(scene, {0.7f, 0.7f, 0.7f}, {0, 0, 0}, 1, true);
  test::add_quad(scene, {0, 0, kD}, {kW, 0, 0}, {0, 0, -kD}, white, "floor");
  test::add_quad(scene, {0, 0, 0}, {0, 0, kD}, {0, kH, 0}, white, "wall -x");
  test::add_quad(scene, {kW, 0, kD}, {-kW, 0, 0}, {0, kH, 0}, white, "wall +z");
  // The z = 0 wall around the window x 1.5..2.5, y 0.8..1.8, facing +z.
  test::add_quad(scene, {0, 0, 0}, {kW, 0, 0}, {0, 0.8f, 0}, white, "wall -z below");
  test::add_quad(scene, {0, 1.8f, 0}, {kW, 0, 0}, {0, kH - 1.8f, 0}, white, "wall -z above");
  test::add_quad(scene, {0, 0.8f, 0}, {1.5f, 0, 0}, {0, 1, 0}, white, "wall -z left");
  test::add_quad(scene, {2.5f, 0.8f, 0}, {kW - 2.5f, 0, 0}, {0, 1, 0}, white, "wall -z right");
  if (one_face) {
    test::add_quad(scene, {0, kH, kD}, {kW, 0, 0}, {0, 0, -kD}, two_sided, "ceiling, normal up");
    test::add_quad(scene, {kW, 0, 0}, {0, kH, 0}, {0, 0, kD}, two_sided, "wall +x, normal out");
  } else {
    test::add_quad(scene, {0, kH, 0}, {kW, 0, 0}, {0, 0, kD}, white, "ceiling, facing in");
    test::add_quad(scene, {kW, 0, 0}, {0, 0, kD}, {0, kH, 0}, white, "wall +x, facing in");
  }
  Light lamp;
  lamp.intensity = kLampCandela;
  lamp.position = kLamp;
  Light sun;
  sun.type = LightType::Directional;
  sun.intensity = kSunLux;
  sun.direction = kSunDirection;
  scene.lights = {lamp, sun};
  return scene;
}

BakeResult bake_room(bool one_face) {
  // Rays enough that two seeds of one room agree to 0.9% in 95% of the cells (4x the default
  // gather, whose texels along the sun patch's edge differed by up to 18% between seeds).
  BakeOptions options;
  options.direct.punctual_rays = 16;
  options.gather.rays = 1024;
  test::Baked b = test::bake_scene(room(one_face), {16, 512, 2}, options);
  test::expect_finite_and_non_negative(b.result);
  return std::move(b.result);
}

// A texel on the inside: within the room and facing into it.
bool inside(Vec3 p, Vec3 n) {
  const float e = 0.01f;
  if (p.x < -e || p.x > kW + e || p.y < -e || p.y > kH + e || p.z < -e || p.z > kD + e) return false;
  const Vec3 middle{kW / 2, kH / 2, kD / 2};
  return dot(n, middle - p) > 0;
}

bool ceiling_inside(Vec3 p, Vec3 n) { return inside(p, n) && n.y < -0.9f; }

// Interior irradiance (red channel, lux) per 0.25 m cell of each interior surface, area-weighted:
// the two bakes' texels lie at different places on their pages, so cells are what correspond.
std::map<std::tuple<int, int, int>, double> interior_cells(const BakeResult& r) {
  std::map<std::tuple<int, int, int>, std::pair<double, double>> sums;
  const Elements& e = r.elements;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i) || !inside(e.position[i], e.normal[i])) continue;
    const Vec3 n = e.normal[i], p = e.position[i];
    const int axis = std::fabs(n.x) > 0.9f ? 0 : std::fabs(n.y) > 0.9f ? 1 : 2;
    const int surface = 2 * axis + (n[axis] > 0);
    const int u = int(std::floor(p[(axis + 1) % 3] / 0.25f)), v = int(std::floor(p[(axis + 2) % 3] / 0.25f));
    auto& s = sums[{surface, u, v}];
    s.first += double(r.irradiance[i].x) * e.area[i];
    s.second += e.area[i];
  }
  std::map<std::tuple<int, int, int>, double> cells;
  for (const auto& [key, s] : sums)
    if (s.second > 0) cells[key] = s.first / s.second;
  return cells;
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + ptrdiff_t(v.size() / 2), v.end());
  return v[v.size() / 2];
}

std::vector<double> interior_texels(const BakeResult& r) {
  std::vector<double> v;
  for (size_t i = 0; i < r.elements.size(); ++i)
    if (r.elements.valid(i) && inside(r.elements.position[i], r.elements.normal[i])) v.push_back(r.irradiance[i].x);
  return v;
}

TEST(OneFaceWalls, RoomWithDoubleSidedCeilingAndWallMatchesInwardFacingRoom) {
  const BakeResult one_face = bake_room(true), reference = bake_room(false);
  const double median_one_face = median(interior_texels(one_face)), median_reference = median(interior_texels(reference));
  const auto cells = interior_cells(one_face), reference_cells = interior_cells(reference);
  std::vector<double> differences;
  for (const auto& [key, value] : reference_cells) {
    auto other = cells.find(key);
    ASSERT_NE(other, cells.end()) << "cell " << std::get<0>(key) << " " << std::get<1>(key) << " " << std::get<2>(key);
    differences.push_back(std::fabs(other->second / value - 1));
  }
  std::sort(differences.begin(), differences.end());
  const double p95 = differences[size_t(0.95 * double(differences.size()))];
  RecordProperty("median_lux_one_face", std::to_string(median_one_face));
  RecordProperty("median_lux_reference", std::to_string(median_reference));
  RecordProperty("cells", std::to_string(differences.size()));
  RecordProperty("cell_p95_relative_difference", std::to_string(p95));
  RecordProperty("cell_worst_relative_difference", std::to_string(differences.back()));
  RecordProperty("energy_balance", std::to_string(one_face.report.balance.relative_error));
  EXPECT_GT(differences.size(), 750u);  // every interior surface, 59 m2 in 0.25 m cells
  // 2%: the median interior irradiance and 95% of the 0.25 m cells (16 texels each) agree with
  // the inward-facing room's (measured: medians 0.06% apart, p95 1.1%, worst cell 3.7%; the
  // reference against itself with another seed: p95 0.9%, worst 4.2%). A ceiling showing the
  // sunlit roof reads several times too bright under the lamp and away from it.
  EXPECT_NEAR(median_one_face, median_reference, 0.02 * median_reference);
  EXPECT_LT(p95, 0.02);
  EXPECT_LT(std::fabs(one_face.report.balance.relative_error), 0.01);
}

TEST(OneFaceWalls, InsideOfDoubleSidedCeilingShowsTheLampNotTheSunlitRoof) {
  const BakeResult r = bake_room(true);
  const Elements& e = r.elements;
  // The roof: the ceiling's front, lit by the sun alone (nothing above it reflects), flat.
  const double roof = kSunLux * -kSunDirection.y;
  size_t roof_count = 0;
  const double worst_roof = test::worst_relative_error(
      r, [](Vec3 p, Vec3 n) { return n.y > 0.9f && p.y > kH - 0.01f; }, [&](Vec3, Vec3) { return roof; }, &roof_count);
  EXPECT_GT(roof_count, 2000u);
  EXPECT_LT(worst_roof, 1e-3);
  // Inside: the lamp 0.3 m below makes a hotspot, I / d^2 straight above it, falling off to the
  // corners; the texel nearest above the lamp holds that plus what the room reflects.
  const double hotspot = kLampCandela / (0.3 * 0.3);
  size_t nearest = SIZE_MAX;
  float nearest_distance = INFINITY;
  std::vector<double> ceiling;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i) || !ceiling_inside(e.position[i], e.normal[i])) continue;
    ceiling.push_back(r.irradiance[i].x);
    const float d = length(e.position[i] - Vec3{kLamp.x, kH, kLamp.z});
    if (d < nearest_distance) nearest_distance = d, nearest = i;
  }
  ASSERT_NE(nearest, SIZE_MAX);
  ASSERT_LT(nearest_distance, 0.05f);
  const double above_lamp = r.irradiance[nearest].x, typical = median(ceiling);
  RecordProperty("above_lamp_lux", std::to_string(above_lamp));
  RecordProperty("ceiling_median_lux", std::to_string(typical));
  EXPECT_GT(above_lamp, 0.98 * hotspot);  // a 6 cm texel sees the lamp from 1-2% off its axis
  EXPECT_LT(above_lamp, 1.2 * hotspot);
  EXPECT_LT(typical, 0.25 * above_lamp);  // a hotspot, not the roof's flat light
  EXPECT_GT(std::fabs(typical / roof - 1), 0.3);
}

}  // namespace
}  // namespace radbake
