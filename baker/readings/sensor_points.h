// Illuminance at points that are not surfaces (a work plane in the air, points a user lists), as a
// light meter held there reads it: lamps and the sky and sun by shadow rays from the point, and
// the light every surface sends (its emission and what it reflects, from the finished bake) by
// cosine-distributed rays that take the exitance of the texel they strike.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "baker/direct/sky_light.h"
#include "baker/surface/bake_geometry.h"
#include "baker/surface/elements.h"
#include "baker/surface/ray_tracer.h"
#include "baker/surface/surface.h"
#include "base/math.h"
#include "base/progress.h"
#include "base/scene.h"
#include "daylight/sky.h"

namespace radbake {

struct Sensor {
  Vec3 position;       // world space, metres
  Vec3 normal{0, 1, 0};  // unit: which way the meter faces (up for a work plane)
};

// A sensor is one point, so it can afford many more rays than a texel: its sky is sampled apart
// from the texels' (a texel takes SkyLight::rays).
struct SensorOptions {
  uint32_t rays = 4096;       // cosine-distributed rays per sensor for the light surfaces send
  uint32_t sky_rays = 16384;  // cosine-distributed rays per sensor for the sky and the ground
};

// The valid elements a sensor's cosine-distributed gather rays strike (kSensorBatches batches of
// rays_per_batch(rays), sky_light.h), one entry per ray that strikes one (rays that leave the
// scene or strike a back face are not listed), batch after batch: batch b's end at batch_end[b].
// The surfaces' part of its illuminance is the sum of their exitances over the rays cast.
struct SensorHits {
  std::vector<int64_t> elements;
  std::array<size_t, kSensorBatches> batch_end{};
};
SensorHits sensor_gather_hits(const Sensor& sensor, size_t index, const Elements& elements, const Surface& surface,
                              const RayTracer& tracer, uint32_t rays, uint64_t seed);

// Per sensor, lux (photopic: base/math.h) and its noise: the standard error of the mean of its
// batches, each batch's reading being the exact lamps plus its share of the sky rays and of the
// gather rays. `exitance` is per element, lm/m2 (emission plus reflected light); `sky` may be
// disabled. The noise of the finished bake's exitances, which every batch reads alike, is not in it.
struct SensorReadings {
  std::vector<double> lux, standard_error;
};
SensorReadings sensor_illuminance(const std::vector<Sensor>& sensors, const std::vector<Light>& lights,
                                  const BakeGeometry& geometry, const std::vector<Rgb>& exitance, const SkyLight& sky,
                                  const SkyPortals& portals, const SensorOptions& options, uint64_t seed,
                                  Progress& progress);

}  // namespace radbake
