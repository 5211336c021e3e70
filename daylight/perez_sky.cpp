#include "daylight/perez_sky.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace radbake {
namespace {

constexpr double kDegree = M_PI / 180;

// Lower bounds of Perez's clearness bins 2..8 (Perez et al. 1990, Table 1; the 1993 sky model
// uses the same bins). Bin 1 starts at epsilon = 1.
constexpr double kBinLowerBounds[7] = {1.065, 1.230, 1.500, 1.950, 2.800, 4.500, 6.200};

// One coefficient of the sky model as eq. 6 of Perez, Seals, Michalsky 1993 builds it from the
// sun's zenith angle Z (radians) and the brightness delta: x1 + x2 Z + delta (x3 + x4 Z). In bin 1
// c and d take other forms of the same four numbers (eqs. 7 and 8).
struct FittedCoefficient {
  double x1, x2, x3, x4;
};
struct DistributionFit {
  FittedCoefficient a, b, c, d, e;
};

// Perez, Seals, Michalsky 1993, Table 1 (with the erratum, Solar Energy 51(5):423), one row per
// clearness bin. Checked against the copies in Radiance's gendaylit.c and gendaymtx.c, which
// agree with each other to the last digit.
constexpr DistributionFit kDistributionFits[8] = {
    {// bin 1: 1.000 - 1.065 (overcast)
     {1.3525, -0.2576, -0.2690, -1.4366},
     {-0.7670, 0.0007, 1.2734, -0.1233},
     {2.8000, 0.6004, 1.2375, 1.0000},
     {1.8734, 0.6297, 0.9738, 0.2809},
     {0.0356, -0.1246, -0.5718, 0.9938}},
    {// bin 2: 1.065 - 1.230
     {-1.2219, -0.7730, 1.4148, 1.1016},
     {-0.2054, 0.0367, -3.9128, 0.9156},
     {6.9750, 0.1774, 6.4477, -0.1239},
     {-1.5798, -0.5081, -1.7812, 0.1080},
     {0.2624, 0.0672, -0.2190, -0.4285}},
    {// bin 3: 1.230 - 1.500
     {-1.1000, -0.2515, 0.8952, 0.0156},
     {0.2782, -0.1812, -4.5000, 1.1766},
     {24.7219, -13.0812, -37.7000, 34.8438},
     {-5.0000, 1.5218, 3.9229, -2.6204},
     {-0.0156, 0.1597, 0.4199, -0.5562}},
    {// bin 4: 1.500 - 1.950
     {-0.5484, -0.6654, -0.2672, 0.7117},
     {0.7234, -0.6219, -5.6812, 2.6297},
     {33.3389, -18.3000, -62.2500, 52.0781},
     {-3.5000, 0.0016, 1.1477, 0.1062},
     {0.4659, -0.3296, -0.0876, -0.0329}},
    {// bin 5: 1.950 - 2.800
     {-0.6000, -0.3566, -2.5000, 2.3250},
     {0.2937, 0.0496, -5.6812, 1.8415},
     {21.0000, -4.7656, -21.5906, 7.2492},
     {-3.5000, -0.1554, 1.4062, 0.3988},
     {0.0032, 0.0766, -0.0656, -0.1294}},
    {// bin 6: 2.800 - 4.500
     {-1.0156, -0.3670, 1.0078, 1.4051},
     {0.2875, -0.5328, -3.8500, 3.3750},
     {14.0000, -0.9999, -7.1406, 7.5469},
     {-3.4000, -0.1078, -1.0750, 1.5702},
     {-0.0672, 0.4016, 0.3017, -0.4844}},
    {// bin 7: 4.500 - 6.200
     {-1.0000, 0.0211, 0.5025, -0.5119},
     {-0.3000, 0.1922, 0.7023, -1.6317},
     {19.0000, -5.0000, 1.2438, -1.9094},
     {-4.0000, 0.0250, 0.3844, 0.2656},
     {1.0468, -0.3788, -2.4517, 1.4656}},
    {// bin 8: 6.200 and clearer
     {-1.0500, 0.0289, 0.4260, 0.3590},
     {-0.3250, 0.1156, 0.7781, 0.0025},
     {31.0625, -14.5000, -46.1148, 55.3750},
     {-7.2312, 0.4050, 13.3500, 0.6234},
     {1.5000, -0.6426, 1.8564, 0.5636}},
};

// Luminous efficacy, lm/W, as a + b W + c f(Z) + d g(delta) (Perez et al. 1990, Table 4):
// for the diffuse light f = cos Z, g = ln delta (eq. 7); for the direct light
// f = exp(5.73 Z - 5), g = delta (eq. 8). W is the precipitable water in cm, Z radians.
struct EfficacyFit {
  double a, b, c, d;
};
constexpr EfficacyFit kDiffuseEfficacy[8] = {
    {97.24, -0.46, 12.00, -8.91},    {107.22, 1.15, 0.59, -3.95},    {104.97, 2.96, -5.53, -8.77},
    {102.39, 5.59, -13.95, -13.90},  {100.71, 5.94, -22.75, -23.74}, {106.42, 3.83, -36.15, -28.83},
    {141.88, 1.90, -53.24, -14.03},  {152.23, 0.35, -45.27, -7.98},
};
constexpr EfficacyFit kDirectEfficacy[8] = {
    {57.20, -4.55, -2.98, 117.12},   {98.99, -3.46, -1.21, 12.38},   {109.83, -4.90, -1.71, -8.81},
    {110.34, -5.84, -1.99, -4.56},   {106.36, -3.97, -1.75, -6.16},  {107.19, -1.25, -1.51, -26.73},
    {105.75, 0.77, -1.26, -34.44},   {101.18, 1.58, -1.10, -8.29},
};

// The range of delta the coefficients are used over (Radiance's gendaylit and gendaymtx): the
// fits extrapolate badly beyond what the data covered.
constexpr double kLeastBrightness = 0.01, kMostBrightness = 0.6;
// In bins 2-5 both Radiance programs raise delta to 0.2 before the coefficients. Without that, a
// scan over irradiances that can occur (global not above extraterrestrial, every sun height)
// found skies with negative luminance or b > 0 in each of these four bins; with it, in none.
constexpr double kLeastBrightnessInBins2To5 = 0.2;

// W/m2 at the mean Sun-Earth distance; the value gendaylit and gendaymtx use.
constexpr double kSolarConstant = 1367;

std::string format(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

// (Mean over actual Sun-Earth distance)^2 on a day of the year: Spencer 1971's series, as in
// Iqbal 1983, eq. 1.2.1.
double eccentricity_factor(int day_of_year) {
  const double day_angle = 2 * M_PI * (day_of_year - 1) / 365;
  return 1.00011 + 0.034221 * std::cos(day_angle) + 0.00128 * std::sin(day_angle) +
         0.000719 * std::cos(2 * day_angle) + 0.000077 * std::sin(2 * day_angle);
}

// Relative optical air mass, Kasten 1966 (the one Perez et al. 1990 use); finite at the horizon,
// where 1 / cos Z is not.
double air_mass(double sun_zenith) {
  const double degrees = sun_zenith / kDegree;
  return 1 / (std::cos(sun_zenith) + 0.15 * std::pow(93.885 - degrees, -1.253));
}

double evaluate(const FittedCoefficient& x, double zenith, double brightness) {
  return x.x1 + x.x2 * zenith + brightness * (x.x3 + x.x4 * zenith);
}

// Above the horizon the gradation lies between its zenith value 1 + a exp(b) and its horizon value
// 1 (exp(b / cos Z) falls from exp(b) to 0 when b < 0), so it is positive when both ends are. The
// indicatrix is checked every 0.05 degree over the angles from the sun that the sky holds: it is
// smooth, and the smallest structure it has (its circumsolar peak) is degrees wide.
bool luminance_is_positive_above_the_horizon(const PerezCoefficients& p, double sun_zenith) {
  if (!(p.b < 0) || !(1 + p.a * std::exp(p.b) > 0)) return false;
  const double farthest = sun_zenith + 0.5 * M_PI;
  const int steps = static_cast<int>(std::ceil(farthest / (0.05 * kDegree)));
  for (int i = 0; i <= steps; ++i) {
    const double from_sun = farthest * i / steps;
    const double cos_from_sun = std::cos(from_sun);
    if (!(1 + p.c * std::exp(p.d * from_sun) + p.e * cos_from_sun * cos_from_sun > 0)) return false;
  }
  return true;
}

}  // namespace

int perez_clearness_bin(double clearness) {
  if (!(clearness >= 1))
    throw std::invalid_argument("Perez sky clearness must be at least 1, got " + format(clearness));
  int bin = 1;
  for (double lower : kBinLowerBounds)
    if (clearness >= lower) ++bin;
  return bin;
}

PerezCoefficients perez_coefficients(double clearness, double brightness, double sun_zenith) {
  if (!std::isfinite(clearness) || !std::isfinite(brightness) || !std::isfinite(sun_zenith))
    throw std::invalid_argument("Perez sky clearness, brightness and sun zenith angle must be finite numbers");
  const int bin = perez_clearness_bin(clearness);
  double delta = std::fmin(std::fmax(brightness, kLeastBrightness), kMostBrightness);
  if (bin >= 2 && bin <= 5) delta = std::fmax(delta, kLeastBrightnessInBins2To5);
  const DistributionFit& fit = kDistributionFits[bin - 1];
  const double z = sun_zenith;
  PerezCoefficients p;
  p.a = evaluate(fit.a, z, delta);
  p.b = evaluate(fit.b, z, delta);
  p.e = evaluate(fit.e, z, delta);
  if (bin == 1) {  // eqs. 7 and 8: the overcast bin's circumsolar terms
    p.c = std::exp(std::pow(delta * (fit.c.x1 + fit.c.x2 * z), fit.c.x3)) - fit.c.x4;
    p.d = -std::exp(delta * (fit.d.x1 + fit.d.x2 * z)) + fit.d.x3 + delta * fit.d.x4;
  } else {
    p.c = evaluate(fit.c, z, delta);
    p.d = evaluate(fit.d, z, delta);
  }
  return p;
}

PerezSky perez_sky(double direct_normal_irradiance, double diffuse_horizontal_irradiance, double sun_zenith,
                   int day_of_year, std::optional<double> dew_point) {
  const double dni = direct_normal_irradiance, dhi = diffuse_horizontal_irradiance;
  if (!std::isfinite(dni) || dni < 0)
    throw std::invalid_argument("direct normal irradiance must be a finite number >= 0 W/m2, got " + format(dni));
  if (!std::isfinite(dhi) || dhi < 0)
    throw std::invalid_argument("diffuse horizontal irradiance must be a finite number >= 0 W/m2, got " +
                                format(dhi));
  if (dhi == 0)
    throw std::invalid_argument(
        "diffuse horizontal irradiance is 0 W/m2: there is no sky to shape (the Perez clearness would be "
        "infinite)");
  if (!std::isfinite(sun_zenith) || sun_zenith < 0)
    throw std::invalid_argument("sun zenith angle must be a finite number >= 0 radians, got " + format(sun_zenith));
  if (sun_zenith >= 0.5 * M_PI)
    throw std::invalid_argument("the sun is at or below the horizon (zenith angle " + format(sun_zenith / kDegree) +
                                " degrees): the Perez sky is defined only while the sun is up");
  if (day_of_year < 1 || day_of_year > 366)
    throw std::invalid_argument("day of year must be 1..366, got " + std::to_string(day_of_year));
  if (dew_point && !std::isfinite(*dew_point))
    throw std::invalid_argument("dew point must be a finite number of degrees Celsius");

  const double extraterrestrial = kSolarConstant * eccentricity_factor(day_of_year);  // W/m2, normal
  if (dni > extraterrestrial)
    throw std::invalid_argument("direct normal irradiance " + format(dni) +
                                " W/m2 is more than reaches the top of the atmosphere that day (" +
                                format(extraterrestrial) + " W/m2)");

  PerezSky sky;
  // Perez et al. 1990, eq. 1: the 1.041 Z^3 terms make epsilon nearly independent of the sun's
  // height for a given cloud cover.
  const double z3 = 1.041 * sun_zenith * sun_zenith * sun_zenith;
  sky.clearness = ((dhi + dni) / dhi + z3) / (1 + z3);
  sky.brightness = dhi * air_mass(sun_zenith) / extraterrestrial;  // eq. 2
  sky.clearness_bin = perez_clearness_bin(sky.clearness);
  sky.precipitable_water = dew_point ? std::exp(0.07 * *dew_point - 0.075) : 2.0;

  const int i = sky.clearness_bin - 1;
  const double delta = std::fmin(std::fmax(sky.brightness, kLeastBrightness), kMostBrightness);
  const double w = sky.precipitable_water;
  const EfficacyFit& diffuse = kDiffuseEfficacy[i];
  const EfficacyFit& direct = kDirectEfficacy[i];
  const double diffuse_efficacy =
      diffuse.a + diffuse.b * w + diffuse.c * std::cos(sun_zenith) + diffuse.d * std::log(delta);  // lm/W
  // The direct fit goes negative for a sun near the horizon in the overcast bins; there is no
  // direct light to speak of then.
  const double direct_efficacy =
      std::fmax(0.0, direct.a + direct.b * w + direct.c * std::exp(5.73 * sun_zenith - 5) + direct.d * delta);
  sky.diffuse_horizontal_illuminance = dhi * diffuse_efficacy;
  sky.direct_normal_illuminance = dni * direct_efficacy;

  sky.distribution.model = SkyModel::Perez;
  sky.distribution.perez = perez_coefficients(sky.clearness, sky.brightness, sun_zenith);
  if (!luminance_is_positive_above_the_horizon(sky.distribution.perez, sun_zenith)) {
    const PerezCoefficients& p = sky.distribution.perez;
    throw std::domain_error("the Perez 1993 fit gives no valid sky for clearness " + format(sky.clearness) +
                            ", brightness " + format(sky.brightness) + " and the sun " +
                            format(sun_zenith / kDegree) + " degrees from the zenith (a " + format(p.a) + ", b " +
                            format(p.b) + ", c " + format(p.c) + ", d " + format(p.d) + ", e " + format(p.e) +
                            "): its luminance is zero or negative somewhere above the horizon");
  }
  // The ratio does not depend on the sun's azimuth: the whole sky turns with it.
  sky.zenith_luminance = sky.diffuse_horizontal_illuminance /
                         horizontal_illuminance_over_zenith_luminance(sky.distribution, sun_zenith, 0);
  return sky;
}

}  // namespace radbake
