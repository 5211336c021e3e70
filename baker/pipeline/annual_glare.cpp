#include "baker/pipeline/annual_glare.h"

#include <cmath>

#include "baker/readings/glare.h"

namespace radbake {

AnnualGlare annual_glare(const AnnualDaylight& daylight, const std::vector<EyeView>& eyes,
                         const std::vector<SkyLight>& hours, const std::vector<bool>& occupied) {
  const double sun_disc = 2 * M_PI * (1 - std::cos(0.2665 * M_PI / 180));  // sr
  AnnualGlare out;
  out.dgp.assign(hours.size() * eyes.size(), 0.0f);
  out.eyes.resize(eyes.size());
  for (size_t h = 0; h < hours.size(); ++h) {
    if (!hours[h].enabled) continue;
    for (size_t e = 0; e < eyes.size(); ++e) {
      const double ev = daylight.eye_lux[h * eyes.size() + e], seen = daylight.eye_sun_seen[h * eyes.size() + e];
      std::vector<GlareSource> sun;
      if (seen > 0) {
        const Vec3 view = normalize(eyes[e].direction);
        const Vec3 up = normalize(eyes[e].up - view * dot(eyes[e].up, view));
        const Vec3 toward = sun_direction(hours[h]);
        sun.push_back({hours[h].sun_illuminance * seen / sun_disc, sun_disc, position_index(toward, view, up), toward});
      }
      const double dgp = daylight_glare_probability(ev, sun);
      out.dgp[h * eyes.size() + e] = float(dgp);
      if (!occupied[h]) continue;
      EyeGlareSummary& s = out.eyes[e];
      ++s.occupied_hours;
      s.mean_dgp += dgp, s.over_035 += dgp >= 0.35, s.over_040 += dgp >= 0.40, s.over_045 += dgp >= 0.45;
    }
  }
  for (EyeGlareSummary& s : out.eyes)
    if (s.occupied_hours > 0)
      for (double* v : {&s.mean_dgp, &s.over_035, &s.over_040, &s.over_045}) *v /= double(s.occupied_hours);
  return out;
}

}  // namespace radbake
