// A year of weather, as EnergyPlus weather files (EPW) give it: the site, and per hour the sun's
// direct normal and the sky's diffuse horizontal irradiance. Plain data: io/analysis/epw_reader.cpp reads
// it; daylight/annual_skies.cpp turns each hour into a Perez sky.
#pragma once

#include <cmath>
#include <string>
#include <vector>

namespace radbake {

struct WeatherHour {
  int month = 1, day = 1;
  int hour = 1;                     // 1..24: the hour ending at this local standard time (EPW's)
  double direct_normal = 0;         // W/m2
  double diffuse_horizontal = 0;    // W/m2
  double dew_point = NAN;           // degrees C; NaN: missing
};

struct Weather {
  std::string place;                // "City, Country" as the file names it
  double latitude = 0;              // degrees, north positive
  double longitude = 0;             // degrees, east positive
  double utc_offset = 0;            // hours: local standard time minus UTC
  double elevation = 0;             // metres
  std::vector<WeatherHour> hours;   // 8760 (or 8784 in a leap year), in the file's order
};

}  // namespace radbake
