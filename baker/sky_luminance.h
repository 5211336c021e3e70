// How the sky's luminance is spread over the vault, relative to its zenith: the CIE standard
// general sky (ISO 15469:2004 / CIE S 011/E:2003, its 15 types from overcast to clear), the
// traditional CIE overcast sky (Moon and Spencer 1942) and a uniform sky. Angles in radians;
// azimuths measured the same way for the view and the sun (which way is north is the caller's).
#pragma once

#include <stdexcept>

namespace radbake {

enum class SkyModel {
  CieGeneral,   // one of the 15 standard types, `cie_type`
  CieOvercast,  // L = Lz (1 + 2 cos Z) / 3
  Uniform,      // L = Lz everywhere
};

struct SkyDistribution {
  SkyModel model = SkyModel::CieGeneral;
  int cie_type = 12;  // 1..15: 1-6 overcast, 7-10 intermediate, 11-15 clear (12: the CIE clear sky)
};

// L(Z, alpha) / L_zenith for a view `zenith` and `azimuth` with the sun at `sun_zenith`,
// `sun_azimuth`; zero below the horizon. Throws std::invalid_argument for a type outside 1..15.
double relative_sky_luminance(const SkyDistribution& sky, double zenith, double azimuth, double sun_zenith,
                              double sun_azimuth);

// Illuminance on an unobstructed horizontal plane over the zenith luminance (E_h / L_z, sr):
// pi for the uniform sky, 7 pi / 9 for the traditional overcast one. By quadrature over the
// vault, fine enough for 1e-5 relative; what the daylight factor divides by.
double horizontal_illuminance_over_zenith_luminance(const SkyDistribution& sky, double sun_zenith,
                                                    double sun_azimuth);

}  // namespace radbake
