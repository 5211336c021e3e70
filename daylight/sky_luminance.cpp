#include "daylight/sky_luminance.h"

#include <cmath>
#include <string>

namespace radbake {
namespace {

// ISO 15469 Table 1: gradation (a, b) and indicatrix (c, d, e) of the 15 standard skies.
struct CieParameters {
  double a, b, c, d, e;
};
constexpr CieParameters kCieTypes[15] = {
    {4.0, -0.70, 0, -1.0, 0},      {4.0, -0.70, 2, -1.5, 0.15},   {1.1, -0.8, 0, -1.0, 0},
    {1.1, -0.8, 2, -1.5, 0.15},    {0, -1.0, 0, -1.0, 0},         {0, -1.0, 2, -1.5, 0.15},
    {0, -1.0, 5, -2.5, 0.30},      {0, -1.0, 10, -3.0, 0.45},     {-1.0, -0.55, 2, -1.5, 0.15},
    {-1.0, -0.55, 5, -2.5, 0.30},  {-1.0, -0.55, 10, -3.0, 0.45}, {-1.0, -0.32, 10, -3.0, 0.45},
    {-1.0, -0.32, 16, -3.0, 0.30}, {-1.0, -0.15, 16, -3.0, 0.30}, {-1.0, -0.15, 24, -2.8, 0.15},
};

const CieParameters& cie_parameters(int type) {
  if (type < 1 || type > 15) throw std::invalid_argument("CIE sky type must be 1..15, got " + std::to_string(type));
  return kCieTypes[type - 1];
}

// Gradation: luminance against zenith angle; phi(90 degrees) = 1 (the limit of exp(b / cos Z)).
double gradation(const CieParameters& p, double zenith) {
  const double c = std::cos(zenith);
  return c > 0 ? 1 + p.a * std::exp(p.b / c) : 1.0;
}

// Indicatrix: luminance against the angle from the sun.
double indicatrix(const CieParameters& p, double from_sun) {
  const double half_pi = 0.5 * M_PI;
  return 1 + p.c * (std::exp(p.d * from_sun) - std::exp(p.d * half_pi)) + p.e * std::cos(from_sun) * std::cos(from_sun);
}

// The angle between a view and the sun, radians.
double angle_from_sun(double zenith, double azimuth, double sun_zenith, double sun_azimuth) {
  const double cos_from_sun = std::cos(sun_zenith) * std::cos(zenith) +
                              std::sin(sun_zenith) * std::sin(zenith) * std::cos(azimuth - sun_azimuth);
  return std::acos(std::fmax(-1.0, std::fmin(1.0, cos_from_sun)));
}

// The Perez sky's two factors, the same shape as the CIE sky's but with no normalising terms
// (Perez, Seals, Michalsky 1993, eq. 1). Its gradation at the horizon is 1, the limit of
// exp(b / cos Z) for b < 0.
double perez_gradation(const PerezCoefficients& p, double zenith) {
  const double c = std::cos(zenith);
  return c > 0 ? 1 + p.a * std::exp(p.b / c) : 1.0;
}

double perez_indicatrix(const PerezCoefficients& p, double from_sun) {
  const double cos_from_sun = std::cos(from_sun);
  return 1 + p.c * std::exp(p.d * from_sun) + p.e * cos_from_sun * cos_from_sun;
}

double relative_perez_luminance(const PerezCoefficients& p, double zenith, double azimuth, double sun_zenith,
                                double sun_azimuth) {
  // With b >= 0, exp(b / cos Z) grows without bound toward the horizon and the luminance with it
  // (to minus infinity when a < 0): coefficients fitted to real skies never do that.
  if (!(p.b < 0))
    throw std::invalid_argument("Perez sky coefficient b must be negative, got " + std::to_string(p.b));
  const double at_zenith = perez_gradation(p, 0) * perez_indicatrix(p, sun_zenith);
  if (!(at_zenith > 0))
    throw std::invalid_argument("Perez sky coefficients give a zenith luminance of " + std::to_string(at_zenith) +
                                " (not positive): nothing to be relative to");
  const double from_sun = angle_from_sun(zenith, azimuth, sun_zenith, sun_azimuth);
  return perez_gradation(p, zenith) * perez_indicatrix(p, from_sun) / at_zenith;
}

}  // namespace

double relative_sky_luminance(const SkyDistribution& sky, double zenith, double azimuth, double sun_zenith,
                              double sun_azimuth) {
  if (!(zenith <= 0.5 * M_PI)) return 0;
  switch (sky.model) {
    case SkyModel::Uniform:
      return 1;
    case SkyModel::CieOvercast:
      return (1 + 2 * std::cos(zenith)) / 3;
    case SkyModel::Perez:
      return relative_perez_luminance(sky.perez, zenith, azimuth, sun_zenith, sun_azimuth);
    case SkyModel::CieGeneral:
      break;
  }
  const CieParameters& p = cie_parameters(sky.cie_type);
  const double from_sun = angle_from_sun(zenith, azimuth, sun_zenith, sun_azimuth);
  return indicatrix(p, from_sun) * gradation(p, zenith) / (indicatrix(p, sun_zenith) * gradation(p, 0));
}

double horizontal_illuminance_over_zenith_luminance(const SkyDistribution& sky, double sun_zenith,
                                                    double sun_azimuth) {
  // Midpoint rule in (Z, alpha) with the cos Z sin Z dZ dalpha measure: smooth integrands, and
  // the circumsolar peak of the clear skies is spread over degrees, not arcminutes. Every sky here
  // is symmetric about the sun's vertical, so azimuths are taken from the sun's and each half
  // ring counts twice.
  constexpr int kZenithSteps = 360, kAzimuthSteps = 720;
  const double dz = 0.5 * M_PI / kZenithSteps, da = 2 * M_PI / kAzimuthSteps;
  double sum = 0;
  for (int i = 0; i < kZenithSteps; ++i) {
    const double z = (i + 0.5) * dz;
    double ring = 0;
    for (int j = 0; j < kAzimuthSteps / 2; ++j)
      ring += relative_sky_luminance(sky, z, sun_azimuth + (j + 0.5) * da, sun_zenith, sun_azimuth);
    sum += 2 * ring * std::cos(z) * std::sin(z);
  }
  return sum * dz * da;
}

}  // namespace radbake
