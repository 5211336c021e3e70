// Glare (baker/readings/glare.h, baker/readings/luminance_view.h): Guth's position index and Wienold's DGP on a
// constructed view whose answer is worked by hand, and a fisheye rendered from a bake whose
// vertical illuminance is the one the bake's sensor reads there.
#include <gtest/gtest.h>

#include <cmath>

#include "baker/pipeline/annual_glare.h"
#include "baker/pipeline/bake.h"
#include "baker/readings/glare.h"
#include "baker/surface/back_faces.h"
#include "daylight/daylight_sky.h"
#include "daylight/sky.h"
#include "io/gltf/gltf_loader.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

constexpr double kDegree = M_PI / 180;
const Vec3 kView{0, 0, -1}, kUp{0, 1, 0}, kRight{1, 0, 0};

Vec3 toward(double sigma_degrees, Vec3 across) {
  return normalize(kView * float(std::cos(sigma_degrees * kDegree)) + across * float(std::sin(sigma_degrees * kDegree)));
}

TEST(Glare, GuthsPositionIndexAtPointsWorkedByHand) {
  EXPECT_DOUBLE_EQ(position_index(kView, kView, kUp), 1.0);  // on the line of sight
  // 30 degrees to the side (tau 90): exp(6.49990e-3 x 30 + 21.0e-5 x 900) = exp(0.384) = 1.4681.
  EXPECT_NEAR(position_index(toward(30, kRight), kView, kUp), 1.4681, 1e-4);
  // 30 degrees above (tau 0): exp(33.98e-3 x 30 + 21e-5 x 900) = exp(1.2084) = 3.3481.
  EXPECT_NEAR(position_index(toward(30, kUp), kView, kUp), 3.3481, 1e-4);
  EXPECT_DOUBLE_EQ(position_index(kView * -1.0f, kView, kUp), 16.0);  // behind the eye
  // Below the line of sight, evalglare's Iwata: 30 degrees down counts as sigma = atan(1.15 tan 30).
  const double sigma = std::atan(1.15 * std::tan(30 * kDegree)) / kDegree;
  EXPECT_NEAR(position_index(toward(30, kUp * -1.0f), kView, kUp),
              std::exp(6.49990e-3 * sigma + 21.0e-5 * sigma * sigma), 1e-4);
}

TEST(Glare, AConstructedViewGivesWienoldsFormulasDgp) {
  // A uniform 1000 cd/m2 field and one source of 100,000 cd/m2, 3 degrees in radius, 30 degrees
  // to the right of the line of sight: Ev = pi 1000 + 99,000 w cos 30, w = 2 pi (1 - cos 3).
  FisheyeImage image;
  image.size = 600;
  image.luminance.assign(size_t(image.size) * image.size, 1000.0f);
  const Vec3 source = toward(30, kRight);
  for (int y = 0; y < image.size; ++y)
    for (int x = 0; x < image.size; ++x) {
      Vec3 d;
      double omega;
      if (fisheye_pixel(image, x, y, &d, &omega) && dot(d, source) > std::cos(3 * kDegree))
        image.luminance[size_t(y) * image.size + x] = 100000;
    }
  const double w = 2 * M_PI * (1 - std::cos(3 * kDegree));
  const double ev = M_PI * 1000 + 99000 * w * std::cos(30 * kDegree);
  const double by_hand = 5.87e-5 * ev + 9.18e-2 * std::log10(1 + 1e10 * w / (std::pow(ev, 1.87) * 1.4681 * 1.4681)) + 0.16;
  const Glare g = evaluate_glare(image);
  ASSERT_EQ(g.sources.size(), 1u);
  EXPECT_NEAR(g.sources[0].luminance, 100000, 1);
  EXPECT_NEAR(g.sources[0].solid_angle, w, 0.02 * w);  // 2%: the disc drawn in 0.3-degree pixels
  EXPECT_NEAR(g.sources[0].position_index, 1.4681, 0.01);
  EXPECT_NEAR(g.vertical_illuminance, ev, 0.005 * ev);  // 0.5%: the same pixels
  EXPECT_NEAR(g.dgp, by_hand, 0.002);                   // what those two move DGP by, at most
  EXPECT_GT(g.dgp, 0.45);                                // intolerable glare by Wienold's scale
}

TEST(Glare, AFisheyesIlluminanceIsTheSensorsThere) {
  // The classroom under a low December sun seen through its windows, from the middle of the room
  // looking south: the image's Ev against the bake's sensor at the eye, facing the same way.
  Scene scene = load_gltf(test::source_path("samples/classroom/classroom.gltf")).scene;
  add_back_faces(scene);
  const Atlas atlas = test::unwrap(scene, AtlasOptions{});
  DaylightOptions d;
  d.sky = SkyKind::Perez;
  d.site = SiteAndTime{};
  d.site->latitude = 51.5, d.site->longitude = -0.12, d.site->year = 2026, d.site->month = 12, d.site->day = 21,
  d.site->hour = 10;
  d.direct_normal_irradiance = 450, d.diffuse_horizontal_irradiance = 60;
  BakeOptions options;
  options.sky = daylight_sky(d).light;
  const EyeView eye{{4.5f, 1.2f, 3.5f}, {0, 0, 1}, {0, 1, 0}};
  options.views = {eye};
  options.sensors = {{eye.position, eye.direction}};
  options.sensor.rays = 16384;  // the sensor's own noise well under the 2% compared
  const BakeResult r = bake(scene, atlas, options);
  ASSERT_EQ(r.glare.size(), 1u);
  const double sensor = r.sensor_lux[0], image = r.glare[0].vertical_illuminance;
  RecordProperty("fisheye Ev / sensor", std::to_string(image / sensor));
  EXPECT_NEAR(image, sensor, 0.02 * sensor);
  EXPECT_GT(r.glare[0].sources.size(), 0u) << "the windows and the sun in them";
}

}  // namespace
}  // namespace radbake

namespace radbake {
namespace {

TEST(AnnualGlare, HourlyDgpIsWienoldsFormulaWithTheSunAsTheSource) {
  // Two occupied hours at one eye looking along the sun's direction of the second hour (zenith
  // 60 degrees, due south): the first without sun (Ev 2000 lx), the second with 500 lx of direct
  // normal sun fully seen (Ev 3000 lx), a source on the line of sight (P = 1).
  SkyLight dark_sun, sunny;
  dark_sun.enabled = sunny.enabled = true;
  sunny.sun_zenith = 60 * M_PI / 180, sunny.sun_azimuth = M_PI, sunny.sun_illuminance = 500;
  const Vec3 toward = sun_direction(sunny);
  AnnualDaylight daylight;
  daylight.eyes = 1;
  daylight.eye_lux = {2000, 3000};
  daylight.eye_sun_seen = {0, 1};
  const AnnualGlare g = annual_glare(daylight, {EyeView{{0, 1.2f, 0}, toward, {0, 1, 0}}}, {dark_sun, sunny}, {true, true});
  const double disc = 2 * M_PI * (1 - std::cos(0.2665 * M_PI / 180)), sun_luminance = 500 / disc;
  const double second = 5.87e-5 * 3000 + 9.18e-2 * std::log10(1 + sun_luminance * sun_luminance * disc / std::pow(3000, 1.87)) + 0.16;
  ASSERT_EQ(g.dgp.size(), 2u);
  EXPECT_NEAR(g.dgp[0], 5.87e-5 * 2000 + 0.16, 1e-6);
  EXPECT_NEAR(g.dgp[1], second, 1e-5);
  EXPECT_EQ(g.eyes[0].occupied_hours, 2u);
  EXPECT_NEAR(g.eyes[0].mean_dgp, (g.dgp[0] + g.dgp[1]) / 2, 1e-6);
  EXPECT_DOUBLE_EQ(g.eyes[0].over_045, second >= 0.45 ? 0.5 : 0.0);
  EXPECT_DOUBLE_EQ(g.eyes[0].over_035, 0.5);  // 0.277 under, the sun hour over
}

}  // namespace
}  // namespace radbake
