#include "baker/readings/work_plane.h"

#include <algorithm>
#include <cmath>

#include "base/errors.h"

namespace radbake {
namespace {

// A hit on the top side of a surface that faces up (within 45 degrees).
bool faces_up(const Surface& surface, const Hit& hit) { return hit.front && surface.normal[hit.triangle].y > 0.7f; }

bool is_floor(const Scene& scene, const Surface& surface, uint32_t triangle, const std::vector<std::string>& over) {
  if (over.empty()) return true;
  const std::string& name = scene.instances[surface.instance[triangle]].name;
  return std::any_of(over.begin(), over.end(), [&](const std::string& part) { return name.find(part) != std::string::npos; });
}

}  // namespace

WorkPlane work_plane(const Scene& scene, const Surface& surface, const RayTracer& tracer,
                     const WorkPlaneOptions& options) {
  // The extent: the floors' own (named ones), or everything's.
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (uint32_t t = 0; t < surface.triangle_count(); ++t) {
    if (!(surface.area[t] > 0)) continue;
    const bool counts = options.over.empty() || is_floor(scene, surface, t, options.over);
    for (int k = 0; k < 3; ++k) {
      const Vec3 c = surface.corners[3 * t + k];
      if (!counts) continue;
      lo = {std::min(lo.x, c.x), std::min(lo.y, c.y), std::min(lo.z, c.z)};
      hi = {std::max(hi.x, c.x), std::max(hi.y, c.y), std::max(hi.z, c.z)};
    }
  }
  if (!(lo.x <= hi.x)) throw InputError("no surface is named like the work plane's floors (--work-plane-over)");
  float top = -INFINITY;
  for (const Vec3& c : surface.corners) top = std::max(top, c.y);
  WorkPlane plane;
  plane.spacing = options.spacing;
  const double columns = std::ceil((hi.x - lo.x) / options.spacing), rows = std::ceil((hi.z - lo.z) / options.spacing);
  if (!(columns * rows <= double(options.max_points)))
    throw InputError("the work plane would have " + std::to_string(uint64_t(std::max(columns, 1.0) * std::max(rows, 1.0))) +
                     " points, more than " + std::to_string(options.max_points) + ": raise --work-plane-spacing");
  plane.columns = std::max(1, int(columns));
  plane.rows = std::max(1, int(rows));
  // Centred over the extent.
  plane.x0 = 0.5 * (lo.x + hi.x) - 0.5 * plane.columns * options.spacing;
  plane.z0 = 0.5 * (lo.z + hi.z) - 0.5 * plane.rows * options.spacing;
  plane.sensor_at.assign(size_t(plane.columns) * size_t(plane.rows), -1);
  const float start = top + 1;
  for (int r = 0; r < plane.rows; ++r)
    for (int c = 0; c < plane.columns; ++c) {
      const float x = float(plane.x0 + (c + 0.5) * options.spacing), z = float(plane.z0 + (r + 0.5) * options.spacing);
      // Down through every surface to the lowest floor under the point.
      float floor_y = NAN, t_near = 0;
      for (int crossed = 0; crossed < 256; ++crossed) {
        const Hit hit = tracer.intersect({x, start, z}, {0, -1, 0}, t_near, INFINITY);
        if (hit.missed()) break;
        if (faces_up(surface, hit) && is_floor(scene, surface, hit.triangle, options.over))
          floor_y = start - hit.distance;
        t_near = hit.distance * (1 + 1e-6f) + 1e-6f;
      }
      if (std::isnan(floor_y)) continue;
      plane.sensor_at[size_t(r) * size_t(plane.columns) + size_t(c)] = int32_t(plane.sensors.size());
      plane.sensors.push_back({{x, float(floor_y + options.height), z}, {0, 1, 0}});
    }
  if (plane.sensors.empty()) throw InputError("the work plane found no floor facing up under its grid");
  return plane;
}

}  // namespace radbake
