#include "io/analysis/analysis_outputs.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "base/errors.h"
#include "io/files/written_file.h"
#include "io/files/regular_file.h"
#include "io/lightmaps/lightmap_images.h"

namespace radbake {
namespace {

void write_false_colour(const std::string& path, const std::vector<float>& values, int width, int height,
                        const FalseColourScale& scale, int cell_pixels) {
  const FalseColourResult image = false_colour(values, width, height, scale, cell_pixels);
  write_png(path, image.image.width, image.image.height, image.image.rgb);
}

// Per page, each texel's photopic value times `factor` where an element wrote it, NaN in
// the padding.
std::vector<float> page_values(const LightmapPage& page, double factor) {
  std::vector<float> values(page.texels.size(), std::numeric_limits<float>::quiet_NaN());
  for (size_t k = 0; k < values.size(); ++k)
    if (page.valid[k]) values[k] = float(photopic(page.texels[k]) * factor);
  return values;
}

// An image of one value per pixel as a page of grey texels, for write_exr.
LightmapPage grey_page(int width, int height, const std::vector<float>& values) {
  LightmapPage page;
  page.width = width, page.height = height;
  page.valid.assign(values.size(), 1);
  for (float v : values) page.texels.push_back(Rgb{v, v, v});
  return page;
}

}  // namespace

std::vector<std::string> write_work_plane_maps(const std::string& folder, const std::string& stem,
                                               const WorkPlane& plane, const std::vector<double>& values,
                                               FalseColourScale scale) {
  if (scale.max == 0) {
    std::vector<float> readings;
    for (const WorkPlaneStorey& storey : plane.storeys)
      for (int32_t k : storey.sensor_at)
        if (k >= 0) readings.push_back(float(values[size_t(k)]));
    scale.max = automatic_scale_max(readings);
  }
  // Cells large enough that a small room's grid reads at a glance (about 480 pixels across).
  const int cell = std::clamp(480 / std::max(plane.columns, plane.rows), 2, 64);
  std::vector<std::string> names;
  for (size_t s = 0; s < plane.storeys.size(); ++s) {
    const std::vector<int32_t>& at = plane.storeys[s].sensor_at;
    std::vector<float> grid(at.size(), std::numeric_limits<float>::quiet_NaN());
    for (size_t k = 0; k < grid.size(); ++k)
      if (at[k] >= 0) grid[k] = float(values[size_t(at[k])]);
    FalseColourResult image = false_colour(grid, plane.columns, plane.rows, scale, cell);
    for (const WorkPlaneRoom& room : plane.rooms)
      if (room.storey == int(s)) label_cell(image.image, std::to_string(room.number), room.label_column, room.label_row, cell);
    names.push_back(plane.storeys.size() == 1 ? stem + ".png" : stem + "_storey_" + std::to_string(s + 1) + ".png");
    write_png(folder + "/" + names.back(), image.image.width, image.image.height, image.image.rgb);
  }
  return names;
}

void write_page_map(const std::string& path, const LightmapPage& page, const FalseColourScale& scale) {
  write_false_colour(path, page_values(page, 1), page.width, page.height, scale, 1);
}

ReadingSummary summarise(const std::vector<double>& values, const std::vector<double>& standard_errors) {
  ReadingSummary s;
  s.count = values.size();
  if (values.empty()) return s;
  s.min = *std::min_element(values.begin(), values.end());
  s.max = *std::max_element(values.begin(), values.end());
  double total = 0, squared_errors = 0;
  for (double v : values) total += v;
  for (double e : standard_errors) squared_errors += e * e;
  s.mean = total / double(values.size());
  s.uniformity = s.mean > 0 ? s.min / s.mean : 0.0;
  if (!standard_errors.empty() && s.mean > 0) s.noise = std::sqrt(squared_errors / double(standard_errors.size())) / s.mean;
  return s;
}

std::vector<Sensor> read_sensor_csv(const std::string& path, size_t max_points) {
  std::istringstream in(read_regular_file(path, "sensor file", kMostSensorFileBytes));
  std::vector<Sensor> sensors;
  std::string line;
  bool header_seen = false;
  for (size_t number = 1; std::getline(in, line); ++number) {
    if (line.size() > 4096) throw InputError(clipped(path) + " line " + std::to_string(number) + ": too long for a sensor");
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // a spreadsheet's UTF-8 byte-order mark
    if (line.find_first_not_of(" \t") == std::string::npos || line[line.find_first_not_of(" \t")] == '#') continue;
    std::vector<double> fields;
    std::stringstream cells(line);
    std::string cell;
    bool numeric = true;
    while (std::getline(cells, cell, ',')) {
      char* end = nullptr;
      const double v = std::strtod(cell.c_str(), &end);
      while (end && (*end == ' ' || *end == '\t')) ++end;
      if (end == cell.c_str() || (end && *end != '\0')) numeric = false;
      fields.push_back(v);
    }
    // One header (x,y,z or any names), anywhere before the first point: after comments, say.
    if (!numeric && sensors.empty() && !header_seen) {
      header_seen = true;
      continue;
    }
    const bool finite = std::all_of(fields.begin(), fields.end(), [](double v) { return std::isfinite(v) && std::fabs(v) < 1e7; });
    if (!numeric || !finite || (fields.size() != 3 && fields.size() != 6))
      throw InputError(clipped(path) + " line " + std::to_string(number) +
                       ": a sensor is x,y,z or x,y,z,nx,ny,nz (metres, finite numbers)");
    if (sensors.size() >= max_points)
      throw InputError(clipped(path) + " holds more than " + std::to_string(max_points) + " sensors");
    Sensor s;
    s.position = {float(fields[0]), float(fields[1]), float(fields[2])};
    if (fields.size() == 6) {
      const Vec3 n{float(fields[3]), float(fields[4]), float(fields[5])};
      if (!(length(n) > 1e-6f))
        throw InputError(clipped(path) + " line " + std::to_string(number) + ": the sensor's normal is zero");
      s.normal = normalize(n);
    }
    sensors.push_back(s);
  }
  if (sensors.empty()) throw InputError("the sensor file '" + clipped(path) + "' holds no sensor");
  return sensors;
}

namespace {

// sensors.csv, and the summaries of the listed sensors (the work plane's come after them).
void write_sensors(const BakeResult& result, const std::vector<double>& error, double to_percent,
                   const std::string& folder, AnalysisFiles& out) {
  const std::vector<double>& lux = result.sensor_lux;
  std::ofstream csv(folder + "/sensors.csv");
  csv << "x,y,z,nx,ny,nz,lux" << (to_percent > 0 ? ",daylight_factor_percent" : "") << ",lux_standard_error"
      << (to_percent > 0 ? ",daylight_factor_standard_error_percent" : "") << "\n";
  char row[256];
  for (size_t k = 0; k < result.sensors.size(); ++k) {
    const Sensor& s = result.sensors[k];
    std::snprintf(row, sizeof row, "%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.6g", s.position.x, s.position.y, s.position.z,
                  s.normal.x, s.normal.y, s.normal.z, lux[k]);
    csv << row;
    if (to_percent > 0) {
      std::snprintf(row, sizeof row, ",%.6g", lux[k] * to_percent);
      csv << row;
    }
    std::snprintf(row, sizeof row, ",%.3g", error[k]);
    csv << row;
    if (to_percent > 0) {
      std::snprintf(row, sizeof row, ",%.3g", error[k] * to_percent);
      csv << row;
    }
    csv << "\n";
  }
  close_written(csv, folder + "/sensors.csv");
  out.files.push_back("sensors.csv");
  // The listed sensors come first, the work plane's after them; each set has its own summary.
  const ptrdiff_t listed_count = ptrdiff_t(lux.size() - result.work_plane.sensors.size());
  const std::vector<double> listed(lux.begin(), lux.begin() + listed_count);
  const std::vector<double> listed_error(error.begin(), error.begin() + listed_count);
  out.sensors = summarise(listed, listed_error);
  if (to_percent > 0) {
    std::vector<double> percent(listed), percent_error(listed_error);
    for (double& v : percent) v *= to_percent;
    for (double& v : percent_error) v *= to_percent;
    out.sensors_daylight_factor = summarise(percent, percent_error);
  }
}

// The work plane's readings: lux and their standard errors, and the same in percent of the
// outdoor illuminance when there is a daylight factor; summarised over any set of its sensors.
struct PlaneReadings {
  std::vector<double> lux, error, percent, percent_error;  // percent: empty without a daylight factor

  PlaneReadings(const std::vector<double>& lux_, const std::vector<double>& error_, double to_percent)
      : lux(lux_), error(error_) {
    if (to_percent <= 0) return;
    percent = lux, percent_error = error;
    for (double& v : percent) v *= to_percent;
    for (double& v : percent_error) v *= to_percent;
  }
  bool in_percent() const { return !percent.empty(); }
  ReadingSummary lux_at(const std::vector<int32_t>& sensors) const { return at(sensors, lux, error); }
  ReadingSummary percent_at(const std::vector<int32_t>& sensors) const { return at(sensors, percent, percent_error); }

 private:
  static ReadingSummary at(const std::vector<int32_t>& sensors, const std::vector<double>& values,
                           const std::vector<double>& errors) {
    std::vector<double> readings, reading_errors;
    for (int32_t k : sensors)
      if (k >= 0) readings.push_back(values[size_t(k)]), reading_errors.push_back(errors[size_t(k)]);
    return summarise(readings, reading_errors);
  }
};

// Each storey's summaries and the work plane's in all.
void summarise_storeys(const WorkPlane& plane, const PlaneReadings& readings, AnalysisFiles& out) {
  std::vector<int32_t> all;
  for (const WorkPlaneStorey& storey : plane.storeys) {
    StoreyReadings summary;
    summary.floor_height = storey.floor_height;
    summary.lux = readings.lux_at(storey.sensor_at);
    if (readings.in_percent()) summary.daylight_factor = readings.percent_at(storey.sensor_at);
    out.storeys.push_back(summary);
    all.insert(all.end(), storey.sensor_at.begin(), storey.sensor_at.end());
  }
  out.work_plane = readings.lux_at(all);
  if (readings.in_percent()) out.work_plane_daylight_factor = readings.percent_at(all);
}

// Each storey's false-colour maps, in lux and in percent.
void write_storey_maps(const WorkPlane& plane, const PlaneReadings& readings, const FalseColourScale& map_scale,
                       const std::string& folder, AnalysisFiles& out) {
  FalseColourScale scale = map_scale;
  scale.unit = "lx";
  const std::vector<std::string> maps = write_work_plane_maps(folder, "work_plane", plane, readings.lux, scale);
  std::vector<std::string> percent_maps;
  if (readings.in_percent()) {
    scale.unit = "%";
    scale.max = 0;  // the lux scale's max means nothing in percent
    percent_maps = write_work_plane_maps(folder, "work_plane_daylight_factor", plane, readings.percent, scale);
  }
  for (size_t s = 0; s < out.storeys.size(); ++s) {
    out.storeys[s].maps.push_back(maps[s]);
    if (!percent_maps.empty()) out.storeys[s].maps.push_back(percent_maps[s]);
    out.files.insert(out.files.end(), out.storeys[s].maps.begin(), out.storeys[s].maps.end());
  }
}

// work_plane_rooms.csv: each room's area, centre and readings.
void write_rooms(const BakeResult& result, const PlaneReadings& readings, const std::string& folder, AnalysisFiles& out) {
  const WorkPlane& plane = result.work_plane;
  std::ofstream csv(folder + "/work_plane_rooms.csv");
  csv << "storey,room,points,area_m2,centre_x,centre_z,min_lx,mean_lx,max_lx,uniformity"
      << (readings.in_percent() ? ",daylight_factor_min_percent,daylight_factor_mean_percent,daylight_factor_max_percent" : "")
      << "\n";
  for (const WorkPlaneRoom& room : plane.rooms) {
    RoomReadings r;
    r.storey = room.storey, r.number = room.number;
    r.area = double(room.sensors.size()) * plane.spacing * plane.spacing;
    for (int32_t k : room.sensors)
      r.centre_x += result.sensors[size_t(k)].position.x, r.centre_z += result.sensors[size_t(k)].position.z;
    r.centre_x /= double(room.sensors.size()), r.centre_z /= double(room.sensors.size());
    r.lux = readings.lux_at(room.sensors);
    if (readings.in_percent()) r.daylight_factor = readings.percent_at(room.sensors);
    char row[320];
    std::snprintf(row, sizeof row, "%d,%d,%zu,%.3f,%.3f,%.3f,%.6g,%.6g,%.6g,%.4f", r.storey + 1, r.number, r.lux.count,
                  r.area, r.centre_x, r.centre_z, r.lux.min, r.lux.mean, r.lux.max, r.lux.uniformity);
    csv << row;
    if (readings.in_percent()) {
      std::snprintf(row, sizeof row, ",%.4g,%.4g,%.4g", r.daylight_factor.min, r.daylight_factor.mean, r.daylight_factor.max);
      csv << row;
    }
    csv << "\n";
    out.rooms.push_back(r);
  }
  close_written(csv, folder + "/work_plane_rooms.csv");
  out.files.push_back("work_plane_rooms.csv");
}

// The work plane's summaries per storey, room and in all, its maps and work_plane_rooms.csv.
void write_work_plane(const BakeResult& result, const std::vector<double>& error, double to_percent,
                      const FalseColourScale& map_scale, const std::string& folder, AnalysisFiles& out) {
  out.outdoor_points = result.work_plane.outdoor_points;
  out.sliver_points = result.work_plane.sliver_points;
  const PlaneReadings readings(result.sensor_lux, error, to_percent);
  summarise_storeys(result.work_plane, readings, out);
  write_storey_maps(result.work_plane, readings, map_scale, folder, out);
  write_rooms(result, readings, folder, out);
}

// Each eye's fisheye and perspective luminance, as EXR and false colour.
void write_views(const BakeResult& result, const std::vector<EyeView>& eyes, const std::string& folder,
                 AnalysisFiles& out) {
  for (size_t v = 0; v < result.views.size(); ++v) {
    const FisheyeImage& image = result.views[v];
    const Glare& glare = result.glare[v];
    out.views.push_back({eyes[v], glare});
    const std::string exr = "view_" + std::to_string(v) + ".exr", png = "view_" + std::to_string(v) + ".png";
    write_exr(folder + "/" + exr, grey_page(image.size, image.size, image.luminance));
    FalseColourScale scale;
    scale.logarithmic = true;
    scale.decades = 4;
    scale.unit = "cd/m2";
    std::vector<float> values(image.luminance);
    for (int y = 0; y < image.size; ++y)
      for (int x = 0; x < image.size; ++x) {
        Vec3 d;
        double omega;
        if (!fisheye_pixel(image, x, y, &d, &omega)) values[size_t(y) * size_t(image.size) + size_t(x)] = std::numeric_limits<float>::quiet_NaN();
      }
    write_false_colour(folder + "/" + png, values, image.size, image.size, scale, 1);
    out.files.insert(out.files.end(), {exr, png});
    // The same eye in perspective, for looking at.
    const PerspectiveImage& flat = result.perspectives[v];
    const std::string flat_exr = "view_" + std::to_string(v) + "_perspective.exr", flat_png = "view_" + std::to_string(v) + "_perspective.png";
    write_exr(folder + "/" + flat_exr, grey_page(flat.width, flat.height, flat.luminance));
    write_false_colour(folder + "/" + flat_png, flat.luminance, flat.width, flat.height, scale, 1);
    out.files.insert(out.files.end(), {flat_exr, flat_png});
  }
}

// The pages in false colour, and in daylight factors when the pages hold lux under an overcast sky.
void write_page_maps(const std::vector<LightmapPage>& pages, const std::string& name, const AnalysisOptions& options,
                     double to_percent, const std::string& folder, AnalysisFiles& out) {
  for (size_t p = 0; p < pages.size(); ++p) {
    const LightmapPage& page = pages[p];
    if (options.false_colour_pages) {
      FalseColourScale scale = options.scale;
      scale.unit = options.lightmap_is_irradiance ? "lx" : "lm/m2";
      const std::string file = name + "_false_colour_" + std::to_string(p) + ".png";
      write_page_map(folder + "/" + file, page, scale);
      out.files.push_back(file);
    }
    if (to_percent > 0 && options.lightmap_is_irradiance) {
      FalseColourScale scale = options.scale;
      scale.unit = "%";
      scale.max = 0;  // the lux scale's max means nothing in percent
      const std::string file = name + "_daylight_factor_" + std::to_string(p) + ".png";
      write_false_colour(folder + "/" + file, page_values(page, to_percent), page.width, page.height, scale, 1);
      out.files.push_back(file);
    }
  }
}

}  // namespace

AnalysisFiles write_analysis(const BakeResult& result, const std::string& folder, const std::string& name,
                             const AnalysisOptions& options) {
  AnalysisFiles out;
  const double to_percent = options.daylight_factor_reference > 0 ? 100 / options.daylight_factor_reference : 0;
  // The readings' noise, when the bake states it (sensor_points.h), else none.
  std::vector<double> error = result.sensor_standard_error;
  error.resize(result.sensor_lux.size(), 0.0);
  if (!result.sensors.empty()) write_sensors(result, error, to_percent, folder, out);
  if (!result.work_plane.sensors.empty()) write_work_plane(result, error, to_percent, options.scale, folder, out);
  write_views(result, options.views, folder, out);
  write_page_maps(result.pages, name, options, to_percent, folder, out);
  return out;
}

}  // namespace radbake
