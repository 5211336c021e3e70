// The sun, a disc 0.53 degree across, by shadow rays to points spread over it (soft shadow edges,
// as wide as the disc's angle times the distance to what casts them).
//
// The sky as a light source: each texel's illuminance from the sky it sees, by cosine-distributed
// rays from points over its footprint; a ray that leaves the scene upward takes the sky's
// luminance in its direction, one that leaves below the horizon the ground's: an endless
// Lambertian plane lit by the whole unobstructed sky, L = rho E_h / pi. One that strikes a
// surface, none. The light the surfaces then reflect is the solve's, as for lamps.
#pragma once

#include <cstdint>
#include <vector>

#include "baker/elements.h"
#include "baker/light_direction.h"
#include "baker/progress.h"
#include "baker/ray_tracer.h"
#include "baker/sampling.h"
#include "baker/sky_luminance.h"
#include "baker/surface.h"

namespace radbake {

struct SkyLight {
  bool enabled = false;
  SkyDistribution distribution;
  double zenith_luminance = 0;           // cd/m2
  // lux, the sky alone on an unobstructed horizontal plane, when known (daylight_sky sets it);
  // 0: worked out from the distribution by quadrature when needed.
  double sky_horizontal_illuminance = 0;
  double sun_zenith = 0, sun_azimuth = 0;  // radians; azimuth from north, eastward
  Vec3 up{0, 1, 0};                      // the scene's zenith (glTF: +Y)
  Vec3 north{0, 0, -1};                  // the scene's north, perpendicular to `up`
  double sun_illuminance = 0;            // lux, direct normal (on a plane facing the sun); 0: no sun
  double ground_reflectance = 0.2;       // of the ground beyond the scene, below the horizon
  uint32_t rays = 256;                   // sky rays per texel
  uint32_t sun_rays = 32;                // shadow rays per texel to the sun's disc
};

// The direction the sun shines from, in the scene.
Vec3 sun_direction(const SkyLight& sky);

// What a ray that leaves the scene meets, and where the sun's disc is: shared by the sky's rays
// and the path tracer's.
class SkyView {
 public:
  explicit SkyView(const SkyLight& sky);
  // cd/m2 toward unit `direction`: the sky's above the horizon, the ground's (rho E_h / pi, lit by
  // the whole sky and the sun) below. The sun's disc is not in it: it is reached by toward_sun.
  double luminance(Vec3 direction) const;
  bool sun_up() const { return sun_up_; }
  // A direction to a point of the sun's disc, spread uniformly over it by u in the unit square.
  Vec3 toward_sun(Vec2 u) const;
  const SkyLight& sky() const { return sky_; }

 private:
  const SkyLight& sky_;
  Vec3 up_, north_, east_, sun_, sun_t_, sun_b_;
  bool sun_up_ = false;
  double ground_ = 0;  // cd/m2
};

// The patterns of a point's sky rays and sun rays, drawn from its generator in the order the sky's
// irradiance draws them: ray k of n leaves from origin_of(cmj_sample(k, n, origin)) along
// hemisphere_direction(n, ng, cmj_sample(k, n, direction)); sun ray k toward
// toward_sun(cmj_sample(k, n, sun_disc)). Daylight coefficients cast the very same rays.
struct SkyRayPatterns {
  uint32_t origin, direction, sun_origin, sun_disc;
  explicit SkyRayPatterns(Rng& rng)
      : origin(rng.next_u32()), direction(rng.next_u32()), sun_origin(rng.next_u32()), sun_disc(rng.next_u32()) {}
};

// Rays start a millionth of the scene off a sensor, so a sensor lying on a surface (a work plane
// at height 0) does not see the surface it lies on.
inline Vec3 sensor_origin(Vec3 position, Vec3 normal, float scene_extent) { return position + normal * (1e-6f * scene_extent); }

// The share of the sun's disc seen from `origin`: `rays` shadow rays spread over the disc by
// `pattern`, each counting what of it passes (glazing); 0 when the sun is down or absent.
double sun_disc_seen(const SkyView& view, const RayTracer& tracer, Vec3 origin, uint32_t rays, uint32_t pattern);

// At points in the air (sensors) facing `normals`, lux; each point's rays all start at it.
std::vector<double> sky_illuminance_at(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                                       const RayTracer& tracer, const SkyLight& sky, uint64_t seed);

// Per element of `range` (the first at index 0), lux (grey: the sky is white); with `directions`,
// where it comes from (light_direction.h).
std::vector<Rgb> sky_irradiance(const Elements& elements, const Surface& surface, const RayTracer& tracer,
                                const SkyLight& sky, uint64_t seed, Progress& progress, ElementRange range = {},
                                std::vector<LightDirection>* directions = nullptr);

}  // namespace radbake
