#include "baker/pipeline/ray_budget.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "base/errors.h"

namespace radbake {
namespace {

// Patches as build_patches makes them: blocks of a given size, or at most the budget.
double patch_count(const PatchOptions& patches, uint64_t texels) {
  if (patches.block_size > 0) return std::max(1.0, double(texels) / (double(patches.block_size) * patches.block_size));
  return double(patch_budget(patches, size_t(texels)));
}

// Probes on the grid place_probes lays: the bounds over the spacing along each axis (at least one,
// at most 10^6), until the grid holds at most max_probes.
double probe_count(const ProbeOptions& probes, const Vec3& extent) {
  const double spacing = probes.spacing > 0 ? probes.spacing : std::max({extent.x, extent.y, extent.z}) / 8;
  if (!(spacing > 0)) return 0;
  double grid = 1;
  for (int a = 0; a < 3; ++a) grid *= std::clamp(std::floor(double(extent[a]) / spacing), 1.0, 1e6);
  return std::min(grid, double(std::max<size_t>(1, probes.max_probes)));
}

std::string shown(double rays) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", rays);
  return text;
}

}  // namespace

RayCounts ray_counts(const Scene& scene, const Atlas& atlas, const std::vector<Sensor>& sensors, uint64_t daylit_hours) {
  RayCounts c;
  c.texels = atlas.stats.covered_texels ? atlas.stats.covered_texels : atlas.stats.page_texels;
  c.sensors = sensors.size();
  c.daylit_hours = daylit_hours;
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (const MeshInstance& inst : scene.instances)
    for (const Vec3& p : inst.positions)
      for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  if (!(lo.x <= hi.x)) return c;
  c.extent = hi - lo;
  const float margin = 0.1f * std::max({c.extent.x, c.extent.y, c.extent.z});
  for (const Sensor& s : sensors)
    for (int a = 0; a < 3; ++a)
      if (s.position[a] < lo[a] - margin || s.position[a] > hi[a] + margin) {
        ++c.sensors_outside;
        break;
      }
  return c;
}

std::vector<StageRays> estimate_stage_rays(const BakeOptions& o, const RayCounts& c) {
  std::vector<StageRays> stages;
  const double texels = double(c.texels);
  if (o.method == Method::PathTrace) {
    // Each path is at least its first ray; the scenes radbake bakes average three to five bounces.
    stages.push_back({"path tracing", "--samples", texels * o.path_trace.samples * 4});
  } else {
    const double patches = patch_count(o.patches, c.texels);
    if (o.form_factors.method == FormFactorMethod::Hemicube) {
      // A hemicube's top face and four half sides: three times the top face's pixels, each a ray.
      const double side = o.form_factors.hemicube_resolution;
      stages.push_back({"form factors", "--hemicube-resolution", patches * 3 * side * side});
    } else {
      stages.push_back({"form factors", "--patch-rays", patches * o.form_factors.rays_per_patch});
    }
    stages.push_back({"final gather", "--gather-rays", texels * o.gather.rays});
  }
  if (o.probes.enabled) {
    const double per_probe = double(o.probes.rays) + o.probes.emitter_samples;
    stages.push_back({"light probes", "--probes and --probe-rays", probe_count(o.probes, c.extent) * per_probe});
  }
  if (c.sensors > 0) {
    const double per_sensor = double(o.sensor.rays) + (o.sky.enabled ? o.sensor.sky_rays : 0);
    stages.push_back({std::to_string(c.sensors) + " sensors", "--sensors, --sensor-rays and --sensor-sky-rays",
                      double(c.sensors) * per_sensor});
  }
  if (c.daylit_hours > 0 && c.sensors > 0)
    stages.push_back({std::to_string(c.daylit_hours) + " daylit hours at " + std::to_string(c.sensors) + " sensors",
                      "--weather and --sensors", double(c.daylit_hours) * double(c.sensors) * o.sky.sun_rays});
  return stages;
}

void check_ray_budget(const std::vector<StageRays>& stages, double max_rays) {
  for (const StageRays& s : stages)
    if (s.rays > max_rays)
      throw InputError("the " + s.stage + " would cast about " + shown(s.rays) + " rays (" + s.option +
                       "), more than --max-rays " + shown(max_rays) + " allows (about an hour on 2 cores): lower " +
                       s.option + " or raise --max-rays");
}

}  // namespace radbake
