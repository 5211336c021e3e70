#include "daylight/sky.h"

#include <cmath>

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

SkyView::SkyView(const SkyLight& sky) : sky_(sky), sun_(sun_direction(sky)) {
  const Compass c(sky);
  up_ = c.up, north_ = c.north, east_ = c.east;
  orthonormal_basis(sun_, sun_t_, sun_b_);
  sun_up_ = sky.sun_illuminance > 0 && dot(sun_, up_) > 0;
  const double sky_lux = sky.sky_horizontal_illuminance > 0
                            ? sky.sky_horizontal_illuminance
                            : sky.zenith_luminance * horizontal_illuminance_over_zenith_luminance(
                                                         sky.distribution, sky.sun_zenith, sky.sun_azimuth);
  ground_ = sky.ground_reflectance / M_PI * (sky_lux + (sun_up_ ? sky.sun_illuminance * dot(sun_, up_) : 0.0));
}

double SkyView::luminance(Vec3 d) const {
  const float height = dot(d, up_);
  if (!(height > 0)) return ground_;
  const double zenith = std::acos(std::fmin(1.0f, height));
  const double azimuth = std::atan2(double(dot(d, east_)), double(dot(d, north_)));
  return sky_.zenith_luminance *
         relative_sky_luminance(sky_.distribution, zenith, azimuth, sky_.sun_zenith, sky_.sun_azimuth);
}

Vec3 SkyView::toward_sun(Vec2 u) const {
  const double radius = kSunRadius * std::sqrt(u.x), turn = 2 * M_PI * u.y;
  return normalize(sun_ + (sun_t_ * float(std::cos(turn)) + sun_b_ * float(std::sin(turn))) * float(std::tan(radius)));
}

}  // namespace radbake
