#include "daylight/sky_luminance.h"

#include <cmath>
#include <string>
#include <vector>

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

// Indicatrix: luminance against the angle from the sun, given with its cosine (which a quadrature
// has before the angle: cos(acos(x)) again cost a third of a year's skies).
double indicatrix(const CieParameters& p, double from_sun, double cos_from_sun) {
  const double half_pi = 0.5 * M_PI;
  return 1 + p.c * (std::exp(p.d * from_sun) - std::exp(p.d * half_pi)) + p.e * cos_from_sun * cos_from_sun;
}

// The Perez sky's two factors, the same shape as the CIE sky's but with no normalising terms
// (Perez, Seals, Michalsky 1993, eq. 1). Its gradation at the horizon is 1, the limit of
// exp(b / cos Z) for b < 0.
double perez_gradation(const PerezCoefficients& p, double zenith) {
  const double c = std::cos(zenith);
  return c > 0 ? 1 + p.a * std::exp(p.b / c) : 1.0;
}

double perez_indicatrix(const PerezCoefficients& p, double from_sun, double cos_from_sun) {
  return 1 + p.c * std::exp(p.d * from_sun) + p.e * cos_from_sun * cos_from_sun;
}

// The terms of relative_sky_luminance that depend on the sky and its sun alone, worked out once, so
// that a quadrature over the vault evaluates per point only what changes there (a year's Perez
// skies took 26 s of a 35 s annual bake when every point recomputed them).
class SkyShape {
 public:
  SkyShape(const SkyDistribution& sky, double sun_zenith)
      : sky_(sky), cos_sun_zenith_(std::cos(sun_zenith)), sin_sun_zenith_(std::sin(sun_zenith)) {
    if (sky.model == SkyModel::CieGeneral) {
      const CieParameters& p = cie_parameters(sky.cie_type);
      normaliser_ = indicatrix(p, sun_zenith, cos_sun_zenith_) * gradation(p, 0);
    } else if (sky.model == SkyModel::Perez) {
      const PerezCoefficients& p = sky.perez;
      // With b >= 0, exp(b / cos Z) grows without bound toward the horizon and the luminance with
      // it (to minus infinity when a < 0): coefficients fitted to real skies never do that.
      if (!(p.b < 0))
        throw std::invalid_argument("Perez sky coefficient b must be negative, got " + std::to_string(p.b));
      normaliser_ = perez_gradation(p, 0) * perez_indicatrix(p, sun_zenith, cos_sun_zenith_);
      if (!(normaliser_ > 0))
        throw std::invalid_argument("Perez sky coefficients give a zenith luminance of " + std::to_string(normaliser_) +
                                    " (not positive): nothing to be relative to");
    }
  }

  // Luminance against the zenith angle; for the traditional overcast and the uniform sky, all there is.
  double gradation_at(double zenith) const {
    switch (sky_.model) {
      case SkyModel::Uniform:
        return 1;
      case SkyModel::CieOvercast:
        return (1 + 2 * std::cos(zenith)) / 3;
      case SkyModel::Perez:
        return perez_gradation(sky_.perez, zenith);
      case SkyModel::CieGeneral:
        break;
    }
    return gradation(cie_parameters(sky_.cie_type), zenith);
  }

  // The cosine of the angle between a view and the sun, from the view's zenith angle and its
  // azimuth measured from the sun's.
  double cos_from_sun(double cos_zenith, double sin_zenith, double cos_azimuth_from_sun) const {
    return cos_sun_zenith_ * cos_zenith + sin_sun_zenith_ * sin_zenith * cos_azimuth_from_sun;
  }

  // L / L_zenith at a point above the horizon whose gradation_at() is `gradation_there`.
  double relative(double gradation_there, double cos_from_sun) const {
    if (sky_.model == SkyModel::Uniform || sky_.model == SkyModel::CieOvercast) return gradation_there;
    const double cosine = std::fmax(-1.0, std::fmin(1.0, cos_from_sun)), from_sun = std::acos(cosine);
    const double towards_sun = sky_.model == SkyModel::Perez ? perez_indicatrix(sky_.perez, from_sun, cosine)
                                                             : indicatrix(cie_parameters(sky_.cie_type), from_sun, cosine);
    return gradation_there * towards_sun / normaliser_;
  }

 private:
  const SkyDistribution& sky_;
  double cos_sun_zenith_, sin_sun_zenith_;
  double normaliser_ = 1;  // the numerator's value at the zenith
};

}  // namespace

double relative_sky_luminance(const SkyDistribution& sky, double zenith, double azimuth, double sun_zenith,
                              double sun_azimuth) {
  if (!(zenith <= 0.5 * M_PI)) return 0;
  const SkyShape shape(sky, sun_zenith);
  return shape.relative(shape.gradation_at(zenith),
                        shape.cos_from_sun(std::cos(zenith), std::sin(zenith), std::cos(azimuth - sun_azimuth)));
}

double horizontal_illuminance_over_zenith_luminance(const SkyDistribution& sky, double sun_zenith,
                                                    double sun_azimuth) {
  // Midpoint rule in (Z, alpha) with the cos Z sin Z dZ dalpha measure: smooth integrands, and
  // the circumsolar peak of the clear skies is spread over degrees, not arcminutes. Every sky here
  // is symmetric about the sun's vertical, so azimuths are taken from the sun's and each half
  // ring counts twice.
  constexpr int kZenithSteps = 360, kAzimuthSteps = 720;
  const double dz = 0.5 * M_PI / kZenithSteps, da = 2 * M_PI / kAzimuthSteps;
  const SkyShape shape(sky, sun_zenith);
  std::vector<double> cos_azimuth_from_sun(kAzimuthSteps / 2);
  for (int j = 0; j < kAzimuthSteps / 2; ++j) {
    const double azimuth = sun_azimuth + (j + 0.5) * da;
    cos_azimuth_from_sun[size_t(j)] = std::cos(azimuth - sun_azimuth);
  }
  double sum = 0;
  for (int i = 0; i < kZenithSteps; ++i) {
    const double z = (i + 0.5) * dz, cos_z = std::cos(z), sin_z = std::sin(z), gradation_there = shape.gradation_at(z);
    double ring = 0;
    for (double cos_azimuth : cos_azimuth_from_sun)
      ring += shape.relative(gradation_there, shape.cos_from_sun(cos_z, sin_z, cos_azimuth));
    sum += 2 * ring * cos_z * sin_z;
  }
  return sum * dz * da;
}

}  // namespace radbake
