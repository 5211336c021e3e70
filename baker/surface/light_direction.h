// Where the light a texel receives comes from (--directional, directional_lightmaps.h): the sum of
// the unit directions it arrives along, each weighted by the irradiance it brings, per colour
// channel (lux). Its direction is the light's dominant one; its length over the irradiance, 1 when
// all the light comes from one direction, says how directional the light is.
#pragma once

#include "base/math.h"

namespace radbake {

struct LightDirection {
  Rgb x{}, y{}, z{};

  // `lux` arriving along unit `toward` (pointing away from the texel, toward the light).
  void add(const Rgb& lux, Vec3 toward) {
    x += lux * toward.x;
    y += lux * toward.y;
    z += lux * toward.z;
  }
  LightDirection& operator+=(const LightDirection& o) {
    x += o.x;
    y += o.y;
    z += o.z;
    return *this;
  }
  LightDirection operator*(const Rgb& s) const { return {x * s, y * s, z * s}; }
  LightDirection operator*(float s) const { return {x * s, y * s, z * s}; }
  Vec3 channel(int c) const { return {x[c], y[c], z[c]}; }
};

}  // namespace radbake
