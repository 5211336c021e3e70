// EnergyPlus weather files (EPW): the LOCATION line and the hourly rows, of which radbake reads
// the date and hour, the dew point, and the direct normal and diffuse horizontal irradiance.
#pragma once

#include <string>

#include "daylight/weather.h"

namespace radbake {

// Throws InputError naming the line and field for a file that is not a year of EPW weather: no
// LOCATION line, a site off the globe, other than 8760 or 8784 rows, a field that is not a
// number, irradiance missing (9999) or out of range; files over 64 MB are refused unread.
Weather read_epw(const std::string& path);

}  // namespace radbake
