// `radbake diff` as a test script sees it: exit status 0 when the thresholds hold, 1 when one is
// exceeded (named on stderr), 2 with one error line for anything that cannot be compared.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

#include "io/lightmaps/lightmap_images.h"
#include "support/commands.h"
#include "support/images.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

using test::Outcome;
using test::radbake;

// A bake folder as radbake writes it, as far as `diff` reads it: pages of one value each.
std::string bake_folder(const std::string& name, const std::vector<std::pair<int, float>>& pages,
                        const std::string& quantity = "irradiance", const std::string& unit = "lx") {
  std::string folder = test::fresh_folder(name);
  for (size_t p = 0; p < pages.size(); ++p) {
    LightmapPage page;
    page.width = page.height = pages[p].first;
    page.texels.assign(size_t(page.width) * size_t(page.height), Rgb{1, 1, 1} * pages[p].second);
    page.valid.assign(page.texels.size(), 1);
    write_exr(folder + "/room_lightmap_" + std::to_string(p) + ".exr", page);
  }
  std::ofstream(folder + "/report.json")
      << nlohmann::json{{"lightmaps", {{"quantity", quantity}, {"unit", unit}}}}.dump();
  return folder;
}

size_t lines(const std::string& text) { return size_t(std::count(text.begin(), text.end(), '\n')); }

TEST(Diff, ABakeAgainstItselfDiffersByNothing) {
  std::string a = bake_folder("diff_same", {{8, 100}, {4, 50}});
  Outcome r = radbake("diff " + a + " " + a + " --max-rmse 0 --max-error 0");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_NE(r.out.find("0.00%"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  all "), std::string::npos) << r.out;  // two pages: a line for both together
}

TEST(Diff, ExceededThresholdsExitOneAndAreNamed) {
  // B is 10% (10 lux) brighter than A everywhere.
  std::string a = bake_folder("diff_a", {{8, 100}}), b = bake_folder("diff_b", {{8, 110}});
  Outcome holds = radbake("diff " + a + " " + b + " --max-rmse 10.5 --max-p50 11 --max-p99 11 --max-error 10.5");
  EXPECT_EQ(holds.status, 0) << holds.err;
  EXPECT_NE(holds.out.find("rmse  10%, limit 10.5%: ok"), std::string::npos) << holds.out;

  Outcome exceeded = radbake("diff " + a + " " + b + " --max-rmse 5 --max-p99 11 --max-error 2");
  EXPECT_EQ(exceeded.status, 1);
  EXPECT_EQ(exceeded.err,
            "radbake: diff: rmse 10% exceeds --max-rmse 5%\n"
            "radbake: diff: error 10 lx exceeds --max-error 2 lx\n");
  EXPECT_NE(exceeded.out.find("EXCEEDED"), std::string::npos);
}

TEST(Diff, JsonHoldsTheStatisticsAndTheVerdict) {
  std::string a = bake_folder("diff_json_a", {{8, 100}}), b = bake_folder("diff_json_b", {{8, 110}});
  Outcome r = radbake("diff " + a + " " + b + " --json --max-p95 5");
  EXPECT_EQ(r.status, 1);
  nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["unit"], "lx");
  EXPECT_EQ(j["pages"][0]["texels"], 64);
  // The page values are exact in half float, so only double rounding remains.
  EXPECT_NEAR(j["all"]["rmse_percent"].get<double>(), 10, 1e-6);
  EXPECT_NEAR(j["all"]["max_error"].get<double>(), 10, 1e-6);
  EXPECT_EQ(j["checks"][0]["name"], "p95");
  EXPECT_TRUE(j["checks"][0]["exceeded"].get<bool>());
  EXPECT_FALSE(j["passed"].get<bool>());
}

TEST(Diff, DifferenceImagesShowWhereAndWhichWay) {
  std::string a = bake_folder("diff_image_a", {{8, 100}, {4, 100}}), b = bake_folder("diff_image_b", {{8, 110}, {4, 90}});
  std::string images = test::fresh_folder("diff_images") + "/new";  // created by radbake
  Outcome r = radbake("diff " + a + " " + b + " --diff-images " + images);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("full colour at 10%"), std::string::npos) << r.out;  // the scale is stated
  const std::pair<const char*, std::vector<uint8_t>> expected[] = {{"/room_lightmap_0_diff.png", {255, 0, 0}},
                                                                   {"/room_lightmap_1_diff.png", {0, 0, 255}}};
  for (const auto& [file, colour] : expected) {
    const std::vector<uint8_t> px = test::read_png_rgb(images + file);
    ASSERT_GE(px.size(), 3u) << file;
    EXPECT_EQ(std::vector<uint8_t>(px.begin(), px.begin() + 3), colour) << file;
  }
}

// A folder whose one page, x_lightmap_0.exr, `make` puts there.
std::string folder_with_page(const std::string& folder, const std::function<void(const std::string&)>& make) {
  std::filesystem::create_directories(folder);
  make(folder + "/x_lightmap_0.exr");
  return folder;
}

// A copy of `bake`'s page 0 whose header claims width x height texels (its data and display
// windows rewritten; the pixels stay 8 x 8).
std::string page_claiming(const std::string& bake, const std::string& parent, int32_t width, int32_t height) {
  std::ifstream in(bake + "/room_lightmap_0.exr", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const std::string attribute : {"dataWindow", "displayWindow"}) {
    const size_t at = bytes.find(attribute + std::string("\0box2i\0", 7));
    EXPECT_NE(at, std::string::npos) << attribute;
    if (at == std::string::npos) continue;
    const int32_t box[4] = {0, 0, width - 1, height - 1};
    std::memcpy(&bytes[at + attribute.size() + 7 + 4], box, sizeof box);  // after the name, the type and the size
  }
  std::filesystem::create_directories(parent + "/huge");
  const std::string out = parent + "/huge/huge_lightmap_0.exr";
  std::ofstream(out, std::ios::binary) << bytes;
  return out;
}

class DiffBadInput : public ::testing::TestWithParam<std::pair<std::string, std::string>> {};

TEST_P(DiffBadInput, ExitsTwoWithOneErrorLine) {
  std::string parent = test::fresh_folder("diff_bad_" + GetParam().first);
  // A folder per case: ctest runs the cases in parallel, and a shared one was remade under another.
  const std::string a = bake_folder("diff_bad_a_" + GetParam().first, {{8, 100}});
  std::ofstream(parent + "/junk_lightmap_0.exr") << "not an image";
  // Made only for the case that runs: another case's folders are remade by its own process.
  const std::string other = parent + "/other";
  const std::map<std::string, std::function<std::string()>> args = {
      {"missing", [&] { return a + " " + parent + "/nothing"; }},
      {"unreadable", [&] { return a + " " + parent; }},
      {"unknown_option", [&] { return a + " " + a + " --max-rsme 3"; }},
      {"bad_number", [&] { return a + " " + a + " --max-rmse three"; }},
      {"one_bake", [&] { return a; }},
      {"three_bakes", [&] { return a + " " + a + " " + a; }},
      {"page_size", [&] { return a + " " + bake_folder("diff_bad_size", {{16, 100}}); }},
      {"page_count", [&] { return a + " " + bake_folder("diff_bad_count", {{8, 100}, {8, 100}}); }},
      {"quantity", [&] { return a + " " + bake_folder("diff_bad_other_quantity", {{8, 100}}, "radiosity", "lm/m2"); }},
      // Each of these once took diff down (std::bad_alloc) or hung it.
      {"huge_header", [&] { return a + " " + page_claiming(a, parent, 65536, 65536); }},
      {"dev_zero", [&] { return a + " /dev/zero"; }},
      {"fifo", [&] { return a + " " + test::make_fifo(parent + "/pipe.exr"); }},
      {"fifo_page", [&] { return a + " " + folder_with_page(other, [](const std::string& page) { test::make_fifo(page); }); }},
      {"link_to_dev_zero", [&] {
         return a + " " + folder_with_page(other, [](const std::string& page) {
                  std::filesystem::create_symlink("/dev/zero", page);
                });
       }},
      {"link_to_fifo", [&] {
         return a + " " + folder_with_page(other, [&](const std::string& page) {
                  std::filesystem::create_symlink(test::make_fifo(parent + "/another_pipe"), page);
                });
       }},
  };
  Outcome r = radbake("diff " + args.at(GetParam().first)());
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("radbake: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(GetParam().second), std::string::npos) << r.err;
  EXPECT_EQ(lines(r.err), 1u) << r.err;
  EXPECT_EQ(r.out, "");
}

INSTANTIATE_TEST_SUITE_P(
    Cases, DiffBadInput,
    ::testing::Values(std::make_pair("missing", "nothing does not exist"),
                      std::make_pair("unreadable", "junk_lightmap_0.exr is not an OpenEXR lightmap page (no OpenEXR signature)"),
                      std::make_pair("unknown_option", "unknown option --max-rsme"),
                      std::make_pair("bad_number", "--max-rmse needs a number"),
                      std::make_pair("one_bake", "missing bakes to compare"),
                      std::make_pair("three_bakes", "unexpected argument"),
                      std::make_pair("page_size", "page 0 is 8x8 in the reference but 16x16 in the other bake"),
                      std::make_pair("page_count", "different page counts: 1 in the reference, 2 in the other bake"),
                      std::make_pair("quantity", "holds irradiance (lx) but"),
                      std::make_pair("huge_header", "claims 65536 x 65536 texels; radbake's lightmap pages are 1 to 16384"),
                      std::make_pair("dev_zero", "'/dev/zero' is not a regular file"),
                      std::make_pair("fifo", "pipe.exr' is not a regular file"),
                      std::make_pair("fifo_page", "x_lightmap_0.exr' is not a regular file"),
                      std::make_pair("link_to_dev_zero", "x_lightmap_0.exr' is not a regular file"),
                      std::make_pair("link_to_fifo", "x_lightmap_0.exr' is not a regular file")),
    [](const auto& info) { return info.param.first; });

TEST(Diff, HelpDefinesTheStatistics) {
  Outcome r = radbake("diff --help");
  EXPECT_EQ(r.status, 0);
  for (const char* text : {"radbake diff A B", "--max-rmse PCT", "--max-p50 PCT", "--max-error X", "--diff-images DIR",
                           "zero in both bakes", "mean of |B - A| over R, G, B", "max(A, floor)"})
    EXPECT_NE(r.out.find(text), std::string::npos) << text;
}

}  // namespace
}  // namespace radbake
