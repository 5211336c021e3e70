// NREL SPA's published test vector (Reda and Andreas 2004, table A4.1): NREL at Golden, Colorado,
// 2003-10-17 12:30:30 local time (UTC-7). SPA's answer: zenith 50.111622, azimuth 194.340241
// degrees.
#pragma once

#include "daylight/sun_position.h"

namespace radbake::test {

inline SiteAndTime spa_test_site() {
  SiteAndTime golden;
  golden.latitude = 39.742476;
  golden.longitude = -105.1786;
  golden.elevation = 1830.14;
  golden.pressure = 820;
  golden.temperature = 11;
  golden.year = 2003, golden.month = 10, golden.day = 17;
  golden.hour = 12, golden.minute = 30, golden.second = 30;
  golden.utc_offset = -7;
  golden.delta_t = 67;
  return golden;
}

constexpr double kSpaZenith = 50.111622, kSpaAzimuth = 194.340241;  // degrees

}  // namespace radbake::test
