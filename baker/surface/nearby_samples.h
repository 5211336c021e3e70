// The valid samples near a point, from any chart: where a ray strikes a part whose own texel holds
// no sample on the hit's side (a window frame's step, a sill between frame and room), the sample of
// a neighbouring part in sight of the hit stands for it.
#pragma once

#include <cstdint>
#include <vector>

#include "baker/surface/elements.h"
#include "baker/surface/surface.h"

namespace radbake {

// Indexes the valid samples of `elements` by cell (Elements::sample_cell...), once every sample has
// its final place.
void index_samples(Elements& elements, const Surface& surface);

// The valid elements whose sample lies within `radius` metres of `point`, nearest first, at most
// `most` of them.
std::vector<uint32_t> samples_near(const Elements& elements, Vec3 point, float radius, size_t most);

}  // namespace radbake
