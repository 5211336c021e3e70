// Hostile option values and inputs: each is refused before anything is read or
// written, with one `radbake: error:` line that names the option and what it allows, exit 2.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <string>

#include "support/commands.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

namespace fs = std::filesystem;

struct BadOption {
  const char* name;   // the case, for the test's name
  std::string args;   // after `bake SCENE -o OUTDIR`
  const char* says;   // in the error line
};

class BadOptionValue : public ::testing::TestWithParam<BadOption> {};

TEST_P(BadOptionValue, IsOneLineNamingTheOptionAndExitsTwo) {
  const std::string parent = test::fresh_folder(std::string("cli_option_") + GetParam().name);
  test::Outcome r = test::radbake("bake " + test::source_path("tests/fixtures/lit_room.glb") + " -o " + parent + "/out " +
                                  GetParam().args);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err.rfind("radbake: error: option ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(GetParam().says), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_LT(r.err.size(), 200u) << r.err;  // a huge value is not echoed whole
  EXPECT_FALSE(fs::exists(parent + "/out"));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BadOptionValue,
    ::testing::Values(
        BadOption{"patch_size_not_a_power_of_two", "--patch-size 3", "--patch-size must be 0 (auto) or a power of two"},
        BadOption{"patch_size_negative", "--patch-size -4", "--patch-size must be between 0 and 16384"},
        BadOption{"gather_rays_zero", "--gather-rays 0", "--gather-rays must be between 1 and 1048576, got '0'"},
        BadOption{"emission_scale_zero", "--emission-scale 0", "--emission-scale must be between 1e-06 and 1000000000"},
        BadOption{"emission_scale_negative", "--emission-scale -683", "--emission-scale must be between"},
        BadOption{"density_nan", "--density nan", "--density needs a number, got 'nan'"},
        BadOption{"density_infinite", "--density inf", "--density must be between"},
        BadOption{"density_zero", "--density 0", "--density must be between 1e-06"},
        BadOption{"tolerance_zero", "--tolerance 0", "--tolerance must be between 1e-09 and 1"},
        BadOption{"tolerance_not_a_number", "--tolerance 1%", "--tolerance needs a number, got '1%'"},
        BadOption{"threads_negative", "--threads -2", "--threads must be between 0 and 1024"},
        BadOption{"threads_fraction", "--threads 1.5", "--threads needs a whole number"},
        BadOption{"seed_too_large", "--seed 1e300", "--seed must be between 0 and 9007199254740992"},
        BadOption{"max_page_size_small", "--max-page-size 8", "--max-page-size must be between 16 and 16384"},
        BadOption{"padding_overflows_a_double", "--padding 1e999", "--padding must be between 0 and 64"},
        BadOption{"padding_huge_text", "--padding " + std::string(100000, '9'), "--padding must be between 0 and 64, got '999"},
        BadOption{"chart_angle_zero", "--chart-angle 0", "--chart-angle must be between 1 and 89"},
        BadOption{"patch_rays_few", "--patch-rays 8", "--patch-rays must be between 16"},
        BadOption{"hemicube_resolution_odd", "--hemicube-resolution 7", "--hemicube-resolution must be even"},
        BadOption{"subdivide_negative", "--subdivide -0.1", "--subdivide must be between 0 and 10"},
        BadOption{"subdivide_rounds_zero", "--subdivide-rounds 0", "--subdivide-rounds must be between 1 and 12"},
        BadOption{"preview_every_negative", "--preview-every -1", "--preview-every must be between 0"},
        BadOption{"area_light_rays_zero", "--area-light-rays 0", "--area-light-rays must be between 1 and 65536"},
        BadOption{"light_rays_zero", "--light-rays 0", "--light-rays must be between 1 and 65536"},
        BadOption{"png_scale_zero", "--png-scale 0", "--png-scale must be between"},
        BadOption{"empty_value", "--threads=", "--threads needs a number, got ''"},
        BadOption{"unknown_word", "--solver fastest", "--solver must be shooting, gauss-seidel or jacobi, got 'fastest'"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(CliInput, AFifoIsNotAFileNotAMissingOne) {
  const std::string parent = test::fresh_folder("cli_fifo");
  const std::string fifo = parent + "/scene.gltf";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  test::Outcome r = test::radbake("bake " + fifo + " -o " + parent + "/out");  // must not block on the pipe
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("scene.gltf: not a regular file"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("no such file"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(parent + "/out"));
}

TEST(CliInput, AHugePathIsClippedInTheErrorLine) {
  const std::string parent = test::fresh_folder("cli_long_path");
  const std::string path = parent + "/" + std::string(200, 'd') + "/" + std::string(200, 'e') + "/scene.gltf";
  test::Outcome r = test::radbake("bake " + path + " -o " + parent + "/out");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("ddd...eee"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("eee/scene.gltf: no such file"), std::string::npos) << r.err;
  EXPECT_LT(r.err.size(), 160u) << r.err;
}

TEST(CliInput, AHugeUriQuotedInTheErrorLineIsClipped) {
  // A 1.2 MB URI of a scheme radbake does not read: the message quotes it, clipped.
  const std::string uri = "https://example.invalid/" + std::string(1200000, 'x');
  const std::string scene = test::write_text_file(
      "huge_data_uri.gltf", R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 5, "uri": ")" + uri + R"("}]})");
  test::Outcome r = test::radbake("bake " + scene + " -o " + test::fresh_folder("cli_huge_uri") + "/out");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("/buffers/0/uri: URI 'https://example.invalid/xxx"), std::string::npos) << r.err.substr(0, 400);
  EXPECT_NE(r.err.find("..."), std::string::npos) << r.err.substr(0, 400);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
  EXPECT_LT(r.err.size(), 500u);
}

}  // namespace
}  // namespace radbake
