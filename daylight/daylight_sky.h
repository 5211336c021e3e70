// From what a user says about daylight (a sky type, a site and a moment or the sun's position,
// how bright the sky and the sun are, which way is north) to the SkyLight the bake uses, with the
// figures a report shows. Throws InputError for what cannot be baked (the sun below the horizon
// under a sky that needs it, north along the vertical, a sunny sky with no sun brightness).
#pragma once

#include <optional>
#include <string>

#include "daylight/sky.h"
#include "daylight/sun_position.h"

namespace radbake {

enum class SkyKind {
  None,
  Uniform,      // the same luminance everywhere
  CieOvercast,  // the traditional CIE overcast sky (Moon and Spencer), for daylight factors
  CieGeneral,   // one of the 15 CIE standard general skies, `cie_type`
  Perez,        // the Perez all-weather sky from an hour of weather (needs a site and time)
};

struct DaylightOptions {
  SkyKind sky = SkyKind::None;
  int cie_type = 12;                         // with CieGeneral: 1..15
  double sky_illuminance = 10000;            // lux, unobstructed horizontal from the sky alone
  std::optional<double> sun_illuminance;     // lux, direct normal; unset: none (an error for skies 7..15)
  // Perez: the weather's irradiance, W/m2 (< 0: not given), and its dew point (degrees C; unset:
  // 2 cm of precipitable water).
  double direct_normal_irradiance = -1, diffuse_horizontal_irradiance = -1;
  std::optional<double> dew_point;
  // Where the sun is: from a site and a moment, or given (degrees, azimuth from north eastward).
  std::optional<SiteAndTime> site;
  std::optional<SunPosition> sun;
  Vec3 up{0, 1, 0};                          // the scene's zenith (glTF: +Y)
  Vec3 north{0, 0, -1};                      // projected onto the horizontal plane
  double ground_reflectance = 0.2;
  uint32_t sky_rays = 256, sun_rays = 32;    // per texel
};

// What the bake's daylight was, for report.json.
struct DaylightSummary {
  std::string sky;                     // "cie-12", "cie-overcast", "uniform"
  double sun_zenith = 0, sun_azimuth = 0;  // degrees, azimuth from north eastward
  bool sun_known = false;              // a site and moment or a position was given
  double zenith_luminance = 0;         // cd/m2
  double sky_illuminance = 0;          // lux, unobstructed horizontal, sky alone
  double sun_illuminance = 0;          // lux, direct normal (0 when the sun is down or absent)
  double exterior_horizontal_illuminance = 0;  // lux, sky plus sun on an open horizontal plane
  double perez_clearness = 0, perez_brightness = 0;  // epsilon and delta; 0 for other skies
};

struct Daylight {
  SkyLight light;
  DaylightSummary summary;
};

Daylight daylight_sky(const DaylightOptions& options);

// What a daylight factor divides by: the horizontal illuminance the sky gives an unobstructed
// plane, lux. Defined for overcast skies without a sun (CIE overcast, a uniform sky, ISO 15469
// types 1 to 6); throws InputError for any other.
double daylight_factor_reference(const DaylightOptions& options, const Daylight& daylight);

}  // namespace radbake
