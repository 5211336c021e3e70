// The lighting-analysis files a bake writes on request: the sensors' readings as CSV, the work
// plane as a heat map, false-colour lightmap pages (lux, or daylight factor) with legends, and the
// statistics report.json gives (min, mean, max, uniformity).
#pragma once

#include <string>
#include <vector>

#include "baker/pipeline/bake_result.h"
#include "io/analysis/false_colour.h"

namespace radbake {

struct AnalysisOptions {
  bool false_colour_pages = false;  // NAME_false_colour_N.png: the stored quantity per texel
  FalseColourScale scale;           // for the pages and the work plane (max 0: automatic each)
  // The unobstructed sky's horizontal illuminance, lux: readings over it are daylight factors
  // (CIE overcast sky). 0: no daylight factor.
  double daylight_factor_reference = 0;
  bool lightmap_is_irradiance = true;  // pages hold lux (else lm/m2: no daylight factor pages)
  std::vector<EyeView> views;          // the bake's BakeOptions::views, for the report
};

struct ReadingSummary {
  size_t count = 0;
  double min = 0, mean = 0, max = 0;  // arithmetic mean over the points (a regular grid: the area mean)
  double uniformity = 0;              // min / mean (EN 12464's U0), 0 when the mean is 0
  double noise = 0;                   // the RMS of the points' standard errors over the mean (0: not stated)
};

// `standard_errors`, when given, parallel to `values` and in their unit.
ReadingSummary summarise(const std::vector<double>& values, const std::vector<double>& standard_errors = {});

struct ViewGlare {
  EyeView eye;
  Glare glare;
};

struct StoreyReadings {
  double floor_height = 0;                  // metres
  ReadingSummary lux, daylight_factor;      // daylight factor in percent, when asked
  std::vector<std::string> maps;            // its images, relative to the folder
};

struct RoomReadings {
  int storey = 0, number = 0;               // as WorkPlaneRoom: storey index, number on the map
  double area = 0;                          // m2: points times the grid cell's area
  double centre_x = 0, centre_z = 0;        // metres: the mean of its points
  ReadingSummary lux, daylight_factor;
};

struct AnalysisFiles {
  std::vector<std::string> files;  // written, relative to the folder
  std::vector<ViewGlare> views;    // per BakeOptions::views
  ReadingSummary sensors, work_plane;              // lux
  ReadingSummary sensors_daylight_factor, work_plane_daylight_factor;  // percent, when asked
  std::vector<StoreyReadings> storeys;             // the work plane's, lowest first
  std::vector<RoomReadings> rooms;                 // by storey, then number
  size_t outdoor_points = 0, sliver_points = 0;    // floor points the work plane left out (WorkPlane)
};

// Sensors from a CSV file: a line per point, "x,y,z" or "x,y,z,nx,ny,nz" in metres (the normal
// defaults to +Y, up); an optional header line, blank lines and lines starting with '#' are
// skipped. Throws InputError naming the file and line for anything else, and beyond max_points.
std::vector<Sensor> read_sensor_csv(const std::string& path, size_t max_points = 1000000);

// The work plane seen from above (-Z up, +X right) in false colour with a legend, an image per
// storey with each room's number on it: STEM.png for one storey, else STEM_storey_N.png (N = 1
// lowest). `values` per sensor, indexed as the storeys' sensor_at index them; cells without a point
// are grey. One scale for every storey; an automatic one is taken from the plane's own points.
// Returns the images' names.
std::vector<std::string> write_work_plane_maps(const std::string& folder, const std::string& stem,
                                               const WorkPlane& plane, const std::vector<double>& values,
                                               FalseColourScale scale);

// A lightmap page in false colour with a legend: each written texel's value (photopic: base/math.h),
// the padding grey.
void write_page_map(const std::string& path, const LightmapPage& page, const FalseColourScale& scale);

// Writes into `folder`: sensors.csv (every sensor: position, normal, lux, and the daylight factor
// in percent when asked), the work plane's maps (write_work_plane_maps: work_plane and
// work_plane_daylight_factor) and work_plane_rooms.csv (a row per room: storey, number, points,
// area, centre, lux and daylight factor statistics), NAME_false_colour_N.png and NAME_daylight_factor_N.png per page, and
// per view view_N.exr (its fisheye luminance, cd/m2) and view_N.png (the same in false colour,
// four decades), and view_N_perspective.exr and .png (the eye in perspective, 70 degrees across).
AnalysisFiles write_analysis(const BakeResult& result, const std::string& folder, const std::string& name,
                             const AnalysisOptions& options);

}  // namespace radbake
