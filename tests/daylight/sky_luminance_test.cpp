// Sky luminance distributions against published values for ISO 15469's standard skies
// and the closed forms of the uniform and traditional overcast skies.
#include <gtest/gtest.h>

#include <cmath>

#include "daylight/sky_luminance.h"

namespace radbake {
namespace {

double radians(double degrees) { return degrees * M_PI / 180; }

SkyDistribution cie(int type) { return {SkyModel::CieGeneral, type}; }

TEST(SkyLuminance, CieStandardSkiesMatchTheReferenceValues) {
  // Z = 45 degrees, alpha = 180, sun at Zs = 30, alpha_s = 0. The values are given to 7 digits:
  // 1e-6 bounds their rounding.
  EXPECT_NEAR(relative_sky_luminance(cie(1), radians(45), radians(180), radians(30), 0), 0.8325846, 1e-6);
  EXPECT_NEAR(relative_sky_luminance(cie(12), radians(45), radians(180), radians(30), 0), 0.4544524, 1e-6);
}

TEST(SkyLuminance, EveryTypeIsOneAtTheZenithAndDarkBelowTheHorizon) {
  for (int type = 1; type <= 15; ++type) {
    // At the zenith the formula's numerator and denominator are the same product: 1 to rounding.
    EXPECT_NEAR(relative_sky_luminance(cie(type), 0, 0, radians(40), radians(120)), 1.0, 1e-12) << type;
    EXPECT_EQ(relative_sky_luminance(cie(type), radians(95), 0, radians(40), radians(120)), 0.0) << type;
    EXPECT_GT(relative_sky_luminance(cie(type), radians(89.9), radians(10), radians(40), radians(120)), 0.0) << type;
  }
}

TEST(SkyLuminance, ClearSkiesAreBrightestTowardTheSunOvercastOnesAtTheZenith) {
  const double sun_zenith = radians(50), sun_azimuth = radians(180);
  // Type 12 (CIE clear): 10 degrees from the sun is brighter than the zenith; the opposite side
  // of the vault at the same height is darker than the zenith.
  EXPECT_GT(relative_sky_luminance(cie(12), radians(40), radians(180), sun_zenith, sun_azimuth), 1.0);
  EXPECT_LT(relative_sky_luminance(cie(12), radians(50), 0, sun_zenith, sun_azimuth), 1.0);
  // Type 1 (overcast, steep gradation): no azimuth dependence, darker toward the horizon.
  EXPECT_DOUBLE_EQ(relative_sky_luminance(cie(1), radians(60), 0, sun_zenith, sun_azimuth),
                   relative_sky_luminance(cie(1), radians(60), radians(180), sun_zenith, sun_azimuth));
  EXPECT_LT(relative_sky_luminance(cie(1), radians(80), 0, sun_zenith, sun_azimuth), 0.5);
}

TEST(SkyLuminance, HorizontalIlluminanceOfTheClosedFormSkies) {
  // E_h = integral of L cos Z over the vault: pi L for a uniform sky, 7 pi / 9 L_z for the
  // traditional overcast sky (Moon and Spencer). 1e-5 bounds the quadrature's error.
  EXPECT_NEAR(horizontal_illuminance_over_zenith_luminance({SkyModel::Uniform, 0}, 0, 0) / M_PI, 1.0, 1e-5);
  EXPECT_NEAR(horizontal_illuminance_over_zenith_luminance({SkyModel::CieOvercast, 0}, 0, 0) / (7 * M_PI / 9), 1.0,
              1e-5);
  EXPECT_NEAR(relative_sky_luminance({SkyModel::CieOvercast, 0}, radians(90) - 1e-9, 0, 0, 0), 1.0 / 3, 1e-8);
}

TEST(SkyLuminance, ATypeOutsideOneToFifteenIsRefused) {
  EXPECT_THROW(relative_sky_luminance(cie(0), 0.1, 0, 0.5, 0), std::invalid_argument);
  EXPECT_THROW(relative_sky_luminance(cie(16), 0.1, 0, 0.5, 0), std::invalid_argument);
}

SkyDistribution perez(PerezCoefficients coefficients) {
  SkyDistribution sky;
  sky.model = SkyModel::Perez;
  sky.perez = coefficients;
  return sky;
}

TEST(SkyLuminance, PerezDefaultCoefficientsMakeAUniformSky) {
  // a = c = e = 0: both factors are 1. The quadrature's 1e-5 bounds the integral.
  const SkyDistribution uniform = perez({});
  EXPECT_EQ(relative_sky_luminance(uniform, radians(70), radians(30), radians(40), radians(120)), 1.0);
  EXPECT_EQ(relative_sky_luminance(uniform, radians(91), 0, radians(40), radians(120)), 0.0);
  EXPECT_NEAR(horizontal_illuminance_over_zenith_luminance(uniform, radians(40), 0) / M_PI, 1.0, 1e-5);
}

TEST(SkyLuminance, PerezSkyByItsFormula) {
  // A clear sky's coefficients (gendaylit's for epsilon 6.69, delta 0.095, Zs = 16.55 degrees);
  // sun at Zs = 30 degrees, alpha_s = 0, view Z = 45 degrees, alpha = 180: gamma = 75 degrees.
  // f(45, 75) = (1 - 0.991543 exp(-0.217932 / cos 45)) (1 + 24.024665 exp(-5.834306 x 1.308997)
  //             + 1.505375 cos^2 75) = 0.271447 x 1.112426 = 0.301965;
  // f(0, 30)  = (1 - 0.991543 exp(-0.217932)) (1 + 24.024665 exp(-5.834306 x 0.523599)
  //             + 1.505375 cos^2 30) = 0.202621 x 3.261325 = 0.660812;
  // L / Lz = 0.301965 / 0.660812 = 0.456961. 1e-5 bounds the rounding of those six digits.
  const SkyDistribution clear = perez({-0.991543, -0.217932, 24.024665, -5.834306, 1.505375});
  EXPECT_NEAR(relative_sky_luminance(clear, radians(45), radians(180), radians(30), 0), 0.456961, 1e-5);
  EXPECT_NEAR(relative_sky_luminance(clear, 0, 0, radians(30), 0), 1.0, 1e-12);
  EXPECT_GT(relative_sky_luminance(clear, radians(25), 0, radians(30), 0), 2.0);  // near the sun
  // At the horizon exp(b / cos Z) -> 0: the gradation is 1 and the luminance stays finite.
  EXPECT_GT(relative_sky_luminance(clear, radians(90), radians(180), radians(30), 0), 0.0);
}

TEST(SkyLuminance, PerezCoefficientsThatMakeNoSkyAreRefused) {
  // b >= 0: exp(b / cos Z) grows without bound toward the horizon.
  EXPECT_THROW(relative_sky_luminance(perez({-1, 0.1, 0, -1, 0}), 0.5, 0, 0.3, 0), std::invalid_argument);
  // 1 + a exp(b) < 0: a negative zenith, nothing to be relative to.
  EXPECT_THROW(relative_sky_luminance(perez({-1.5, -0.1, 0, -1, 0}), 0.5, 0, 0.3, 0), std::invalid_argument);
}

}  // namespace
}  // namespace radbake
