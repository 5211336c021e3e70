// Lightmap EXR pages keep the baked values: half float where that is exact enough, full float
// where half would overflow (daylight illuminance passes 65504 lux). Every page is written in
// every encoding of page_encodings(), under the names LightmapFiles gives, and each file reads
// back as the page: the seam a new encoding plugs into. Directional pages go through the same
// encodings, their 8-bit files packed linearly.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "io/lightmaps/directional_outputs.h"
#include "io/lightmaps/lightmap_images.h"
#include "io/lightmaps/page_encodings.h"
#include "support/images.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

LightmapPage page_with(Rgb value) {
  LightmapPage page;
  page.width = page.height = 4;
  page.texels.assign(16, value);
  page.valid.assign(16, 1);
  return page;
}

TEST(LightmapImages, InteriorValuesAreHalfFloat) {
  std::string path = test::fresh_folder("exr_half") + "/page.exr";
  write_exr(path, page_with({500.0f, 250.0f, 12.5f}));
  EXPECT_EQ(test::exr_storage(path), test::ExrStorage::Half);
  LightmapPage back = read_lightmap_exr(path);
  EXPECT_FLOAT_EQ(back.texels[5].x, 500.0f);  // exactly representable in half
}

TEST(LightmapImages, DaylightValuesAreFullFloatNotInfinity) {
  std::string path = test::fresh_folder("exr_float") + "/page.exr";
  write_exr(path, page_with({110000.0f, 98765.4f, 70000.0f}));
  EXPECT_EQ(test::exr_storage(path), test::ExrStorage::Float);
  LightmapPage back = read_lightmap_exr(path);
  EXPECT_FLOAT_EQ(back.texels[5].x, 110000.0f);
  EXPECT_FLOAT_EQ(back.texels[5].y, 98765.4f);
}

TEST(PageEncodings, EveryPageInEveryEncodingUnderItsNameReadsBack) {
  const std::string folder = test::fresh_folder("page_encodings");
  const std::vector<LightmapPage> pages = {page_with({100, 50, 25}), page_with({200, 200, 200})};
  const LightmapFiles files = write_lightmaps(pages, folder, "scene", "irradiance", "lx", 200.0f);
  ASSERT_EQ(files.files.size(), pages.size());
  ASSERT_GE(page_encodings().size(), 2u);
  for (size_t p = 0; p < pages.size(); ++p) {
    ASSERT_EQ(files.files[p].size(), page_encodings().size());
    for (size_t k = 0; k < page_encodings().size(); ++k) {
      EXPECT_EQ(files.files[p][k], "scene_lightmap_" + std::to_string(p) + page_encodings()[k].extension);
      EXPECT_TRUE(std::filesystem::is_regular_file(folder + "/" + files.files[p][k])) << files.files[p][k];
    }
    EXPECT_EQ(files.texture(p), "scene_lightmap_" + std::to_string(p) + ".png");
    // The EXR holds the lux themselves (exact in half float here); the PNG the sRGB encoding of
    // lux / 200, to its 8 bits (half a step of 255).
    const LightmapPage exr = read_lightmap_exr(folder + "/scene_lightmap_" + std::to_string(p) + ".exr");
    EXPECT_FLOAT_EQ(exr.texels[5].x, pages[p].texels[5].x);
    EXPECT_FLOAT_EQ(exr.texels[5].z, pages[p].texels[5].z);
    const std::vector<uint8_t> png = test::read_png_rgb(folder + "/" + files.texture(p));
    ASSERT_EQ(png.size(), 16u * 3);
    for (int c = 0; c < 3; ++c) {
      const double linear = pages[p].texels[5][c] / 200.0;
      const double srgb = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
      EXPECT_NEAR(png[5 * 3 + size_t(c)], 255 * srgb, 0.5 + 1e-6) << "page " << p << ", channel " << c;
    }
  }
}

// A dominant-direction page (components in [-1, 1]) in every encoding: the EXR holds the
// components, the PNG (value + 1) / 2 in 8 linear bits, no sRGB curve.
TEST(PageEncodings, DirectionalPagesAreWrittenInEveryEncodingTheirPngLinear) {
  const std::string folder = test::fresh_folder("directional_encodings");
  const std::vector<std::vector<LightmapPage>> sets = {{page_with({0.5f, -0.5f, 0.0f})}};
  const DirectionalFiles files = write_directional(Directional::Dominant, sets, folder, "scene");
  ASSERT_EQ(files.sets.size(), 1u);
  const DirectionalSet& set = files.sets[0];
  EXPECT_FLOAT_EQ(set.scale, 2.0f);
  EXPECT_FLOAT_EQ(set.offset, -1.0f);
  ASSERT_EQ(set.files.size(), 1u);
  ASSERT_EQ(set.files[0].size(), page_encodings().size());
  for (size_t k = 0; k < page_encodings().size(); ++k) {
    EXPECT_EQ(set.files[0][k], "scene_dominant_direction_0" + page_encodings()[k].extension);
    EXPECT_TRUE(std::filesystem::is_regular_file(folder + "/" + set.files[0][k])) << set.files[0][k];
  }
  const LightmapPage exr = read_lightmap_exr(folder + "/scene_dominant_direction_0.exr");
  EXPECT_FLOAT_EQ(exr.texels[5].x, 0.5f);
  EXPECT_FLOAT_EQ(exr.texels[5].y, -0.5f);
  const std::vector<uint8_t> png = test::read_png_rgb(folder + "/scene_dominant_direction_0.png");
  ASSERT_EQ(png.size(), 16u * 3);
  // 255 * (value + 1) / 2 rounded: 191.25, 63.75 and 127.5; an sRGB curve would give 225, 137, 188.
  EXPECT_EQ(png[5 * 3 + 0], 191);
  EXPECT_EQ(png[5 * 3 + 1], 64);
  EXPECT_EQ(png[5 * 3 + 2], 128);
}

}  // namespace
}  // namespace radbake
