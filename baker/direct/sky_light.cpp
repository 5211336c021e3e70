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

SkyRaySet::SkyRaySet(const SkyPortals& portals, uint32_t count, Vec3 at, Vec3 normal, float reach)
    : portals_(portals, at, normal, reach),
      count_(std::max<uint32_t>(1, count)),
      cosine_(portals_.empty() || count_ < 2 ? count_ : std::max<uint32_t>(1, count_ / 4)) {}

Vec3 SkyRaySet::direction(uint32_t k, Vec3 n, Vec3 ng, Vec3 origin, uint32_t pattern) const {
  if (k < cosine_) return hemisphere_direction(n, ng, cmj_sample(k, cosine_, pattern));
  // The aimed rays' own stratification, apart from the cosine-distributed ones'.
  return portals_.aim(origin, cmj_sample(k - cosine_, count_ - cosine_, pattern ^ 0x9e3779b9u));
}

double SkyRaySet::lux_per_luminance(Vec3 d, Vec3 n, Vec3 ng, Vec3 origin) const {
  if (cosine_ == count_) return M_PI / count_;
  const double c = double(dot(n, d));
  if (!(c > 0) || !(dot(ng, d) > 0)) return 0;
  return c / (double(cosine_) * c / M_PI + double(count_ - cosine_) * portals_.density(origin, d));
}

namespace {

// A point's sky rays: batches of SkyRaySets, and shadow rays to the sun's disc.
struct SkyRays {
  SkyView view;
  const RayTracer& tracer;
  uint32_t sun_rays;

  SkyRays(const SkyLight& s, const RayTracer& t) : view(s), tracer(t), sun_rays(std::max<uint32_t>(1, s.sun_rays)) {}

  // Lux from the sky and the ground by one batch of rays from origin_of(u) for a
  // stratified u in the unit square (a point of a texel's footprint, or one point); with `from`,
  // adds where it comes from (light_direction.h), lux per batch; with `interleaved`, adds ray k's
  // share to interleaved[k % kSensorBatches].
  template <class OriginOf>
  double batch(const SkyRaySet& set, Vec3 n, Vec3 ng, const OriginOf& origin_of, uint32_t origin_pattern,
               uint32_t direction_pattern, Vec3* from, double* interleaved = nullptr) const {
    const uint32_t count = set.count();
    double lux = 0;
    for (uint32_t k = 0; k < count; ++k) {
      const Vec3 origin = origin_of(cmj_sample(k, count, origin_pattern));
      const Vec3 d = set.direction(k, n, ng, origin, direction_pattern);
      if (!(dot(ng, d) > 0)) continue;
      // Traced first: most rays from a room's surfaces strike another, and only those that reach
      // the sky need their weight (a sum over the glazing).
      const float passes = tracer.transmittance(origin, d, 0.0f, INFINITY);
      if (!(passes > 0)) continue;
      const double seen = set.lux_per_luminance(d, n, ng, origin) * passes * view.luminance(d);
      lux += seen;
      if (from) *from += d * float(seen);
      if (interleaved) interleaved[k % kSensorBatches] += seen;
    }
    return lux;
  }

  // Lux from the sun's disc on a surface of shading normal n and geometric normal ng: its points
  // not hidden, by cos(incidence).
  template <class OriginOf>
  double sun(Vec3 n, Vec3 ng, const OriginOf& origin_of, const SkyRayPatterns& pattern, Vec3* from) const {
    if (!view.sun_up()) return 0;
    double seen = 0;
    Vec3 sun_from{};
    for (uint32_t k = 0; k < sun_rays; ++k) {
      const Vec3 origin = origin_of(cmj_sample(k, sun_rays, pattern.sun_origin));
      const Vec3 d = view.toward_sun(cmj_sample(k, sun_rays, pattern.sun_disc));
      const float incidence = dot(n, d);
      if (incidence > 0 && dot(ng, d) > 0) {
        const double part = incidence * tracer.transmittance(origin, d, 0.0f, INFINITY);
        seen += part;
        sun_from += d * float(part);
      }
    }
    if (from) *from += sun_from * float(view.sky().sun_illuminance / sun_rays);
    return view.sky().sun_illuminance * seen / sun_rays;
  }
};

}  // namespace

std::vector<Rgb> sky_irradiance(const Elements& e, const Surface& surface, const RayTracer& tracer,
                                const SkyLight& sky, const SkyPortals& portals, uint64_t seed, Progress& progress,
                                ElementRange range, std::vector<LightDirection>* directions,
                                std::vector<float>* standard_error) {
  range = range.within(e.size());
  std::vector<Rgb> irradiance(range.size());
  if (directions) directions->assign(range.size(), {});
  if (standard_error) standard_error->assign(range.size(), 0.0f);
  const SkyRays rays(sky, tracer);
  progress.begin("sky", range.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(range.begin, range.end, 64), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i) {
      if (!e.valid(i)) continue;
      const Vec3 ng = surface.normal[e.triangle[i]];
      Rng rng(seed, Stream::Sky, i);
      const SkyRayPatterns pattern(rng);
      auto origin_of = [&](Vec2 u) { return footprint_point(e, surface, i, u) + ng * e.offset[i]; };
      Vec3 from{};
      const SkyRaySet set(portals, std::max<uint32_t>(1, sky.rays), e.position[i], ng, surface.texel_size(e.triangle[i]));
      // One stratified set of all the rays, which is worth far more than independent batches of
      // them; its noise is stated from its interleaved eighths (rays k, k + 8, ...), each a
      // coarser stratified set: their spread over sqrt(8) overstates the whole set's error.
      double eighths[kSensorBatches] = {};
      const double mean =
          rays.batch(set, e.normal[i], ng, origin_of, pattern.origin, pattern.direction, directions ? &from : nullptr, eighths);
      double squares = 0;
      for (double part : eighths) squares += (part * kSensorBatches - mean) * (part * kSensorBatches - mean);
      const double error = std::sqrt(squares / (kSensorBatches - 1) / kSensorBatches);
      const float lux = float(mean + rays.sun(e.normal[i], ng, origin_of, pattern, directions ? &from : nullptr));
      irradiance[i - range.begin] = Rgb{lux, lux, lux};
      if (standard_error) (*standard_error)[i - range.begin] = float(error);
      if (directions) (*directions)[i - range.begin] = {Rgb{1, 1, 1} * from.x, Rgb{1, 1, 1} * from.y, Rgb{1, 1, 1} * from.z};
    }
    progress.advance(r.size());
  });
  progress.end();
  return irradiance;
}

std::vector<SensorBatches> sky_illuminance_at(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                                              const RayTracer& tracer, const SkyLight& sky, const SkyPortals& portals,
                                              uint32_t rays, uint64_t seed) {
  std::vector<SensorBatches> lux(points.size());
  const SkyRays cast(sky, tracer);
  const uint32_t per_batch = rays_per_batch(rays);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size(), 4), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i) {
      Rng rng(seed, Stream::SensorSky, i);
      const SensorRayPatterns pattern(rng);
      const Vec3 n = normals[i];
      auto at_point = [&](Vec2) { return points[i]; };
      const double sun = cast.sun(n, n, at_point, pattern.sky, nullptr);
      const SkyRaySet set(portals, per_batch, points[i], n);
      for (uint32_t b = 0; b < kSensorBatches; ++b) lux[i][b] = cast.batch(set, n, n, at_point, 0, pattern.batch[b], nullptr) + sun;
    }
  });
  return lux;
}

}  // namespace radbake
