#include "baker/sky_light.h"

#include <tbb/parallel_for.h>

#include <cmath>

#include "baker/sampling.h"

namespace radbake {

std::vector<Rgb> sky_irradiance(const Elements& e, const Surface& surface, const RayTracer& tracer,
                                const SkyLight& sky, uint64_t seed, Progress& progress) {
  std::vector<Rgb> irradiance(e.size());
  const Vec3 up = normalize(sky.up), north = normalize(sky.north), east = normalize(cross(north, up));
  const uint32_t rays = std::max<uint32_t>(1, sky.rays);
  // The ground's luminance over the zenith's.
  const double ground = sky.ground_reflectance / M_PI *
                        horizontal_illuminance_over_zenith_luminance(sky.distribution, sky.sun_zenith, sky.sun_azimuth);
  progress.begin("sky", e.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, e.size(), 64), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i) {
      if (!e.valid(i)) continue;
      const Vec3 ng = surface.normal[e.triangle[i]];
      Rng rng(seed, Stream::Sky, i);
      const uint32_t origin_pattern = rng.next_u32(), direction_pattern = rng.next_u32();
      double luminance = 0;
      for (uint32_t k = 0; k < rays; ++k) {
        const Vec3 origin = footprint_point(e, surface, i, cmj_sample(k, rays, origin_pattern)) + ng * e.offset[i];
        const Vec3 d = hemisphere_direction(e.normal[i], ng, cmj_sample(k, rays, direction_pattern));
        const float height = dot(d, up);
        if (tracer.occluded(origin, d, 0.0f, INFINITY)) continue;
        if (!(height > 0)) {
          luminance += ground;
          continue;
        }
        const double zenith = std::acos(std::fmin(1.0f, height));
        const double azimuth = std::atan2(double(dot(d, east)), double(dot(d, north)));
        luminance += relative_sky_luminance(sky.distribution, zenith, azimuth, sky.sun_zenith, sky.sun_azimuth);
      }
      // Cosine-distributed directions: E = pi * (mean luminance seen).
      const float lux = float(M_PI * sky.zenith_luminance * luminance / rays);
      irradiance[i] = Rgb{lux, lux, lux};
    }
    progress.advance(r.size());
  });
  progress.end();
  return irradiance;
}

}  // namespace radbake
