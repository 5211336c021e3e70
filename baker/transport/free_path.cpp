#include "baker/transport/free_path.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "baker/surface/sampling.h"

namespace radbake {

double mean_free_path(const Elements& e, const Surface& surface, const RayTracer& tracer, uint64_t seed,
                      uint32_t rays) {
  std::vector<double> cumulative_area;
  std::vector<uint32_t> element;
  double total = 0;
  for (size_t i = 0; i < e.size(); ++i)
    if (e.valid(i) && e.area[i] > 0) {
      total += e.area[i];
      cumulative_area.push_back(total);
      element.push_back(uint32_t(i));
    }
  if (element.empty()) return INFINITY;
  double sum = 0;
  uint32_t struck = 0;
  for (uint32_t k = 0; k < rays; ++k) {
    Rng rng(seed, Stream::FreePath, k);
    const double at = (double(k) + rng.uniform()) / rays * total;  // stratified over the area
    const size_t which = size_t(std::lower_bound(cumulative_area.begin(), cumulative_area.end(), at) -
                                cumulative_area.begin());
    const uint32_t i = element[std::min(which, element.size() - 1)];
    const Vec3 ng = surface.normal[e.triangle[i]];
    const Vec3 origin = footprint_point(e, surface, i, {rng.uniform(), rng.uniform()}) + ng * e.offset[i];
    const Vec3 dir = hemisphere_direction(e.normal[i], ng, {rng.uniform(), rng.uniform()});
    const Hit hit = tracer.intersect(origin, dir, 0.0f, INFINITY);
    if (hit.missed()) continue;
    sum += hit.distance;
    ++struck;
  }
  return struck ? sum / struck : INFINITY;
}

}  // namespace radbake
