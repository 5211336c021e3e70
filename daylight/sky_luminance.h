// How the sky's luminance is spread over the vault, relative to its zenith: the CIE standard
// general sky (ISO 15469:2004 / CIE S 011/E:2003, its 15 types from overcast to clear), the
// traditional CIE overcast sky (Moon and Spencer 1942), a uniform sky and the Perez all-weather
// sky (Perez, Seals, Michalsky 1993; its coefficients from weather data: daylight/perez_sky.h).
// Angles in radians; azimuths measured the same way for the view and the sun (which way is north
// is the caller's).
#pragma once

#include <stdexcept>

namespace radbake {

enum class SkyModel {
  CieGeneral,   // one of the 15 standard types, `cie_type`
  CieOvercast,  // L = Lz (1 + 2 cos Z) / 3
  Uniform,      // L = Lz everywhere
  Perez,        // the Perez all-weather sky, coefficients `perez`
};

// The Perez all-weather sky's five coefficients: L(Z, gamma) is proportional to
//   [1 + a exp(b / cos Z)] [1 + c exp(d gamma) + e cos^2 gamma],
// Z the view's zenith angle, gamma its angle from the sun, both in radians. They depend on the
// sun and the weather (perez_sky() derives them); the defaults make a uniform sky.
struct PerezCoefficients {
  double a = 0;   // dimensionless: darkening (< 0) or brightening (> 0) toward the horizon
  double b = -1;  // dimensionless, must be negative: how close to the horizon that gradation sets in
  double c = 0;   // dimensionless: strength of the brightening around the sun
  double d = -1;  // per radian, negative: how fast it falls off with the angle from the sun
  double e = 0;   // dimensionless: light scattered backward (the cos^2 gamma term)
};

struct SkyDistribution {
  SkyModel model = SkyModel::CieGeneral;
  int cie_type = 12;  // 1..15: 1-6 overcast, 7-10 intermediate, 11-15 clear (12: the CIE clear sky)
  PerezCoefficients perez{};  // for SkyModel::Perez; they hold for one sun zenith angle only
};

// L(Z, alpha) / L_zenith for a view `zenith` and `azimuth` with the sun at `sun_zenith`,
// `sun_azimuth`; zero below the horizon. Throws std::invalid_argument for a type outside 1..15,
// and for Perez coefficients that make no sky: b >= 0 (luminance without bound at the horizon) or
// a zenith luminance <= 0 (nothing to be relative to).
double relative_sky_luminance(const SkyDistribution& sky, double zenith, double azimuth, double sun_zenith,
                              double sun_azimuth);

// Illuminance on an unobstructed horizontal plane over the zenith luminance (E_h / L_z, sr):
// pi for the uniform sky, 7 pi / 9 for the traditional overcast one. By quadrature over the
// vault, fine enough for 1e-5 relative; what the daylight factor divides by.
double horizontal_illuminance_over_zenith_luminance(const SkyDistribution& sky, double sun_zenith,
                                                    double sun_azimuth);

}  // namespace radbake
