// How far light goes between the scene's surfaces, to size patches by the rooms they light.
#pragma once

#include <cstdint>

#include "baker/surface/elements.h"
#include "baker/surface/ray_tracer.h"
#include "baker/surface/surface.h"

namespace radbake {

// The mean distance, in metres, that a cosine-weighted ray from a random point of the valid
// surface (chosen by area) goes before it strikes a surface; rays that leave the scene do not
// count. In a closed room it is about 4 V / S (a 4 x 5 x 2.5 m room: 2.4 m). Infinity when no ray
// strikes anything.
double mean_free_path(const Elements& elements, const Surface& surface, const RayTracer& tracer, uint64_t seed,
                      uint32_t rays = 4096);

}  // namespace radbake
