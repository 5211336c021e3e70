#include "baker/direct/sky_light.h"

#include <tbb/parallel_for.h>

#include <cmath>

#include "baker/surface/sampling.h"

namespace radbake {

double sun_disc_seen(const SkyView& view, const RayTracer& tracer, Vec3 origin, uint32_t rays, uint32_t pattern) {
  if (!view.sky().enabled || !view.sun_up()) return 0;
  rays = std::max<uint32_t>(1, rays);
  double seen = 0;
  for (uint32_t k = 0; k < rays; ++k) seen += tracer.transmittance(origin, view.toward_sun(cmj_sample(k, rays, pattern)), 0.0f, INFINITY);
  return seen / rays;
}

namespace {

// A point's sky rays: cosine-distributed over its hemisphere, and shadow rays to the sun's disc.
struct SkyRays {
  SkyView view;
  const RayTracer& tracer;
  uint32_t rays, sun_rays;

  SkyRays(const SkyLight& s, const RayTracer& t)
      : view(s), tracer(t), rays(std::max<uint32_t>(1, s.rays)), sun_rays(std::max<uint32_t>(1, s.sun_rays)) {}

  // Lux on a surface of shading normal n and geometric normal ng, rays from origin_of(u) for a
  // stratified u in the unit square (a point of a texel's footprint, or one point).
  // With `from`, also where the light comes from (light_direction.h; grey).
  template <class OriginOf>
  double lux(Vec3 n, Vec3 ng, const OriginOf& origin_of, Rng& rng, Vec3* from = nullptr) const {
    const SkyRayPatterns pattern(rng);
    double luminance = 0;  // cd/m2, summed over the rays
    Vec3 sky_from{}, sun_from{};
    for (uint32_t k = 0; k < rays; ++k) {
      const Vec3 origin = origin_of(cmj_sample(k, rays, pattern.origin));
      const Vec3 d = hemisphere_direction(n, ng, cmj_sample(k, rays, pattern.direction));
      const float passes = tracer.transmittance(origin, d, 0.0f, INFINITY);
      if (passes > 0) {
        const double seen = passes * view.luminance(d);
        luminance += seen;
        if (from) sky_from += d * float(seen);
      }
    }
    // Cosine-distributed directions: E = pi * (mean luminance seen).
    double lux = M_PI * luminance / rays;
    if (from) *from = sky_from * float(M_PI / rays);
    if (!view.sun_up()) return lux;
    double seen = 0;  // cos(incidence) over the disc's points that are not hidden
    for (uint32_t k = 0; k < sun_rays; ++k) {
      const Vec3 origin = origin_of(cmj_sample(k, sun_rays, pattern.sun_origin));
      const Vec3 d = view.toward_sun(cmj_sample(k, sun_rays, pattern.sun_disc));
      const float incidence = dot(n, d);
      if (incidence > 0 && dot(ng, d) > 0) {
        const double part = incidence * tracer.transmittance(origin, d, 0.0f, INFINITY);
        seen += part;
        if (from) sun_from += d * float(part);
      }
    }
    if (from) *from += sun_from * float(view.sky().sun_illuminance / sun_rays);
    return lux + view.sky().sun_illuminance * seen / sun_rays;
  }
};

}  // namespace

std::vector<Rgb> sky_irradiance(const Elements& e, const Surface& surface, const RayTracer& tracer,
                                const SkyLight& sky, uint64_t seed, Progress& progress, ElementRange range,
                                std::vector<LightDirection>* directions) {
  range = range.within(e.size());
  std::vector<Rgb> irradiance(range.size());
  if (directions) directions->assign(range.size(), {});
  const SkyRays rays(sky, tracer);
  progress.begin("sky", range.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(range.begin, range.end, 64), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i) {
      if (!e.valid(i)) continue;
      const Vec3 ng = surface.normal[e.triangle[i]];
      Rng rng(seed, Stream::Sky, i);
      Vec3 from{};
      const float lux = float(rays.lux(e.normal[i], ng, [&](Vec2 u) {
        return footprint_point(e, surface, i, u) + ng * e.offset[i];
      }, rng, directions ? &from : nullptr));
      irradiance[i - range.begin] = Rgb{lux, lux, lux};
      if (directions) (*directions)[i - range.begin] = {Rgb{1, 1, 1} * from.x, Rgb{1, 1, 1} * from.y, Rgb{1, 1, 1} * from.z};
    }
    progress.advance(r.size());
  });
  progress.end();
  return irradiance;
}

std::vector<SensorBatches> sky_illuminance_at(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                                              const RayTracer& tracer, const SkyLight& sky, uint32_t rays, uint64_t seed) {
  std::vector<SensorBatches> lux(points.size());
  const SkyView view(sky);
  const uint32_t per_batch = rays_per_batch(rays), sun_rays = std::max<uint32_t>(1, sky.sun_rays);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size(), 4), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i) {
      Rng rng(seed, Stream::SensorSky, i);
      const SensorRayPatterns pattern(rng);
      const Vec3 n = normals[i];
      double sun = 0;  // lux: cos(incidence) over the disc's points that are not hidden
      if (view.sun_up()) {
        for (uint32_t k = 0; k < sun_rays; ++k) {
          const Vec3 d = view.toward_sun(cmj_sample(k, sun_rays, pattern.sky.sun_disc));
          if (dot(n, d) > 0) sun += dot(n, d) * tracer.transmittance(points[i], d, 0.0f, INFINITY);
        }
        sun *= sky.sun_illuminance / sun_rays;
      }
      for (uint32_t b = 0; b < kSensorBatches; ++b) {
        double luminance = 0;  // cd/m2, summed over the batch's cosine-distributed rays
        for (uint32_t k = 0; k < per_batch; ++k) {
          const Vec3 d = hemisphere_direction(n, n, cmj_sample(k, per_batch, pattern.batch[b]));
          const float passes = tracer.transmittance(points[i], d, 0.0f, INFINITY);
          if (passes > 0) luminance += passes * view.luminance(d);
        }
        lux[i][b] = M_PI * luminance / per_batch + sun;
      }
    }
  });
  return lux;
}

}  // namespace radbake
