#include "daylight/daylight_sky.h"

#include <cmath>
#include <cstdio>

#include "base/errors.h"
#include "daylight/perez_sky.h"

namespace radbake {
namespace {

constexpr double kDegree = M_PI / 180;

// ISO 15469 types 1, 3 and 5 have no indicatrix: their luminance does not depend on the sun.
bool sky_follows_sun(const DaylightOptions& o) {
  return o.sky == SkyKind::Perez ||
         (o.sky == SkyKind::CieGeneral && o.cie_type != 1 && o.cie_type != 3 && o.cie_type != 5);
}

int day_of_year(const SiteAndTime& site) {
  static const int before_month[12] = {0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334};
  const bool leap = (site.year % 4 == 0 && site.year % 100 != 0) || site.year % 400 == 0;
  return before_month[site.month - 1] + site.day + (leap && site.month > 2 ? 1 : 0);
}

// The Perez model's sky for the site's hour, as the sky light takes it; the model's own refusals
// as the user's errors.
PerezSky weather_sky(const DaylightOptions& o, double sun_zenith_degrees) {
  if (!o.site) throw InputError("sky perez needs the hour's site and time (--latitude, --longitude, --date, --time)");
  if (o.direct_normal_irradiance < 0 || o.diffuse_horizontal_irradiance < 0)
    throw InputError("sky perez needs the hour's weather: --direct-normal and --diffuse-horizontal irradiance in W/m2");
  try {
    return perez_sky(o.direct_normal_irradiance, o.diffuse_horizontal_irradiance, sun_zenith_degrees * kDegree,
                     day_of_year(*o.site), o.dew_point);
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("sky perez: ") + e.what());
  } catch (const std::domain_error& e) {
    throw InputError(std::string("sky perez: ") + e.what() + "; bake this hour under a CIE sky");
  }
}

std::string sky_name(const DaylightOptions& o) {
  switch (o.sky) {
    case SkyKind::Uniform: return "uniform";
    case SkyKind::CieOvercast: return "cie-overcast";
    case SkyKind::CieGeneral: return "cie-" + std::to_string(o.cie_type);
    case SkyKind::Perez: return "perez";
    case SkyKind::None: break;
  }
  return "none";
}

std::string degrees_text(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", v);
  return text;
}

}  // namespace

Daylight daylight_sky(const DaylightOptions& o) {
  Daylight out;
  if (o.sky == SkyKind::None) return out;
  if (o.sky == SkyKind::CieGeneral && (o.cie_type < 1 || o.cie_type > 15))
    throw InputError("CIE sky type must be 1..15, got " + std::to_string(o.cie_type));
  if (o.sky == SkyKind::CieGeneral && o.cie_type >= 7 && !o.sun_illuminance)
    throw InputError("sky " + sky_name(o) +
                     " has a sun: give its direct normal illuminance in lux (--sun-illuminance, 0 for none)");
  if (o.sky == SkyKind::Perez && o.sun_illuminance)
    throw InputError("sky perez takes the sun's illuminance from the weather (--direct-normal), not --sun-illuminance");
  double sun_lux = o.sun_illuminance.value_or(0.0);

  DaylightSummary& s = out.summary;
  s.sky = sky_name(o);
  if (o.sun) {
    s.sun_zenith = o.sun->zenith;
    s.sun_azimuth = o.sun->azimuth;
    s.sun_known = true;
  } else if (o.site) {
    const SunPosition p = sun_position(*o.site);
    s.sun_zenith = p.zenith;
    s.sun_azimuth = p.azimuth;
    s.sun_known = true;
  }
  const bool needs_sun = sky_follows_sun(o) || sun_lux > 0;
  if (needs_sun && !s.sun_known)
    throw InputError("sky " + s.sky + (sun_lux > 0 ? " with a sun" : "") +
                     " needs the sun's position: a site and time (--latitude, --longitude, --date, --time) or "
                     "--sun-position");
  if (needs_sun && s.sun_zenith >= 90)
    throw InputError("the sun is below the horizon then (zenith " + degrees_text(s.sun_zenith) +
                     " degrees): no daylight to bake under sky " + s.sky);

  SkyLight& light = out.light;
  light.enabled = true;
  light.distribution.model = o.sky == SkyKind::Uniform       ? SkyModel::Uniform
                             : o.sky == SkyKind::CieOvercast ? SkyModel::CieOvercast
                                                             : SkyModel::CieGeneral;  // Perez: below
  light.distribution.cie_type = o.cie_type;
  double sky_lux = o.sky_illuminance, perez_zenith_luminance = 0;
  if (o.sky == SkyKind::Perez) {
    const PerezSky weather = weather_sky(o, s.sun_zenith);
    light.distribution = weather.distribution;
    sky_lux = weather.diffuse_horizontal_illuminance;
    perez_zenith_luminance = weather.zenith_luminance;  // the fit's quadrature, not done twice
    sun_lux = weather.direct_normal_illuminance;
    s.perez_clearness = weather.clearness;
    s.perez_brightness = weather.brightness;
  }
  light.sun_zenith = s.sun_zenith * kDegree;
  light.sun_azimuth = s.sun_azimuth * kDegree;
  light.up = normalize(o.up);
  const Vec3 north = o.north - light.up * dot(o.north, light.up);
  if (!(length(north) > 1e-6f * length(o.north)))
    throw InputError("north must not point straight up or down: it is a direction along the ground");
  light.north = normalize(north);
  light.ground_reflectance = o.ground_reflectance;
  light.rays = o.sky_rays;
  light.sun_rays = o.sun_rays;
  light.zenith_luminance =
      o.sky == SkyKind::Perez
          ? perez_zenith_luminance
          : sky_lux / horizontal_illuminance_over_zenith_luminance(light.distribution, light.sun_zenith, light.sun_azimuth);
  light.sky_horizontal_illuminance = sky_lux;
  light.sun_illuminance = sun_lux;

  s.zenith_luminance = light.zenith_luminance;
  s.sky_illuminance = sky_lux;
  s.sun_illuminance = sun_lux;
  s.exterior_horizontal_illuminance = sky_lux + sun_lux * std::cos(light.sun_zenith);
  return out;
}

double daylight_factor_reference(const DaylightOptions& o, const Daylight& daylight) {
  const bool overcast = o.sky == SkyKind::CieOvercast || o.sky == SkyKind::Uniform ||
                        (o.sky == SkyKind::CieGeneral && o.cie_type <= 6);
  if (!overcast || daylight.summary.sun_illuminance > 0)
    throw InputError("a daylight factor needs an overcast sky without a sun (--sky cie-overcast, uniform or cie-1 .. "
                     "cie-6), not sky " + (o.sky == SkyKind::None ? std::string("none") : daylight.summary.sky) +
                     (daylight.summary.sun_illuminance > 0 ? " with a sun" : ""));
  return daylight.summary.sky_illuminance;
}

}  // namespace radbake
