// Daylight coefficients (baker/annual_daylight.h) against single-hour bakes of the same sky: the
// classroom sample at three hours of London weather, every sensor within 2%.
#include <gtest/gtest.h>

#include <cmath>

#include "baker/annual_daylight.h"
#include "baker/back_faces.h"
#include "baker/daylight.h"
#include "io/gltf.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

SkyLight london_hour(int month, int day, double hour, double direct_normal, double diffuse_horizontal) {
  DaylightOptions o;
  o.sky = SkyKind::Perez;
  o.site = SiteAndTime{};
  o.site->latitude = 51.5, o.site->longitude = -0.12;
  o.site->year = 2026, o.site->month = month, o.site->day = day, o.site->hour = hour;
  o.direct_normal_irradiance = direct_normal, o.diffuse_horizontal_irradiance = diffuse_horizontal;
  return daylight_sky(o).light;
}

TEST(AnnualDaylight, CoefficientsMatchSingleHourBakesAtEverySensor) {
  Scene scene = load_gltf(test::source_path("samples/classroom/classroom.gltf")).scene;
  add_back_faces(scene);  // the glazing and the overhang are double-sided
  const Atlas atlas = test::unwrap(scene, AtlasOptions{});
  // Clear noon in June, an overcast March morning, a low December sun (W/m2 of weather).
  const std::vector<SkyLight> hours = {london_hour(6, 21, 12, 750, 120), london_hour(3, 15, 9, 0, 110),
                                       london_hour(12, 21, 10, 450, 60)};
  std::vector<Sensor> sensors;
  for (float x : {1.5f, 4.5f, 7.5f})
    for (float z : {1.2f, 3.5f, 6.2f}) sensors.push_back({{x, 0.8f, z}, {0, 1, 0}});
  BakeOptions options;
  options.sky = hours[0];
  options.sensors = sensors;
  const AnnualDaylight annual = annual_daylight(scene, atlas, options, hours, AnnualDaylightOptions{});
  ASSERT_EQ(annual.lux.size(), hours.size() * sensors.size());
  for (size_t h = 0; h < hours.size(); ++h) {
    BakeOptions single = options;
    single.sky = hours[h];
    const BakeResult single_bake = bake(scene, atlas, single);
    for (size_t s = 0; s < sensors.size(); ++s) {
      const double reference = single_bake.sensor_lux[s], coefficients = annual.lux[h * sensors.size() + s];
      RecordProperty("hour " + std::to_string(h) + " sensor " + std::to_string(s),
                     std::to_string(coefficients) + " / " + std::to_string(reference));
      // 2%: the bound, for patches of sky and sun bins in place of the sky itself.
      EXPECT_NEAR(coefficients, reference, 0.02 * reference) << "hour " << h << ", sensor " << s;
      EXPECT_GT(reference, 10.0) << "a sensor the daylight does not reach tests nothing";
    }
  }
}

}  // namespace
}  // namespace radbake
