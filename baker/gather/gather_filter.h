// Texel-space filtering of the final gather's noise. Indirect light varies slowly except near other
// surfaces, so each texel's gathered irradiance is replaced by a weighted least-squares plane
// through its neighbours on the page that lie on the same surface (same plane and facing, world
// distance matching page distance), weighted by a Gaussian over page distance (sigma = radius / 2).
// A plane rather than a mean, so that light falling off across the kernel, and a kernel cut off
// on one side (a wall's foot, a chart's edge), are not pulled toward the far side's level. The
// kernel shrinks where surfaces are near: a neighbour counts only while its distance stays under
// `validity` times the nearer of the two texels' harmonic mean distance to what their gather
// rays struck (Ward's irradiance-cache validity radius). In the open a 7 x 7 kernel cuts the
// noise about five times; in a contact region it closes to the texel itself.
#pragma once

#include <vector>

#include "baker/surface/elements.h"
#include "baker/surface/surface.h"
#include "base/math.h"

namespace radbake {

struct GatherFilterOptions {
  int radius = 0;              // texels each side; 0: no filtering
  float validity = 1.0f;  // neighbours within this multiple of the harmonic mean distance
};

// `indirect`: gathered irradiance per element, lux; `harmonic_distance`: per element, metres (0 for
// none). Elements with `use[i] == 0` are neither filtered nor used.
std::vector<Rgb> filter_gathered(const Elements& elements, const Surface& surface, const std::vector<Rgb>& indirect,
                                 const std::vector<float>& harmonic_distance, const std::vector<uint8_t>& use,
                                 const GatherFilterOptions& options);

}  // namespace radbake
