// The independent reference: irradiance at every lightmap texel by unbiased Monte Carlo path
// tracing over the same surfaces, materials, lights and units as the radiosity bake, with none of
// its machinery (no patches, form factors, solve or gather). Each path starts at a point of the
// texel's footprint, takes direct light from every punctual light, one sampled point of an
// emitting triangle and the sun at every vertex (next-event estimation), and continues by
// cosine-distributed bounces off Lambertian surfaces until Russian roulette ends it or it leaves
// the scene for the sky. Texel values converge to the
// exact mean irradiance over the footprint; each comes with its standard error, estimated from
// the spread of its own paths.
#pragma once

#include <cstdint>
#include <vector>

#include "baker/surface/elements.h"
#include "baker/surface/material_sampler.h"
#include "baker/surface/ray_tracer.h"
#include "base/progress.h"
#include "base/scene.h"
#include "daylight/sky.h"

namespace radbake {

struct PathTraceOptions {
  uint32_t samples = 1024;  // paths per texel, rounded down to a multiple of 8 (the batches the
                            // noise is estimated from); the noise falls as 1 / sqrt(samples)
  // Per element, nonzero: traced; empty: every element. The others stay 0: a reference for a few
  // regions can afford many more paths than one for the whole page.
  std::vector<uint8_t> only;
};

struct PathTraced {
  std::vector<Rgb> irradiance;        // per element, lux (0 for buried elements and those not traced)
  std::vector<float> standard_error;  // per element, lux: of the mean over RGB, from its batches' spread
  uint32_t samples = 0;               // paths per texel traced
  // The noise estimate: the RMS of the texels' standard errors over the mean irradiance of the
  // valid texels, which is what the noise adds to a relative RMSE measured against these values
  // (radbake diff divides by the reference's mean texel value the same way).
  double relative_noise = 0;
  double mean_irradiance = 0;         // lux, mean over the valid elements traced and over RGB
  double mean_path_vertices = 0;      // surface hits per path, the first included
};

// `materials` reads reflectance and emission at any surface point; `lights` are the scene's
// punctual lights (every one is traced: the path tracer culls nothing). With `sky` (may be null or
// disabled), a path that leaves the scene takes the sky's or the ground's luminance, and every
// vertex takes the sun by a shadow ray to a point of its disc.
PathTraced path_trace(const Elements& elements, const Surface& surface, const MaterialSampler& materials,
                      const std::vector<Light>& lights, const SkyLight* sky, const RayTracer& tracer,
                      const PathTraceOptions& options, uint64_t seed, Progress& progress);

// Irradiance (lux) at points in the air, point i facing unit normals[i], by `samples` paths each
// (rounded down to a multiple of 8, the batches), with the standard error of each point's
// photopic reading (base/math.h) from its batches' spread: the reference light probes and sensors
// are measured against (--method pathtrace reads sensors so).
struct PathTracedPoints {
  std::vector<Rgb> irradiance;
  std::vector<double> standard_error;  // lux, photopic
};
PathTracedPoints path_trace_points(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                                   const Elements& elements, const Surface& surface, const MaterialSampler& materials,
                                   const std::vector<Light>& lights, const SkyLight* sky, const RayTracer& tracer,
                                   uint32_t samples, uint64_t seed);

}  // namespace radbake
