// Form factors between patches by hemicubes (Cohen & Greenberg 1985): a half cube over each
// patch's centre, its faces split into pixels that each carry a precomputed delta form factor;
// each pixel's nearest surface (one Embree ray through the pixel centre: the item buffer's depth
// test) receives that share. Every hemicube is turned about its normal by a random angle, so the
// regular pixel grid does not alias the same way on every patch.
//
// A hemicube sees from one point, so it measures the patch's centre, not its area: accurate when
// patches are small against their distance to what they see (the classic assumption), biased for
// large patches close together, which ray casting over the patch area is not.
#pragma once

#include <cstdint>
#include <vector>

#include "baker/transport/patch_transport.h"

namespace radbake {

// Measures the rows of the patches in `which` into `into` (sized for all patches). `resolution`:
// pixels per side of the top face (even, 2..4096); the side faces are resolution x resolution / 2,
// so a hemicube casts 3 * resolution^2 rays.
void measure_hemicube_rows(const Elements& elements, const Patches& patches, const Surface& surface,
                           const RayTracer& tracer, int resolution, const std::vector<uint32_t>& which, uint64_t seed,
                           Progress& progress, MeasuredRows& into);

// All rows by hemicubes, balanced.
PatchTransport hemicube_patch_transport(const Elements& elements, const Patches& patches, const Surface& surface,
                                        const RayTracer& tracer, int resolution, uint64_t seed, Progress& progress);

}  // namespace radbake
