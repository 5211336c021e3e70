// CIE 171:2006, "Test cases to assess the accuracy of lighting computer programs": the cases
// radbake's light sources already cover, each against the report's closed form.
//
// Geometry of 5.3 to 5.7. The report itself is not public. The dimensions, measurement points and
// reference tables below are those the public CyclesCIEtest validation transcribed
// (github.com/jjathompson4/CyclesCIEtest, engine/cie171/test_cases.py; it cross-checks them against
// the published Iray and AGi32 validations of CIE 171). Each is confirmed here the way that
// matters: the closed form, evaluated for that geometry, gives the report's table (each test with
// a table checks it). Coordinates are radbake's: y is up (the report's z).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

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
  options.gather_rays = 16384;  // F is 13% to 45%: 16,384 rays keep a texel's noise near 1%
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
  options.gather_rays = 65536;
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

}  // namespace
}  // namespace radbake
