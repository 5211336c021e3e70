#include "baker/readings/surface_statistics.h"

#include <algorithm>
#include <cmath>

namespace radbake {

std::vector<SurfaceStatistics> surface_statistics(const Scene& scene, const Surface& surface,
                                                  const Elements& elements, const std::vector<Rgb>& irradiance,
                                                  const std::vector<float>& open_view,
                                                  const std::vector<float>& standard_error) {
  std::vector<SurfaceStatistics> out(scene.instances.size());
  std::vector<double> weighted(scene.instances.size(), 0.0), open(scene.instances.size(), 0.0),
      variance(scene.instances.size(), 0.0);
  for (size_t k = 0; k < out.size(); ++k) {
    const MeshInstance& inst = scene.instances[k];
    out[k].instance = int(k);
    out[k].name = inst.back_of >= 0 ? scene.instances[size_t(inst.back_of)].name + " (back)" : inst.name;
    out[k].min = INFINITY;
  }
  for (size_t i = 0; i < elements.size(); ++i) {
    if (!elements.valid(i)) continue;
    SurfaceStatistics& s = out[surface.instance[elements.triangle[i]]];
    const double lux = photopic(irradiance[i]);
    s.area += elements.area[i];
    weighted[size_t(s.instance)] += lux * elements.area[i];
    if (!open_view.empty()) open[size_t(s.instance)] += double(open_view[i]) * elements.area[i];
    if (!standard_error.empty()) variance[size_t(s.instance)] += std::pow(double(standard_error[i]) * elements.area[i], 2);
    s.min = std::min(s.min, lux);
    s.max = std::max(s.max, lux);
  }
  std::vector<SurfaceStatistics> kept;
  for (SurfaceStatistics& s : out) {
    if (!(s.area > 0)) continue;  // no texel: hidden, degenerate or outside the atlas
    s.mean = weighted[size_t(s.instance)] / s.area;
    s.uniformity = s.mean > 0 ? s.min / s.mean : 0.0;
    s.open_view = open_view.empty() ? NAN : open[size_t(s.instance)] / s.area;
    s.standard_error = standard_error.empty() ? NAN : std::sqrt(variance[size_t(s.instance)]) / s.area;
    kept.push_back(std::move(s));
  }
  return kept;
}

}  // namespace radbake
