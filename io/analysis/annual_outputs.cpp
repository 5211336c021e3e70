#include "io/analysis/annual_outputs.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <tuple>

#include "io/analysis/analysis_outputs.h"
#include "io/files/written_file.h"
#include "io/lightmaps/lightmap_images.h"

namespace radbake {
namespace {

// Little-endian float32, as the machine holds them (x86 and ARM both are).
void write_floats(const std::string& path, const std::vector<float>& values) {
  static_assert(sizeof(float) == 4, "float32");
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(values.data()), std::streamsize(values.size() * sizeof(float)));
  close_written(out, path);
}

}  // namespace

std::vector<std::string> write_annual(const AnnualRun& run, const std::string& folder) {
  const AnnualDaylight& a = *run.daylight;
  const AnnualMetrics& m = *run.metrics;
  std::vector<std::string> files;
  write_floats(folder + "/annual_illuminance.f32", a.lux);
  files.push_back("annual_illuminance.f32");
  {
    const std::string path = folder + "/annual_sensors.csv";
    std::ofstream csv(path);
    csv << "x,y,z,nx,ny,nz,daylight_autonomy_percent,udi_short_percent,udi_supplementary_percent,"
           "udi_autonomous_percent,udi_exceeded_percent,udi_useful_percent,sun_hours\n";
    char row[320];
    for (size_t k = 0; k < a.sensors.size(); ++k) {
      const Sensor& s = a.sensors[k];
      const SensorMetrics& x = m.sensors[k];
      std::snprintf(row, sizeof row, "%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.2f,%.2f,%.2f,%.2f,%.2f,%.2f,%zu\n", s.position.x,
                    s.position.y, s.position.z, s.normal.x, s.normal.y, s.normal.z, 100 * x.daylight_autonomy,
                    100 * x.udi_short, 100 * x.udi_supplementary, 100 * x.udi_autonomous, 100 * x.udi_exceeded,
                    100 * x.udi_useful, x.sun_hours);
      csv << row;
    }
    close_written(csv, path);
    files.push_back("annual_sensors.csv");
  }
  if (!a.work_plane.sensors.empty()) {
    std::vector<double> da, udi, sun_hours;
    for (const SensorMetrics& x : m.sensors)
      da.push_back(100 * x.daylight_autonomy), udi.push_back(100 * x.udi_autonomous), sun_hours.push_back(double(x.sun_hours));
    FalseColourScale percent;
    percent.unit = "%";
    percent.max = 100;
    FalseColourScale hours;
    hours.unit = "";  // hours of the sun's direct light at 1000 lx or more
    for (const auto& [stem, values, scale] : {std::tuple{"work_plane_daylight_autonomy", &da, percent},
                                              std::tuple{"work_plane_udi_autonomous", &udi, percent},
                                              std::tuple{"work_plane_sun_hours", &sun_hours, hours}}) {
      const std::vector<std::string> maps = write_work_plane_maps(folder, stem, a.work_plane, *values, scale);
      files.insert(files.end(), maps.begin(), maps.end());
    }
  }
  for (size_t p = 0; p < a.texel_daylight_autonomy.size(); ++p) {
    FalseColourScale percent;
    percent.unit = "%";
    percent.max = 100;
    const std::string n = std::to_string(p);
    write_page_map(folder + "/" + run.name + "_daylight_autonomy_" + n + ".png", a.texel_daylight_autonomy[p], percent);
    write_page_map(folder + "/" + run.name + "_udi_" + n + ".png", a.texel_udi[p], percent);
    write_exr(folder + "/" + run.name + "_mean_lux_" + n + ".exr", a.texel_mean_lux[p]);
    files.insert(files.end(), {run.name + "_daylight_autonomy_" + n + ".png", run.name + "_udi_" + n + ".png",
                               run.name + "_mean_lux_" + n + ".exr"});
  }
  nlohmann::ordered_json views = nlohmann::ordered_json::array();
  if (run.glare && !run.eyes->empty()) {
    write_floats(folder + "/annual_dgp.f32", run.glare->dgp);
    files.push_back("annual_dgp.f32");
    for (size_t e = 0; e < run.eyes->size(); ++e) {
      const EyeView& eye = (*run.eyes)[e];
      const EyeGlareSummary& g = run.glare->eyes[e];
      views.push_back({{"position", {eye.position.x, eye.position.y, eye.position.z}},
                       {"direction", {eye.direction.x, eye.direction.y, eye.direction.z}},
                       {"method", "enhanced simplified DGP (Wienold 2009): Ev by the coefficients, the sun's disc the one source"},
                       {"occupied_daylit_hours", g.occupied_hours}, {"mean_dgp", g.mean_dgp},
                       {"share_dgp_035_or_more", g.over_035}, {"share_dgp_040_or_more", g.over_040},
                       {"share_dgp_045_or_more", g.over_045}});
    }
  }
  files.push_back("report.json");
  const AnnualMetricsOptions& o = *run.metric_options;
  nlohmann::ordered_json report = {
      {"generator", "radbake"},
      {"input", run.input},
      {"options", nlohmann::ordered_json::object()},
      {"weather", {{"file", run.weather_file}, {"place", run.weather->place}, {"latitude", run.weather->latitude},
                   {"longitude", run.weather->longitude}, {"utc_offset_hours", run.weather->utc_offset},
                   {"hours", run.weather->hours.size()}, {"daylit_hours", run.skies->daylit},
                   {"hours_under_a_substitute_overcast_sky", run.skies->substituted}}},
      {"series", {{"file", "annual_illuminance.f32"}, {"type", "float32 little-endian"}, {"unit", "lx"},
                  {"layout", "hour-major: every sensor for the weather file's first hour, then its next"},
                  {"hours", a.hours}, {"sensors", a.sensors.size()}}},
      {"coefficients", {{"sky_patches_with_ground", a.sky_patches}, {"sun_bins", a.sun_bins},
                        {"seconds", a.coefficient_seconds}, {"hours_seconds", a.hours_seconds}}},
      {"metrics", {{"occupied", std::to_string(run.occupied_from) + ":00-" + std::to_string(run.occupied_to) + ":00 local standard time"},
                   {"occupied_hours", m.occupied_hours},
                   {"sDA_percent", 100 * m.sda}, {"sDA_threshold_lux", o.da_threshold}, {"sDA_share_percent", 100 * o.sda_share},
                   {"ASE_percent", 100 * m.ase}, {"ASE_threshold_lux", o.ase_threshold}, {"ASE_hours", o.ase_hours},
                   {"mean_daylight_autonomy_percent", 100 * m.mean_daylight_autonomy},
                   {"mean_udi_useful_percent", 100 * m.mean_udi_useful},
                   {"udi_bins_lux", {o.udi_low, o.udi_supplementary, o.udi_high}},
                   {"udi_useful_lux", {o.udi_low, o.udi_classic_high}}}},
      {"views", views},
      {"total_seconds", run.total_seconds},
      {"peak_memory_bytes", run.peak_memory_bytes},
      {"files", files},
  };
  for (const auto& [k, v] : run.options) report["options"][k] = v;
  const std::string path = folder + "/report.json";
  std::ofstream out(path);
  out << report.dump(2) << "\n";
  close_written(out, path);
  return files;
}

}  // namespace radbake
