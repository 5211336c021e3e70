// The Perez all-weather sky from what a weather file gives: direct normal and diffuse horizontal
// irradiance (W/m2), the sun's zenith angle, the day of the year and, if known, the dew point.
// Three published models in a row:
//  - the sky's clearness epsilon and brightness delta (Perez, Ineichen, Seals, Michalsky, Stewart
//    1990, "Modeling daylight availability and irradiance components from direct and global
//    irradiance", eqs. 1 and 2), which put the hour in one of eight clearness bins;
//  - the luminous efficacy of the diffuse and of the direct light (the same paper, Table 4,
//    eqs. 7 and 8): lux from W/m2, given the precipitable water;
//  - the luminance distribution (Perez, Seals, Michalsky 1993, "All-weather model for sky
//    luminance distribution", Table 1 with the 1993 erratum): the coefficients a..e.
// The zenith luminance then scales the distribution so that the sky lights an open horizontal
// plane with the diffuse illuminance.
#pragma once

#include <optional>

#include "daylight/sky_luminance.h"

namespace radbake {

struct PerezSky {
  SkyDistribution distribution;             // SkyModel::Perez with this sun's coefficients a..e
  double clearness = 1;                     // epsilon, dimensionless, >= 1: 1 overcast, > 6.2 clear
  double brightness = 0;                    // delta, dimensionless: DHI x air mass / extraterrestrial
  int clearness_bin = 1;                    // 1..8, Perez's bins of epsilon (1: 1 to 1.065, 8: 6.2 up)
  double precipitable_water = 2;            // cm, from the dew point (2 when none is given)
  double diffuse_horizontal_illuminance = 0;  // lux, the sky alone on an open horizontal plane
  double direct_normal_illuminance = 0;     // lux, the sun alone on a plane facing it
  double zenith_luminance = 0;              // cd/m2, gives the sky the diffuse horizontal illuminance
};

// Perez's bin (1..8) of a sky clearness epsilon; bounds 1.065, 1.23, 1.5, 1.95, 2.8, 4.5, 6.2.
int perez_clearness_bin(double clearness);

// The coefficients a..e (Perez, Seals, Michalsky 1993, eqs. 6-8 and Table 1) for a sky of
// clearness epsilon and brightness delta with the sun at `sun_zenith` (radians). Delta is held to
// 0.01..0.6, and to at least 0.2 in bins 2-5, as Radiance's gendaylit and gendaymtx hold it: below
// those the fitted coefficients give skies of negative luminance. Throws std::invalid_argument for
// a clearness below 1 or a non-finite argument.
PerezCoefficients perez_coefficients(double clearness, double brightness, double sun_zenith);

// The Perez sky for one hour of weather. `direct_normal_irradiance` and
// `diffuse_horizontal_irradiance` in W/m2; `sun_zenith` in radians, above the horizon;
// `day_of_year` 1..366 (for the Sun-Earth distance, so the extraterrestrial irradiance);
// `dew_point` in degrees Celsius gives the precipitable water W = exp(0.07 Td - 0.075) cm
// (Perez et al. 1990, after Wright, Perez and Michalsky 1989); without one, W = 2 cm, as gendaylit
// assumes.
//
// Throws std::invalid_argument with the reason for: a negative, NaN or infinite irradiance; a
// diffuse irradiance of 0 (no sky to shape: the clearness would be infinite); a direct normal
// irradiance above the extraterrestrial one; the sun at or below the horizon (the model is not
// defined there: call it only while the sun is up); a day outside 1..366; a non-finite dew point.
// Throws std::domain_error when the fitted coefficients give this hour a sky of zero or negative
// luminance somewhere above the horizon (it happens: clearness 2.8-4.5 with little diffuse light
// and a high sun, for one); the caller chooses the fallback.
PerezSky perez_sky(double direct_normal_irradiance, double diffuse_horizontal_irradiance, double sun_zenith,
                   int day_of_year, std::optional<double> dew_point = std::nullopt);

}  // namespace radbake
