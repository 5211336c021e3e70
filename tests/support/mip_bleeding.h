// How much a neighbouring chart bleeds into what a texel reads at each mip level of a lightmap
// page (docs/mip_bleeding.md): shared by tests/baker/finish/mip_bleeding_test.cpp, which asserts it, and
// bench/mip_bleeding.cpp, which prints the table.
#pragma once

#include <vector>

#include "support/scene_builders.h"

namespace radbake::test {

struct MipLevelBleed {
  int level = 0;       // 0: the page itself; L: box-filtered 2^L x 2^L
  int side = 0;        // texels per side at this level (the larger side)
  // Reads at the centres of the chart's own covered (valid) texels, bilinear at this level,
  // against what it would read if its chart were alone on the page (dilated from it alone):
  double worst_code = 0;      // 8-bit sRGB PNG code units, worst channel of the worst texel
  double worst_relative = 0;  // |difference| / max(value alone, 10% of the page's mean level)
  double share_visible = 0;   // share of chart texels whose bleed is 1 code or more
  // The same reads against the texel's level-0 value: bleed plus the chart's own minification blur.
  double worst_code_vs_level0 = 0;
  // Level 0 only: reads at a 5 x 5 grid of points over each covered texel (corners included), so
  // anywhere a bilinear, unmipmapped sampler reads within the chart; bleed in code units.
  double anywhere_code = 0;
};

struct MipBleedTable {
  int padding = 0;
  int width = 0, height = 0;
  float png_scale = 0;  // the page's PNG intensity (lux encoded as 255)
  // Black texels of the dilated page, and how many of them are covered texels that are black
  // themselves: dilation filling the whole page adds none.
  size_t black_texels = 0, black_covered_texels = 0;
  std::vector<MipLevelBleed> levels;
};

// Bakes `scene` with lightmap padding `padding` on pages of at most `page_size`, then measures
// page 0's mip chain (box filter, averaged in linear values as GPUs do for sRGB textures).
MipBleedTable measure_mip_bleeding(const Scene& scene, int page_size, int padding, const BakeOptions& options);

}  // namespace radbake::test
