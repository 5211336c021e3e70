// From the user's daylight options to the sky light (daylight/daylight_sky.h): the sky's brightness, the
// sun's place from a site and a moment, which way north is, and what cannot be baked.
#include <gtest/gtest.h>

#include <cmath>

#include "base/errors.h"
#include "daylight/daylight_sky.h"
#include "daylight/sky.h"
#include "support/spa_test_vector.h"

namespace radbake {
namespace {

DaylightOptions golden_colorado() {
  DaylightOptions o;
  o.sky = SkyKind::CieGeneral;
  o.cie_type = 12;
  o.sun_illuminance = 80000;
  o.site = test::spa_test_site();
  return o;
}

TEST(Daylight, TheZenithLuminanceGivesTheSkyIlluminanceAskedFor) {
  DaylightOptions o;
  o.sky_illuminance = 10000;
  o.sky = SkyKind::CieOvercast;
  // Closed form: E_h = 7 pi / 9 L_z for the traditional overcast sky; 1e-5 bounds the quadrature.
  EXPECT_NEAR(daylight_sky(o).light.zenith_luminance, 10000 / (7 * M_PI / 9), 1e-5 * 10000 / (7 * M_PI / 9));
  o.sky = SkyKind::Uniform;
  EXPECT_NEAR(daylight_sky(o).light.zenith_luminance, 10000 / M_PI, 1e-5 * 10000 / M_PI);
  o.sky = SkyKind::None;
  EXPECT_FALSE(daylight_sky(o).light.enabled);
}

TEST(Daylight, ASiteAndAMomentPlaceTheSunWithinAHundredthOfADegreeOfSpa) {
  const Daylight d = daylight_sky(golden_colorado());
  EXPECT_NEAR(d.summary.sun_zenith, test::kSpaZenith, 0.01);
  EXPECT_NEAR(d.summary.sun_azimuth, test::kSpaAzimuth, 0.01);
  EXPECT_NEAR(d.light.sun_zenith, test::kSpaZenith * M_PI / 180, 0.01 * M_PI / 180);
  EXPECT_DOUBLE_EQ(d.light.sun_illuminance, 80000);
  // On an open horizontal plane: the sky's 10,000 lx plus E_n cos Z.
  EXPECT_NEAR(d.summary.exterior_horizontal_illuminance, 10000 + 80000 * std::cos(d.light.sun_zenith), 1e-6);
}

TEST(Daylight, NorthTurnsTheSunAboutTheVertical) {
  DaylightOptions o;
  o.sky = SkyKind::Uniform;
  o.sun_illuminance = 1000;
  o.sun = SunPosition{60, 90};  // in the east, 30 degrees up
  // Default north -Z: east is +X.
  Vec3 d = sun_direction(daylight_sky(o).light);
  EXPECT_NEAR(d.x, std::sin(M_PI / 3), 1e-6);
  EXPECT_NEAR(d.y, 0.5, 1e-6);
  EXPECT_NEAR(d.z, 0, 1e-6);
  // North along +X (tilted vectors are laid flat): east is +Z.
  o.north = {1, 0.5f, 0};
  d = sun_direction(daylight_sky(o).light);
  EXPECT_NEAR(d.x, 0, 1e-6);
  EXPECT_NEAR(d.y, 0.5, 1e-6);
  EXPECT_NEAR(d.z, std::sin(M_PI / 3), 1e-6);
}

void expect_refused(const DaylightOptions& o, const std::string& says) {
  try {
    daylight_sky(o);
    ADD_FAILURE() << "not refused: " << says;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
  }
}

TEST(Daylight, WhatCannotBeBakedIsRefusedWithTheReason) {
  DaylightOptions sunny = golden_colorado();
  sunny.sun_illuminance.reset();
  expect_refused(sunny, "has a sun: give its direct normal illuminance");
  DaylightOptions night = golden_colorado();
  night.site->hour = 23;
  expect_refused(night, "the sun is below the horizon");
  DaylightOptions nowhere = golden_colorado();
  nowhere.site.reset();
  expect_refused(nowhere, "needs the sun's position");
  DaylightOptions vertical_north = golden_colorado();
  vertical_north.north = {0, 2, 0};
  expect_refused(vertical_north, "north must not point straight up or down");
  // Overcast skies do not follow the sun: no position needed, and night is no error.
  DaylightOptions overcast;
  overcast.sky = SkyKind::CieGeneral;
  overcast.cie_type = 1;
  EXPECT_TRUE(daylight_sky(overcast).light.enabled);
  overcast.sky = SkyKind::CieOvercast;
  overcast.site = night.site;
  EXPECT_TRUE(daylight_sky(overcast).light.enabled);
}

}  // namespace
}  // namespace radbake
