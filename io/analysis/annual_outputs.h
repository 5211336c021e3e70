// What a year of daylight (`radbake bake --weather`) writes: the hourly series, each sensor's
// metrics, work-plane maps of them, and report.json.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "baker/pipeline/annual_daylight.h"
#include "baker/pipeline/annual_glare.h"
#include "daylight/annual_metrics.h"
#include "daylight/annual_skies.h"
#include "daylight/weather.h"

namespace radbake {

struct AnnualRun {
  std::string input, weather_file;
  std::string name;  // the scene's, for the texel maps' files
  std::vector<std::pair<std::string, std::string>> options;
  const Weather* weather = nullptr;
  const AnnualSkies* skies = nullptr;
  const AnnualDaylight* daylight = nullptr;
  const AnnualMetrics* metrics = nullptr;
  const AnnualMetricsOptions* metric_options = nullptr;
  const AnnualGlare* glare = nullptr;        // with eyes
  const std::vector<EyeView>* eyes = nullptr;
  int occupied_from = 8, occupied_to = 18;
  double total_seconds = 0;
  size_t peak_memory_bytes = 0;
};

// Writes into `folder`: annual_illuminance.f32 (little-endian float32, lux, hour-major: all
// sensors for the file's first hour, then the next), annual_sensors.csv (position, normal, DA,
// UDI bins in percent of the occupied hours, sun hours), with a work plane the maps
// work_plane_daylight_autonomy, work_plane_udi_autonomous and work_plane_sun_hours (a PNG per storey,
// write_work_plane_maps),
// with eyes annual_dgp.f32 (float32, hour-major, eye by eye), per lightmap page
// NAME_daylight_autonomy_N.png, NAME_udi_N.png (percent) and NAME_mean_lux_N.exr, then
// report.json. Returns the files written, relative to the folder.
std::vector<std::string> write_annual(const AnnualRun& run, const std::string& folder);

}  // namespace radbake
