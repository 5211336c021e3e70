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

// A building's sunlit outside (1000 cd/m2) is 60% of its lit area; the camera a display file
// opens on stands inside, where it sees the rooms (10 cd/m2) and a little of the outside through
// a window. Metered on what that camera sees, the rooms show at the key and the window is the
// share allowed to clip; metered on the area, the outside set the exposure and the rooms were
// 100 times too dark.
TEST(Exposure, MetersWhatTheDisplayCameraSees) {
  const LightmapPage page = page_of(1000, 0, 600, 1000);
  std::vector<std::vector<float>> seen{std::vector<float>(1000, 0.0f)};
  for (size_t i = 0; i < 400; ++i) seen[0][i] = 3;  // the rooms: 1200 rays
  seen[0][999] = 12;                               // the window: 1% of the rays
  const Exposure inside = choose_exposure({page}, {}, &seen);
  EXPECT_TRUE(inside.metered_view);
  EXPECT_FALSE(inside.limited_by_highlights);
  EXPECT_FLOAT_EQ(inside.exposure, 0.18f / 10);
  EXPECT_NE(inside.method.find("what the display camera sees"), std::string::npos) << inside.method;
  const Exposure area = choose_exposure({page}, {});
  EXPECT_FALSE(area.metered_view);
  EXPECT_FLOAT_EQ(area.exposure, 0.18f / 1000);
  // The outside through more of the view (10% of the rays): it sets the exposure, clipping on no
  // more than 2% of what is seen.
  seen[0][999] = 0;
  for (size_t i = 900; i < 1000; ++i) seen[0][i] = 1.34f;  // 134 of 1334 rays
  const Exposure window = choose_exposure({page}, {}, &seen);
  EXPECT_TRUE(window.limited_by_highlights);
  EXPECT_FLOAT_EQ(window.exposure, 1.0f / 1000);
  // A camera that sees no surface leaves the area metered.
  const std::vector<std::vector<float>> nothing{std::vector<float>(1000, 0.0f)};
  EXPECT_FLOAT_EQ(choose_exposure({page}, {}, &nothing).exposure, area.exposure);
}

}  // namespace
}  // namespace radbake
