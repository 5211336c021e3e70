#include "baker/readings/sensor_points.h"

#include <tbb/parallel_for.h>

#include <cmath>

#include "baker/direct/direct_light.h"
#include "baker/surface/sampling.h"
#include "baker/transport/patch_transport.h"

namespace radbake {

SensorHits sensor_gather_hits(const Sensor& s, size_t index, const Elements& elements, const Surface& surface,
                              const RayTracer& tracer, uint32_t rays, uint64_t seed) {
  const Vec3 origin = sensor_origin(s.position, s.normal, surface.scene_extent);
  Rng rng(seed, Stream::SensorGather, index);
  uint32_t pattern[kSensorBatches];
  for (uint32_t& p : pattern) p = rng.next_u32();
  const uint32_t per_batch = rays_per_batch(rays);
  SensorHits hits;
  for (uint32_t b = 0; b < kSensorBatches; ++b) {
    for (uint32_t k = 0; k < per_batch; ++k) {
      const Vec3 d = cosine_direction(s.normal, cmj_sample(k, per_batch, pattern[b]));
      const Hit hit = tracer.intersect_light_path(origin, d, 0.0f, INFINITY);
      if (hit.missed() || !hit.front) continue;
      const int64_t element = element_for_hit(elements, surface, tracer, hit, kFromTheOpen);
      if (element >= 0 && elements.valid(size_t(element))) hits.elements.push_back(element);
    }
    hits.batch_end[b] = hits.elements.size();
  }
  return hits;
}

SensorReadings sensor_illuminance(const std::vector<Sensor>& sensors, const std::vector<Light>& lights,
                                  const BakeGeometry& geometry, const std::vector<Rgb>& exitance, const SkyLight& sky,
                                  const SkyPortals& portals, const SensorOptions& options, uint64_t seed,
                                  Progress& progress) {
  const Elements& elements = geometry.elements;
  const Surface& surface = *geometry.surface;
  const RayTracer& tracer = *geometry.tracer;
  std::vector<SensorBatches> batches(sensors.size(), SensorBatches{});
  if (sky.enabled) {
    std::vector<Vec3> points, normals;
    for (const Sensor& s : sensors) points.push_back(sensor_origin(s.position, s.normal, surface.scene_extent)), normals.push_back(s.normal);
    batches = sky_illuminance_at(points, normals, tracer, sky, portals, options.sky_rays, seed);
  }
  const uint32_t per_batch = rays_per_batch(options.rays);
  SensorReadings out;
  out.lux.assign(sensors.size(), 0.0);
  out.standard_error.assign(sensors.size(), 0.0);
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
      const SensorHits hits = sensor_gather_hits(s, i, elements, surface, tracer, options.rays, seed);
      double mean = 0, square = 0;
      for (uint32_t b = 0; b < kSensorBatches; ++b) {
        Rgb seen{};
        for (size_t h = b ? hits.batch_end[b - 1] : 0; h < hits.batch_end[b]; ++h) seen += exitance[size_t(hits.elements[h])];
        const double lux = photopic(direct + seen / float(per_batch)) + batches[i][b];
        mean += lux, square += lux * lux;
      }
      mean /= kSensorBatches;
      out.lux[i] = mean;
      const double variance = std::max(0.0, (square / kSensorBatches - mean * mean) * kSensorBatches / (kSensorBatches - 1));
      out.standard_error[i] = std::sqrt(variance / kSensorBatches);
    }
    progress.advance(r.size());
  });
  progress.end();
  return out;
}

}  // namespace radbake
