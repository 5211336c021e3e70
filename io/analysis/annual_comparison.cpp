#include "io/analysis/annual_comparison.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "base/errors.h"
#include "io/files/regular_file.h"
#include "io/lightmaps/lightmap_images.h"

namespace radbake {
namespace {

nlohmann::json read_report(const std::string& folder) {
  try {
    return nlohmann::json::parse(read_regular_file(folder + "/report.json", "report", kMostReportBytes));
  } catch (const InputError&) {
    return nullptr;
  } catch (const nlohmann::json::exception&) {
    return nullptr;
  }
}

}  // namespace

bool is_annual_folder(const std::string& folder) {
  const nlohmann::json report = read_report(folder);
  return report.is_object() && report.contains("series");
}

AnnualFolder read_annual_folder(const std::string& folder) {
  const nlohmann::json report = read_report(folder);
  if (!report.is_object() || !report.contains("metrics") || !report["metrics"].is_object())
    throw InputError(folder + " holds no report.json of a year of daylight (radbake bake --weather)");
  AnnualFolder f;
  f.folder = folder;
  const nlohmann::json& m = report["metrics"];
  for (const char* key : {"sDA_percent", "ASE_percent", "mean_daylight_autonomy_percent", "mean_udi_useful_percent"})
    if (m.contains(key) && m[key].is_number()) f.metrics.push_back({key, m[key].get<double>()});
  if (report.contains("views") && report["views"].is_array())
    for (size_t v = 0; v < report["views"].size(); ++v) {
      const nlohmann::json& view = report["views"][v];
      for (const char* key : {"mean_dgp", "share_dgp_045_or_more"})
        if (view.contains(key) && view[key].is_number())
          f.metrics.push_back({"view_" + std::to_string(v) + "_" + key, view[key].get<double>()});
    }
  std::istringstream csv(read_regular_file(folder + "/annual_sensors.csv", "annual sensor file", kMostSensorFileBytes));
  std::string line;
  std::getline(csv, line);
  for (size_t row = 2; std::getline(csv, line); ++row) {
    std::vector<double> fields;
    std::stringstream in(line);
    for (std::string x; std::getline(in, x, ',');) {
      char* end = nullptr;
      const double v = std::strtod(x.c_str(), &end);
      if (end == x.c_str() || !std::isfinite(v)) throw InputError(folder + "/annual_sensors.csv, line " + std::to_string(row) + ": not a number");
      fields.push_back(v);
    }
    if (fields.size() < 7) throw InputError(folder + "/annual_sensors.csv, line " + std::to_string(row) + ": too few fields");
    f.positions.push_back({float(fields[0]), float(fields[1]), float(fields[2])});
    f.daylight_autonomy.push_back(fields[6]);
  }
  return f;
}

std::vector<double> daylight_autonomy_change(const AnnualFolder& a, const AnnualFolder& b) {
  if (a.positions.size() != b.positions.size())
    throw InputError(a.folder + " and " + b.folder + " were measured at different sensors (" +
                     std::to_string(a.positions.size()) + " and " + std::to_string(b.positions.size()) + ")");
  std::vector<double> change(a.positions.size());
  for (size_t k = 0; k < change.size(); ++k) {
    if (length(a.positions[k] - b.positions[k]) > 1e-3f)
      throw InputError(a.folder + " and " + b.folder + " were measured at different sensors (sensor " +
                       std::to_string(k) + " differs)");
    change[k] = b.daylight_autonomy[k] - a.daylight_autonomy[k];
  }
  return change;
}

void write_daylight_autonomy_change_map(const std::string& path, const AnnualFolder& a, const std::vector<double>& change,
                                        double full_colour) {
  std::map<long, int> column, row;  // positions in millimetres -> grid index
  for (const Vec3& p : a.positions) column[std::lround(p.x * 1000)] = 0, row[std::lround(p.z * 1000)] = 0;
  int i = 0;
  for (auto& [x, c] : column) c = i++;
  i = 0;
  for (auto& [z, r] : row) r = i++;
  constexpr int kCell = 16;
  const int width = std::max<int>(1, int(column.size())) * kCell, height = std::max<int>(1, int(row.size())) * kCell;
  std::vector<uint8_t> rgb(size_t(width) * size_t(height) * 3, 0);
  for (size_t k = 0; k < change.size(); ++k) {
    const int cx = column[std::lround(a.positions[k].x * 1000)], cz = row[std::lround(a.positions[k].z * 1000)];
    const double t = std::clamp(change[k] / full_colour, -1.0, 1.0);
    const uint8_t fade = uint8_t(std::lround(255 * (1 - std::fabs(t))));
    const uint8_t colour[3] = {t >= 0 ? uint8_t(255) : fade, fade, t <= 0 ? uint8_t(255) : fade};
    for (int y = cz * kCell; y < (cz + 1) * kCell; ++y)
      for (int x = cx * kCell; x < (cx + 1) * kCell; ++x)
        std::copy(colour, colour + 3, &rgb[(size_t(y) * size_t(width) + size_t(x)) * 3]);
  }
  write_png(path, width, height, rgb);
}

}  // namespace radbake
