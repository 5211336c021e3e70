// Indirect irradiance at texel resolution: each element gathers the solved patch exitance over
// its hemisphere with stratified cosine-distributed rays. Emission is left out (direct light
// already counts it), so the rays only carry light that surfaces reflect. A ray landing within
// three widths of the struck patch (the near field: a block's foot, a corner, a lamp close to a
// ceiling) takes the struck texel's own exitance, its reflectance times its direct light plus its
// own gathered indirect light (solved together with its neighbours'), instead of the patch mean;
// what the near field takes beyond the mean, the patch's far receivers get less of, in proportion
// to their far share of it (form factors less the near field's share), so no light is made or lost.
#pragma once

#include <cstdint>
#include <vector>

#include "baker/elements.h"
#include "baker/patch_transport.h"
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

// `patch_exitance`: the solve's reflected exitance per patch; `direct`: irradiance per element
// from lights and emitters, lux; `near_field` false: every ray takes the patch mean.
GatheredLight gather_indirect(const Elements& elements, const Patches& patches, const Surface& surface,
                              const RayTracer& tracer, const PatchTransport& transport,
                              const std::vector<Rgb>& patch_exitance, const std::vector<Rgb>& direct, uint32_t rays,
                              bool near_field, uint64_t seed, Progress& progress, GatherStats* stats = nullptr);

}  // namespace radbake
