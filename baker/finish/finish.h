// Turns per-element values into what engines read: lightmap pages with every texel filled (charts
// dilated outward so bilinear filtering and mip-mapping never read an unlit texel), and one value
// per output vertex.
#pragma once

#include <vector>

#include "baker/surface/elements.h"
#include "base/math.h"
#include "uv/atlas.h"

namespace radbake {

struct LightmapPage {
  int width = 0, height = 0;
  std::vector<Rgb> texels;     // rows top to bottom
  std::vector<uint8_t> valid;  // 1 where a valid element wrote the texel (before dilation)
};

// Fills every texel that no element wrote (valid == 0) from its nearest written neighbours, so
// bilinear filtering never reads an unlit texel anywhere on the page.
void dilate_page(LightmapPage& page);

// With `dilate` false, texels without a valid element stay black: what the debug dumps show.
std::vector<LightmapPage> compose_pages(const Elements& elements, const std::vector<Rgb>& values,
                                        const std::vector<AtlasPage>& pages, bool dilate = true);

// Per instance, per atlas output vertex: the elements of the vertex's chart around it, fitted by
// a plane in lightmap space and evaluated at the vertex, so values extrapolate to surface edges
// instead of averaging in the dark beyond them.
std::vector<std::vector<Rgb>> vertex_values(const Elements& elements, const Surface& surface, const Atlas& atlas,
                                            const std::vector<LightmapPage>& pages, const std::vector<Rgb>& values);

}  // namespace radbake
