// The Perez all-weather sky (daylight/perez_sky.h) against Radiance's gendaylit, run for four hours
// of weather, and against an integral of its own over the vault.
//
// The reference program: gendaylit.c (RCS 2.21, 2021/01/28) and sun.c of Radiance 6.1a
// (LBNL-ETA/Radiance, master at bcffc2b5, 2026-08-19), built with `gcc -O2 gendaylit.c sun.c -lm`
// against that tree's color.h (Debian 12 has no radiance package). Each case ran three times: as
// written, with `-O 1` (W/m2/sr) and with `-O 2` (cd/m2). From its output:
//  - the line `# epsilon, delta, atmospheric precipitable water content : ...` (4 decimals);
//  - the sun's direction (`solar source sun`, `4 x y z 0.533`): z, 6 decimals, is cos Zs;
//  - the sky (`10 A1 A2 a b c d e x y z`): a..e to 6 decimals; A1 to 4 significant digits is the
//    diffuse horizontal irradiance (-O 1) or illuminance (-O 2) over gendaylit's sum of the
//    relative luminance f = [1 + a exp(b / cos Z)] [1 + c exp(d gamma) + e cos^2 gamma] over
//    145 directions, so A1(-O 2) / A1(-O 1) is the diffuse luminous efficacy and A1(-O 2) f its
//    luminance in cd/m2;
//  - the sun's luminance with -O 2 (`3 L L L`, 4 digits): direct normal illuminance over the
//    disc's solid angle 2 pi (1 - cos 0.2665 degree).
// gendaylit's day number is jdate(month, day) of a non-leap year.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "daylight/perez_sky.h"
#include "daylight/sky_luminance.h"

namespace radbake {
namespace {

double radians(double degrees) { return degrees * M_PI / 180; }

struct GendaylitCase {
  const char* command;
  double direct_normal_irradiance;    // W/m2, the -W arguments
  double diffuse_horizontal_irradiance;  // W/m2
  int day_of_year;
  std::optional<double> dew_point;    // degrees Celsius, the -d argument
  double cos_sun_zenith;              // the sun's printed direction, z
  double clearness, brightness, precipitable_water;  // printed epsilon, delta (-), W (cm)
  PerezCoefficients coefficients;     // printed a..e
  double sky_scale_irradiance;        // A1 with -O 1, W/m2/sr
  double sky_scale_illuminance;       // A1 with -O 2, cd/m2
  double sun_luminance;               // the sun's with -O 2, cd/m2
  int expected_bin;                   // Perez 1990 Table 1 for the printed epsilon
};

// Clear: June noon at 40 degrees north.
const GendaylitCase kClear = {"gendaylit 6 21 12 -a 40 -o 105 -m 105 -W 700 120",
                              700, 120, 172, std::nullopt, 0.958563, 6.6905, 0.0946, 2.0000,
                              {-0.991543, -0.217932, 24.024665, -5.834306, 1.505375},
                              4.853e+01, 6.229e+03, 1.066e+09, 8};
// Intermediate: a March morning.
const GendaylitCase kIntermediate = {"gendaylit 3 21 10 -a 40 -o 105 -m 105 -W 300 200",
                                     300, 200, 80, std::nullopt, 0.646154, 1.8921, 0.2242, 2.0000,
                                     {-1.047506, -0.578383, 13.631034, -3.220625, 0.153677},
                                     4.695e+01, 5.885e+03, 4.224e+08, 4};
// Overcast: a December noon with a trace of direct sun.
const GendaylitCase kOvercast = {"gendaylit 12 21 12 -a 40 -o 105 -m 105 -W 15 150",
                                 15, 150, 355, std::nullopt, 0.446914, 1.0414, 0.2363, 2.0000,
                                 {0.627641, -0.497556, 1.183440, -0.795737, 0.022582},
                                 2.480e+01, 2.841e+03, 1.420e+07, 1};
// Intermediate with little diffuse light (delta 0.095, raised to 0.2 for the coefficients in
// bins 2-5) and a humid day (dew point 18 C: W = 3.27 cm).
const GendaylitCase kHazy = {"gendaylit 9 1 15 -a 40 -o 105 -m 105 -W 250 80 -d 18",
                             250, 80, 244, 18.0, 0.623994, 2.7845, 0.0954, 3.2707,
                             {-1.002770, -0.467703, 13.707799, -3.286606, 0.035573},
                             2.163e+01, 3.499e+03, 3.339e+08, 5};

// gendaylit's sun: a disc 0.533 degree across.
const double kSunSolidAngle = 2 * M_PI * (1 - std::cos(radians(0.2665)));  // sr

// The published formula (Perez, Seals, Michalsky 1993, eq. 1), written again here so the checks
// of the distribution do not go through relative_sky_luminance.
double perez_formula(const PerezCoefficients& p, double zenith, double from_sun) {
  return (1 + p.a * std::exp(p.b / std::cos(zenith))) *
         (1 + p.c * std::exp(p.d * from_sun) + p.e * std::cos(from_sun) * std::cos(from_sun));
}

double angle_between(double zenith, double azimuth, double other_zenith, double other_azimuth) {
  return std::acos(std::fmin(1.0, std::cos(zenith) * std::cos(other_zenith) +
                                      std::sin(zenith) * std::sin(other_zenith) * std::cos(azimuth - other_azimuth)));
}

void expect_matches_gendaylit(const GendaylitCase& c) {
  SCOPED_TRACE(c.command);
  const double sun_zenith = std::acos(c.cos_sun_zenith);
  const PerezSky sky =
      perez_sky(c.direct_normal_irradiance, c.diffuse_horizontal_irradiance, sun_zenith, c.day_of_year, c.dew_point);

  // 6e-5 bounds the 4 printed decimals (5e-5) and what the sun's zenith angle, known from a
  // 6-decimal cosine to 2e-6 radian, moves epsilon (3e-6 at most here).
  EXPECT_NEAR(sky.clearness, c.clearness, 6e-5);
  EXPECT_NEAR(sky.brightness, c.brightness, 6e-5);
  EXPECT_NEAR(sky.precipitable_water, c.precipitable_water, 6e-5);
  EXPECT_EQ(sky.clearness_bin, c.expected_bin);

  // 5e-5 bounds the 6 printed decimals (5e-7), gendaylit's table held in floats (1e-5 in a
  // coefficient) and the sun's zenith angle known to 2e-6 radian (coefficients move at most 15
  // per radian: 3e-5).
  EXPECT_EQ(sky.distribution.model, SkyModel::Perez);
  const PerezCoefficients& ours = sky.distribution.perez;
  EXPECT_NEAR(ours.a, c.coefficients.a, 5e-5);
  EXPECT_NEAR(ours.b, c.coefficients.b, 5e-5);
  EXPECT_NEAR(ours.c, c.coefficients.c, 5e-5);
  EXPECT_NEAR(ours.d, c.coefficients.d, 5e-5);
  EXPECT_NEAR(ours.e, c.coefficients.e, 5e-5);

  // Luminance relative to the zenith in five directions (zenith angle, azimuth from the sun's),
  // against the formula on gendaylit's coefficients. 1e-4 relative bounds what the coefficients'
  // differences above move it.
  const double sun_azimuth = radians(200);
  const double directions[5][2] = {{sun_zenith * 0.5, 0}, {radians(45), radians(45)}, {radians(60), radians(90)},
                                   {radians(80), radians(180)}, {radians(89), radians(10)}};
  for (const auto& d : directions) {
    const double expected = perez_formula(c.coefficients, d[0], angle_between(d[0], d[1], sun_zenith, 0)) /
                            perez_formula(c.coefficients, 0, sun_zenith);
    const double got = relative_sky_luminance(sky.distribution, d[0], sun_azimuth + d[1], sun_zenith, sun_azimuth);
    EXPECT_NEAR(got / expected, 1.0, 1e-4) << "Z " << d[0] << ", from the sun's azimuth " << d[1];
  }

  // Illuminances from the Perez 1990 efficacies. 1e-3 relative bounds the two 4-digit numbers the
  // diffuse one comes from (5e-4 each); 5e-4 the one the direct one comes from.
  const double diffuse_illuminance =
      c.diffuse_horizontal_irradiance * c.sky_scale_illuminance / c.sky_scale_irradiance;
  const double direct_illuminance = c.sun_luminance * kSunSolidAngle;
  EXPECT_NEAR(sky.diffuse_horizontal_illuminance / diffuse_illuminance, 1.0, 1e-3);
  EXPECT_NEAR(sky.direct_normal_illuminance / direct_illuminance, 1.0, 5e-4);

  // Zenith luminance. gendaylit scales its sky by a sum over 145 directions with equal weights,
  // which overstates the integral of f cos Z over the vault by 0.4-0.9% on these four skies (we
  // compared it with a 600 x 1200 midpoint sum); its zenith luminance is that much lower than
  // ours, which divides by the integral itself. The bounds hold that difference and no more.
  const double their_zenith_luminance = c.sky_scale_illuminance * perez_formula(c.coefficients, 0, sun_zenith);
  const double ratio = sky.zenith_luminance / their_zenith_luminance;
  EXPECT_GT(ratio, 1.0);
  EXPECT_LT(ratio, 1.01);

  ::testing::Test::RecordProperty("clearness", std::to_string(sky.clearness));
  ::testing::Test::RecordProperty("brightness", std::to_string(sky.brightness));
  ::testing::Test::RecordProperty("diffuse_lux", std::to_string(sky.diffuse_horizontal_illuminance));
  ::testing::Test::RecordProperty("gendaylit_diffuse_lux", std::to_string(diffuse_illuminance));
  ::testing::Test::RecordProperty("direct_lux", std::to_string(sky.direct_normal_illuminance));
  ::testing::Test::RecordProperty("gendaylit_direct_lux", std::to_string(direct_illuminance));
  ::testing::Test::RecordProperty("zenith_cd_m2", std::to_string(sky.zenith_luminance));
  ::testing::Test::RecordProperty("gendaylit_zenith_cd_m2", std::to_string(their_zenith_luminance));
}

TEST(PerezSky, ClearSkyMatchesGendaylit) { expect_matches_gendaylit(kClear); }
TEST(PerezSky, IntermediateSkyMatchesGendaylit) { expect_matches_gendaylit(kIntermediate); }
TEST(PerezSky, OvercastSkyMatchesGendaylit) { expect_matches_gendaylit(kOvercast); }
TEST(PerezSky, HazySkyWithADewPointMatchesGendaylit) { expect_matches_gendaylit(kHazy); }

TEST(PerezSky, ClearnessBinsFollowPerezTableOne) {
  EXPECT_EQ(perez_clearness_bin(1.0), 1);
  EXPECT_EQ(perez_clearness_bin(1.0649), 1);
  EXPECT_EQ(perez_clearness_bin(1.065), 2);  // a bound belongs to the bin above it
  EXPECT_EQ(perez_clearness_bin(2.8), 6);
  EXPECT_EQ(perez_clearness_bin(6.1999), 7);
  EXPECT_EQ(perez_clearness_bin(6.2), 8);
  EXPECT_EQ(perez_clearness_bin(40), 8);  // bin 8 has no upper bound
  EXPECT_THROW(perez_clearness_bin(0.99), std::invalid_argument);
}

// The sky lights an open horizontal plane with the diffuse illuminance: the zenith luminance times
// the integral of the relative luminance, summed here on another grid than
// horizontal_illuminance_over_zenith_luminance's (cells of equal projected solid angle, midpoints
// in sin^2 Z and azimuth), equals the illuminance from the efficacy.
TEST(PerezSky, ItsSkyGivesTheDiffuseHorizontalIlluminance) {
  for (const GendaylitCase* c : {&kClear, &kIntermediate, &kOvercast, &kHazy}) {
    SCOPED_TRACE(c->command);
    const double sun_zenith = std::acos(c->cos_sun_zenith), sun_azimuth = radians(135);
    const PerezSky sky = perez_sky(c->direct_normal_irradiance, c->diffuse_horizontal_irradiance, sun_zenith,
                                   c->day_of_year, c->dew_point);
    // cos Z sin Z dZ dalpha = d(sin^2 Z) dalpha / 2: equal weights in (sin^2 Z, alpha).
    constexpr int kRings = 600, kSectors = 1200;
    double sum = 0;
    for (int i = 0; i < kRings; ++i) {
      const double zenith = std::asin(std::sqrt((i + 0.5) / kRings));
      for (int j = 0; j < kSectors; ++j)
        sum += relative_sky_luminance(sky.distribution, zenith, 2 * M_PI * (j + 0.5) / kSectors, sun_zenith,
                                      sun_azimuth);
    }
    const double illuminance = sky.zenith_luminance * sum * 0.5 * (1.0 / kRings) * (2 * M_PI / kSectors);
    // 2e-5 bounds the two quadratures' errors: on these skies each is within 5e-6 of a 2880 x 5760
    // midpoint sum in (Z, alpha).
    EXPECT_NEAR(illuminance / sky.diffuse_horizontal_illuminance, 1.0, 2e-5);
  }
}

std::string refusal(const std::function<void()>& call) {
  try {
    call();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no std::invalid_argument)";
}

TEST(PerezSky, InvalidInputsAreRefusedWithTheReason) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const double z = radians(40);
  EXPECT_NE(refusal([&] { perez_sky(-1, 100, z, 100); }).find("direct normal irradiance"), std::string::npos);
  EXPECT_NE(refusal([&] { perez_sky(nan, 100, z, 100); }).find("direct normal irradiance"), std::string::npos);
  EXPECT_NE(refusal([&] { perez_sky(inf, 100, z, 100); }).find("direct normal irradiance"), std::string::npos);
  EXPECT_NE(refusal([&] { perez_sky(500, -5, z, 100); }).find("diffuse horizontal irradiance"), std::string::npos);
  EXPECT_NE(refusal([&] { perez_sky(500, nan, z, 100); }).find("diffuse horizontal irradiance"), std::string::npos);
  EXPECT_NE(refusal([&] { perez_sky(500, 0, z, 100); }).find("no sky"), std::string::npos);
  EXPECT_NE(refusal([&] { perez_sky(0, 100, radians(90), 100); }).find("horizon"), std::string::npos);
  EXPECT_NE(refusal([&] { perez_sky(0, 100, radians(95), 100); }).find("horizon"), std::string::npos);
  EXPECT_NE(refusal([&] { perez_sky(0, 100, -0.1, 100); }).find("zenith"), std::string::npos);
  EXPECT_NE(refusal([&] { perez_sky(0, 100, nan, 100); }).find("zenith"), std::string::npos);
  EXPECT_NE(refusal([&] { perez_sky(0, 100, z, 0); }).find("day of year"), std::string::npos);
  EXPECT_NE(refusal([&] { perez_sky(0, 100, z, 367); }).find("day of year"), std::string::npos);
  EXPECT_NE(refusal([&] { perez_sky(0, 100, z, 100, nan); }).find("dew point"), std::string::npos);
  // 1367 W/m2 x 1.033 reaches the top of the atmosphere on 3 January; no more can arrive below it.
  EXPECT_NE(refusal([&] { perez_sky(1420, 100, z, 3); }).find("top of the atmosphere"), std::string::npos);
  EXPECT_NO_THROW(perez_sky(1400, 100, z, 3));
  EXPECT_NO_THROW(perez_sky(0, 100, radians(89.9), 100));  // still above the horizon
}

// Where the 1993 fit leaves the skies it was fitted to, there is no sky to return.
TEST(PerezSky, AnHourTheFitGivesNoValidSkyIsRefused) {
  // `gendaylit 6 21 12 -a 30 -o 105 -m 105 -W 200 80` (sun 83.4 degrees up, epsilon 3.50): b > 0,
  // a sky without bound at the horizon. gendaylit says "positive Perez parameter B (= 0.015738),
  // printing error sky" (a black one); we find b = 0.0157386.
  EXPECT_THROW(perez_sky(200, 80, std::acos(0.993460), 172), std::domain_error);
  // `gendaylit 6 21 12 -a 37 -o 105 -m 105 -W 200 70 -O 2` (epsilon 3.8183, delta 0.0544): b is
  // -0.004574 but a = -1.029488 makes 1 + a exp(b) < 0, a negative zenith; gendaylit prints the sky
  // with A1 = -6.017e+04.
  EXPECT_THROW(perez_sky(200, 70, std::acos(0.972156), 172), std::domain_error);
}

}  // namespace
}  // namespace radbake
