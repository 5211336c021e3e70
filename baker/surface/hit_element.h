// Which element a ray that strikes a surface takes its light from: the texel's that holds the
// point struck, or a neighbour's on the hit's side of any wall or cover, or none, and why.
#pragma once

#include <cstdint>

#include "baker/surface/elements.h"
#include "baker/surface/ray_fates.h"
#include "baker/surface/ray_tracer.h"

namespace radbake {

// The element that stands for a hit point (the texel's on the hit's side of any wall or cover
// crossing it), or -1 for none. `seen_from` is the ray origin's kUnderCover flag (0 in the open): a
// hit across the mouth of a thin gap, in it from the open or out of it from inside, is none.
int64_t element_for_hit(const Elements& elements, const Surface& surface, const RayTracer& tracer, const Hit& hit,
                        uint8_t seen_from);
constexpr uint8_t kFromTheOpen = 0;  // seen_from for a point off the surfaces (sensors, probes, eyes)

// element_for_hit's answer with, for none, why: NoElement, BuriedElement, OtherSide, SealedGap or
// InsideGeometry.
struct HitElement {
  int64_t element = -1;
  RayFate fate = RayFate::TookLight;
};
HitElement element_standing_for(const Elements& elements, const Surface& surface, const RayTracer& tracer,
                                const Hit& hit, uint8_t seen_from);

}  // namespace radbake
