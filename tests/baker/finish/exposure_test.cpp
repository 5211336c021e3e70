// The automatic exposure meters the lit surface: black texels do not move it, the median lit
// luminance shows at the key, and highlights clip on no more than the share allowed.
#include <gtest/gtest.h>

#include <algorithm>

#include "baker/finish/exposure.h"

namespace radbake {
namespace {

// One page of `n` texels: `black` at 0 cd/m2, `bright` at `bright_level`, the rest grey at 10.
LightmapPage page_of(size_t n, size_t black, size_t bright, float bright_level) {
  LightmapPage page;
  page.width = int(n), page.height = 1;
  page.texels.assign(n, Rgb{10, 10, 10});
  page.valid.assign(n, 1);
  for (size_t i = 0; i < black; ++i) page.texels[i] = Rgb{0, 0, 0};
  for (size_t i = 0; i < bright; ++i) page.texels[n - 1 - i] = Rgb{bright_level, bright_level, bright_level};
  return page;
}

double clipped_share_of_lit(const LightmapPage& page, float exposure) {
  size_t lit = 0, clipped = 0;
  for (const Rgb& c : page.texels) {
    if (c.x <= 0) continue;
    ++lit;
    clipped += std::max({c.x, c.y, c.z}) * exposure > 1.0f + 1e-6f;  // 1e-6: 1/x * x in float
  }
  return double(clipped) / double(lit);
}

TEST(Exposure, BlackTexelsDoNotMoveTheMeter) {
  // The engine case: 14% of texels exactly 0. A log-mean would be pulled towards 0 and the
  // exposure towards infinity; the lit median is the same whatever the black share.
  const Exposure none = choose_exposure({page_of(1000, 0, 0, 0)}, {});
  const Exposure some = choose_exposure({page_of(1000, 140, 0, 0)}, {});
  const Exposure most = choose_exposure({page_of(1000, 900, 0, 0)}, {});
  EXPECT_FLOAT_EQ(none.exposure, 0.18f / 10);  // the median lit surface (10 cd/m2) at the key
  EXPECT_FLOAT_EQ(some.exposure, none.exposure);
  EXPECT_FLOAT_EQ(most.exposure, none.exposure);
  EXPECT_NEAR(some.lit_share, 0.86, 1e-9);
  EXPECT_FALSE(some.limited_by_highlights);
  EXPECT_NE(some.method.find("median"), std::string::npos);
}

TEST(Exposure, HighlightsClipOnNoMoreThanTheShareAllowed) {
  // 5% of the surface 100 times brighter than the rest: at the key they would clip (10 * 100 *
  // 0.018 = 18), so the exposure drops until at most 2% of the lit area clips.
  const LightmapPage page = page_of(1000, 0, 50, 1000);
  const Exposure e = choose_exposure({page}, {});
  EXPECT_TRUE(e.limited_by_highlights);
  EXPECT_LE(clipped_share_of_lit(page, e.exposure), ExposureOptions{}.max_clipped_share);
  EXPECT_LT(e.exposure, 0.18f / 10);
  // A lamp on 1.5% of the area is allowed to clip: the rest stays at the key.
  const LightmapPage lamp = page_of(1000, 0, 15, 1000);
  const Exposure at_key = choose_exposure({lamp}, {});
  EXPECT_FALSE(at_key.limited_by_highlights);
  EXPECT_FLOAT_EQ(at_key.exposure, 0.18f / 10);
}

TEST(Exposure, UncoveredTexelsAndGivenExposures) {
  LightmapPage page = page_of(100, 0, 0, 0);
  for (size_t i = 0; i < 50; ++i) page.texels[i] = Rgb{1e6f, 1e6f, 1e6f}, page.valid[i] = 0;  // padding, dilated
  EXPECT_FLOAT_EQ(choose_exposure({page}, {}).exposure, 0.018f);
  ExposureOptions given;
  given.exposure = 3;
  const Exposure e = choose_exposure({page}, given);
  EXPECT_FLOAT_EQ(e.exposure, 3);
  EXPECT_FALSE(e.automatic);
  // Nothing lit at all: a neutral 1 per cd/m2, said so.
  const Exposure dark = choose_exposure({page_of(10, 10, 0, 0)}, {});
  EXPECT_FLOAT_EQ(dark.exposure, 1);
  EXPECT_NE(dark.method.find("nothing is lit"), std::string::npos);
}

}  // namespace
}  // namespace radbake
