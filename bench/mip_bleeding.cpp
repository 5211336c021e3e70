// Prints docs/mip_bleeding.md's table: how far a neighbouring chart bleeds into the Cornell box's
// lightmap page at each mip level, for several paddings.
//   ./build/mip_bleeding [PAGE_SIZE [PADDING...]]   (default 512, paddings 2 4 8)
#include <cstdio>
#include <cstdlib>

#include "io/gltf/gltf_loader.h"
#include "support/mip_bleeding.h"

int main(int argc, char** argv) {
  using namespace radbake;
  const int page_size = argc > 1 ? std::atoi(argv[1]) : 512;
  std::vector<int> paddings;
  for (int i = 2; i < argc; ++i) paddings.push_back(std::atoi(argv[i]));
  if (paddings.empty()) paddings = {2, 4, 8};
  const Scene scene = load_gltf(test::source_path("samples/cornell_box/cornell_box.gltf")).scene;
  for (int padding : paddings) {
    const test::MipBleedTable t = test::measure_mip_bleeding(scene, page_size, padding, BakeOptions{});
    std::printf("\npadding %d: page %dx%d, PNG intensity %.0f lx; level 0 read anywhere in a chart texel: bleed %.3g codes\n\n",
                padding, t.width, t.height, double(t.png_scale), t.levels[0].anywhere_code);
    std::printf("| level | side | bleed, worst (codes) | bleed, worst (relative) | texels with bleed >= 1 code | vs level 0, worst (codes) |\n");
    std::printf("|---:|---:|---:|---:|---:|---:|\n");
    for (const test::MipLevelBleed& l : t.levels)
      std::printf("| %d | %d | %.1f | %.1f%% | %.2f%% | %.1f |\n", l.level, l.side, l.worst_code, 100 * l.worst_relative,
                  100 * l.share_visible, l.worst_code_vs_level0);
  }
  return 0;
}
