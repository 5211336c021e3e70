// The lightmap sampler has no mipmaps (minFilter LINEAR) because mip levels blend neighbouring
// charts (docs/mip_bleeding.md). These check what that choice rests on: at level 0 a bilinear read
// anywhere in a chart's texels reads nothing of another chart (padding and dilation suffice), while
// a level-2 read does, so padding alone would not make mipmaps safe; and dilation leaves no texel
// of the page black.
#include <gtest/gtest.h>

#include "io/gltf/gltf_loader.h"
#include "support/mip_bleeding.h"

namespace radbake {
namespace {

TEST(MipBleeding, WithoutMipmapsNoChartReadsAnotherAndWithThemItDoes) {
  const Scene scene = load_gltf(test::source_path("samples/cornell_box/cornell_box.gltf")).scene;
  BakeOptions options;
  options.gather.rays = 64;  // the page's noise does not matter here, only which chart a read reaches
  for (int padding : {2, 4}) {
    const test::MipBleedTable t = test::measure_mip_bleeding(scene, 128, padding, options);
    ASSERT_GE(t.levels.size(), 3u);
    // Exactly zero: the reads touch the same texels with the same values, whatever the others are.
    EXPECT_EQ(t.levels[0].anywhere_code, 0.0) << "padding " << padding;
    EXPECT_EQ(t.levels[0].worst_code, 0.0) << "padding " << padding;
    // Measured on a 128-texel page with the default ray counts: 45 (padding 2) and 99 (padding 4)
    // codes at level 2 (./build/mip_bleeding 128 2 4). One code is the least a viewer can see; a
    // measurement finding less would be missing the bleed.
    EXPECT_GE(t.levels[2].worst_code, 1.0) << "padding " << padding;
    EXPECT_EQ(t.black_texels, t.black_covered_texels) << "dilation left texels black";
    EXPECT_LT(t.black_texels, size_t(t.width) * size_t(t.height)) << "an all-black page proves nothing";
  }
}

}  // namespace
}  // namespace radbake
