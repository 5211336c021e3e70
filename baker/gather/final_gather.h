// Indirect irradiance at texel resolution: each element gathers the solved patch exitance over
// its hemisphere with stratified cosine-distributed rays. Emission is left out (direct light
// already counts it), so the rays only carry light that surfaces reflect. A ray landing within
// three widths of the struck patch (the near field: a block's foot, a corner, a lamp close to a
// ceiling) takes the struck texel's own exitance, its reflectance times its direct light plus its
// own gathered indirect light (solved together with its neighbours'). A ray landing farther takes
// the struck texel's reflected direct light plus its patch's reflected indirect light, so a patch
// the sun lights in part gives its light to those that see that part. What the near field takes
// beyond that (its texels' own indirect light against their patch's), the patch's far receivers get
// less of, in proportion to their far share of it (form factors less the near field's share), so no
// light is made or lost.
#pragma once

#include <cstdint>
#include <vector>

#include "baker/gather/gather_filter.h"
#include "baker/surface/bake_geometry.h"
#include "baker/surface/elements.h"
#include "baker/surface/light_direction.h"
#include "baker/surface/ray_fates.h"
#include "baker/surface/ray_tracer.h"
#include "baker/transport/patch_transport.h"
#include "baker/transport/patches.h"
#include "base/progress.h"

namespace radbake {

struct GatherStats {
  RayFates fates;  // where the gather rays of all valid elements ended
};

struct GatheredLight {
  std::vector<Rgb> irradiance;           // per element, lux
  // Per element with directions asked for: where the gathered light comes from, per channel
  // divided by the irradiance the rays found (a mean direction, length 1 when it all comes from
  // one direction), so it stays right when the near field and the filter change the irradiance.
  std::vector<LightDirection> mean_direction;
  // Per element, metres: the harmonic mean of its rays' distances to what they struck (rays
  // leaving the scene count as infinitely far; infinite if all did), how near other surfaces are.
  std::vector<float> harmonic_distance;
  // Per element: the share of its gather rays that left the scene (cosine-weighted, so the view of
  // the open it has: about 1 on a roof, under 0.1 in a room with windows), 0 for none cast.
  std::vector<float> open_view;
  // Per element: the share of its gather rays that struck a back face or a front face that took no
  // light (lost to the scene, as the form factors' `lost`), 0 for none cast.
  std::vector<float> lost_share;
};

// Gather rays from a receiver that landed near, on one struck element (the near field).
struct NearLanding {
  uint32_t receiver, struck, count;
};

// What the gather rays of a range of elements found: the part of the gather a process of a team
// computes (shared_stage.h). The rest, finish_gather, needs every range.
struct GatherTrace {
  std::vector<Rgb> irradiance;          // per element of the range, lux, before the near field is solved
  std::vector<float> harmonic_distance; // per element of the range, metres
  std::vector<float> open_view;         // per element of the range, as GatheredLight's
  std::vector<float> lost_share;        // per element of the range, as GatheredLight's
  // Per element of the range, lux: what its far rays took beyond their struck patches' mean
  // exitance, a change of what its patch receives that the solve did not know.
  std::vector<Rgb> far_beyond_mean;
  std::vector<LightDirection> mean_direction;  // per element of the range, as GatheredLight's; empty unless asked
  std::vector<NearLanding> landings;    // by receiver, then struck element
  RayFates fates;                       // where its rays ended
};

// What every range needs besides the elements: per patch, the irradiance it gathers in the solve
// (gathered_irradiance of the solved exitance), how far its near field reaches, and its texels'
// area-weighted mean reflected direct light (lm/m2), which a far ray's struck texel's own replaces.
// `direct`: per element, lux.
struct GatherInputs {
  std::vector<Rgb> patch_indirect;
  std::vector<float> near_reach;
  std::vector<Rgb> reflected_direct;
};
GatherInputs gather_inputs(const Elements& elements, const Patches& patches, const Surface& surface,
                           std::vector<Rgb> patch_indirect, const std::vector<Rgb>& direct);

// The final gather's settings (the quality presets set them, quality_presets.cpp).
struct GatherOptions {
  uint32_t rays = 256;          // hemisphere rays per texel for indirect light
  bool near_field = true;       // rays landing close by take the texel's exitance; false: every ray
                                // lands far (its struck texel's reflected direct light and its
                                // patch's reflected indirect light)
  GatherFilterOptions filter;   // texel-space filtering of the gather's noise, after it
};

// `patch_exitance`: the solve's reflected exitance per patch; `direct`: irradiance per element
// from lights and emitters, lux.
GatherTrace trace_gather(const BakeGeometry& geometry, const Patches& patches, const GatherInputs& inputs,
                         const std::vector<Rgb>& patch_exitance, const std::vector<Rgb>& direct,
                         const GatherOptions& options, uint64_t seed, ElementRange range, bool directions = false);

// The near field solved and its light balanced over the patches, from the traces of all the
// ranges in element order (`whole`: their irradiance, harmonic distance and landings joined).
GatheredLight finish_gather(const Elements& elements, const Patches& patches, const PatchTransport& transport,
                            const GatherInputs& inputs, const std::vector<Rgb>& patch_exitance,
                            const std::vector<Rgb>& direct, const GatherOptions& options, GatherTrace whole,
                            GatherStats* stats = nullptr);

}  // namespace radbake
