#include "daylight/annual_skies.h"

#include <tbb/parallel_for.h>

#include "base/errors.h"
#include "daylight/daylight_sky.h"

namespace radbake {

AnnualSkies annual_skies(const Weather& weather, const DaylightOptions& base) {
  AnnualSkies out;
  out.hours.resize(weather.hours.size());
  const int year = weather.hours.size() == 8784 ? 2024 : 2025;  // a leap year when the file has one
  std::vector<uint8_t> daylit(weather.hours.size(), 0), substituted(weather.hours.size(), 0);
  tbb::parallel_for(size_t(0), weather.hours.size(), [&](size_t k) {
    const WeatherHour& w = weather.hours[k];
    SiteAndTime site;
    site.latitude = weather.latitude, site.longitude = weather.longitude, site.elevation = weather.elevation;
    site.utc_offset = weather.utc_offset;
    site.year = year, site.month = w.month, site.day = w.day;
    site.hour = w.hour - 1, site.minute = 30;  // EPW's hour h ends at h:00
    if (!(sun_position(site).zenith < 90) || !(w.diffuse_horizontal > 0)) return;
    DaylightOptions o = base;
    o.sky = SkyKind::Perez;
    o.sun.reset();
    o.sun_illuminance.reset();
    o.site = site;
    o.direct_normal_irradiance = w.direct_normal, o.diffuse_horizontal_irradiance = w.diffuse_horizontal;
    if (std::isfinite(w.dew_point)) o.dew_point = w.dew_point;
    else o.dew_point.reset();
    daylit[k] = 1;
    try {
      out.hours[k] = daylight_sky(o).light;
    } catch (const InputError&) {
      DaylightOptions overcast = base;
      overcast.sky = SkyKind::CieOvercast;
      overcast.sky_illuminance = 120 * w.diffuse_horizontal;
      overcast.site.reset(), overcast.sun.reset(), overcast.sun_illuminance.reset();
      out.hours[k] = daylight_sky(overcast).light;
      substituted[k] = 1;
    }
  });
  for (size_t k = 0; k < daylit.size(); ++k) out.daylit += daylit[k], out.substituted += substituted[k];
  return out;
}

}  // namespace radbake
