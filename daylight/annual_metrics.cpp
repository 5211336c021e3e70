#include "daylight/annual_metrics.h"

#include <stdexcept>

namespace radbake {

AnnualMetrics annual_metrics(const std::vector<float>& lux, const std::vector<float>& sun_lux, size_t sensors,
                             const std::vector<bool>& occupied, const AnnualMetricsOptions& o) {
  if (lux.size() != occupied.size() * sensors || sun_lux.size() != lux.size())
    throw std::invalid_argument("annual_metrics: the series do not hold every sensor for every hour");
  AnnualMetrics m;
  m.sensors.resize(sensors);
  for (size_t h = 0; h < occupied.size(); ++h) {
    if (!occupied[h]) continue;
    ++m.occupied_hours;
    for (size_t s = 0; s < sensors; ++s) {
      const double e = lux[h * sensors + s];
      SensorMetrics& x = m.sensors[s];
      x.daylight_autonomy += e >= o.da_threshold;
      x.udi_short += e < o.udi_low;
      x.udi_supplementary += e >= o.udi_low && e < o.udi_supplementary;
      x.udi_autonomous += e >= o.udi_supplementary && e <= o.udi_high;
      x.udi_exceeded += e > o.udi_high;
      x.udi_useful += e >= o.udi_low && e <= o.udi_classic_high;
      x.sun_hours += sun_lux[h * sensors + s] >= o.ase_threshold;
    }
  }
  if (m.occupied_hours == 0 || sensors == 0) return m;
  const double hours = double(m.occupied_hours);
  size_t autonomous = 0, sunny = 0;
  for (SensorMetrics& x : m.sensors) {
    for (double* share : {&x.daylight_autonomy, &x.udi_short, &x.udi_supplementary, &x.udi_autonomous,
                          &x.udi_exceeded, &x.udi_useful})
      *share /= hours;
    autonomous += x.daylight_autonomy >= o.sda_share;
    sunny += double(x.sun_hours) > o.ase_hours;
    m.mean_daylight_autonomy += x.daylight_autonomy / double(sensors);
    m.mean_udi_useful += x.udi_useful / double(sensors);
  }
  m.sda = double(autonomous) / double(sensors);
  m.ase = double(sunny) / double(sensors);
  return m;
}

}  // namespace radbake
