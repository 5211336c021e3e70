// Climate-based metrics (daylight/annual_metrics.h) on a series whose answers are known by hand.
#include <gtest/gtest.h>

#include "daylight/annual_metrics.h"

namespace radbake {
namespace {

TEST(AnnualMetrics, ASeriesWorkedByHandGivesItsDaUdiSdaAndAse) {
  // 12 hours, the first 2 unoccupied (their 10,000 lux must not count); 4 sensors.
  const size_t sensors = 4, hours = 12;
  std::vector<bool> occupied(hours, true);
  occupied[0] = occupied[1] = false;
  std::vector<float> lux(hours * sensors, 10000), sun(hours * sensors, 10000);
  for (size_t h = 2; h < hours; ++h) {
    const size_t k = h - 2;  // 0..9 over the occupied hours
    float* e = &lux[h * sensors];
    float* d = &sun[h * sensors];
    e[0] = 50;                       // always short of 100 lux
    e[1] = k < 5 ? 300.0f : 299.0f;  // half the hours at 300: DA300 exactly 50%
    e[2] = 2500;                     // autonomous, but over the classic 2000
    e[3] = 3500;                     // exceeded
    d[0] = d[1] = 0;
    d[2] = k < 3 ? 1000.0f : 999.9f;  // 3 hours at 1000: not more than 3
    d[3] = k < 4 ? 1000.0f : 0.0f;    // 4 hours: more than 3
  }
  AnnualMetricsOptions options;
  options.ase_hours = 3;  // the series is 10 occupied hours, not a year
  const AnnualMetrics m = annual_metrics(lux, sun, sensors, occupied, options);
  EXPECT_EQ(m.occupied_hours, 10u);
  EXPECT_DOUBLE_EQ(m.sensors[0].daylight_autonomy, 0);
  EXPECT_DOUBLE_EQ(m.sensors[0].udi_short, 1);
  EXPECT_DOUBLE_EQ(m.sensors[1].daylight_autonomy, 0.5);
  EXPECT_DOUBLE_EQ(m.sensors[1].udi_supplementary, 0.5);
  EXPECT_DOUBLE_EQ(m.sensors[1].udi_autonomous, 0.5);
  EXPECT_DOUBLE_EQ(m.sensors[1].udi_useful, 1);
  EXPECT_DOUBLE_EQ(m.sensors[2].daylight_autonomy, 1);
  EXPECT_DOUBLE_EQ(m.sensors[2].udi_autonomous, 1);
  EXPECT_DOUBLE_EQ(m.sensors[2].udi_useful, 0);
  EXPECT_DOUBLE_EQ(m.sensors[3].udi_exceeded, 1);
  EXPECT_EQ(m.sensors[2].sun_hours, 3u);
  EXPECT_EQ(m.sensors[3].sun_hours, 4u);
  EXPECT_DOUBLE_EQ(m.sda, 0.75);  // sensors 1, 2 and 3 reach 300 lux half the time or more
  EXPECT_DOUBLE_EQ(m.ase, 0.25);  // sensor 3 alone has the sun more than 3 hours
  EXPECT_DOUBLE_EQ(m.mean_daylight_autonomy, (0 + 0.5 + 1 + 1) / 4);
  for (const SensorMetrics& x : m.sensors)
    EXPECT_DOUBLE_EQ(x.udi_short + x.udi_supplementary + x.udi_autonomous + x.udi_exceeded, 1);
}

TEST(AnnualMetrics, SeriesThatDoNotCoverEveryHourAreRefused) {
  EXPECT_THROW(annual_metrics(std::vector<float>(10), std::vector<float>(10), 3, std::vector<bool>(4, true)),
               std::invalid_argument);
}

}  // namespace
}  // namespace radbake
