#include "daylight/sun_position.h"

#include <cmath>

namespace radbake {
namespace {

constexpr double kDegree = M_PI / 180;

double wrap_degrees(double x) {
  x = std::fmod(x, 360.0);
  return x < 0 ? x + 360 : x;
}

// Julian day of a Gregorian calendar date, the day's fraction included (Meeus 7.1).
double julian_day(int year, int month, double day) {
  if (month <= 2) year -= 1, month += 12;
  const int a = year / 100, b = 2 - a + a / 4;
  return std::floor(365.25 * (year + 4716)) + std::floor(30.6001 * (month + 1)) + day + b - 1524.5;
}

}  // namespace

SunPosition sun_position(const SiteAndTime& s) {
  const double day_fraction = (s.hour - s.utc_offset + (s.minute + s.second / 60) / 60) / 24;
  const double jd = julian_day(s.year, s.month, s.day + day_fraction);  // universal time
  const double t = (jd + s.delta_t / 86400 - 2451545.0) / 36525;         // Julian centuries, TT

  // The sun's apparent longitude and the obliquity (Meeus 25.2-25.8, 22.2-22.3).
  const double mean_longitude = 280.46646 + t * (36000.76983 + t * 0.0003032);
  const double anomaly = 357.52911 + t * (35999.05029 - t * 0.0001537);
  const double m = anomaly * kDegree;
  const double centre = (1.914602 - t * (0.004817 + t * 0.000014)) * std::sin(m) +
                        (0.019993 - t * 0.000101) * std::sin(2 * m) + 0.000289 * std::sin(3 * m);
  const double true_longitude = mean_longitude + centre;
  const double node = (125.04 - 1934.136 * t) * kDegree;
  const double longitude = (true_longitude - 0.00569 - 0.00478 * std::sin(node)) * kDegree;
  const double mean_obliquity = 23.0 + (26.0 + (21.448 - t * (46.8150 + t * (0.00059 - t * 0.001813))) / 60) / 60;
  const double obliquity = (mean_obliquity + 0.00256 * std::cos(node)) * kDegree;
  const double right_ascension = std::atan2(std::cos(obliquity) * std::sin(longitude), std::cos(longitude));
  const double declination = std::asin(std::sin(obliquity) * std::sin(longitude));

  // Apparent sidereal time at Greenwich (Meeus 12.4, nutation in right ascension from the main
  // term of the nutation in longitude, 22.A), then the site's hour angle.
  const double tu = (jd - 2451545.0) / 36525;
  const double nutation = -17.20 / 3600 * std::sin(node);
  const double sidereal = wrap_degrees(280.46061837 + 360.98564736629 * (jd - 2451545.0) +
                                       tu * tu * (0.000387933 - tu / 38710000) +
                                       nutation * std::cos(obliquity));
  const double hour_angle = (sidereal + s.longitude) * kDegree - right_ascension;

  // Topocentric: the site sees the sun from the Earth's surface, not its centre (SPA 3.12).
  const double eccentricity = 0.016708634 - t * (0.000042037 + t * 0.0000001267);
  const double distance = 1.000001018 * (1 - eccentricity * eccentricity) /
                          (1 + eccentricity * std::cos(m + centre * kDegree));  // AU
  const double parallax = 8.794 / 3600 / distance * kDegree;
  const double phi = s.latitude * kDegree;
  const double u = std::atan(0.99664719 * std::tan(phi));
  const double x = std::cos(u) + s.elevation / 6378140 * std::cos(phi);
  const double y = 0.99664719 * std::sin(u) + s.elevation / 6378140 * std::sin(phi);
  const double shift = std::atan2(-x * std::sin(parallax) * std::sin(hour_angle),
                                  std::cos(declination) - x * std::sin(parallax) * std::cos(hour_angle));
  const double topocentric_declination =
      std::atan2((std::sin(declination) - y * std::sin(parallax)) * std::cos(shift),
                 std::cos(declination) - x * std::sin(parallax) * std::cos(hour_angle));
  const double h = hour_angle - shift;

  const double elevation = std::asin(std::sin(phi) * std::sin(topocentric_declination) +
                                     std::cos(phi) * std::cos(topocentric_declination) * std::cos(h)) / kDegree;
  // Refraction lifts the sun while any of it is above the horizon (SPA eq. 42).
  double refraction = 0;
  if (elevation >= -(0.26667 + 0.5667))
    refraction = s.pressure / 1010 * 283 / (273 + s.temperature) * 1.02 /
                 (60 * std::tan((elevation + 10.3 / (elevation + 5.11)) * kDegree));
  SunPosition out;
  out.zenith = 90 - (elevation + refraction);
  const double from_south = std::atan2(std::sin(h), std::cos(h) * std::sin(phi) -
                                                        std::tan(topocentric_declination) * std::cos(phi));
  out.azimuth = wrap_degrees(from_south / kDegree + 180);
  return out;
}

}  // namespace radbake
