// Reading a bake back for `radbake diff`: an EXR page, or an output folder's pages by index, with
// the quantity and unit its report.json names; anything else is an InputError that says why.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "base/errors.h"
#include "io/lightmaps/bake_lightmaps.h"
#include "io/lightmaps/lightmap_images.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

LightmapPage page_of(int width, Rgb value) {
  LightmapPage page;
  page.width = page.height = width;
  page.texels.assign(size_t(width) * size_t(width), value);
  page.valid.assign(page.texels.size(), 1);
  return page;
}

void write_report(const std::string& folder, const std::string& lightmaps) {
  std::ofstream(folder + "/report.json") << R"({"generator": "radbake", "lightmaps": )" << lightmaps << "}";
}

std::string error_reading(const std::string& path) {
  try {
    read_bake_lightmaps(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(BakeLightmaps, AFolderGivesItsPagesByIndexAndItsUnit) {
  std::string folder = test::fresh_folder("bake_lightmaps_folder");
  // Written out of order, with the PNGs and glTF a bake leaves beside them.
  write_exr(folder + "/room_lightmap_1.exr", page_of(8, {2, 2, 2}));
  write_exr(folder + "/room_lightmap_0.exr", page_of(4, {1, 1, 1}));
  std::ofstream(folder + "/room_lightmap_0.png") << "not read";
  std::ofstream(folder + "/room.gltf") << "{}";
  write_report(folder, R"({"quantity": "radiosity", "unit": "lm/m2"})");
  BakeLightmaps bake = read_bake_lightmaps(folder);
  ASSERT_EQ(bake.pages.size(), 2u);
  EXPECT_EQ(bake.pages[0].width, 4);
  EXPECT_EQ(bake.pages[1].width, 8);
  EXPECT_EQ(bake.pages[1].texels[0].x, 2.0f);
  EXPECT_EQ(bake.files[1], folder + "/room_lightmap_1.exr");
  EXPECT_EQ(bake.quantity, "radiosity");
  EXPECT_EQ(bake.unit, "lm/m2");
}

TEST(BakeLightmaps, APageAloneIsReadAsIrradianceInLux) {
  std::string folder = test::fresh_folder("bake_lightmaps_page");
  write_exr(folder + "/page.exr", page_of(4, {3, 3, 3}));
  BakeLightmaps bake = read_bake_lightmaps(folder + "/page.exr");
  ASSERT_EQ(bake.pages.size(), 1u);
  EXPECT_EQ(bake.pages[0].texels[5].y, 3.0f);
  EXPECT_EQ(bake.unit, "lx");
  // A page inside a bake's folder takes the folder's report.
  write_report(folder, R"({"quantity": "radiosity", "unit": "lm/m2"})");
  EXPECT_EQ(read_bake_lightmaps(folder + "/page.exr").unit, "lm/m2");
}

TEST(BakeLightmaps, WhatCannotBeComparedSaysWhy) {
  std::string folder = test::fresh_folder("bake_lightmaps_bad");
  EXPECT_NE(error_reading(folder + "/nothing").find("does not exist"), std::string::npos);
  EXPECT_NE(error_reading(folder).find("holds no lightmap pages"), std::string::npos);

  write_exr(folder + "/room_lightmap_0.exr", page_of(4, {1, 1, 1}));
  write_exr(folder + "/room_lightmap_2.exr", page_of(4, {1, 1, 1}));
  EXPECT_NE(error_reading(folder).find("has no page 1 (room_lightmap_1.exr)"), std::string::npos) << error_reading(folder);

  write_exr(folder + "/room_lightmap_1.exr", page_of(4, {1, 1, 1}));
  write_exr(folder + "/hall_lightmap_0.exr", page_of(4, {1, 1, 1}));
  EXPECT_NE(error_reading(folder).find("more than one bake"), std::string::npos);
  std::filesystem::remove(folder + "/hall_lightmap_0.exr");

  std::ofstream(folder + "/room_lightmap_1.exr") << "not an image";
  EXPECT_NE(error_reading(folder).find(folder + "/room_lightmap_1.exr is not an OpenEXR lightmap page (no OpenEXR signature)"),
            std::string::npos) << error_reading(folder);
  // Cut short after its header: OpenEXR's own words stay out of the message.
  write_exr(folder + "/room_lightmap_1.exr", page_of(64, {1, 1, 1}));
  std::filesystem::resize_file(folder + "/room_lightmap_1.exr", std::filesystem::file_size(folder + "/room_lightmap_1.exr") / 2);
  EXPECT_EQ(error_reading(folder), "cannot read " + folder + "/room_lightmap_1.exr: its pixels are damaged or cut short");
  write_exr(folder + "/room_lightmap_1.exr", page_of(4, {1, 1, 1}));

  std::ofstream(folder + "/report.json") << "{ truncated";
  EXPECT_NE(error_reading(folder).find("is not a radbake report"), std::string::npos);
  write_report(folder, R"({"quantity": "irradiance"})");
  EXPECT_NE(error_reading(folder).find("is not a radbake report"), std::string::npos);
  write_report(folder, R"({"quantity": "irradiance", "unit": "lx"})");
  EXPECT_EQ(error_reading(folder), "no error");
}

}  // namespace
}  // namespace radbake
