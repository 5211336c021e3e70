// CIE 171:2006, "Test cases to assess the accuracy of lighting computer programs": the cases
// radbake's light sources already cover, each against the report's closed form.
//
// Geometry of 5.3 to 5.12. The report itself is not public. The dimensions, measurement points and
// reference tables below are those the public CyclesCIEtest validation transcribed
// (github.com/jjathompson4/CyclesCIEtest, engine/cie171/test_cases.py and test_cases_daylight.py;
// it cross-checks them against the published Iray and AGi32 validations of CIE 171). Each is
// confirmed here the way that matters: the closed form, evaluated for that geometry, gives the
// report's table (each test with a table checks it). Coordinates are radbake's: y is up (the
// report's z).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "daylight/daylight_sky.h"
#include "support/closed_forms.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

Light point_light(Vec3 position, float candela) {
  Light bulb;
  bulb.type = LightType::Point;
  bulb.intensity = candela;
  bulb.position = position;
  return bulb;
}

// The black 4 m x 4 m x 3 m room of 5.3, 5.4 and 5.9 (floor y = 0, walls z = 0, z = 4, x = 0, x = 4),
// its surfaces facing in, the ceiling around a centred square hole of side `hole` (none at 0).
void add_room(Scene& scene, int material, float hole) {
  test::add_quad(scene, {0, 0, 4}, {4, 0, 0}, {0, 0, -4}, material, "floor");
  test::add_quad(scene, {0, 0, 0}, {4, 0, 0}, {0, 3, 0}, material, "south wall");
  test::add_quad(scene, {4, 0, 4}, {-4, 0, 0}, {0, 3, 0}, material, "north wall");
  test::add_quad(scene, {0, 0, 4}, {0, 0, -4}, {0, 3, 0}, material, "west wall");
  test::add_quad(scene, {4, 0, 0}, {0, 0, 4}, {0, 3, 0}, material, "east wall");
  if (hole <= 0) {
    test::add_quad(scene, {0, 3, 0}, {4, 0, 0}, {0, 0, 4}, material, "ceiling");
    return;
  }
  if (hole >= 4) return;  // no roof at all
  const float lo = 2 - hole / 2, hi = 2 + hole / 2;  // the ceiling, facing down, around [lo, hi]^2
  test::add_quad(scene, {0, 3, 0}, {4, 0, 0}, {0, 0, lo}, material, "roof");
  test::add_quad(scene, {0, 3, hi}, {4, 0, 0}, {0, 0, 4 - hi}, material, "roof");
  test::add_quad(scene, {0, 3, lo}, {lo, 0, 0}, {0, 0, hole}, material, "roof");
  test::add_quad(scene, {hi, 3, lo}, {4 - hi, 0, 0}, {0, 0, hole}, material, "roof");
}

// The largest |measured / expected - 1| over the texels checked, and where it was.
struct Pointwise {
  size_t checked = 0;
  double worst = 0;
  Vec3 worst_at{};
  void add(double measured, double expected, Vec3 at) {
    const double error = std::fabs(measured / expected - 1);
    if (error > worst) worst = error, worst_at = at;
    ++checked;
  }
};

// What the lightmap reads at `point` on the plane facing `normal`: the least-squares plane through
// the values of that plane's texels whose sample points lie within `radius` (a little over one
// texel: the four or more around the point), as a reader interpolating between texels gets it.
// The report's points fall on texel edges and corners, not on texel centres.
double reading_at(const Elements& e, const std::vector<double>& value, Vec3 point, Vec3 normal, double radius) {
  Vec3 t, b;
  orthonormal_basis(normal, t, b);
  double m[3][3] = {}, r[3] = {};
  size_t n = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    const Vec3 d = e.position[i] - point;
    if (!e.valid(i) || dot(e.normal[i], normal) < 0.999f || std::fabs(dot(d, normal)) > 0.01f) continue;
    const double f[3] = {1, dot(d, t), dot(d, b)};
    if (f[1] * f[1] + f[2] * f[2] > radius * radius) continue;
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) m[j][k] += f[j] * f[k];
      r[j] += f[j] * value[i];
    }
    ++n;
  }
  auto det3 = [](const double (&a)[3][3]) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  };
  const double det = det3(m);
  if (n < 3 || std::fabs(det) < 1e-12) return NAN;
  double c[3][3];  // Cramer's rule for the constant term
  for (int j = 0; j < 3; ++j) c[j][0] = r[j], c[j][1] = m[j][1], c[j][2] = m[j][2];
  return det3(c) / det;
}

// A table row of the report: a measurement point, its normal, and the report's value there.
struct ReportPoint {
  const char* name;
  Vec3 at, normal;
  double value;
};

struct Readings {
  double worst = 0;  // relative error, over the report's points that are not 0
  std::string text;  // name=reading for each, for the test's record
};

// The lightmap read at each of the report's points (reading_at), against the report's values.
template <size_t N>
Readings read_at_report_points(const Elements& e, const std::vector<double>& value, const ReportPoint (&table)[N],
                               double radius) {
  Readings r;
  for (const ReportPoint& p : table) {
    const double reading = reading_at(e, value, p.at, p.normal, radius);
    r.worst = std::max(r.worst, p.value > 0 ? std::fabs(reading / p.value - 1) : 0.0);
    r.text += std::string(p.name) + "=" + std::to_string(reading) + " ";
  }
  return r;
}

// 5.2: a point source over a floor. Direct illuminance E = I cos(theta) / d^2 at every point of a
// black floor (the report's table is this formula at chosen points; here every texel's sample
// point is checked). A 1000 cd source 3 m over a 10 m x 10 m floor.
TEST(Cie171, Case5_2PointSourceOverAFloor) {
  Scene scene;
  const int black = test::add_material(scene, {0, 0, 0});
  test::add_quad(scene, {-5, 0, 5}, {10, 0, 0}, {0, 0, -10}, black, "floor");
  const Vec3 source{0, 3, 0};
  scene.lights.push_back(point_light(source, 1000));
  AtlasOptions atlas;
  atlas.texel_density = 4;  // 25 cm texels, 1,600 of them
  const BakeResult r = test::bake_scene(scene, atlas, BakeOptions{}).result;
  const Elements& e = r.elements;
  size_t checked = 0;
  double worst = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i)) continue;
    const double exact = test::point_light_lux(1000, source, e.position[i], e.normal[i]);
    // Each texel is the mean over its footprint, the formula is at its sample point: the
    // difference is the field's curvature over 25 cm, 1.4% at worst (measured), right under the
    // source; CIE 171 asks 5% pointwise.
    worst = std::max(worst, std::fabs(sum(r.irradiance[i]) / 3 / exact - 1));
    ++checked;
  }
  RecordProperty("worst_relative_error", std::to_string(worst));
  EXPECT_GT(checked, 1000u);
  EXPECT_LT(worst, 0.05);
}

// 5.3: a square area source in a black room. A Lambertian 1 m x 1 m source of luminance
// 1000 cd/m2 (normal intensity 1000 cd, flux 1000 pi lm) fills the middle of the ceiling of a black
// 4 m x 4 m x 3 m room, facing down. At a point, E = pi L F with F the form factor to the source:
// Howell B-3 on the floor (parallel), Lambert's contour integral on the walls (perpendicular).
// The report's table gives the floor along its centre line, 0.25 m to 3.75 m from a wall, and
// that wall's centre line, 0.25 m to 2.75 m up. This geometry gives the table within 0.26%, some
// values above, some below (the floor's G to J: 61.42, 79.26, 95.67, 105.78 lx in closed form for
// the table's 61.27, 79.18, 95.52, 105.89): the report's rounding or its own integration, as no
// source 1% or 2% larger, smaller, higher or lower comes within 0.23% of it. Every texel of the
// floor and the four walls is checked against the closed form, and the lightmap read at the
// table's points against the table.
TEST(Cie171, Case5_3AreaSourceInABlackRoom) {
  constexpr double kLuminance = 1000;  // cd/m2
  const std::vector<Vec3> source = {{1.5f, 3, 1.5f}, {2.5f, 3, 1.5f}, {2.5f, 3, 2.5f}, {1.5f, 3, 2.5f}};
  auto closed_form = [&](Vec3 at, Vec3 normal) {
    if (normal.y > 0.9f)  // the floor
      return M_PI * kLuminance * test::point_to_rectangle(at.x, at.z, 1.5, 2.5, 1.5, 2.5, 3.0 - at.y);
    return M_PI * kLuminance * test::point_to_polygon(at, normal, source);
  };
  const Vec3 up{0, 1, 0}, into_room{0, 0, 1};  // the floor's normal; the south wall's (z = 0)
  const ReportPoint table[] = {
      {"G", {2, 0, 0.25f}, up, 61.27},        {"H", {2, 0, 0.75f}, up, 79.18},
      {"I", {2, 0, 1.25f}, up, 95.52},        {"J", {2, 0, 1.75f}, up, 105.89},
      {"K", {2, 0, 2.25f}, up, 105.89},       {"L", {2, 0, 2.75f}, up, 95.52},
      {"M", {2, 0, 3.25f}, up, 79.18},        {"N", {2, 0, 3.75f}, up, 61.27},
      {"A", {2, 2.75f, 0}, into_room, 32.68}, {"B", {2, 2.25f, 0}, into_room, 75.09},
      {"C", {2, 1.75f, 0}, into_room, 81.38}, {"D", {2, 1.25f, 0}, into_room, 69.12},
      {"E", {2, 0.75f, 0}, into_room, 53.41}, {"F", {2, 0.25f, 0}, into_room, 39.90},
  };
  // The geometry is the report's: its closed form gives the table's values.
  double table_vs_closed_form = 0;
  for (const ReportPoint& p : table)
    table_vs_closed_form = std::max(table_vs_closed_form, std::fabs(p.value / closed_form(p.at, p.normal) - 1));
  RecordProperty("table_vs_closed_form", std::to_string(table_vs_closed_form));
  // Bounds how far the table is from this geometry's closed form: measured 0.26% (F), 0.25% (G).
  EXPECT_LT(table_vs_closed_form, 0.003);

  Scene scene;
  const int black = test::add_material(scene, {0, 0, 0});
  const int lamp = test::add_material(scene, {0, 0, 0}, {1, 1, 1}, float(kLuminance));
  add_room(scene, black, 1);
  test::add_quad(scene, source[0], {1, 0, 0}, {0, 0, 1}, lamp, "source");  // faces down
  AtlasOptions atlas;
  atlas.texel_density = 8;  // 12.5 cm texels, 4,096 of them over the floor and walls
  const BakeResult r = test::bake_scene(scene, atlas, BakeOptions{}).result;
  const Elements& e = r.elements;
  std::vector<double> lux(e.size());
  Pointwise texels;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i)) continue;
    lux[i] = sum(r.irradiance[i]) / 3;
    if (e.normal[i].y < -0.9f) continue;  // the ceiling and the source, in the source's plane: dark
    texels.add(lux[i], closed_form(e.position[i], e.normal[i]), e.position[i]);
  }
  RecordProperty("texels_checked", std::to_string(texels.checked));
  RecordProperty("worst_texel_error", std::to_string(texels.worst));
  EXPECT_GT(texels.checked, 4000u);
  // CIE 171's 5% pointwise, on every texel. Each texel is the mean over its footprint, the closed
  // form is at its sample point; measured 0.94% at worst.
  EXPECT_LT(texels.worst, 0.05) << "at " << texels.worst_at.x << ", " << texels.worst_at.y << ", "
                                << texels.worst_at.z;
  // The lightmap read at the report's points, against the report's numbers.
  const Readings readings = read_at_report_points(e, lux, table, 0.15);
  RecordProperty("readings_lux", readings.text);
  RecordProperty("worst_point_error", std::to_string(readings.worst));
  // CIE 171's 5% at the report's points: the bake, the interpolation between texels and the table's
  // own 0.26% together. Measured 1.0% at worst (A, 0.25 m under the ceiling: 32.35 lx for 32.68).
  EXPECT_LT(readings.worst, 0.05);
}

// 5.4: flux conservation. A 10,000 lm isotropic point source (795.8 cd) in the middle of a black
// 4 m x 4 m x 3 m room: every lumen lands on a surface, so the illuminance times the area, summed
// over the room, is the source's flux (the report's R_S = Phi_i / Phi_0 = 1). Each surface's share
// is the intensity times the solid angle it fills, and every texel gets I cos(theta) / d^2.
TEST(Cie171, Case5_4FluxFromAPointSourceIsConserved) {
  constexpr double kFlux = 10000, kCandela = kFlux / (4 * M_PI);
  const Vec3 source{2, 1.5f, 2};
  Scene scene;
  add_room(scene, test::add_material(scene, {0, 0, 0}), 0);
  scene.lights.push_back(point_light(source, float(kCandela)));
  AtlasOptions atlas;
  atlas.texel_density = 8;  // 12.5 cm texels
  const BakeResult r = test::bake_scene(scene, atlas, BakeOptions{}).result;
  const Elements& e = r.elements;
  // Flux per surface, by its normal: floor, ceiling, then the walls facing +z, -z, +x, -x.
  const Vec3 normals[6] = {{0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}};
  double flux[6] = {}, area = 0;
  Pointwise texels;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i)) continue;
    const double lux = sum(r.irradiance[i]) / 3;
    texels.add(lux, test::point_light_lux(kCandela, source, e.position[i], e.normal[i]), e.position[i]);
    for (int s = 0; s < 6; ++s)
      if (dot(e.normal[i], normals[s]) > 0.99f) flux[s] += lux * e.area[i];
    area += e.area[i];
  }
  const double floor_share = kCandela * test::centred_rectangle_solid_angle(2, 2, 1.5);
  const double wall_share = kCandela * test::centred_rectangle_solid_angle(2, 1.5, 2);
  const double expected[6] = {floor_share, floor_share, wall_share, wall_share, wall_share, wall_share};
  double total = 0, worst_surface = 0;
  std::string shares;
  for (int s = 0; s < 6; ++s) {
    total += flux[s];
    worst_surface = std::max(worst_surface, std::fabs(flux[s] / expected[s] - 1));
    shares += std::to_string(flux[s]) + " ";
  }
  RecordProperty("flux_lm", std::to_string(total));
  RecordProperty("surface_flux_lm", shares);
  RecordProperty("worst_surface_error", std::to_string(worst_surface));
  RecordProperty("worst_texel_error", std::to_string(texels.worst));
  EXPECT_NEAR(2 * floor_share + 4 * wall_share, kFlux, 1e-6 * kFlux);  // the solid angles fill 4 pi
  EXPECT_NEAR(area, 80.0, 0.08);  // the texels cover the room, to 0.1%
  EXPECT_GT(texels.checked, 4000u);
  // CIE 171's 5% pointwise, on every texel: measured 1.3% at worst (the footprint's curvature).
  EXPECT_LT(texels.worst, 0.05);
  // A sum of texel means times areas is the integral up to the field's curvature within each texel,
  // which averages out over a surface: 0.5% bounds that. Measured 0.021% on the worst surface, and
  // 9,999.2 lm (-0.008%) in all.
  EXPECT_LT(worst_surface, 0.005);
  EXPECT_NEAR(total / kFlux, 1.0, 0.005);
}

// 5.4 with daylight. The report's 5.4 also has daylight scenarios, the flux through an opening
// (so its transcriptions say; its geometry is not transcribed), so this one is built from the
// intent: the black room of 5.9 with its 1 m unglazed roof opening, under a uniform sky of
// luminance L. The flux through a horizontal opening of area A under it is pi L A, and every lumen
// of it lands inside.
TEST(Cie171, Case5_4FluxThroughARoofOpeningIsConserved) {
  constexpr double kLuminance = 1000;  // cd/m2
  Scene scene;
  add_room(scene, test::add_material(scene, {0, 0, 0}), 1);
  BakeOptions options;
  options.sky.enabled = true;
  options.sky.distribution.model = SkyModel::Uniform;
  options.sky.zenith_luminance = float(kLuminance);
  // A texel's noise (tens of percent in the corners, where 0.3% of its rays find the opening)
  // averages out over the room's 711 texels.
  options.sky.rays = 8192;
  AtlasOptions atlas;
  atlas.texel_density = 3;  // 33 cm texels
  const BakeResult r = test::bake_scene(scene, atlas, options).result;
  const Elements& e = r.elements;
  double flux = 0, area = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i)) continue;
    flux += sum(r.irradiance[i]) / 3 * e.area[i];
    area += e.area[i];
  }
  const double entering = M_PI * kLuminance * 1.0;  // 1 m2
  RecordProperty("flux_lm", std::to_string(flux));
  RecordProperty("entering_lm", std::to_string(entering));
  EXPECT_NEAR(area, 79.0, 0.08);  // 80 m2 of room less the opening, to 0.1%
  // 0.5% bounds what is left of the rays' noise summed over the room: measured 3,144.1 lm for
  // 3,141.6 (+0.08%).
  EXPECT_NEAR(flux / entering, 1.0, 0.005);
}

// 5.6: light reflected by a diffuse surface. A 4 m x 4 m floor of reflectance 0.3, lit uniformly
// (E_hz), is the only source for the black surfaces that see it: the measurement wall standing on
// the floor's edge (4 m wide, from 0.5 m to 3 m up) and a 4 m x 4 m ceiling 3 m over the floor.
// The floor's exitance is M = rho E_hz (luminance M / pi), so a point receives E = rho E_hz F, F
// its form factor to the floor; the report tabulates E / (rho E_hz) in percent (its scenario 2;
// scenarios 1 and 3, other floor sizes, are not transcribed, so not built). Sunlight at 30 degrees'
// elevation from the side (x) lights the floor without touching the wall or the ceiling, so all
// that reaches them is the floor's reflection, solved and gathered like any other.
TEST(Cie171, Case5_6LightReflectedByADiffuseFloor) {
  constexpr double kRho = 0.3, kSun = 1000, kElevation = 30 * M_PI / 180;
  const double e_hz = kSun * std::sin(kElevation);
  const std::vector<Vec3> lit_floor = {{0, 0, 0}, {4, 0, 0}, {4, 0, 4}, {0, 0, 4}};
  const Vec3 into_room{0, 0, 1}, down{0, -1, 0};
  const ReportPoint table[] = {  // percent
      {"B", {2, 0.75f, 0}, into_room, 35.901}, {"C", {2, 1.25f, 0}, into_room, 27.992},
      {"D", {2, 1.75f, 0}, into_room, 21.639}, {"E", {2, 2.25f, 0}, into_room, 16.716},
      {"F", {2, 2.75f, 0}, into_room, 12.967}, {"G", {2, 3, 0.25f}, down, 26.80},
      {"H", {2, 3, 0.75f}, down, 30.94},       {"I", {2, 3, 1.25f}, down, 33.98},
      {"J", {2, 3, 1.75f}, down, 35.57},       {"K", {2, 3, 2.25f}, down, 35.57},
      {"L", {2, 3, 2.75f}, down, 33.98},       {"M", {2, 3, 3.25f}, down, 30.94},
      {"N", {2, 3, 3.75f}, down, 26.80},
  };
  double table_vs_closed_form = 0;
  for (const ReportPoint& p : table) {
    const double closed_form = 100 * test::point_to_polygon(p.at, p.normal, lit_floor);
    table_vs_closed_form = std::max(table_vs_closed_form, std::fabs(p.value / closed_form - 1));
  }
  RecordProperty("table_vs_closed_form", std::to_string(table_vs_closed_form));
  // Bounds how far the table is from this geometry's closed form: its rounding, measured 0.018%.
  EXPECT_LT(table_vs_closed_form, 0.0005);

  Scene scene;
  const int grey = test::add_material(scene, {float(kRho), float(kRho), float(kRho)});
  const int black = test::add_material(scene, {0, 0, 0});
  test::add_quad(scene, {0, 0, 4}, {4, 0, 0}, {0, 0, -4}, grey, "floor");
  test::add_quad(scene, {0, 0.5f, 0}, {4, 0, 0}, {0, 2.5f, 0}, black, "measurement wall");
  test::add_quad(scene, {0, 3, 0}, {4, 0, 0}, {0, 0, 4}, black, "ceiling");
  Light sun;
  sun.type = LightType::Directional;
  sun.intensity = float(kSun);
  sun.direction = {float(std::cos(kElevation)), -float(std::sin(kElevation)), 0};  // parallel to the wall
  scene.lights.push_back(sun);
  AtlasOptions atlas;
  atlas.texel_density = 4;  // 25 cm texels
  BakeOptions options;
  options.keep_direct = true;  // the measured surfaces get no sunlight; keep_direct makes sure
  options.gather.rays = 16384;  // F is 13% to 45%: 16,384 rays keep a texel's noise near 1%
  const BakeResult r = test::bake_scene(scene, atlas, options).result;
  const Elements& e = r.elements;
  std::vector<double> percent(e.size());
  Pointwise floor_texels, texels;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i)) continue;
    if (e.normal[i].y > 0.9f) {  // the floor: the sun alone, nothing comes back from black surfaces
      floor_texels.add(sum(r.irradiance[i]) / 3, e_hz, e.position[i]);
      continue;
    }
    percent[i] = 100 * (sum(r.irradiance[i]) - sum(r.direct[i])) / 3 / (kRho * e_hz);
    texels.add(percent[i], 100 * test::point_to_polygon(e.position[i], e.normal[i], lit_floor), e.position[i]);
  }
  RecordProperty("worst_floor_error", std::to_string(floor_texels.worst));
  RecordProperty("worst_texel_error", std::to_string(texels.worst));
  // E_hz is the same everywhere on the floor (no shadow, nothing reflected back): measured exact.
  EXPECT_LT(floor_texels.worst, 1e-4);
  EXPECT_GT(texels.checked, 400u);
  // CIE 171's 5% pointwise, on every texel of the wall and the ceiling: the gather's noise and the
  // footprint's curvature, measured 1.1% at worst.
  EXPECT_LT(texels.worst, 0.05) << "at " << texels.worst_at.x << ", " << texels.worst_at.y << ", "
                                << texels.worst_at.z;
  const Readings readings = read_at_report_points(e, percent, table, 0.3);
  RecordProperty("readings_percent", readings.text);
  RecordProperty("worst_point_error", std::to_string(readings.worst));
  // CIE 171's 5% at the report's points, read from the lightmap: measured 0.52% at worst (I,
  // 33.80% for 33.98%).
  EXPECT_LT(readings.worst, 0.05);
}

// 5.7: diffuse reflection past an obstruction. A 4 m x 3 m wall of reflectance 0.6, lit uniformly
// (E_v), faces a black measurement wall 4 m away across a black floor (2.5 m of it measured); a
// black block 4 m wide, 1 m high and 0.2 m thick stands on the floor 2.5 m from the measurement
// wall and hides the bottom of the lit wall from it. E / (rho E_v) at a point is the form factor to
// the part of the lit wall it sees: a rectangle, cut along the line the block's top edge (the near
// one from below, the far one from above) throws onto the lit wall.
// The report's Table 19 is a known erratum (Ashdown, "CIE 171:2006 - Errata", Lighting Analysts;
// Dau 2016, the Iray validation, recomputed it). The test holds the bake to the closed form, and the
// closed form reproduces the corrected table the Iray validation published, quoted below.
// Sunlight at 60 degrees' incidence on the lit wall passes over the measurement wall and the block.
TEST(Cie171, Case5_7AnObstructionHidesPartOfAReflectingWall) {
  constexpr double kRho = 0.6, kSun = 1000, kIncidence = 60 * M_PI / 180;
  const double e_v = kSun * std::cos(kIncidence);
  // The lit wall (z = 4) seen from p, over the block's top edges (y = 1 at z = 2.5 and z = 2.7).
  auto form_factor = [](Vec3 p, Vec3 normal) {
    double cut = 0;  // height on the lit wall below which the block hides it
    for (double edge : {2.5, 2.7}) cut = std::max(cut, p.y + (4 - p.z) / (edge - p.z) * (1 - p.y));
    if (cut >= 3) return 0.0;
    const float y = float(cut);
    return test::point_to_polygon(p, normal, {{0, y, 4}, {4, y, 4}, {4, 3, 4}, {0, 3, 4}});
  };
  const Vec3 into_room{0, 0, 1}, up{0, 1, 0};
  const ReportPoint table[] = {  // percent, as corrected by the Iray validation
      {"A", {2, 2.75f, 0}, into_room, 16.07}, {"B", {2, 2.25f, 0}, into_room, 16.33},
      {"C", {2, 1.75f, 0}, into_room, 15.40}, {"D", {2, 1.25f, 0}, into_room, 13.32},
      {"E", {2, 0.75f, 0}, into_room, 10.32}, {"F", {2, 0.25f, 0}, into_room, 7.08},
      {"G", {2, 0, 0.25f}, up, 3.38},         {"H", {2, 0, 0.75f}, up, 3.63},
      {"I", {2, 0, 1.25f}, up, 3.01},         {"J", {2, 0, 1.75f}, up, 0},
      {"K", {2, 0, 2.25f}, up, 0},
  };
  double table_vs_closed_form = 0;  // in percentage points: J and K are zero
  for (const ReportPoint& p : table)
    table_vs_closed_form = std::max(table_vs_closed_form, std::fabs(p.value - 100 * form_factor(p.at, p.normal)));
  RecordProperty("table_vs_closed_form_points", std::to_string(table_vs_closed_form));
  // Bounds how far the corrected table is from this geometry's closed form: its rounding to 0.01,
  // measured 0.0031 points.
  EXPECT_LT(table_vs_closed_form, 0.006);

  Scene scene;
  const int grey = test::add_material(scene, {float(kRho), float(kRho), float(kRho)});
  const int black = test::add_material(scene, {0, 0, 0});
  test::add_quad(scene, {4, 0, 4}, {-4, 0, 0}, {0, 3, 0}, grey, "lit wall");
  test::add_quad(scene, {0, 0, 0}, {4, 0, 0}, {0, 3, 0}, black, "measurement wall");
  test::add_quad(scene, {0, 0, 2.5f}, {4, 0, 0}, {0, 0, -2.5f}, black, "floor");
  test::add_quad(scene, {4, 0, 2.5f}, {-4, 0, 0}, {0, 1, 0}, black, "block");      // faces -z
  test::add_quad(scene, {0, 0, 2.7f}, {4, 0, 0}, {0, 1, 0}, black, "block");       // faces +z
  test::add_quad(scene, {0, 1, 2.7f}, {4, 0, 0}, {0, 0, -0.2f}, black, "block");   // top
  test::add_quad(scene, {0, 0, 2.5f}, {0, 0, 0.2f}, {0, 1, 0}, black, "block");    // faces -x
  test::add_quad(scene, {4, 0, 2.7f}, {0, 0, -0.2f}, {0, 1, 0}, black, "block");   // faces +x
  Light sun;
  sun.type = LightType::Directional;
  sun.intensity = float(kSun);
  sun.direction = {0, -float(std::sin(kIncidence)), float(std::cos(kIncidence))};
  scene.lights.push_back(sun);
  AtlasOptions atlas;
  atlas.texel_density = 4;  // 25 cm texels
  BakeOptions options;
  options.keep_direct = true;  // the sun falls on the floor too: only the reflected part is measured
  // The floor sees only the top of the lit wall over the block (from 1.67 m up at G, 2.2 m at I:
  // F 3%): with 65,536 gather rays its worst texel is 3.1% off, with 32,768 3.4%, with 16,384 4.9%.
  options.gather.rays = 65536;
  const BakeResult r = test::bake_scene(scene, atlas, options).result;
  const Elements& e = r.elements;
  std::vector<double> percent(e.size());
  Pointwise lit, texels;
  // Percentage points, where the block hides all or nearly all of the lit wall (F under 2%: the
  // floor from 1.5 m on, where F falls to zero within a texel): relative error means nothing there.
  double worst_faint = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i)) continue;
    const Vec3 p = e.position[i], n = e.normal[i];
    if (n.z < -0.9f && p.z > 3.99f) {  // the lit wall: the sun alone, uniform
      lit.add(sum(r.irradiance[i]) / 3, e_v, p);
      continue;
    }
    const bool measured = (n.z > 0.9f && p.z < 0.01f) || (n.y > 0.9f && p.y < 0.01f);
    if (!measured) continue;
    percent[i] = 100 * (sum(r.irradiance[i]) - sum(r.direct[i])) / 3 / (kRho * e_v);
    const double expected = 100 * form_factor(p, n);
    if (expected >= 2)
      texels.add(percent[i], expected, p);
    else
      worst_faint = std::max(worst_faint, std::fabs(percent[i] - expected));
  }
  RecordProperty("worst_lit_wall_error", std::to_string(lit.worst));
  RecordProperty("worst_texel_error", std::to_string(texels.worst));
  RecordProperty("worst_faint_texel_points", std::to_string(worst_faint));
  // E_v is the same everywhere on the lit wall (nothing shades it): measured exact.
  EXPECT_LT(lit.worst, 1e-4);
  EXPECT_GT(texels.checked, 200u);
  // CIE 171's 5% pointwise, on every texel of the measurement wall and floor with F of 2% or more:
  // the gather's noise and the footprint's curvature, measured 3.1% at worst (the floor, 1.375 m out).
  EXPECT_LT(texels.worst, 0.05) << "at " << texels.worst_at.x << ", " << texels.worst_at.y << ", "
                                << texels.worst_at.z;
  // Where F is under 2%, 0.15 points: 5% of the report's dimmest lit point (I, 3.01%), the absolute
  // accuracy CIE 171 asks there. Measured 0.079 points (the texels the shadow line crosses, where
  // the footprint's mean is 4% under the sample point's value).
  EXPECT_LT(worst_faint, 0.15);
  const Readings readings = read_at_report_points(e, percent, table, 0.3);
  RecordProperty("readings_percent", readings.text);
  RecordProperty("worst_point_error", std::to_string(readings.worst));
  // CIE 171's 5% at the report's lit points, read from the lightmap: measured 2.8% at worst (I,
  // 2.93% for 3.01%). J and K (0) are held by the texels above: a reading at J, where F reaches 0,
  // fits a plane across that kink (0.53 points).
  EXPECT_LT(readings.worst, 0.05);
}

// 5.8: interreflections in a closed cube. A source of flux Phi inside a room of surface S and
// uniform reflectance rho: every lumen is reflected rho, rho^2, ... times before it is absorbed,
// so the mean indirect illuminance is rho Phi / (S (1 - rho)), whatever the source's position.
class Cie171Cube : public ::testing::TestWithParam<float> {};

TEST_P(Cie171Cube, Case5_8MeanIndirectIlluminanceIsRhoPhiOverSOneMinusRho) {
  const float rho = GetParam();
  Scene scene;
  const int walls = test::add_material(scene, {rho, rho, rho});
  test::add_box(scene, {0, 0, 0}, {4, 4, 4}, true, walls, "cube");
  const float candela = 1000;
  scene.lights.push_back(point_light({1.3f, 2.9f, 2.2f}, candela));  // off centre, on purpose
  BakeOptions options;
  options.keep_direct = true;
  options.solve.tolerance = 1e-4;
  const BakeResult r = test::bake_scene(scene, AtlasOptions{}, options).result;
  const Elements& e = r.elements;
  double indirect = 0, area = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i)) continue;
    indirect += (sum(r.irradiance[i]) - sum(r.direct[i])) / 3 * e.area[i];
    area += e.area[i];
  }
  const double phi = 4 * M_PI * candela, surface = 6 * 4.0 * 4.0;
  const double expected = rho * phi / (surface * (1 - rho));
  RecordProperty("mean_indirect_lux", std::to_string(indirect / area));
  RecordProperty("expected_lux", std::to_string(expected));
  EXPECT_NEAR(area, surface, 1e-3 * surface);
  // Measured -0.005%, -0.008% and -0.019% for rho 0.5, 0.9, 0.95. 1% bounds the solve's
  // stopping point (0.01% of the light unshot, spread by its ambient term) and the form factors'
  // sampling, which reciprocity keeps conservative.
  EXPECT_NEAR(indirect / area / expected, 1.0, 0.01);
}

INSTANTIATE_TEST_SUITE_P(Reflectances, Cie171Cube, ::testing::Values(0.5f, 0.9f, 0.95f),
                         [](const auto& info) { return "rho_" + std::to_string(int(std::lround(info.param * 100))); });

// 5.9: the sky component through a roof opening. A black 4 m x 4 m x 3 m room with a 1 m square
// opening in the middle of its roof, under a uniform sky of luminance L: at a floor point the
// sky component, E / (pi L), is the view factor to the opening (Howell B-3 in closed form).
TEST(Cie171, Case5_9SkyComponentThroughARoofOpeningIsTheViewFactor) {
  Scene scene;
  const int black = test::add_material(scene, {0, 0, 0});
  add_room(scene, black, 1);  // the roof, facing down, around the opening [1.5, 2.5] x [1.5, 2.5]
  BakeOptions options;
  options.sky.enabled = true;
  options.sky.distribution.model = SkyModel::Uniform;
  options.sky.zenith_luminance = 1000;  // cd/m2
  // 0.3% (corners) to 3% (centre) of a floor texel's cosine-weighted rays reach the opening:
  // 131,072 of them keep a corner texel's noise near 1.5%.
  options.sky.rays = 131072;
  AtlasOptions atlas;
  atlas.texel_density = 3;  // 33 cm texels
  const BakeResult r = test::bake_scene(scene, atlas, options).result;
  const Elements& e = r.elements;
  size_t checked = 0;
  double worst = 0, mean_error = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i) || e.normal[i].y < 0.9f || e.position[i].y > 0.01f) continue;  // floor texels
    const Vec3 p = e.position[i];
    const double view_factor = test::point_to_rectangle(p.x, p.z, 1.5, 2.5, 1.5, 2.5, 3.0);
    const double sky_component = sum(r.irradiance[i]) / 3 / (M_PI * 1000);
    worst = std::max(worst, std::fabs(sky_component / view_factor - 1));
    mean_error += sky_component / view_factor - 1;
    ++checked;
  }
  mean_error /= double(checked);
  RecordProperty("worst_relative_error", std::to_string(worst));
  RecordProperty("mean_relative_error", std::to_string(mean_error));
  EXPECT_GT(checked, 100u);
  // CIE 171's 5% pointwise; the mean within 0.5% bounds the bias (the noise averages out).
  // Measured: 2.4% at worst, -0.02% on average over the 144 floor texels.
  EXPECT_LT(worst, 0.05);
  EXPECT_LT(std::fabs(mean_error), 0.005);
}


// ---------------------------------------------------------------------------------------------
// Daylight, cases 5.9 to 5.12: sky components through openings in the black 4 m x 4 m x 3 m room
// (nothing inside it reflects), under the report's 16 skies: the 15 CIE standard general skies
// (ISO 15469) and, sixteenth, the traditional CIE overcast sky. In every case the sun is 60 degrees
// up, due south (for the skies that depend on it), and direct sunlight is left out. The report
// tabulates the sky component SC, the illuminance from the sky seen through the opening in percent
// of the exterior horizontal illuminance E_hz (the whole unobstructed sky on a horizontal plane);
// for the facade openings SC plus the external reflected component ERC, the ground seen through
// the opening, of uniform luminance rho E_hz / pi with rho = 0.3 (the report's definition, which is
// the ground radbake's sky puts below the horizon when there is no sun).
//   5.9  roof opening, unglazed: 1 m x 1 m in the middle of the roof, or the whole roof (Tables B.1
//        to B.4);
//   5.10 the same glazed with 6 mm clear glass (Tables B.5 to B.8);
//   5.11 facade opening in the south wall, unglazed: 2 m wide and 1 m high on a 1 m sill in the
//        middle, or the whole wall, 4 m x 3 m (Tables B.9 to B.14);
//   5.12 the same glazed (Tables B.15 to B.20).
// The report's points (its Figs. 15 and 20): A to F up the middle of the north wall (z = 0), 2.75 m
// to 0.25 m high; G to N along the floor's centre line from that wall, 0.25 m to 3.75 m out; and for
// the facade openings G' to N' on the ceiling over them. The tables are those the CyclesCIEtest
// repository transcribed (its engine/cie171/test_cases_daylight.py, with notes in its
// docs/CIE/NOTES.md and IMPLEMENTATION_AUDIT.md); this geometry and its orientation are confirmed the way 5.3's are: the
// closed form below, for the 16 skies, gives the tables. Where a table departs from it, the test
// names the entries and says why, and holds the bake to the closed form there.
//
// The closed form is independent of baker/: the sky's luminance from ISO 15469's formula
// (test::cie171_sky_luminance), E_hz and the illuminance through the opening by quadrature in
// double precision (test::illuminance_through_opening), not by rays.

constexpr double kSunZenith = M_PI / 6, kSunAzimuth = M_PI;  // 60 degrees up, due south
constexpr double kGroundReflectance = 0.3;                   // the facade cases' ground
constexpr double kExteriorLux = 10000;                       // E_hz of the bakes' skies
constexpr int kCieOvercast = 16;                             // the tables' sixteenth sky

// The sky's luminance relative to its zenith in the direction d, in the scene's frame: y up, north
// -z (SkyLight's default), so east is +x and the sun, due south, is toward +z.
double sky_toward(int type, test::Vec3d d) {
  return test::cie171_sky_luminance(type, std::acos(std::clamp(d.y, -1.0, 1.0)), std::atan2(d.x, -d.z), kSunZenith,
                                    kSunAzimuth);
}

// One of the report's skies: its type (kCieOvercast for the CIE overcast sky) and E_hz / L_z.
struct ReportSky {
  int type;
  double horizontal;  // sr
  explicit ReportSky(int t)
      : type(t), horizontal(test::cie171_sky_horizontal_illuminance(t, kSunZenith, kSunAzimuth)) {}
};

// An opening: the parallelogram corner + s u + t v (s, t in [0, 1]), in the roof (y = 3) or in the
// south wall (z = 4, with v vertical).
struct Opening {
  Vec3 corner, u, v;
  bool facade;
};
const Opening kRoof1m{{1.5f, 3, 1.5f}, {1, 0, 0}, {0, 0, 1}, false};
const Opening kRoof4m{{0, 3, 0}, {4, 0, 0}, {0, 0, 4}, false};
const Opening kFacade2x1{{1, 1, 4}, {2, 0, 0}, {0, 1, 0}, true};  // 2 m wide, 1 m high, on a 1 m sill
const Opening kFacade4x3{{0, 0, 4}, {4, 0, 0}, {0, 3, 0}, true};  // the whole south wall

// What fills the opening: nothing; the report's 6 mm clear glass, whose transmittance falls with the
// angle of incidence (test::clear_glass_transmittance); or radbake's glazing, a thin pane of the
// report glass's 0.8788 along its normal, falling away from it as a clear pane of index 1.5 does
// (test::thin_pane_transmittance, normalised).
enum class Glass { None, Report, Radbake };
const float kPaneTransmittance = float(test::clear_glass_transmittance(1));

// The closed form: what x, facing n, gets through the opening, in percent of E_hz. The sky seen
// through it, and below the horizon the ground (luminance rho E_hz / pi), times the glass's share.
double daylight_percent(const Opening& o, Glass glass, const ReportSky& sky, Vec3 x, Vec3 n) {
  const test::Vec3d w = test::to_double(normalize(cross(o.u, o.v)));
  const double ground = kGroundReflectance * sky.horizontal / M_PI;  // relative to L_z
  auto seen = [&](test::Vec3d, test::Vec3d d) {
    double luminance = d.y > 0 ? sky_toward(sky.type, d) : ground;
    const double incidence = std::fabs(d.x * w.x + d.y * w.y + d.z * w.z);  // its cosine on the pane
    if (glass == Glass::Report) luminance *= test::clear_glass_transmittance(incidence);
    if (glass == Glass::Radbake)
      luminance *= kPaneTransmittance * test::thin_pane_transmittance(incidence, 1.5) / test::thin_pane_transmittance(1, 1.5);
    return luminance;
  };
  const test::Vec3d p = test::to_double(x), c = test::to_double(o.corner), u = test::to_double(o.u),
                    v = test::to_double(o.v);
  // Through a facade opening the view turns from ground to sky at the eye's height: integrate the
  // parts below and above it apart (the luminance jumps there).
  const double split = o.facade ? std::clamp((p.y - c.y) / v.y, 0.0, 1.0) : 0.0;
  auto part = [&](double from, double to) {
    if (to <= from) return 0.0;
    const test::Vec3d corner{c.x + v.x * from, c.y + v.y * from, c.z + v.z * from};
    const test::Vec3d side{v.x * (to - from), v.y * (to - from), v.z * (to - from)};
    return test::illuminance_through_opening(p, test::to_double(n), corner, u, side, seen);
  };
  return 100 * (part(0, split) + part(split, 1)) / sky.horizontal;
}

// The report's points: A to F on the north wall, G to N on the floor, G' to N' on the ceiling.
struct DaylightPoint {
  const char* name;
  Vec3 at, normal;
};
const DaylightPoint kDaylightPoints[22] = {
    {"A", {2, 2.75f, 0}, {0, 0, 1}},    {"B", {2, 2.25f, 0}, {0, 0, 1}},    {"C", {2, 1.75f, 0}, {0, 0, 1}},
    {"D", {2, 1.25f, 0}, {0, 0, 1}},    {"E", {2, 0.75f, 0}, {0, 0, 1}},    {"F", {2, 0.25f, 0}, {0, 0, 1}},
    {"G", {2, 0, 0.25f}, {0, 1, 0}},    {"H", {2, 0, 0.75f}, {0, 1, 0}},    {"I", {2, 0, 1.25f}, {0, 1, 0}},
    {"J", {2, 0, 1.75f}, {0, 1, 0}},    {"K", {2, 0, 2.25f}, {0, 1, 0}},    {"L", {2, 0, 2.75f}, {0, 1, 0}},
    {"M", {2, 0, 3.25f}, {0, 1, 0}},    {"N", {2, 0, 3.75f}, {0, 1, 0}},    {"G'", {2, 3, 0.25f}, {0, -1, 0}},
    {"H'", {2, 3, 0.75f}, {0, -1, 0}},  {"I'", {2, 3, 1.25f}, {0, -1, 0}},  {"J'", {2, 3, 1.75f}, {0, -1, 0}},
    {"K'", {2, 3, 2.25f}, {0, -1, 0}},  {"L'", {2, 3, 2.75f}, {0, -1, 0}},  {"M'", {2, 3, 3.25f}, {0, -1, 0}},
    {"N'", {2, 3, 3.75f}, {0, -1, 0}},
};
size_t point_count(const Opening& o) { return o.facade ? 22 : 14; }

// A table of the report, in percent of E_hz: a row per sky (types 1 to 15, then the CIE overcast
// sky) over A to F and G to N; for the facade openings also G' to N', the same under every sky
// (they see only the ground).
struct DaylightTable {
  double rows[16][14];
  double ceiling[8];
  double at(int type, size_t point) const { return point < 14 ? rows[type - 1][point] : ceiling[point - 14]; }
};

// 5.9, the 1 m roof opening: Tables B.1 (A to F) and B.2 (G to N). Type 3's wall values as the
// Iray validation corrected them: the report prints A to F in reverse (the closed form agrees).
const DaylightTable kTableB1B2 = {
    {
        {0.46, 1.64, 2.34, 2.26, 1.88, 1.47, 2.33, 3.11, 3.84, 4.29, 4.29, 3.84, 3.11, 2.33},  // type 1
        {0.40, 1.72, 2.86, 3.15, 2.90, 2.44, 4.00, 5.00, 5.47, 5.37, 4.73, 3.76, 2.76, 1.90},  // type 2
        {0.79, 2.05, 2.46, 2.22, 1.78, 1.36, 2.13, 2.80, 3.42, 3.81, 3.81, 3.42, 2.80, 2.13},  // type 3
        {0.71, 2.17, 3.06, 3.15, 2.79, 2.30, 3.72, 4.58, 4.97, 4.85, 4.27, 3.42, 2.53, 1.77},  // type 4
        {1.04, 2.39, 2.59, 2.20, 1.70, 1.27, 1.95, 2.52, 3.04, 3.37, 3.37, 3.04, 2.52, 1.95},  // type 5
        {0.94, 2.58, 3.27, 3.16, 2.71, 2.19, 3.47, 4.20, 4.49, 4.36, 3.84, 3.09, 2.31, 1.65},  // type 6
        {0.82, 2.52, 3.61, 3.91, 3.69, 3.19, 5.21, 5.96, 5.70, 4.93, 3.92, 2.90, 2.04, 1.39},  // type 7
        {0.72, 2.43, 3.86, 4.56, 4.60, 4.18, 6.94, 7.65, 6.78, 5.38, 3.93, 2.71, 1.80, 1.17},  // type 8
        {1.64, 3.53, 3.67, 3.14, 2.49, 1.91, 2.88, 3.34, 3.45, 3.29, 2.89, 2.37, 1.83, 1.37},  // type 9
        {1.46, 3.52, 4.13, 3.96, 3.45, 2.84, 4.42, 4.85, 4.49, 3.80, 3.02, 2.27, 1.65, 1.18},  // type 10
        {1.30, 3.46, 4.49, 4.69, 4.39, 3.79, 6.01, 6.36, 5.45, 4.23, 3.09, 2.16, 1.48, 1.01},  // type 11
        {1.74, 3.76, 4.55, 4.61, 4.24, 3.63, 5.72, 6.01, 5.12, 3.97, 2.90, 2.03, 1.40, 0.96},  // type 12
        {1.61, 3.76, 4.87, 5.16, 4.89, 4.26, 6.76, 7.01, 5.80, 4.30, 2.98, 1.99, 1.30, 0.86},  // type 13
        {2.22, 4.01, 4.88, 5.05, 4.72, 4.08, 6.43, 6.64, 5.47, 4.05, 2.81, 1.87, 1.23, 0.82},  // type 14
        {2.14, 4.16, 5.23, 5.47, 5.11, 4.41, 6.94, 7.19, 5.93, 4.36, 2.96, 1.90, 1.20, 0.76},  // type 15
        {0.56, 1.78, 2.32, 2.20, 1.82, 1.43, 2.29, 3.07, 3.82, 4.29, 4.29, 3.82, 3.07, 2.29},  // overcast
    },
    {},
};

// 5.9, the whole roof open: Tables B.3 and B.4.
const DaylightTable kTableB3B4 = {
    {
        {37.84, 31.72, 26.85, 22.10, 17.89, 14.38, 31.87, 37.30, 41.27, 43.35, 43.35, 41.27, 37.30, 31.87},  // type 1
        {42.03, 37.03, 32.75, 28.13, 23.70, 19.79, 42.01, 46.99, 49.85, 50.08, 47.76, 42.89, 36.40, 29.02},  // type 2
        {42.77, 34.03, 27.43, 21.81, 17.23, 13.61, 29.16, 33.92, 37.40, 39.22, 39.22, 37.40, 33.92, 29.16},  // type 3
        {46.85, 39.59, 33.65, 28.08, 23.16, 19.04, 39.19, 43.59, 46.07, 46.17, 43.97, 39.50, 33.60, 26.94},  // type 4
        {46.74, 36.05, 28.05, 21.67, 16.73, 12.98, 26.80, 30.95, 33.99, 35.58, 35.58, 33.99, 30.95, 26.80},  // type 5
        {50.91, 41.92, 34.58, 28.15, 22.76, 18.41, 36.63, 40.47, 42.59, 42.57, 40.48, 36.37, 31.03, 25.04},  // type 6
        {51.83, 44.95, 38.55, 32.55, 27.23, 22.77, 44.08, 47.33, 48.53, 47.09, 43.13, 36.83, 29.80, 22.81},  // type 7
        {52.27, 47.46, 41.91, 36.33, 31.13, 26.65, 50.65, 53.33, 53.73, 51.05, 45.38, 37.05, 28.56, 20.78},  // type 8
        {61.28, 47.22, 36.33, 27.92, 21.55, 16.78, 30.70, 33.35, 34.69, 34.41, 32.58, 29.29, 25.19, 20.69},  // type 9
        {61.85, 50.36, 40.59, 32.56, 26.13, 21.10, 37.82, 39.98, 40.52, 38.95, 35.42, 30.18, 24.58, 19.14},  // type 10
        {61.99, 53.01, 44.28, 36.68, 30.26, 25.08, 44.36, 46.04, 45.85, 43.10, 37.95, 30.84, 23.89, 17.68},  // type 11
        {66.34, 54.33, 44.25, 36.10, 29.48, 24.25, 42.33, 43.82, 43.54, 40.85, 35.92, 29.17, 22.62, 16.79},  // type 12
        {66.63, 56.51, 47.18, 39.24, 32.56, 27.15, 42.07, 48.25, 47.47, 43.96, 37.92, 29.91, 22.38, 15.95},  // type 13
        {71.83, 57.51, 46.84, 38.44, 31.62, 26.20, 44.95, 45.99, 45.15, 41.74, 35.96, 28.34, 21.22, 15.16},  // type 14
        {73.20, 60.07, 49.66, 41.13, 34.02, 28.29, 48.42, 49.33, 48.19, 44.25, 37.79, 29.37, 21.53, 14.91},  // type 15
        {39.28, 32.32, 26.79, 21.78, 17.53, 14.05, 31.36, 36.76, 40.71, 42.76, 42.76, 40.71, 36.76, 31.36},  // overcast
    },
    {},
};

// 5.10, the 1 m roof opening glazed: Tables B.5 and B.6.
const DaylightTable kTableB5B6 = {
    {
        {0.15, 1.17, 1.91, 1.92, 1.62, 1.28, 2.04, 2.73, 3.38, 3.78, 3.78, 3.38, 2.73, 2.04},  // type 1
        {0.13, 1.22, 2.34, 2.68, 2.50, 2.12, 3.50, 4.39, 4.81, 4.72, 4.16, 3.31, 2.42, 1.67},  // type 2
        {0.26, 1.45, 2.01, 1.89, 1.54, 1.18, 1.87, 2.46, 3.01, 3.35, 3.35, 3.01, 2.46, 1.87},  // type 3
        {0.24, 1.54, 2.51, 2.68, 2.41, 2.01, 3.26, 4.03, 4.37, 4.26, 3.76, 3.01, 2.22, 1.55},  // type 4
        {0.35, 1.69, 2.12, 1.87, 1.47, 1.11, 1.71, 2.22, 2.68, 2.96, 2.96, 2.68, 2.22, 1.71},  // type 5
        {0.31, 1.82, 2.67, 2.69, 2.34, 1.90, 3.04, 3.69, 3.95, 3.83, 3.37, 2.72, 2.03, 1.44},  // type 6
        {0.28, 1.78, 2.96, 3.33, 3.19, 2.78, 4.56, 5.23, 5.02, 4.34, 3.45, 2.55, 1.79, 1.22},  // type 7
        {0.24, 1.73, 3.16, 3.89, 3.98, 3.64, 6.08, 6.72, 5.97, 4.73, 3.46, 2.38, 1.58, 1.03},  // type 8
        {0.55, 2.49, 3.00, 2.67, 2.15, 1.66, 2.52, 2.93, 3.04, 2.89, 2.54, 2.08, 1.61, 1.20},  // type 9
        {0.49, 2.48, 3.38, 3.37, 2.98, 2.47, 3.87, 4.26, 3.95, 3.34, 2.65, 2.00, 1.45, 1.03},  // type 10
        {0.44, 2.45, 3.68, 4.00, 3.79, 3.30, 5.26, 5.59, 4.79, 3.72, 2.72, 1.90, 1.31, 0.89},  // type 11
        {0.58, 2.65, 3.72, 3.92, 3.66, 3.16, 5.01, 5.28, 4.51, 3.49, 2.55, 1.79, 1.23, 0.84},  // type 12
        {0.54, 2.66, 3.99, 4.40, 4.23, 3.71, 5.91, 6.16, 5.10, 3.79, 2.62, 1.75, 1.14, 0.75},  // type 13
        {0.74, 2.83, 3.99, 4.30, 4.08, 3.55, 5.63, 5.84, 4.81, 3.56, 2.47, 1.65, 1.08, 0.72},  // type 14
        {0.71, 2.94, 4.28, 4.66, 4.42, 3.84, 6.08, 6.32, 5.22, 3.83, 2.60, 1.68, 1.05, 0.66},  // type 15
        {0.19, 1.26, 1.90, 1.87, 1.57, 1.24, 2.00, 2.70, 3.36, 3.78, 3.78, 3.36, 2.70, 2.00},  // overcast
    },
    {},
};

// 5.10, the whole roof glazed: Tables B.7 and B.8.
const DaylightTable kTableB7B8 = {
    {
        {28.64, 25.36, 22.25, 18.71, 15.34, 12.43, 27.88, 32.69, 36.22, 38.07, 38.07, 36.22, 32.69, 27.88},  // type 1
        {32.75, 30.05, 27.34, 23.90, 20.36, 17.13, 36.75, 41.18, 43.74, 43.98, 41.96, 37.67, 31.94, 25.42},  // type 2
        {30.83, 26.68, 22.56, 18.41, 14.76, 11.76, 25.50, 29.73, 32.82, 34.45, 34.45, 32.82, 29.73, 25.50},  // type 3
        {35.03, 31.59, 27.90, 23.79, 19.87, 16.46, 34.27, 38.19, 40.42, 40.55, 38.63, 34.69, 29.48, 23.59},  // type 4
        {32.66, 27.87, 22.92, 18.23, 14.31, 11.20, 23.43, 27.12, 29.83, 31.25, 31.25, 29.83, 27.12, 23.43},  // type 5
        {37.02, 33.01, 28.50, 23.78, 19.50, 15.91, 32.02, 35.45, 37.37, 37.38, 35.56, 31.94, 27.22, 21.92},  // type 6
        {38.66, 35.90, 32.00, 27.60, 23.37, 19.69, 38.53, 41.45, 42.56, 41.35, 37.90, 32.35, 26.15, 19.98},  // type 7
        {39.78, 38.32, 34.97, 30.89, 26.76, 23.07, 44.27, 46.70, 47.12, 44.82, 39.88, 32.56, 25.08, 18.21},  // type 8
        {41.84, 36.14, 29.54, 23.44, 18.41, 14.47, 26.82, 29.20, 30.42, 30.21, 28.61, 25.72, 22.09, 18.10},  // type 9
        {43.50, 39.15, 33.27, 27.44, 22.36, 18.22, 33.03, 34.99, 35.52, 34.19, 31.11, 26.51, 21.56, 16.76},  // type 10
        {44.66, 41.73, 36.52, 31.00, 25.93, 21.67, 38.74, 40.29, 40.19, 37.83, 33.34, 27.10, 20.96, 15.49},  // type 11
        {46.30, 42.34, 36.37, 30.47, 25.25, 20.95, 36.96, 38.34, 38.16, 35.86, 31.56, 25.63, 19.85, 14.71},  // type 12
        {47.40, 44.42, 38.91, 33.18, 27.90, 23.46, 41.10, 42.22, 41.60, 38.58, 33.32, 26.28, 19.65, 13.98},  // type 13
        {49.09, 44.76, 38.51, 32.46, 27.08, 22.63, 39.24, 40.23, 39.57, 36.64, 31.60, 24.91, 18.63, 13.29},  // type 14
        {50.82, 46.97, 40.89, 34.75, 29.15, 24.44, 42.27, 43.16, 42.23, 38.84, 33.21, 25.82, 18.91, 13.07},  // type 15
        {29.21, 25.63, 22.14, 18.43, 15.03, 12.15, 27.44, 32.23, 35.73, 37.56, 37.56, 35.73, 32.23, 27.44},  // overcast
    },
    {},
};

// 5.11, the 2 m x 1 m facade opening: Tables B.9 (A to F), B.10 (G to N) and B.11 (G' to N').
const DaylightTable kTableB9B11 = {
    {
        {0.95, 1.06, 1.25, 1.51, 1.70, 1.86, 0.87, 1.31, 2.02, 3.20, 5.07, 7.64, 9.33, 5.09},  // type 1
        {0.95, 1.06, 1.18, 1.33, 1.55, 1.83, 0.92, 1.42, 2.30, 3.86, 6.58, 10.77, 13.66, 6.33},  // type 2
        {0.95, 1.06, 1.56, 2.42, 2.75, 2.58, 1.08, 1.54, 2.26, 3.40, 5.11, 7.34, 8.61, 4.56},  // type 3
        {0.95, 1.06, 1.45, 2.14, 2.53, 2.58, 1.16, 1.71, 2.62, 4.16, 6.73, 10.52, 12.82, 5.80},  // type 4
        {0.95, 1.06, 1.79, 3.09, 3.54, 3.17, 1.27, 1.75, 2.49, 3.59, 5.19, 7.11, 7.99, 4.13},  // type 5
        {0.95, 1.06, 1.65, 2.76, 3.32, 3.22, 1.37, 1.97, 2.92, 4.46, 6.91, 10.33, 12.07, 5.30},  // type 6
        {0.95, 1.06, 1.53, 2.43, 2.96, 3.01, 1.34, 1.98, 3.04, 4.86, 8.04, 13.00, 15.85, 5.97},  // type 7
        {0.95, 1.06, 1.42, 2.13, 2.64, 2.81, 1.30, 1.96, 3.10, 5.16, 8.96, 15.41, 19.39, 6.50},  // type 8
        {0.95, 1.06, 2.27, 4.61, 5.52, 4.82, 1.87, 2.55, 3.55, 5.05, 7.19, 9.74, 10.30, 4.19},  // type 9
        {0.95, 1.06, 2.08, 4.10, 5.03, 4.61, 1.87, 2.61, 3.77, 5.61, 8.50, 12.47, 13.77, 4.81},  // type 10
        {0.95, 1.06, 1.91, 3.65, 4.56, 4.38, 1.84, 2.63, 3.91, 6.04, 9.62, 15.00, 17.13, 5.33},  // type 11
        {0.95, 1.06, 2.39, 4.93, 5.80, 5.01, 2.00, 2.80, 4.06, 6.13, 9.54, 14.57, 16.35, 5.03},  // type 12
        {0.95, 1.06, 2.23, 4.52, 5.43, 4.87, 2.00, 2.85, 4.21, 6.52, 10.43, 16.41, 18.67, 5.43},  // type 13
        {0.95, 1.06, 3.34, 6.87, 7.12, 5.51, 2.14, 2.98, 4.32, 6.55, 10.29, 15.89, 17.82, 5.14},  // type 14
        {0.95, 1.06, 3.17, 6.54, 6.96, 5.58, 2.22, 3.12, 4.57, 6.99, 11.08, 17.18, 19.25, 5.52},  // type 15
        {0.95, 1.06, 1.28, 1.71, 2.06, 2.14, 0.95, 1.38, 2.07, 3.19, 4.97, 7.42, 9.11, 5.04},  // overcast
    },
    {0.38, 0.53, 0.75, 1.08, 1.56, 2.14, 2.40, 1.24},
};

// 5.11, the whole south wall open: Tables B.12 to B.14.
const DaylightTable kTableB12B14 = {
    {
        {5.25, 6.11, 6.98, 7.99, 8.77, 9.35, 4.27, 5.92, 8.33, 11.82, 16.84, 23.83, 33.05, 44.06},  // type 1
        {5.09, 5.78, 6.56, 7.52, 8.49, 9.35, 4.70, 6.71, 9.75, 14.30, 21.00, 30.09, 41.22, 52.94},  // type 2
        {5.93, 7.75, 9.33, 11.09, 12.03, 12.60, 5.09, 6.84, 9.33, 12.87, 17.86, 24.72, 33.68, 44.76},  // type 3
        {5.66, 7.23, 8.72, 10.43, 11.64, 12.58, 5.62, 7.76, 10.91, 15.52, 22.17, 31.06, 41.86, 53.53},  // type 4
        {6.43, 8.96, 11.11, 13.47, 14.57, 15.17, 5.79, 7.63, 10.20, 13.78, 18.76, 25.50, 34.24, 45.29},  // type 5
        {6.10, 8.34, 10.42, 12.76, 14.21, 15.25, 6.43, 8.70, 11.96, 16.65, 23.25, 31.96, 42.44, 54.02},  // type 6
        {5.82, 7.72, 9.56, 11.67, 13.19, 14.41, 6.49, 8.99, 12.70, 18.22, 26.22, 36.60, 48.26, 59.49},  // type 7
        {5.59, 7.18, 8.81, 10.70, 12.23, 13.57, 6.47, 9.14, 13.23, 19.48, 28.80, 40.72, 53.40, 64.13},  // type 8
        {7.42, 11.65, 15.25, 19.22, 21.12, 22.28, 8.36, 10.89, 14.38, 19.18, 25.67, 33.95, 43.73, 55.27},  // type 9
        {7.00, 10.71, 14.02, 17.73, 19.81, 21.25, 8.52, 11.33, 15.32, 20.96, 28.76, 38.52, 49.29, 60.36},  // type 10
        {6.62, 9.87, 12.91, 16.34, 18.51, 20.18, 8.58, 11.61, 16.02, 22.45, 31.52, 42.70, 54.36, 64.85},  // type 11
        {7.63, 12.15, 15.80, 19.96, 22.13, 23.68, 9.26, 12.35, 16.79, 23.17, 32.10, 43.03, 54.44, 65.07},  // type 12
        {7.27, 11.39, 14.85, 18.82, 21.13, 22.89, 9.38, 12.66, 17.43, 24.38, 34.19, 46.11, 58.17, 68.48},  // type 13
        {9.65, 15.54, 19.50, 24.59, 26.56, 28.04, 10.48, 14.00, 19.08, 26.41, 36.64, 48.97, 61.35, 71.65},  // type 14
        {9.25, 14.90, 18.88, 23.94, 26.17, 27.92, 10.48, 14.00, 19.08, 26.41, 36.64, 48.97, 61.35, 71.65},  // type 15
        {5.29, 6.46, 7.67, 8.88, 9.73, 10.29, 4.50, 6.15, 8.53, 12.00, 16.97, 23.91, 33.08, 44.43},  // overcast
    },
    {1.74, 2.29, 3.06, 4.14, 5.63, 7.65, 10.27, 13.59},
};

// 5.12, the 2 m x 1 m facade opening glazed: Tables B.15 to B.17.
const DaylightTable kTableB15B17 = {
    {
        {0.84, 0.94, 1.10, 1.33, 1.50, 1.63, 0.77, 1.15, 1.77, 2.79, 4.38, 6.44, 7.19, 2.16},  // type 1
        {0.84, 0.94, 1.04, 1.17, 1.36, 1.61, 0.81, 1.25, 2.01, 3.36, 5.67, 9.07, 10.54, 2.70},  // type 2
        {0.84, 0.94, 1.38, 2.13, 2.42, 2.27, 0.95, 1.35, 1.98, 2.96, 4.41, 6.19, 6.64, 1.94},  // type 3
        {0.84, 0.94, 1.27, 1.88, 2.23, 2.27, 1.02, 1.50, 2.29, 3.62, 5.80, 8.86, 9.90, 2.47},  // type 4
        {0.84, 0.94, 1.58, 2.72, 3.12, 2.79, 1.11, 1.54, 2.18, 3.13, 4.47, 6.00, 6.17, 1.75},  // type 5
        {0.84, 0.94, 1.45, 2.43, 2.92, 2.83, 1.20, 1.72, 2.55, 3.88, 5.96, 8.70, 9.33, 2.26},  // type 6
        {0.84, 0.94, 1.34, 2.13, 2.61, 2.65, 1.18, 1.73, 2.66, 4.23, 6.93, 10.95, 12.27, 2.56},  // type 7
        {0.84, 0.94, 1.25, 1.88, 2.32, 2.47, 1.14, 1.72, 2.71, 4.49, 7.72, 12.97, 15.03, 2.79},  // type 8
        {0.84, 0.94, 2.00, 4.06, 4.86, 4.24, 1.64, 2.24, 3.11, 4.40, 6.21, 8.22, 7.97, 1.78},  // type 9
        {0.84, 0.94, 1.83, 3.61, 4.42, 4.05, 1.64, 2.29, 3.30, 4.88, 7.33, 10.51, 10.68, 2.06},  // type 10
        {0.84, 0.94, 1.68, 3.21, 4.02, 3.85, 1.62, 2.31, 3.42, 5.26, 8.29, 12.64, 13.30, 2.29},  // type 11
        {0.84, 0.94, 2.10, 4.34, 5.11, 4.41, 1.75, 2.45, 3.55, 5.34, 8.23, 12.28, 12.69, 2.16},  // type 12
        {0.84, 0.94, 1.96, 3.97, 4.78, 4.29, 1.76, 2.50, 3.69, 5.67, 9.00, 13.82, 14.50, 2.34},  // type 13
        {0.84, 0.94, 2.94, 6.04, 6.26, 4.84, 1.88, 2.61, 3.78, 5.70, 8.87, 13.39, 13.85, 2.21},  // type 14
        {0.84, 0.94, 2.78, 5.75, 6.12, 4.91, 1.95, 2.47, 4.00, 6.09, 9.55, 14.48, 14.96, 2.38},  // type 15
        {0.84, 0.94, 1.12, 1.50, 1.81, 1.89, 0.83, 1.21, 1.81, 2.78, 4.28, 6.26, 7.02, 2.13},  // overcast
    },
    {0.33, 0.46, 0.65, 0.94, 1.34, 1.80, 1.85, 0.53},
};

// 5.12, the whole south wall glazed: Tables B.18 to B.20.
const DaylightTable kTableB18B20 = {
    {
        {4.62, 5.38, 6.15, 7.03, 7.72, 8.21, 3.74, 5.17, 7.23, 10.18, 14.30, 19.66, 25.63, 30.02},  // type 1
        {4.47, 5.09, 5.78, 6.62, 7.47, 8.22, 4.11, 5.85, 8.46, 12.30, 17.78, 24.74, 31.91, 36.38},  // type 2
        {5.21, 6.83, 8.22, 9.76, 10.58, 11.07, 4.46, 5.97, 8.11, 11.10, 15.20, 20.48, 26.34, 31.03},  // type 3
        {4.98, 6.36, 7.68, 9.18, 10.24, 11.05, 4.92, 6.77, 9.47, 13.37, 18.82, 25.64, 32.64, 37.32},  // type 4
        {5.65, 7.89, 9.78, 11.86, 12.82, 13.34, 5.07, 6.67, 8.87, 11.91, 16.00, 21.21, 26.96, 31.84},  // type 5
        {5.36, 7.34, 9.18, 11.24, 12.51, 13.40, 5.63, 7.59, 10.39, 14.35, 19.78, 26.47, 33.31, 38.14},  // type 6
        {5.12, 6.79, 8.42, 10.28, 11.60, 12.66, 5.68, 7.84, 11.03, 15.69, 22.26, 30.21, 37.78, 42.18},  // type 7
        {4.92, 6.32, 7.76, 9.42, 10.76, 11.93, 5.66, 7.97, 11.48, 16.76, 24.40, 33.53, 41.74, 45.63},  // type 8
        {6.53, 10.26, 13.43, 16.92, 18.59, 19.59, 7.33, 9.52, 12.51, 16.58, 21.92, 28.33, 34.80, 40.12},  // type 9
        {6.15, 9.43, 12.35, 15.61, 17.43, 18.68, 7.47, 9.90, 13.32, 18.09, 24.51, 32.03, 39.11, 43.91},  // type 10
        {5.83, 8.69, 11.37, 14.38, 16.29, 17.74, 7.51, 10.14, 13.92, 19.35, 26.80, 35.40, 43.03, 47.47},  // type 11
        {6.71, 10.70, 13.92, 17.58, 19.48, 20.82, 8.11, 10.79, 14.60, 20.00, 27.33, 35.75, 43.26, 47.73},  // type 12
        {6.40, 10.03, 13.08, 16.57, 18.59, 20.13, 8.21, 11.05, 15.15, 21.02, 29.08, 38.24, 46.15, 50.26},  // type 13
        {8.49, 13.68, 17.17, 21.65, 23.37, 24.65, 8.87, 11.75, 15.85, 21.69, 29.61, 38.60, 46.41, 50.58},  // type 14
        {8.14, 13.12, 16.63, 21.08, 23.03, 24.54, 9.18, 12.23, 16.59, 22.79, 31.19, 40.68, 48.81, 52.90},  // type 15
        {4.65, 5.69, 6.75, 7.82, 8.56, 9.04, 3.94, 5.36, 7.41, 10.34, 14.42, 19.74, 25.70, 30.40},  // overcast
    },
    {1.52, 2.00, 2.66, 3.57, 4.80, 6.36, 8.09, 9.55},
};

// Where a table departs from the closed form, the reason; nullptr where it does not.
using Departs = std::function<const char*(int type, size_t point)>;

struct TableCheck {
  double worst = 0;            // over the entries that do not depart: relative, beyond the table's rounding
  std::string worst_at;
  size_t checked = 0;
  double worst_departure = 0;  // over those that do
  std::string departures;      // each: "type point table/closed form"
};

// The table against the closed form, every sky and every point. A table value is rounded to 0.01,
// so what counts is how far it lies beyond +-0.005 of the closed form, relative to the closed form.
TableCheck table_vs_closed_form(const DaylightTable& table, const Opening& o, Glass glass, const Departs& departs) {
  TableCheck c;
  for (int type = 1; type <= 16; ++type) {
    const ReportSky sky(type);
    for (size_t k = 0; k < point_count(o); ++k) {
      const DaylightPoint& p = kDaylightPoints[k];
      const double closed_form = daylight_percent(o, glass, sky, p.at, p.normal);
      const double value = table.at(type, k);
      const double error = std::max(0.0, std::fabs(value - closed_form) - 0.005) / closed_form;
      if (const char* why = departs(type, k)) {
        c.worst_departure = std::max(c.worst_departure, error);
        if (error > 0.01)
          c.departures += std::to_string(type) + p.name + " " + std::to_string(value) + "/" +
                          std::to_string(closed_form) + " (" + why + ") ";
        continue;
      }
      if (error > c.worst) c.worst = error, c.worst_at = std::to_string(type) + p.name;
      ++c.checked;
    }
  }
  return c;
}

// The facade cases' room: the 4 m x 4 m x 3 m box with the opening cut out of its south wall (z = 4).
void add_facade_room(Scene& scene, int material, const Opening& o) {
  const float x0 = o.corner.x, x1 = o.corner.x + o.u.x, y0 = o.corner.y, y1 = o.corner.y + o.v.y;
  test::add_quad(scene, {0, 0, 4}, {4, 0, 0}, {0, 0, -4}, material, "floor");
  test::add_quad(scene, {0, 3, 0}, {4, 0, 0}, {0, 0, 4}, material, "ceiling");
  test::add_quad(scene, {0, 0, 0}, {4, 0, 0}, {0, 3, 0}, material, "north wall");
  test::add_quad(scene, {0, 0, 4}, {0, 0, -4}, {0, 3, 0}, material, "west wall");
  test::add_quad(scene, {4, 0, 0}, {0, 0, 4}, {0, 3, 0}, material, "east wall");
  // The south wall, facing -z, around [x0, x1] x [y0, y1].
  if (y0 > 0) test::add_quad(scene, {4, 0, 4}, {-4, 0, 0}, {0, y0, 0}, material, "south wall");
  if (y1 < 3) test::add_quad(scene, {4, y1, 4}, {-4, 0, 0}, {0, 3 - y1, 0}, material, "south wall");
  if (x1 < 4) test::add_quad(scene, {4, y0, 4}, {x1 - 4, 0, 0}, {0, y1 - y0, 0}, material, "south wall");
  if (x0 > 0) test::add_quad(scene, {x0, y0, 4}, {-x0, 0, 0}, {0, y1 - y0, 0}, material, "south wall");
}

struct DaylightBake {
  BakeResult result;
  std::vector<double> percent;         // per element: 100 E / E_hz
  std::vector<double> sensor_percent;  // at the report's points
};

// The room with `o` open (glazed with radbake's pane, or not) under `sky` with E_hz = 10,000 lx and
// no sun, over ground of reflectance 0.3; `density` texels per metre, `rays` sky rays per texel and
// per sensor, and a sensor 1 mm off each of the report's points.
DaylightBake bake_daylight(const Opening& o, bool glazed, const ReportSky& sky, uint32_t rays, float density) {
  Scene scene;
  const int black = test::add_material(scene, {0, 0, 0});
  if (o.facade)
    add_facade_room(scene, black, o);
  else
    add_room(scene, black, length(o.u));
  if (glazed) {
    Material pane;
    pane.name = "6 mm clear glass";
    pane.base_color = {0, 0, 0};
    pane.metallic = 0;
    pane.transmission = 1;  // all of it glazing
    pane.visible_transmittance = kPaneTransmittance;
    scene.materials.push_back(pane);
    // Facing into the room: -y under the roof, -z in the south wall.
    const Vec3 corner = o.facade ? o.corner + o.u : o.corner, u = o.facade ? o.u * -1.0f : o.u;
    test::add_quad(scene, corner, u, o.v, int(scene.materials.size() - 1), "pane");
  }
  // The sky as a user gives it (daylight/daylight_sky.h): its type, E_hz and the sun's position; the
  // library works out its zenith luminance.
  DaylightOptions daylight;
  daylight.sky = sky.type == kCieOvercast ? SkyKind::CieOvercast : SkyKind::CieGeneral;
  if (sky.type != kCieOvercast) daylight.cie_type = sky.type;
  daylight.sky_illuminance = kExteriorLux;
  daylight.sun_illuminance = 0;  // the report leaves direct sunlight out
  daylight.sun = SunPosition{kSunZenith * 180 / M_PI, kSunAzimuth * 180 / M_PI};
  daylight.ground_reflectance = kGroundReflectance;
  daylight.sky_rays = rays;
  BakeOptions options;
  options.sky = daylight_sky(daylight).light;
  for (size_t k = 0; k < point_count(o); ++k)
    options.sensors.push_back({kDaylightPoints[k].at + kDaylightPoints[k].normal * 0.001f, kDaylightPoints[k].normal});
  options.sensor.rays = 16;  // for the light surfaces send: none here, all are black
  // A sensor's rays come in 8 independent batches (so that it can state its noise), each less
  // stratified than one set of them all: four times the texels' rays keep them within their 2%.
  options.sensor.sky_rays = 4 * rays;
  // The closed form's "radbake's pane" (Glass::Radbake) is the Fresnel pane of index 1.5 scaled to
  // 0.8788: the transport is what these cases check; the glazing models, glazing_test.cpp.
  options.glazing.model = GlazingModel::Fresnel;
  AtlasOptions atlas;
  atlas.texel_density = density;
  DaylightBake b{test::bake_scene(scene, atlas, options).result, {}, {}};
  b.percent.resize(b.result.elements.size());
  for (size_t i = 0; i < b.percent.size(); ++i)
    if (b.result.elements.valid(i)) b.percent[i] = 100 * sum(b.result.irradiance[i]) / 3 / kExteriorLux;
  for (double lux : b.result.sensor_lux) b.sensor_percent.push_back(100 * lux / kExteriorLux);
  return b;
}

// The surfaces the report measures: the north wall, the floor and (facade openings) the ceiling.
bool measured_surface(const Opening& o, Vec3 p, Vec3 n) {
  return (n.z > 0.9f && p.z < 0.01f) || (n.y > 0.9f && p.y < 0.01f) || (o.facade && n.y < -0.9f && p.y > 2.99f);
}

// What a texel should hold: the closed form's mean over its footprint, the texel-sized square
// around its sample point in its plane, at its 4 x 4 cell centres (the texel's rays start from
// points spread over the same cells). The room's surfaces, their texels and the basis are all
// axis-aligned; the quads' sides are whole numbers of texels, so no texel is cut.
double texel_percent(const Opening& o, Glass glass, const ReportSky& sky, Vec3 at, Vec3 normal, float texel) {
  Vec3 t, b;
  orthonormal_basis(normal, t, b);
  double sum = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const float s = texel * ((i + 0.5f) / 4 - 0.5f), r = texel * ((j + 0.5f) / 4 - 0.5f);
      sum += daylight_percent(o, glass, sky, at + t * s + b * r, normal);
    }
  return sum / 16;
}

// What a bilinear read of the lightmap gives at `point` on the plane facing `normal`: the texels
// of that plane whose sample points lie within a texel of it, weighted by the tent.
double bilinear_reading(const Elements& e, const std::vector<double>& value, Vec3 point, Vec3 normal, double texel) {
  Vec3 t, b;
  orthonormal_basis(normal, t, b);
  double sum = 0, weights = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    const Vec3 d = e.position[i] - point;
    if (!e.valid(i) || dot(e.normal[i], normal) < 0.999f || std::fabs(dot(d, normal)) > 0.01f) continue;
    const double w = std::max(0.0, 1 - std::fabs(dot(d, t)) / texel) * std::max(0.0, 1 - std::fabs(dot(d, b)) / texel);
    sum += w * value[i], weights += w;
  }
  return weights > 0 ? sum / weights : NAN;
}

// A bake of a daylight case held to the closed form and to the report's table.
struct DaylightCheck {
  size_t texels = 0;
  double worst_texel = 0;  // relative to the closed form's footprint mean, or to the dimmest table value
  Vec3 worst_texel_at{};
  double worst_sensor = 0;          // the sensors at the report's points against the closed form there
  double worst_reading = 0;         // the lightmap read there (bilinear) against the same read of exact texels
  size_t table_points = 0;          // the report's points compared with its table
  double worst_sensor_vs_table = 0, worst_reading_vs_table = 0;
  std::string readings;             // per point: sensor / lightmap / table / closed form, percent
  std::string glass_differs;        // the points where the report's glass and radbake's pane differ
};

// What fills the opening in the report, and in the bake.
Glass report_glass(bool glazed) { return glazed ? Glass::Report : Glass::None; }
Glass baked_glass(bool glazed) { return glazed ? Glass::Radbake : Glass::None; }

// Every texel of the measured surfaces against the closed form's mean over its footprint (for the
// glass radbake simulates); the lightmap read at the report's points against the same read of those
// means (a texel's mean is not the value at its centre: 50 cm texels read at B under the 1 m roof
// opening give 5.4% less than the point's value, 25 cm texels 1% or less); the sensors at the
// report's points against the closed form there; and both against the table, where it does not
// depart from the closed form and, glazed, where the report's glass and radbake's pane give the
// same within 2% (the report's transmittance falls with the angle of incidence, radbake's does not:
// baker/surface/material_sampler.h). A texel's error is relative to its value, or where that is below the
// closed form at the report's dimmest point under this sky, to that value: 5% of it is the absolute
// accuracy CIE 171 asks there (the faintest texels, high on the north wall under the 1 m roof
// opening, see it edge-on).
DaylightCheck check_daylight(const DaylightBake& b, const Opening& o, bool glazed, const ReportSky& sky,
                             const DaylightTable& table, const Departs& departs, float texel) {
  DaylightCheck c;
  const Elements& e = b.result.elements;
  double dimmest = INFINITY;  // the closed form at the report's dimmest point, for the baked glass
  for (size_t k = 0; k < point_count(o); ++k) {
    const DaylightPoint& p = kDaylightPoints[k];
    dimmest = std::min(dimmest, daylight_percent(o, baked_glass(glazed), sky, p.at, p.normal));
  }
  std::vector<double> exact(e.size());  // what each measured texel should hold
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i) || !measured_surface(o, e.position[i], e.normal[i])) continue;
    const double expected = exact[i] = texel_percent(o, baked_glass(glazed), sky, e.position[i], e.normal[i], texel);
    const double error = std::fabs(b.percent[i] - expected) / std::max(expected, dimmest);
    if (error > c.worst_texel) c.worst_texel = error, c.worst_texel_at = e.position[i];
    ++c.texels;
  }
  for (size_t k = 0; k < point_count(o); ++k) {
    const DaylightPoint& p = kDaylightPoints[k];
    const double closed_form = daylight_percent(o, baked_glass(glazed), sky, p.at, p.normal);
    const double report_form = daylight_percent(o, report_glass(glazed), sky, p.at, p.normal);
    const double sensor = b.sensor_percent[k], reading = bilinear_reading(e, b.percent, p.at, p.normal, texel);
    const double value = table.at(sky.type, k);
    c.worst_sensor = std::max(c.worst_sensor, std::fabs(sensor / closed_form - 1));
    c.worst_reading =
        std::max(c.worst_reading, std::fabs(reading / bilinear_reading(e, exact, p.at, p.normal, texel) - 1));
    char text[96];
    std::snprintf(text, sizeof text, "%s=%.3f/%.3f/%.2f/%.3f ", p.name, sensor, reading, value, closed_form);
    c.readings += text;
    if (std::fabs(report_form / closed_form - 1) > 0.02) c.glass_differs += std::string(p.name) + " ";
    if (departs(sky.type, k) || std::fabs(report_form / closed_form - 1) > 0.02) continue;
    c.worst_sensor_vs_table = std::max(c.worst_sensor_vs_table, std::fabs(sensor / value - 1));
    c.worst_reading_vs_table = std::max(c.worst_reading_vs_table, std::fabs(reading / value - 1));
    ++c.table_points;
  }
  return c;
}

void record(const std::string& prefix, const DaylightCheck& c) {
  ::testing::Test::RecordProperty(prefix + "worst_texel_error", std::to_string(c.worst_texel));
  ::testing::Test::RecordProperty(prefix + "worst_sensor_vs_closed_form", std::to_string(c.worst_sensor));
  ::testing::Test::RecordProperty(prefix + "worst_lightmap_reading_vs_exact_texels", std::to_string(c.worst_reading));
  ::testing::Test::RecordProperty(prefix + "worst_sensor_vs_table", std::to_string(c.worst_sensor_vs_table));
  ::testing::Test::RecordProperty(prefix + "worst_lightmap_reading_vs_table", std::to_string(c.worst_reading_vs_table));
  ::testing::Test::RecordProperty(prefix + "table_points", std::to_string(c.table_points));
  ::testing::Test::RecordProperty(prefix + "readings_sensor_lightmap_table_closed_form", c.readings);
  if (!c.glass_differs.empty())
    ::testing::Test::RecordProperty(prefix + "not_compared_with_the_table_glass_differs", c.glass_differs);
}

const char* no_departures(int, size_t) { return nullptr; }

// The report's points A to F (the north wall), G to N (the floor), G' to N' (the ceiling).
constexpr size_t kA = 0, kF = 5, kG = 6, kH = 7, kN = 13;

// Tables B.3, B.4, B.7, B.8: A lies 0.25 m under the edge of the open roof, where the report's own
// integration departs from the closed form (B.3: +5.6% under type 1, -1.6% under type 8: the sign
// changes with the sky). Point A is held to the closed form.
const char* whole_roof_departures(int, size_t point) {
  return point == kA ? "A, 0.25 m under the opening's edge: the report's integration" : nullptr;
}

// Tables B.12 to B.14 and B.18 to B.20: with the whole south wall open, the report's values on the
// north wall alternate about the closed form down the wall, +, 0, -, +, 0, - from A to F (Table
// B.12: A +0.8% to +8.7%, C -0.5% to -3.6%, D +0.5% to +3.4%, F -0.3% to -2.6%): the signature of
// the report's own numerical integration, which no geometry gives. The wall is held to the closed
// form.
const char* whole_facade_departures(int, size_t point) {
  return point >= kA && point <= kF ? "the north wall under the open facade: the report's integration" : nullptr;
}

// Table B.13: type 14's floor row repeats type 15's, all eight values (3.6% to 5.7% off).
const char* table_b12_b14_departures(int type, size_t point) {
  if (type == 14 && point >= kG && point <= kN) return "type 14's floor row repeats type 15's";
  return whole_facade_departures(type, point);
}

// Table B.16: type 15's H reads 2.47 where the closed form gives 2.74, two digits swapped (its
// neighbours agree within 0.1%).
const char* table_b15_b17_departures(int type, size_t point) {
  return type == 15 && point == kH ? "2.47 for 2.74: two digits swapped" : nullptr;
}

TEST(Cie171, DaylightQuadratureIsExactWhereHowellIs) {
  // Under a uniform sky of luminance 1 the quadrature is pi times the view factor, which Howell's
  // B-3 (the floor under a roof opening) and Lambert's contour integral (a wall) give in closed form.
  auto uniform = [](test::Vec3d, test::Vec3d) { return 1.0; };
  double worst = 0;
  for (size_t k = 0; k < 14; ++k) {
    const DaylightPoint& p = kDaylightPoints[k];
    for (const Opening& o : {kRoof1m, kRoof4m, kFacade2x1, kFacade4x3}) {
      const std::vector<Vec3> corners = {o.corner, o.corner + o.u, o.corner + o.u + o.v, o.corner + o.v};
      const double quadrature = test::illuminance_through_opening(test::to_double(p.at), test::to_double(p.normal),
                                                                  test::to_double(o.corner), test::to_double(o.u),
                                                                  test::to_double(o.v), uniform);
      const double exact = M_PI * (p.normal.y > 0.9f && !o.facade
                                       ? test::point_to_rectangle(p.at.x, p.at.z, o.corner.x, o.corner.x + o.u.x,
                                                                  o.corner.z, o.corner.z + o.v.z, 3 - p.at.y)
                                       : test::point_to_polygon(p.at, p.normal, corners));
      worst = std::max(worst, std::fabs(quadrature / exact - 1));
    }
  }
  char text[32];
  std::snprintf(text, sizeof text, "%.2e", worst);
  RecordProperty("worst_relative_error", text);
  // Measured 6.3e-11, A under the open roof (0.25 m from the opening's edge) included.
  EXPECT_LT(worst, 1e-8);
  // E_hz / L_z: pi for a uniform sky (type 5 has neither gradation nor indicatrix), 7 pi / 9 for the
  // CIE overcast sky.
  EXPECT_NEAR(test::cie171_sky_horizontal_illuminance(5, kSunZenith, kSunAzimuth), M_PI, 1e-6);
  EXPECT_NEAR(test::cie171_sky_horizontal_illuminance(kCieOvercast, kSunZenith, kSunAzimuth), 7 * M_PI / 9, 1e-5);
}

void record(const std::string& prefix, const TableCheck& c) {
  ::testing::Test::RecordProperty(prefix + "worst", std::to_string(c.worst) + " at " + c.worst_at);
  ::testing::Test::RecordProperty(prefix + "entries", std::to_string(c.checked));
  ::testing::Test::RecordProperty(prefix + "worst_departure", std::to_string(c.worst_departure));
  ::testing::Test::RecordProperty(prefix + "departures_over_1_percent", c.departures);
}

// The tables' entries depart from the closed form by how much more than their rounding (+-0.005).
TEST(Cie171, Case5_9TheClosedFormGivesTablesB1ToB4) {
  const TableCheck one = table_vs_closed_form(kTableB1B2, kRoof1m, Glass::None, no_departures);
  const TableCheck whole = table_vs_closed_form(kTableB3B4, kRoof4m, Glass::None, [](int type, size_t point) {
    if (type == 13 && point == kG) return "42.07 for 47.01 where H and I agree within 0.2%: a misprint";
    return whole_roof_departures(type, point);
  });
  record("b1_b2_", one);
  record("b3_b4_", whole);
  EXPECT_EQ(one.checked, 16u * 14);
  EXPECT_EQ(whole.checked, 16u * 13 - 1);
  // Measured 0.18% (type 11, I): the 1 m opening's 224 entries, type 3's wall as corrected.
  EXPECT_LT(one.worst, 0.005);
  // Measured 0.57% (type 1, B); A departs by up to 5.6%, type 13's G by 10.5%.
  EXPECT_LT(whole.worst, 0.01);
  EXPECT_GT(whole.worst_departure, 0.05);
}

// 5.10: the report's glass, its transmittance falling with the angle of incidence, gives its
// tables; so does radbake's pane, whose transmittance falls as a clear pane's (under the 1 m
// opening, A sees the glass edge-on: the report's 0.19% under the overcast sky is a third of the
// unglazed 0.56%).
TEST(Cie171, Case5_10TheClosedFormGivesTablesB5ToB8) {
  const TableCheck one = table_vs_closed_form(kTableB5B6, kRoof1m, Glass::Report, no_departures);
  const TableCheck whole = table_vs_closed_form(kTableB7B8, kRoof4m, Glass::Report, whole_roof_departures);
  const TableCheck pane = table_vs_closed_form(kTableB5B6, kRoof1m, Glass::Radbake, no_departures);
  record("b5_b6_", one);
  record("b7_b8_", whole);
  RecordProperty("b5_b6_with_radbakes_pane_worst", std::to_string(pane.worst) + " at " + pane.worst_at);
  EXPECT_EQ(one.checked, 16u * 14);
  // Measured 0.19% (type 15, I).
  EXPECT_LT(one.worst, 0.005);
  // Measured 0.75% (type 1, B); A departs by up to 6.7%, as in Table B.3.
  EXPECT_LT(whole.worst, 0.01);
  // radbake's pane (0.8788 along the normal, falling off as a clear pane of index 1.5) gives the
  // tables too: measured 3.5% at worst, where the pane is seen nearly edge-on. (A pane passing
  // 0.8788 at every angle was 62% off there.)
  EXPECT_LT(pane.worst, 0.05);
}

// 5.11: the 2 m x 1 m opening's tables to their rounding; the whole wall's floor and ceiling within
// 2.3%, worst at N and N' (0.25 m from the opening's bottom and top edges: the sign of the
// difference changes with the sky there too).
TEST(Cie171, Case5_11TheClosedFormGivesTablesB9ToB14) {
  const TableCheck small = table_vs_closed_form(kTableB9B11, kFacade2x1, Glass::None, no_departures);
  const TableCheck whole = table_vs_closed_form(kTableB12B14, kFacade4x3, Glass::None, table_b12_b14_departures);
  record("b9_b11_", small);
  record("b12_b14_", whole);
  EXPECT_EQ(small.checked, 16u * 22);
  EXPECT_EQ(whole.checked, 16u * 16 - 8);
  // Measured 0.32% (type 3, N).
  EXPECT_LT(small.worst, 0.005);
  // Measured 2.3% (type 9, N); the wall departs by up to 8.7%, type 14's floor by up to 5.7%.
  EXPECT_LT(whole.worst, 0.03);
  EXPECT_GT(whole.worst_departure, 0.05);
}

// 5.12: the same with the report's glass.
TEST(Cie171, Case5_12TheClosedFormGivesTablesB15ToB20) {
  const TableCheck small = table_vs_closed_form(kTableB15B17, kFacade2x1, Glass::Report, table_b15_b17_departures);
  const TableCheck whole = table_vs_closed_form(kTableB18B20, kFacade4x3, Glass::Report, whole_facade_departures);
  record("b15_b17_", small);
  record("b18_b20_", whole);
  EXPECT_EQ(small.checked, 16u * 22 - 1);
  EXPECT_EQ(whole.checked, 16u * 16);
  // Measured 0.18% (type 8, L); type 15's H departs by 9.7%.
  EXPECT_LT(small.worst, 0.005);
  EXPECT_GT(small.worst_departure, 0.05);
  // Measured 2.9% (type 9, N); the wall departs by up to 8.8%.
  EXPECT_LT(whole.worst, 0.03);
  EXPECT_GT(whole.worst_departure, 0.05);
}

// One daylight case baked under one sky and checked (check_daylight), what it measured recorded
// under `prefix`, and held to CIE 171's accuracy:
// - every texel within 5% of what it should hold (the bake's noise and bias), and the lightmap read
//   at the report's points within 5% of the same read of exact texels;
// - the sensors at the report's points within 2% of the closed form there: their rays all start at
//   the point, so only their noise is left (0.5% at most, measured before their rays came in
//   batches; 2.1% with as many rays as a texel since, so they get four times as many);
// - the sensors within 5% of the report's table; with 25 cm texels (`fine`) the lightmap read at
//   the report's points too. 50 cm texels average the field over its peak (5.4% at B under the 1 m
//   opening in closed form): that read is recorded, not held to the table.
DaylightCheck bake_and_check(const std::string& prefix, const Opening& o, bool glazed, int type,
                             const DaylightTable& table, const Departs& departs, uint32_t rays, bool fine) {
  const ReportSky sky(type);
  const float density = fine ? 4 : 2;
  const DaylightCheck c = check_daylight(bake_daylight(o, glazed, sky, rays, density), o, glazed, sky, table, departs,
                                         1 / density);
  record(prefix, c);
  EXPECT_GT(c.texels, o.facade ? (fine ? 700u : 170u) : (fine ? 440u : 110u)) << prefix;
  EXPECT_LT(c.worst_texel, 0.05) << prefix << " at " << c.worst_texel_at.x << ", " << c.worst_texel_at.y << ", "
                                 << c.worst_texel_at.z;
  EXPECT_LT(c.worst_reading, 0.05) << prefix;
  EXPECT_LT(c.worst_sensor, 0.02) << prefix;
  EXPECT_GE(c.table_points, 8u) << prefix;
  EXPECT_LT(c.worst_sensor_vs_table, 0.05) << prefix;
  if (fine) {
    EXPECT_LT(c.worst_reading_vs_table, 0.05) << prefix;
  }
  return c;
}

// The small openings take 131,072 rays per texel and per sensor: from a texel high on the north
// wall, 0.1% of them reach the 1 m roof opening, edge-on. The large ones take 16,384.
constexpr uint32_t kSmallOpeningRays = 131072, kLargeOpeningRays = 16384;

// 5.9 under the CIE clear sky (type 12): its brightening round the sun, due south, makes the floor
// brightest near the north wall, which looks south through the opening (G 5.72%, N 0.96%): only
// the report's orientation gives its table. Measured: texels 4.7% at worst (the top row of the
// north wall), the sensors 0.31% from the closed form and 0.42% from the table.
TEST(Cie171, Case5_9OneMetreRoofOpeningUnderTheCieClearSky) {
  const DaylightCheck c = bake_and_check("", kRoof1m, false, 12, kTableB1B2, no_departures, kSmallOpeningRays, false);
  EXPECT_EQ(c.table_points, 14u);
}

// 5.9 with the whole roof open, under the CIE overcast sky and an intermediate sky bright round the
// sun (type 8). Measured: texels 1.0% and 1.4% at worst, the sensors 0.52% and 0.31% from the table,
// the lightmap read at the points 0.67% and 0.75% from it (A, where the table departs, excepted).
TEST(Cie171, Case5_9WholeRoofOpenUnderOvercastAndIntermediateSkies) {
  for (int type : {kCieOvercast, 8}) {
    const DaylightCheck c = bake_and_check("sky_" + std::to_string(type) + "_", kRoof4m, false, type, kTableB3B4,
                                           whole_roof_departures, kLargeOpeningRays, true);
    EXPECT_EQ(c.table_points, 13u);
  }
}

// 5.10: the 1 m roof opening glazed, under the CIE overcast sky. Radbake's pane and the report's
// glass fall off differently toward grazing: the table is compared where the two give the same
// within 2% (13 of the 14 points; not A, high on the wall, which sees the pane nearly edge-on).
// Measured: texels 4.6% at worst, the sensors 0.30% from the closed form and 1.7% from the table.
TEST(Cie171, Case5_10GlazedOneMetreRoofOpeningUnderTheCieOvercastSky) {
  const DaylightCheck c =
      bake_and_check("", kRoof1m, true, kCieOvercast, kTableB5B6, no_departures, kSmallOpeningRays, false);
  EXPECT_EQ(c.table_points, 13u);
}

// 5.10: the whole roof glazed, under the clear sky brightest round the sun (type 15). The table is
// compared at 13 points (not A, which departs). Measured: texels 1.2% at worst, the sensors 0.95%
// and the lightmap 0.82% from the table.
TEST(Cie171, Case5_10GlazedWholeRoofUnderAClearSky) {
  const DaylightCheck c =
      bake_and_check("", kRoof4m, true, 15, kTableB7B8, whole_roof_departures, kLargeOpeningRays, true);
  EXPECT_EQ(c.table_points, 13u);
}

// 5.11: the 2 m x 1 m facade opening under an intermediate sky (type 7). The ceiling sees only the
// ground through it (the ERC), the floor only the sky, the north wall both (A and B only the
// ground). Measured: texels 3.4% at worst, the sensors 0.52% from the closed form and 0.60% from
// the table.
TEST(Cie171, Case5_11FacadeOpeningUnderAnIntermediateSky) {
  const DaylightCheck c =
      bake_and_check("", kFacade2x1, false, 7, kTableB9B11, no_departures, kSmallOpeningRays, false);
  EXPECT_EQ(c.table_points, 22u);
}

// 5.11: the whole south wall open, under the CIE overcast and the CIE clear sky. Measured: texels
// 1.7% and 2.8% at worst; the sensors and the lightmap 1.8% and 1.9% from the table (N', 0.25 m
// from the opening's top edge, the same under both skies: the table's own 1.8% there).
TEST(Cie171, Case5_11WholeFacadeOpenUnderOvercastAndClearSkies) {
  for (int type : {kCieOvercast, 12}) {
    const DaylightCheck c = bake_and_check("sky_" + std::to_string(type) + "_", kFacade4x3, false, type,
                                           kTableB12B14, table_b12_b14_departures, kLargeOpeningRays, true);
    EXPECT_EQ(c.table_points, 16u);
  }
}

// 5.12: the 2 m x 1 m facade opening glazed, under the CIE overcast sky. The table is compared at
// 20 of the 22 points (not N and N', 0.25 m from the facade, which see the pane nearly edge-on).
// Measured: texels 3.3% at worst, the sensors 0.52% from the closed form and 1.1% from the table.
TEST(Cie171, Case5_12GlazedFacadeOpeningUnderTheCieOvercastSky) {
  const DaylightCheck c =
      bake_and_check("", kFacade2x1, true, kCieOvercast, kTableB15B17, table_b15_b17_departures, kSmallOpeningRays,
                     false);
  EXPECT_EQ(c.table_points, 20u);
}

// 5.12: the whole south wall glazed, under an intermediate sky (type 10). The table is compared at
// 16 points (the wall departs). Measured: texels 2.8% at worst, the sensors 1.2% and the lightmap
// 1.8% from the table.
TEST(Cie171, Case5_12GlazedWholeFacadeUnderAnIntermediateSky) {
  const DaylightCheck c =
      bake_and_check("", kFacade4x3, true, 10, kTableB18B20, whole_facade_departures, kLargeOpeningRays, true);
  EXPECT_EQ(c.table_points, 16u);
}

}  // namespace
}  // namespace radbake
