// Climate-based daylight metrics from a year of hourly illuminance at sensors, over the occupied
// hours:
// - daylight autonomy DA (Reinhart and Walkenhorst 2001): the share of hours with at least
//   `da_threshold` lux, and spatial daylight autonomy sDA300/50% (IES LM-83-12): the share of
//   sensors whose DA300 is at least 50%;
// - annual sun exposure ASE1000/250h (IES LM-83-12): the share of sensors that the sun's direct
//   light alone brings at least 1000 lux for more than 250 hours;
// - useful daylight illuminance UDI (Nabil and Mardaljevic 2006; bins of Mardaljevic et al. 2012):
//   the share of hours under 100 lux (fell short), 100-300 (supplementary), 300-3000 (autonomous),
//   over 3000 (exceeded), and the classic useful range 100-2000.
#pragma once

#include <cstddef>
#include <vector>

namespace radbake {

struct AnnualMetricsOptions {
  double da_threshold = 300;       // lux
  double sda_share = 0.5;          // of the occupied hours
  double ase_threshold = 1000;     // lux, the sun's direct light alone
  double ase_hours = 250;          // more than this many occupied hours
  double udi_low = 100, udi_supplementary = 300, udi_high = 3000, udi_classic_high = 2000;  // lux
};

struct SensorMetrics {
  double daylight_autonomy = 0;    // share of occupied hours, 0..1
  double udi_short = 0, udi_supplementary = 0, udi_autonomous = 0, udi_exceeded = 0;  // shares, add up to 1
  double udi_useful = 0;           // share in udi_low .. udi_classic_high
  size_t sun_hours = 0;            // occupied hours with the sun's direct light at ase_threshold or more
};

struct AnnualMetrics {
  std::vector<SensorMetrics> sensors;
  size_t occupied_hours = 0;
  double sda = 0;                  // share of sensors, 0..1
  double ase = 0;                  // share of sensors, 0..1
  double mean_daylight_autonomy = 0, mean_udi_useful = 0;
};

// `lux` and `sun_lux` hold [hour * sensors + sensor]; `occupied` says which hours count.
AnnualMetrics annual_metrics(const std::vector<float>& lux, const std::vector<float>& sun_lux, size_t sensors,
                             const std::vector<bool>& occupied, const AnnualMetricsOptions& options = {});

}  // namespace radbake
