#include "baker/readings/sensor_points.h"

#include <tbb/parallel_for.h>

#include <cmath>

#include "baker/direct/direct_light.h"
#include "baker/direct/sky_light.h"
#include "baker/surface/sampling.h"
#include "baker/transport/patch_transport.h"

namespace radbake {

std::vector<int64_t> sensor_gather_hits(const Sensor& s, size_t index, const Elements& elements, const Surface& surface,
                                        const RayTracer& tracer, uint32_t rays, uint64_t seed) {
  const Vec3 origin = sensor_origin(s.position, s.normal, surface.scene_extent);
  Rng rng(seed, Stream::SensorGather, index);
  const uint32_t pattern = rng.next_u32();
  std::vector<int64_t> hits;
  for (uint32_t k = 0; k < rays; ++k) {
    const Vec3 d = cosine_direction(s.normal, cmj_sample(k, rays, pattern));
    const Hit hit = tracer.intersect_light_path(origin, d, 0.0f, INFINITY);
    if (hit.missed() || !hit.front) continue;
    const int64_t element = element_for_hit(elements, surface, tracer, hit);
    if (element >= 0 && elements.valid(size_t(element))) hits.push_back(element);
  }
  return hits;
}

std::vector<double> sensor_illuminance(const std::vector<Sensor>& sensors, const std::vector<Light>& lights,
                                       const Elements& elements, const std::vector<Rgb>& exitance,
                                       const Surface& surface, const RayTracer& tracer, const SkyLight& sky,
                                       const SensorOptions& options, uint64_t seed, Progress& progress) {
  std::vector<double> lux(sensors.size(), 0.0);
  if (sky.enabled) {
    std::vector<Vec3> points, normals;
    for (const Sensor& s : sensors) points.push_back(sensor_origin(s.position, s.normal, surface.scene_extent)), normals.push_back(s.normal);
    lux = sky_illuminance_at(points, normals, tracer, sky, seed);
  }
  const uint32_t rays = std::max<uint32_t>(1, options.rays);
  progress.begin("sensors", sensors.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, sensors.size(), 4), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i) {
      const Sensor& s = sensors[i];
      const Vec3 origin = sensor_origin(s.position, s.normal, surface.scene_extent);
      // A point light seen from a point: one shadow ray is exact.
      Rgb direct{};
      for (const Light& light : lights) {
        Vec3 to_light{};
        float distance = 0;
        const Rgb value = punctual_light_irradiance(light, s.position, s.normal, &to_light, &distance);
        if (max_component(value) > 0)
          direct += value * tracer.transmittance(origin, to_light, 0.0f,
                                                 std::isfinite(distance) ? distance * (1 - 1e-5f) : INFINITY);
      }
      // Cosine-distributed rays: E = pi * mean radiance = mean exitance of what they strike.
      Rgb seen{};
      for (int64_t element : sensor_gather_hits(s, i, elements, surface, tracer, rays, seed)) seen += exitance[size_t(element)];
      lux[i] += double(sum(direct + seen / float(rays))) / 3.0;
    }
    progress.advance(r.size());
  });
  progress.end();
  return lux;
}

}  // namespace radbake
