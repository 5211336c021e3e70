#include "io/analysis/epw_reader.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

#include "base/errors.h"
#include "io/files/regular_file.h"

namespace radbake {
namespace {

constexpr uint64_t kMostBytes = 64ull << 20;  // a year of EPW is about 1.6 MB
constexpr int kHeaderLines = 8;                     // LOCATION .. DATA PERIODS

std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  for (std::string f; std::getline(in, f, ',');) fields.push_back(f);
  return fields;
}

struct LineReader {
  const std::string& path;
  size_t line = 0;
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError("weather file " + path + ", line " + std::to_string(line) + ": " + what);
  }
  double number(const std::vector<std::string>& fields, size_t k, const char* name) const {
    if (k >= fields.size()) fail(std::string("no ") + name + " (field " + std::to_string(k + 1) + ")");
    const char* text = fields[k].c_str();
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(text, &end);
    while (end && (*end == ' ' || *end == '\r')) ++end;
    if (end == text || *end != '\0' || errno == ERANGE || !std::isfinite(v))
      fail(std::string(name) + " is not a number: '" + fields[k].substr(0, 40) + "'");
    return v;
  }
  double within(const std::vector<std::string>& fields, size_t k, const char* name, double lo, double hi) const {
    const double v = number(fields, k, name);
    if (v < lo || v > hi) {
      std::ostringstream text;
      text << name << " " << v << " is outside " << lo << ".." << hi;
      fail(text.str() + (v == 9999 ? " (9999: missing)" : ""));
    }
    return v;
  }
};

}  // namespace

Weather read_epw(const std::string& path) {
  std::istringstream file(read_regular_file(path, "weather file", kMostBytes));
  Weather weather;
  LineReader reader{path};
  std::string line;
  while (std::getline(file, line)) {
    ++reader.line;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::vector<std::string> f = fields_of(line);
    if (reader.line == 1) {
      if (f.empty() || f[0] != "LOCATION") reader.fail("an EPW file starts with its LOCATION line");
      weather.place = (f.size() > 1 ? f[1] : "") + (f.size() > 3 && !f[3].empty() ? ", " + f[3] : "");
      weather.latitude = reader.within(f, 6, "latitude", -90, 90);
      weather.longitude = reader.within(f, 7, "longitude", -180, 180);
      weather.utc_offset = reader.within(f, 8, "time zone", -12, 14);
      weather.elevation = reader.within(f, 9, "elevation", -1000, 9999.9);
      continue;
    }
    if (reader.line <= kHeaderLines || line.empty()) continue;
    if (weather.hours.size() == 8784) reader.fail("more than a year of hours (8784)");
    WeatherHour h;
    h.month = int(reader.within(f, 1, "month", 1, 12));
    h.day = int(reader.within(f, 2, "day", 1, 31));
    h.hour = int(reader.within(f, 3, "hour", 1, 24));
    const double dew_point = reader.number(f, 7, "dew point");
    h.dew_point = dew_point == 99.9 ? NAN : reader.within(f, 7, "dew point", -70, 70);  // 99.9: missing
    h.direct_normal = reader.within(f, 14, "direct normal irradiance", 0, 1400);
    h.diffuse_horizontal = reader.within(f, 15, "diffuse horizontal irradiance", 0, 900);
    weather.hours.push_back(h);
  }
  if (weather.hours.size() != 8760 && weather.hours.size() != 8784)
    throw InputError("weather file " + path + " has " + std::to_string(weather.hours.size()) +
                     " hours of weather; a year has 8760 (8784 in a leap year)");
  return weather;
}

}  // namespace radbake
