// The sky's patches for daylight coefficients: Tregenza's 145 and Reinhart's subdivisions, against
// their counts and closed-form solid angles.
#include <gtest/gtest.h>

#include <cmath>

#include "daylight/sky_patches.h"

namespace radbake {
namespace {

TEST(SkyPatches, CountsAreTregenzasAndReinhartsAndCoverTheHemisphere) {
  for (auto [m, count] : {std::pair{1, 145u}, {2, 577u}, {4, 2305u}}) {
    const SkyPatches sky(m);
    EXPECT_EQ(sky.size(), count) << "MF:" << m;
    double total = 0;
    for (size_t k = 0; k < sky.size(); ++k) total += sky.solid_angle(k);
    EXPECT_NEAR(total, 2 * M_PI, 1e-9) << "MF:" << m;  // bounds rounding of the sums
  }
  // Tregenza's lowest band, 0-12 degrees, in 30 patches; the cap above 84 degrees.
  const SkyPatches tregenza(1);
  EXPECT_NEAR(tregenza.solid_angle(0), 2 * M_PI * std::sin(12 * M_PI / 180) / 30, 1e-12);
  EXPECT_NEAR(tregenza.solid_angle(144), 2 * M_PI * (1 - std::sin(84 * M_PI / 180)), 1e-12);
}

TEST(SkyPatches, EveryPatchHoldsItsCentreAndDirectionsFallWhereTheRowsSay) {
  for (int m : {1, 2, 4}) {
    const SkyPatches sky(m);
    for (size_t k = 0; k < sky.size(); ++k) {
      double altitude = 0, azimuth = 0;
      sky.centre(k, &altitude, &azimuth);
      EXPECT_EQ(sky.patch_at(altitude, azimuth), k) << "MF:" << m << " patch " << k;
    }
  }
  const SkyPatches tregenza(1);
  const double degree = M_PI / 180;
  EXPECT_EQ(tregenza.patch_at(5 * degree, 1 * degree), 0u);                // north, low
  EXPECT_EQ(tregenza.patch_at(5 * degree, 90 * degree), 7u);               // east: 90 / 12 = 7.5
  EXPECT_EQ(tregenza.patch_at(5 * degree, -1 * degree), 29u);              // just west of north
  EXPECT_EQ(tregenza.patch_at(13 * degree, 1 * degree), 30u);              // second band
  EXPECT_EQ(tregenza.patch_at(85 * degree, 200 * degree), 144u);           // the cap
  EXPECT_EQ(tregenza.patch_at(78 * degree, 359.9 * degree), 143u);         // last of the 6 under the cap
}

}  // namespace
}  // namespace radbake
