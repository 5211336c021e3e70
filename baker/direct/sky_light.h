// The sun, a disc 0.53 degree across, by shadow rays to points spread over it (soft shadow edges,
// as wide as the disc's angle times the distance to what casts them).
//
// The sky as a light source: each texel's illuminance from the sky it sees, by cosine-distributed
// rays from points over its footprint and rays aimed at the glazing (sky_portals.h); a ray that leaves the scene upward takes the sky's
// luminance in its direction, one that leaves below the horizon the ground's: an endless
// Lambertian plane lit by the whole unobstructed sky, L = rho E_h / pi. One that strikes a
// surface, none. The light the surfaces then reflect is the solve's, as for lamps. What the sky and
// the sun are (SkyLight, SkyView) is daylight/sky.h's; this file casts the rays.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "baker/direct/sky_portals.h"
#include "baker/surface/elements.h"
#include "baker/surface/light_direction.h"
#include "baker/surface/ray_tracer.h"
#include "baker/surface/sampling.h"
#include "baker/surface/surface.h"
#include "base/progress.h"
#include "daylight/sky.h"

namespace radbake {

// A sensor's sky rays (SensorOptions::sky_rays) come in kSensorBatches independent stratified
// sets (batches): its value is the mean of its batches' and their spread states its noise, the
// standard error of that mean. A texel's SkyLight::rays are one stratified set, its noise stated
// from the spread of its interleaved eighths (an overstatement: each eighth is a coarser set).
constexpr uint32_t kSensorBatches = 8;
inline uint32_t rays_per_batch(uint32_t rays) { return std::max<uint32_t>(1, rays / kSensorBatches); }

// The patterns of a texel's sky rays and sun rays, drawn from its generator in this order: ray k
// of n leaves from origin_of(cmj_sample(k, n, origin)) along hemisphere_direction(n, ng,
// cmj_sample(k, n, direction)), or, aimed at the glazing (sky_portals.h), by the direction pattern
// likewise; sun ray k toward toward_sun(cmj_sample(k, n, sun_disc)) from origin_of(cmj_sample(k,
// n, sun_origin)). Daylight coefficients cast the very same cosine-distributed rays.
struct SkyRayPatterns {
  uint32_t origin, direction, sun_origin, sun_disc;
  explicit SkyRayPatterns(Rng& rng)
      : origin(rng.next_u32()), direction(rng.next_u32()), sun_origin(rng.next_u32()), sun_disc(rng.next_u32()) {}
};

// A sensor's patterns, drawn from its generator: the sun's (SkyRayPatterns), then one per batch.
// Ray k of batch b of n per batch goes along hemisphere_direction(normal, normal, cmj_sample(k, n,
// batch[b])) or aimed at the glazing likewise; daylight coefficients cast the very same rays.
struct SensorRayPatterns {
  SkyRayPatterns sky;
  uint32_t batch[kSensorBatches];
  explicit SensorRayPatterns(Rng& rng) : sky(rng) {
    for (uint32_t& b : batch) b = rng.next_u32();
  }
};

// One batch of a point's sky rays: `count` of them, cosine-distributed; with glazing in front of the
// surface at `at` facing `normal` (sky_portals.h), a quarter cosine-distributed and the rest aimed
// into the glazing, each weighted by the balance heuristic. Rays start within `reach` (metres) of
// `at`: a texel's footprint.
class SkyRaySet {
 public:
  SkyRaySet(const SkyPortals& portals, uint32_t count, Vec3 at, Vec3 normal, float reach = 0);
  uint32_t count() const { return count_; }
  // Ray k's direction from `origin`, for a surface of shading normal n and geometric normal ng.
  Vec3 direction(uint32_t k, Vec3 n, Vec3 ng, Vec3 origin, uint32_t pattern) const;
  // Lux per cd/m2 of what ray k (along d from `origin`) sees: pi / count for cosine-distributed
  // rays alone, else cos / (N_c cos / pi + N_p p_portals); 0 for a direction behind the surface.
  double lux_per_luminance(Vec3 d, Vec3 n, Vec3 ng, Vec3 origin) const;

 private:
  PortalView portals_;
  uint32_t count_, cosine_;
};

// Rays start a millionth of the scene off a sensor, so a sensor lying on a surface (a work plane
// at height 0) does not see the surface it lies on.
inline Vec3 sensor_origin(Vec3 position, Vec3 normal, float scene_extent) { return position + normal * (1e-6f * scene_extent); }

// The share of the sun's disc seen from `origin`: `rays` shadow rays spread over the disc by
// `pattern`, each counting what of it passes (glazing); 0 when the sun is down or absent.
double sun_disc_seen(const SkyView& view, const RayTracer& tracer, Vec3 origin, uint32_t rays, uint32_t pattern);

// At points in the air (sensors) facing `normals`, lux from the sky, the ground and the sun, per
// batch of `rays` sky rays (SensorRayPatterns; the sun's share, from all of sky.sun_rays, in every
// batch alike); each point's rays all start at it.
using SensorBatches = std::array<double, kSensorBatches>;
std::vector<SensorBatches> sky_illuminance_at(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                                              const RayTracer& tracer, const SkyLight& sky, const SkyPortals& portals,
                                              uint32_t rays, uint64_t seed);

// Per element of `range` (the first at index 0), lux (grey: the sky is white); with `directions`,
// where it comes from (light_direction.h); with `standard_error`, each element's sky noise, lux
// (kSensorBatches above).
std::vector<Rgb> sky_irradiance(const Elements& elements, const Surface& surface, const RayTracer& tracer,
                                const SkyLight& sky, const SkyPortals& portals, uint64_t seed, Progress& progress,
                                ElementRange range = {}, std::vector<LightDirection>* directions = nullptr,
                                std::vector<float>* standard_error = nullptr);

}  // namespace radbake
