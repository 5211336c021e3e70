// Daylight coefficients (baker/pipeline/annual_daylight.h) against single-hour bakes of the same sky: the
// classroom sample at three hours of London weather, every sensor within 2%.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "baker/pipeline/annual_daylight.h"
#include "baker/pipeline/bake.h"
#include "baker/surface/back_faces.h"
#include "daylight/daylight_sky.h"
#include "io/gltf/gltf_loader.h"
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
  AnnualDaylightOptions year;
  year.occupied = {true, true, true};
  const AnnualDaylight annual = annual_daylight(scene, atlas, options, hours, year);
  ASSERT_EQ(annual.lux.size(), hours.size() * sensors.size());
  std::vector<double> single_mean;  // per texel of page 0, the three bakes' mean, lux
  for (size_t h = 0; h < hours.size(); ++h) {
    BakeOptions single = options;
    single.sky = hours[h];
    const BakeResult single_bake = bake(scene, atlas, single);
    const LightmapPage& page = single_bake.pages[0];
    single_mean.resize(page.texels.size(), 0);
    for (size_t k = 0; k < page.texels.size(); ++k) single_mean[k] += double(sum(page.texels[k])) / 3 / double(hours.size());
    for (size_t s = 0; s < sensors.size(); ++s) {
      const double reference = single_bake.sensor_lux[s], coefficients = annual.lux[h * sensors.size() + s];
      RecordProperty("hour " + std::to_string(h) + " sensor " + std::to_string(s),
                     std::to_string(coefficients) + " / " + std::to_string(reference));
      // 2%: the bound for patches of sky and sun bins in place of the sky itself.
      EXPECT_NEAR(coefficients, reference, 0.02 * reference) << "hour " << h << ", sensor " << s;
      EXPECT_GT(reference, 10.0) << "a sensor the daylight does not reach tests nothing";
    }
  }
  // Every texel's mean over the three hours, against the single bakes': the texels' coefficients
  // take the sky by 145 patches and the sun by its bin's centre, and no final gather.
  ASSERT_FALSE(annual.texel_mean_lux.empty());
  const LightmapPage& mean = annual.texel_mean_lux[0];
  std::vector<double> errors;
  double ours = 0, theirs = 0;
  for (size_t k = 0; k < mean.texels.size(); ++k) {
    if (!mean.valid[k] || !(single_mean[k] > 50)) continue;
    const double v = double(sum(mean.texels[k])) / 3;
    ours += v, theirs += single_mean[k];
    errors.push_back(std::fabs(v - single_mean[k]) / single_mean[k]);
  }
  ASSERT_GT(errors.size(), 1000u);
  std::sort(errors.begin(), errors.end());
  const double median = errors[errors.size() / 2], p90 = errors[errors.size() * 9 / 10];
  RecordProperty("texels: mean ratio, median and p90 relative difference",
                 std::to_string(ours / theirs) + " " + std::to_string(median) + " " + std::to_string(p90));
  // Measured: 0.999, median 4.5%, 90th percentile 22%: texels along shadow edges, which the sun
  // bins blur (interpolated between up to 4 bins' centres, up to 2 degrees apart), and each side's
  // own noise. Since sky rays were aimed at the windows (sky_portals.h) a single bake's texels aim half their sky rays at the windows, so
  // the two no longer cast the same rays and their noise no longer cancels here (with the bin the
  // sun falls in, as before, 4.4% and 20%; before, sharing rays, 2.3% and 14%).
  EXPECT_NEAR(ours / theirs, 1.0, 0.02);  // the scene's light over all lit texels
  EXPECT_LT(median, 0.06);
  EXPECT_LT(p90, 0.25);
}

// A 4 x 3 x 4 m room of grey walls lit by a 1 m roof light (an opening in the middle of the
// ceiling) at 11:30 on 21 September in London: the sun, 37 degrees up in the south, lays a 1 m
// patch on the north wall between 1.1 and 1.9 m up. Points of a work plane 0.25 and 0.5 m from that
// wall get most of their light from the patch. The year's coefficients solve the sun at the
// centres of 3-degree bins; taken from the bin's centre the patch moved by up to 9 cm and these
// points read 4-22% off. Interpolated between the bins around the hour's sun, they must
// read as the single hour's bake does, within 3%.
TEST(AnnualDaylight, ASunPatchOnAWallMovesWithTheHoursSunNotItsBin) {
  Scene scene;
  const int grey = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  test::add_quad(scene, {0, 0, 4}, {4, 0, 0}, {0, 0, -4}, grey, "floor");
  test::add_quad(scene, {0, 0, 0}, {4, 0, 0}, {0, 3, 0}, grey, "north wall");
  test::add_quad(scene, {0, 0, 4}, {0, 3, 0}, {4, 0, 0}, grey, "south wall");
  test::add_quad(scene, {0, 0, 0}, {0, 3, 0}, {0, 0, 4}, grey, "west wall");
  test::add_quad(scene, {4, 0, 0}, {0, 0, 4}, {0, 3, 0}, grey, "east wall");
  test::add_quad(scene, {0, 3, 0}, {4, 0, 0}, {0, 0, 1.5f}, grey, "ceiling");
  test::add_quad(scene, {0, 3, 2.5f}, {4, 0, 0}, {0, 0, 1.5f}, grey, "ceiling");
  test::add_quad(scene, {0, 3, 1.5f}, {1.5f, 0, 0}, {0, 0, 1}, grey, "ceiling");
  test::add_quad(scene, {2.5f, 3, 1.5f}, {1.5f, 0, 0}, {0, 0, 1}, grey, "ceiling");
  const Atlas atlas = test::unwrap(scene, test::coarse_atlas());
  const std::vector<SkyLight> hours = {london_hour(9, 21, 11.5, 600, 100)};
  BakeOptions options;
  options.sky = hours[0];
  for (float z : {0.25f, 0.5f})
    for (float x : {1.25f, 1.75f, 2.25f, 2.75f}) options.sensors.push_back({{x, 0.8f, z}, {0, 1, 0}});
  AnnualDaylightOptions year;
  const AnnualDaylight annual = annual_daylight(scene, atlas, options, hours, year);
  const BakeResult single = bake(scene, atlas, options);
  double worst = 0;
  for (size_t s = 0; s < options.sensors.size(); ++s) {
    const double reference = single.sensor_lux[s], coefficients = annual.lux[s];
    worst = std::max(worst, std::fabs(coefficients / reference - 1));
    EXPECT_NEAR(coefficients, reference, 0.03 * reference) << "sensor " << s;
    // No direct sun reaches them: what the sun brings them is the patch's light.
    EXPECT_EQ(annual.sun_lux[s], 0.0f) << "sensor " << s;
  }
  RecordProperty("worst_relative_difference", std::to_string(worst));
}

}  // namespace
}  // namespace radbake
