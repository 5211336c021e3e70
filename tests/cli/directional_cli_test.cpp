// `radbake bake --directional sh|dominant --probes`: the files, what the glTF says of
// them, and that the packed PNG pages decode to the EXR pages' values.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "io/lightmaps/lightmap_images.h"
#include "support/commands.h"
#include "support/images.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

namespace fs = std::filesystem;

std::vector<uint8_t> png_bytes(const std::string& path, int& width, int& height) {
  std::vector<uint8_t> pixels = test::read_png_rgb(path, &width, &height);
  EXPECT_FALSE(pixels.empty()) << path;
  return pixels;
}

TEST(DirectionalCli, ShPagesAndProbesAreWrittenDescribedAndDecodeToTheirValues) {
  const std::string out = test::fresh_folder("directional_cli") + "/out";
  const test::Outcome r = test::radbake("bake " + test::source_path("samples/cornell_box/cornell_box.gltf") + " -o " + out +
                                        " --max-page-size 128 --quiet --directional sh --probes auto");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json gltf = nlohmann::json::parse(test::slurp(out + "/cornell_box.gltf"));
  const nlohmann::json& d = gltf["extras"]["radbake"]["directional"];
  EXPECT_EQ(d["mode"], "sh");
  ASSERT_EQ(d["pages"].size(), 4u);
  const char* names[] = {"sh_c0", "sh_c1x", "sh_c1y", "sh_c1z"};
  for (size_t k = 0; k < 4; ++k) {
    const nlohmann::json& set = d["pages"][k];
    EXPECT_EQ(set["coefficient"], names[k]);
    const float scale = set["png_scale"], offset = set["png_offset"];
    const LightmapPage exr = read_lightmap_exr(out + "/" + set["exr"][0].get<std::string>());
    int w = 0, h = 0;
    const std::vector<uint8_t> png = png_bytes(out + "/" + set["png"][0].get<std::string>(), w, h);
    ASSERT_EQ(w, exr.width);
    ASSERT_EQ(h, exr.height);
    size_t compared = 0;
    for (size_t t = 0; t < exr.texels.size(); ++t)
      for (int c = 0; c < 3; ++c) {
        const float value = exr.texels[t][c];
        if (value < offset || value > offset + scale) continue;  // clipped in the PNG (a few by the lamp)
        // Within half an 8-bit step of the range (and a thousandth of it for float rounding), plus
        // the EXR's half-float rounding.
        EXPECT_NEAR(offset + scale * png[3 * t + size_t(c)] / 255.0f, value,
                    0.5005f * scale / 255 + 1e-3f * std::fabs(value))
            << names[k] << " texel " << t;
        ++compared;
      }
    EXPECT_GT(compared, exr.texels.size() * 3 * 9 / 10) << names[k];  // nearly all within the range
  }
  // The probes: the file, the glTF's extras and the report agree.
  const nlohmann::json probes = nlohmann::json::parse(test::slurp(out + "/cornell_box_probes.json"));
  EXPECT_GT(probes["count"].get<int>(), 100);
  EXPECT_EQ(probes["probes"].size(), probes["count"].get<size_t>());
  EXPECT_EQ(probes["probes"][0]["sh"].size(), 9u);
  EXPECT_EQ(gltf["extras"]["radbake"]["probes"]["count"], probes["count"]);
  EXPECT_EQ(gltf["extras"]["radbake"]["probes"]["file"], "cornell_box_probes.json");
  const nlohmann::json report = nlohmann::json::parse(test::slurp(out + "/report.json"));
  EXPECT_EQ(report["light_probes"]["count"], probes["count"]);
  // And the Khronos validator finds no error or warning in the glTF that describes them.
  const test::Outcome v =
      test::run("node " + test::source_path("tests/tools/validate_gltf.mjs") + " " + out + "/cornell_box.gltf");
  ASSERT_EQ(v.status, 0) << v.out << v.err;
  const nlohmann::json summary = nlohmann::json::parse(v.out);
  EXPECT_EQ(summary["errors"], 0) << v.out;
  EXPECT_EQ(summary["warnings"], 0) << v.out;
}

TEST(DirectionalCli, DominantWritesOneDirectionPageAndBadValuesAreRefused) {
  const std::string parent = test::fresh_folder("directional_cli_dominant");
  const std::string scene = test::source_path("samples/cornell_box/cornell_box.gltf");
  const test::Outcome r = test::radbake("bake " + scene + " -o " + parent + "/out --max-page-size 64 --quiet --directional dominant");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json gltf = nlohmann::json::parse(test::slurp(parent + "/out/cornell_box.gltf"));
  const nlohmann::json& d = gltf["extras"]["radbake"]["directional"];
  EXPECT_EQ(d["mode"], "dominant");
  ASSERT_EQ(d["pages"].size(), 1u);
  const LightmapPage page = read_lightmap_exr(parent + "/out/" + d["pages"][0]["exr"][0].get<std::string>());
  // Directions of length at most 1 (half-float rounding aside), pointing somewhere for lit texels.
  size_t lit = 0;
  for (size_t t = 0; t < page.texels.size(); ++t) {
    EXPECT_LE(length(page.texels[t]), 1.001f) << t;
    lit += length(page.texels[t]) > 0.1f;
  }
  EXPECT_GT(lit, page.texels.size() / 2);
  test::expect_one_line_refusal(test::radbake("bake " + scene + " -o " + parent + "/bad --directional up"),
                                "--directional must be none, sh or dominant", parent + "/bad");
  test::expect_one_line_refusal(test::radbake("bake " + scene + " -o " + parent + "/bad --probes -1"),
                                "--probes", parent + "/bad");
  test::expect_one_line_refusal(test::radbake("bake " + scene + " -o " + parent + "/bad --directional sh --store radiosity"),
                                "directional lightmaps are of the radiosity bake's irradiance", parent + "/bad");
}

}  // namespace
}  // namespace radbake
