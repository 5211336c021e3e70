// A year of weather as a year of skies: each daylit hour's Perez all-weather sky and sun from its
// direct normal and diffuse horizontal irradiance (daylight/daylight_sky.h), at the middle of the hour.
#pragma once

#include <cstdint>
#include <vector>

#include "daylight/daylight_sky.h"
#include "daylight/sky.h"
#include "daylight/weather.h"

namespace radbake {

struct AnnualSkies {
  std::vector<SkyLight> hours;  // parallel to Weather::hours; `enabled` false when the sun is down
  size_t daylit = 0;            // hours with the sun up and some diffuse light
  // Daylit hours whose weather the Perez fit gives no valid sky for: a CIE overcast sky of the
  // same diffuse horizontal illuminance (at 120 lm/W) and no sun stands in.
  size_t substituted = 0;
};

// `base` gives the compass (up, north), the ground's reflectance and the rays; its sky is ignored.
AnnualSkies annual_skies(const Weather& weather, const DaylightOptions& base);

}  // namespace radbake
