// The sky and the sun as light sources, as plain functions of directions: what a ray that leaves
// the scene meets (the sky's luminance above the horizon, the ground's below) and where the sun's
// disc is. The rays that find them are the baker's (baker/direct/sky_light.h).
#pragma once

#include <cstdint>

#include "base/math.h"
#include "daylight/sky_luminance.h"

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

}  // namespace radbake
