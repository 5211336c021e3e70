// Lightmap EXR pages keep the baked values: half float where that is exact enough, full float
// where half would overflow (daylight illuminance passes 65504 lux).
#include <gtest/gtest.h>

#include "io/lightmaps/lightmap_images.h"
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

}  // namespace
}  // namespace radbake
