#include "baker/sky_light.h"

#include <tbb/parallel_for.h>

#include <cmath>

#include "baker/sampling.h"

namespace radbake {

namespace {

constexpr double kSunRadius = 0.2665 * M_PI / 180;  // the disc's angular radius

// The scene's up, north and east, unit length; azimuths turn from north toward east.
struct Compass {
  Vec3 up, north, east;
  explicit Compass(const SkyLight& sky)
      : up(normalize(sky.up)), north(normalize(sky.north)), east(normalize(cross(north, up))) {}
};

}  // namespace

Vec3 sun_direction(const SkyLight& sky) {
  const Compass c(sky);
  const float z = float(sky.sun_zenith), a = float(sky.sun_azimuth);
  return normalize(c.up * std::cos(z) + (c.north * std::cos(a) + c.east * std::sin(a)) * std::sin(z));
}

std::vector<Rgb> sky_irradiance(const Elements& e, const Surface& surface, const RayTracer& tracer,
                                const SkyLight& sky, uint64_t seed, Progress& progress) {
  std::vector<Rgb> irradiance(e.size());
  const Compass compass(sky);
  const Vec3 &up = compass.up, &north = compass.north, &east = compass.east;
  const uint32_t rays = std::max<uint32_t>(1, sky.rays), sun_rays = std::max<uint32_t>(1, sky.sun_rays);
  const Vec3 sun = sun_direction(sky);
  Vec3 sun_t, sun_b;
  orthonormal_basis(sun, sun_t, sun_b);
  const bool sun_up = sky.sun_illuminance > 0 && dot(sun, up) > 0;
  // The ground's luminance, cd/m2: lit by the whole sky and the sun.
  const double ground = sky.ground_reflectance / M_PI *
                        (sky.zenith_luminance * horizontal_illuminance_over_zenith_luminance(
                                                    sky.distribution, sky.sun_zenith, sky.sun_azimuth) +
                         (sun_up ? sky.sun_illuminance * dot(sun, up) : 0.0));
  progress.begin("sky", e.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, e.size(), 64), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i) {
      if (!e.valid(i)) continue;
      const Vec3 ng = surface.normal[e.triangle[i]];
      Rng rng(seed, Stream::Sky, i);
      const uint32_t origin_pattern = rng.next_u32(), direction_pattern = rng.next_u32();
      const uint32_t sun_origin_pattern = rng.next_u32(), sun_disc_pattern = rng.next_u32();
      double luminance = 0;  // cd/m2, summed over the rays
      for (uint32_t k = 0; k < rays; ++k) {
        const Vec3 origin = footprint_point(e, surface, i, cmj_sample(k, rays, origin_pattern)) + ng * e.offset[i];
        const Vec3 d = hemisphere_direction(e.normal[i], ng, cmj_sample(k, rays, direction_pattern));
        const float height = dot(d, up);
        const float passes = tracer.transmittance(origin, d, 0.0f, INFINITY);
        if (!(passes > 0)) continue;
        if (!(height > 0)) {
          luminance += ground * passes;
          continue;
        }
        const double zenith = std::acos(std::fmin(1.0f, height));
        const double azimuth = std::atan2(double(dot(d, east)), double(dot(d, north)));
        luminance += passes * sky.zenith_luminance *
                     relative_sky_luminance(sky.distribution, zenith, azimuth, sky.sun_zenith, sky.sun_azimuth);
      }
      // Cosine-distributed directions: E = pi * (mean luminance seen).
      double lux = M_PI * luminance / rays;
      if (sun_up) {
        double seen = 0;  // cos(incidence) over the disc's points that are not hidden
        for (uint32_t k = 0; k < sun_rays; ++k) {
          const Vec3 origin =
              footprint_point(e, surface, i, cmj_sample(k, sun_rays, sun_origin_pattern)) + ng * e.offset[i];
          const Vec2 u = cmj_sample(k, sun_rays, sun_disc_pattern);
          const double radius = kSunRadius * std::sqrt(u.x), turn = 2 * M_PI * u.y;
          const Vec3 d = normalize(sun + (sun_t * float(std::cos(turn)) + sun_b * float(std::sin(turn))) *
                                             float(std::tan(radius)));
          const float incidence = dot(e.normal[i], d);
          if (incidence > 0 && dot(ng, d) > 0) seen += incidence * tracer.transmittance(origin, d, 0.0f, INFINITY);
        }
        lux += sky.sun_illuminance * seen / sun_rays;
      }
      irradiance[i] = Rgb{float(lux), float(lux), float(lux)};
    }
    progress.advance(r.size());
  });
  progress.end();
  return irradiance;
}

}  // namespace radbake
