// Illuminance at points that are not surfaces (a work plane in the air, points a user lists), as a
// light meter held there reads it: lamps and the sky and sun by shadow rays from the point, and
// the light every surface sends (its emission and what it reflects, from the finished bake) by
// cosine-distributed rays that take the exitance of the texel they strike.
#pragma once

#include <cstdint>
#include <vector>

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

struct SensorOptions {
  uint32_t rays = 1024;  // hemisphere rays per sensor for the light surfaces send; noise ~ 1/sqrt
};

// The valid elements sensor `index`'s `rays` cosine-distributed gather rays strike, one entry per
// ray that strikes one (rays that leave the scene or strike a back face are not listed); the
// surfaces' part of its illuminance is the sum of their exitances over `rays`.
std::vector<int64_t> sensor_gather_hits(const Sensor& sensor, size_t index, const Elements& elements,
                                        const Surface& surface, const RayTracer& tracer, uint32_t rays, uint64_t seed);

// Per sensor, lux (the mean of R, G and B, as the energy balance counts light). `exitance` is per
// element, lm/m2 (emission plus reflected light); `sky` may be disabled.
std::vector<double> sensor_illuminance(const std::vector<Sensor>& sensors, const std::vector<Light>& lights,
                                       const Elements& elements, const std::vector<Rgb>& exitance,
                                       const Surface& surface, const RayTracer& tracer, const SkyLight& sky,
                                       const SensorOptions& options, uint64_t seed, Progress& progress);

}  // namespace radbake
