// Indirect irradiance at texel resolution: each element gathers the solved patch exitance over
// its hemisphere with stratified cosine-distributed rays. Emission is left out (direct light
// already counts it), so the rays only carry light that surfaces reflect.
#pragma once

#include <cstdint>
#include <vector>

#include "baker/elements.h"
#include "baker/patches.h"
#include "baker/progress.h"
#include "baker/ray_tracer.h"

namespace radbake {

struct GatherStats {
  double back_face_fraction = 0;  // of all gather rays, over valid elements
};

struct GatheredLight {
  std::vector<Rgb> irradiance;           // per element, lux
  // Per element, metres: the harmonic mean of its rays' distances to what they struck (rays
  // leaving the scene count as infinitely far; infinite if all did), how near other surfaces are.
  std::vector<float> harmonic_distance;
};

GatheredLight gather_indirect(const Elements& elements, const Patches& patches, const Surface& surface,
                                 const RayTracer& tracer, const std::vector<Rgb>& patch_exitance, uint32_t rays,
                                 uint64_t seed, Progress& progress, GatherStats* stats = nullptr);

}  // namespace radbake
