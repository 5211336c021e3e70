// Two years of daylight side by side (`radbake diff A B` on two `radbake bake --weather`
// folders): a design and its variant (with and without an overhang), metric by metric, and where
// on the work plane daylight autonomy moved.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "base/math.h"

namespace radbake {

struct AnnualFolder {
  std::string folder;
  std::vector<std::pair<std::string, double>> metrics;  // name, value (percent, or DGP), in report order
  std::vector<Vec3> positions;                          // per sensor, from annual_sensors.csv
  std::vector<double> daylight_autonomy;                // percent, per sensor
};

// Whether `folder` holds a year of daylight (its report.json has a "series").
bool is_annual_folder(const std::string& folder);

// Throws InputError for a folder without a readable report.json and annual_sensors.csv.
AnnualFolder read_annual_folder(const std::string& folder);

// B - A per sensor, in percentage points of daylight autonomy; throws InputError when the two
// years were not measured at the same sensors.
std::vector<double> daylight_autonomy_change(const AnnualFolder& a, const AnnualFolder& b);

// A map of the change seen from above (-Z up, +X right), a 16-pixel cell per sensor on the grid
// their x and z positions make: white where unchanged, towards red where B has more daylight
// autonomy, blue where less, full colour at `full_colour` points; black where there is no sensor.
void write_daylight_autonomy_change_map(const std::string& path, const AnnualFolder& a, const std::vector<double>& change,
                                        double full_colour);

}  // namespace radbake
