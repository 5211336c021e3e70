// The radbake command as a pipeline sees it: exit statuses, one-line errors, nothing half-written,
// progress on stderr, and output that the Khronos glTF-Validator accepts.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "io/gltf/gltf_loader.h"
#include "support/commands.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

namespace fs = std::filesystem;

using test::Outcome;
using test::radbake;
using test::run;
using test::slurp;

std::string fixture(const std::string& name) { return test::source_path("tests/fixtures/" + name); }

// Anything the bake left next to the output folder: it must be nothing.
size_t leftovers(const std::string& parent) {
  size_t n = 0;
  for (const auto& entry : fs::directory_iterator(parent)) n += entry.path().filename().string().find(".radbake-") != std::string::npos;
  return n;
}

TEST(Cli, HelpListsTheOptionsAndExitsZero) {
  Outcome r = radbake("--help");
  EXPECT_EQ(r.status, 0);
  for (const char* option : {"--density", "--max-page-size", "--tolerance", "--solver", "--threads", "--seed", "--store",
                             "--quiet", "-o, --output"})
    EXPECT_NE(r.out.find(option), std::string::npos) << option;
}

// The version is written once, as CMake's PROJECT_VERSION; the Blender add-on's bl_info, which
// Blender reads as a literal, must say the same.
TEST(Cli, VersionIsCMakesProjectVersionAndTheAddOnsToo) {
  const Outcome r = radbake("--version");
  EXPECT_EQ(r.status, 0);
  const std::string cmake = slurp(test::source_path("CMakeLists.txt"));
  const size_t at = cmake.find("project(radbake VERSION ");
  ASSERT_NE(at, std::string::npos);
  const std::string version = cmake.substr(at + 24, cmake.find(' ', at + 24) - at - 24);
  EXPECT_EQ(r.out, "radbake " + version + "\n");
  std::string tuple = version;
  for (size_t dot; (dot = tuple.find('.')) != std::string::npos;) tuple.replace(dot, 1, ", ");
  EXPECT_NE(slurp(test::source_path("blender_addon/radbake/__init__.py")).find("\"version\": (" + tuple + "),"),
            std::string::npos)
      << "bl_info's version is not " << version;
}

TEST(Cli, UsageErrorsExitTwoWithOneLine) {
  std::string parent = test::fresh_folder("cli_usage");
  const std::pair<std::string, std::string> cases[] = {
      {"bake " + fixture("lit_room.glb") + " -o " + parent + "/out --frobnicate", "unknown option --frobnicate"},
      {"bake " + fixture("lit_room.glb") + " -o " + parent + "/out --solver magic", "--solver must be"},
      {"bake " + fixture("lit_room.glb") + " -o " + parent + "/out --density -3", "--density must be between"},
      {"bake " + fixture("lit_room.glb") + " -o " + parent + "/out --threads", "--threads needs a value"},
      {"bake " + fixture("lit_room.glb"), "missing -o OUTDIR"},
      {"bake " + fixture("lit_room.glb") + " -o " + parent + "/out --quality best", "--quality must be"},
      {"bake " + fixture("lit_room.glb") + " -o " + parent + "/out --form-factors radar", "--form-factors must be"},
      {"bake " + fixture("lit_room.glb") + " -o " + parent + "/out --hemicube-resolution 7", "must be even"},
      {"frobnicate", "unknown command"},
  };
  for (const auto& [args, says] : cases) {
    Outcome r = radbake(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(parent + "/out"));
  }
}

class CliBadInput : public ::testing::TestWithParam<std::pair<const char*, const char*>> {};

TEST_P(CliBadInput, ExitsTwoWithAClearLineAndWritesNothing) {
  // A folder per case: ctest -j runs the cases side by side.
  std::string parent = test::fresh_folder(std::string("cli_bad_") + GetParam().first);
  Outcome r = radbake("bake " + fixture(std::string("bad/") + GetParam().first) + " -o " + parent + "/out");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("radbake: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(GetParam().second), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(parent + "/out"));
  EXPECT_EQ(leftovers(parent), 0u);
}

INSTANTIATE_TEST_SUITE_P(
    Fixtures, CliBadInput,
    ::testing::Values(std::make_pair("invalid_json.gltf", "not valid JSON"),
                      std::make_pair("missing_buffer.gltf", "missing_buffer.bin"),
                      std::make_pair("index_out_of_range.gltf", "out of range"),
                      std::make_pair("nan_position.gltf", "non-finite"),
                      std::make_pair("infinite_position.gltf", "non-finite"),
                      std::make_pair("no_geometry.gltf", "no triangles"),
                      std::make_pair("no_light.gltf", "nothing in the scene emits light"),
                      std::make_pair("required_extension.gltf", "KHR_draco_mesh_compression")),
    [](const auto& info) {
      std::string name = info.param.first;
      return name.substr(0, name.find('.'));
    });

// Hostile input (tests/fixtures/make_hostile_fixtures.py): exit 2, one line naming the file and
// the JSON pointer of the object at fault, nothing written.
struct HostileCase {
  const char* file;
  const char* pointer;
  const char* says;
};

class CliHostileInput : public ::testing::TestWithParam<HostileCase> {};

TEST_P(CliHostileInput, ExitsTwoNamingTheObjectAndWritesNothing) {
  const std::string input = fixture(std::string("hostile/") + GetParam().file + ".gltf");
  const std::string parent = test::fresh_folder(std::string("cli_hostile_") + GetParam().file);
  const auto start = std::chrono::steady_clock::now();
  Outcome r = radbake("bake " + input + " -o " + parent + "/out");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 30);  // fails fast
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err.rfind("radbake: error: " + input + ": " + GetParam().pointer + ": ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(GetParam().says), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(parent + "/out"));
  EXPECT_EQ(leftovers(parent), 0u);
}

INSTANTIATE_TEST_SUITE_P(
    Fixtures, CliHostileInput,
    ::testing::Values(
        HostileCase{"image_absolute_path", "/images/0/uri", "outside the scene's folder"},
        HostileCase{"image_parent_path", "/images/0/uri", "outside the scene's folder"},
        HostileCase{"buffer_absolute_path", "/buffers/0/uri", "outside the scene's folder"},
        HostileCase{"buffer_parent_path", "/buffers/0/uri", "outside the scene's folder"},
        HostileCase{"accessor_2g_elements", "/accessors/0", "2147483648 elements need"},
        HostileCase{"accessor_2g_zeros", "/", "more than --max-triangles"},
        HostileCase{"instancing_bomb", "/nodes/3/children/0", "at most one parent"},
        HostileCase{"tangent_short", "/meshes/0/primitives/0/attributes/TANGENT", "has 2 elements, POSITION has 4"},
        HostileCase{"material_minus_one", "/meshes/0/primitives/0/material", "is -1; must be from 0 to 0"},
        HostileCase{"texture_transform_1e19",
                    "/materials/0/pbrMetallicRoughness/baseColorTexture/extensions/KHR_texture_transform/scale/0",
                    "must be a number from"},
        HostileCase{"translation_1e20", "/nodes/0", "beyond the 1e7 m radbake bakes"},
        HostileCase{"intensity_3e38", "/extensions/KHR_lights_punctual/lights/0/intensity", "above the 1e+20"},
        HostileCase{"emissive_strength_3e38", "/materials/0/extensions/KHR_materials_emissive_strength/emissiveStrength",
                    "above the 1e+20"},
        HostileCase{"buffer_view_past_buffer", "/bufferViews/4", "runs past the end of buffer 0"},
        HostileCase{"byte_stride_not_multiple_of_4", "/bufferViews/0/byteStride", "multiple of 4"},
        HostileCase{"byte_stride_smaller_than_element", "/accessors/0", "do not fit bufferView 0's byteStride"}),
    [](const auto& info) { return std::string(info.param.file); });

TEST(Cli, DeepExtrasExitTwoWithoutOverflowingTheStack) {
  std::string parent = test::fresh_folder("cli_deep_extras");
  Outcome r = radbake("bake " + fixture("hostile/deep_extras.gltf") + " -o " + parent + "/out");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("JSON nested deeper than 128 levels"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(parent + "/out"));
}

TEST(Cli, BudgetsExceededExitTwoWithTheEstimate) {
  std::string parent = test::fresh_folder("cli_budget");
  const std::string bake = "bake " + fixture("hostile/lit_textured_floor.gltf") + " -o " + parent + "/out";
  Outcome r = radbake(bake + " --max-triangles 1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("the scene has 2 triangles after instancing, more than --max-triangles 1 allows"), std::string::npos)
      << r.err;
  // The default page, 1024 x 1024 texels, is about 0.45 GB of the estimate.
  r = radbake(bake + " --max-memory 200M");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("1048576 lightmap texels"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("more than --max-memory 0.21 GB allows (raise it, or lower --max-page-size or --density)"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(parent + "/out"));
  EXPECT_EQ(radbake(bake + " --max-memory 200M --max-page-size 64 --quiet").status, 0);
}

TEST(Cli, PathTracingStatesItsNoiseAndFallsWithMoreSamples) {
  std::string parent = test::fresh_folder("cli_pathtrace");
  const std::string bake = "bake " + test::source_path("samples/cornell_box/cornell_box.gltf") + " --max-page-size 64 --quiet" +
                           " --method pathtrace -o " + parent;
  Outcome few = radbake(bake + "/few --samples 16"), more = radbake(bake + "/more --samples 64");
  ASSERT_EQ(few.status, 0) << few.err;
  ASSERT_EQ(more.status, 0) << more.err;
  EXPECT_NE(few.out.find("path traced, noise "), std::string::npos) << few.out;
  nlohmann::json a = nlohmann::json::parse(slurp(parent + "/few/report.json"));
  nlohmann::json b = nlohmann::json::parse(slurp(parent + "/more/report.json"));
  EXPECT_EQ(a["options"]["method"], "pathtrace");
  EXPECT_EQ(a["path_tracing"]["samples_per_texel"], 16);
  EXPECT_FALSE(a["energy_balance"]["measured"].get<bool>());
  // No gather and no form factors: their rays and the surfaces' open view are not measured.
  EXPECT_TRUE(a["counts"]["gather_rays"].is_null());
  EXPECT_TRUE(a["counts"]["form_factor_rays"].is_null());
  EXPECT_TRUE(a["surfaces"][0]["open_view"].is_null());
  // Four times the paths, half the noise (within 20% over these few hundred texels).
  EXPECT_NEAR(b["path_tracing"]["relative_noise"].get<double>() / a["path_tracing"]["relative_noise"].get<double>(), 0.5, 0.1);
  Outcome wrong = radbake(bake + "/wrong --method montecarlo");
  EXPECT_EQ(wrong.status, 2);
  EXPECT_NE(wrong.err.find("option --method must be radiosity or pathtrace, got 'montecarlo'"), std::string::npos) << wrong.err;
}

TEST(Cli, AllowExternalFilesLetsAnOutsideImageThroughAndCopiesIt) {
  std::string parent = test::fresh_folder("cli_external");
  const std::string bake = "bake " + fixture("hostile/image_parent_path.gltf") + " -o " + parent + "/out --max-page-size 64";
  EXPECT_EQ(radbake(bake).status, 2);
  Outcome r = radbake(bake + " --allow-external-files --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(slurp(parent + "/out/image_parent_path_image0.png"), slurp(fixture("outside_texture.png")));
  nlohmann::json report = nlohmann::json::parse(slurp(parent + "/out/report.json"));
  EXPECT_EQ(report["options"]["allow-external-files"], "yes");
}

TEST(Cli, BakeWritesTheFolderAndReportsProgressAsPlainLines) {
  std::string parent = test::fresh_folder("cli_bake");
  Outcome r = radbake("bake " + test::source_path("samples/cornell_box/cornell_box.gltf") + " -o " + parent +
                  "/out --max-page-size 128");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("wrote"), std::string::npos);
  // stderr is a file here, so progress comes as plain lines, not a redrawn bar.
  EXPECT_NE(r.err.find("radbake: final gather 100%\n"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\r'), std::string::npos);
  for (const char* file : {"cornell_box.gltf", "cornell_box_lightmap.bin", "cornell_box_lightmap_0.exr",
                           "cornell_box_lightmap_0.png", "cornell_box_display.glb", "report.json"})
    EXPECT_TRUE(fs::exists(parent + "/out/" + file)) << file;
  // Every attribute is rewritten through the atlas, so the input's buffer is left unused and pruned.
  nlohmann::json written = nlohmann::json::parse(slurp(parent + "/out/cornell_box.gltf"));
  ASSERT_EQ(written["buffers"].size(), 1u);
  EXPECT_EQ(written["buffers"][0]["uri"], "cornell_box_lightmap.bin");
  EXPECT_FALSE(fs::exists(parent + "/out/cornell_box_buffer0.bin"));
  nlohmann::json report = nlohmann::json::parse(slurp(parent + "/out/report.json"));
  EXPECT_EQ(report["generator"], "radbake");
  EXPECT_GT(report["counts"]["elements"].get<int>(), 1000);
  EXPECT_GT(report["counts"]["rays"].get<double>(), 1e6);
  EXPECT_TRUE(report["solver"]["converged"].get<bool>());
  EXPECT_LT(std::fabs(report["energy_balance"]["relative_error"].get<double>()), 0.005);
  EXPECT_TRUE(report["seconds"].contains("final gather"));
  EXPECT_EQ(report["lightmaps"]["unit"], "lx");
  EXPECT_EQ(report["options"]["solver"], "shooting");
  // Where the rays ended: shares of each kind's rays that add up to all of them. The box is open
  // at the front (some escape) and its texels stand for every point of its walls (none lost).
  for (const char* kind : {"gather_rays", "form_factor_rays"}) {
    const nlohmann::json& fates = report["counts"][kind];
    ASSERT_TRUE(fates.is_object()) << kind;
    EXPECT_GT(fates["rays"].get<double>(), 1e5) << kind;
    double sum = 0;
    for (const char* fate : {"took_light", "escaped", "back_face", "no_element", "buried_element", "other_side",
                             "sealed_gap", "inside_geometry"})
      sum += fates[fate].get<double>();
    EXPECT_NEAR(sum, 1.0, 1e-9) << kind;
    EXPECT_GT(fates["escaped"].get<double>(), 0.05) << kind;
    EXPECT_LT(fates["front_face_took_none"].get<double>(), 1e-3) << kind;
  }
  // Each surface sees some of the open through the box's front, none most of it.
  double open_view_sum = 0;
  for (const nlohmann::json& surface : report["surfaces"]) {
    const double open = surface["open_view"].get<double>();
    EXPECT_GE(open, 0.0);
    EXPECT_LT(open, 0.5) << surface["name"];
    open_view_sum += open;
  }
  EXPECT_GT(open_view_sum, 0.0);
  EXPECT_EQ(leftovers(parent), 0u);
}

TEST(Cli, ThePlanIsPrintedAndReported) {
  std::string parent = test::fresh_folder("cli_plan");
  Outcome r = radbake("bake " + fixture("lit_room.glb") + " -o " + parent + "/out --max-page-size 64");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("radbake: plan: interreflection: solved"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("radbake: interreflection: stopped after"), std::string::npos) << r.err;
  nlohmann::json report = nlohmann::json::parse(slurp(parent + "/out/report.json"));
  ASSERT_TRUE(report["plan"].is_array());
  EXPECT_EQ(report["plan"][0]["effect"], "interreflection");
  EXPECT_FALSE(report["plan"][0]["reason"].get<std::string>().empty());
  EXPECT_EQ(report["plan"].back()["choice"].get<std::string>().find("stopped after"), 0u);

  r = radbake("bake " + fixture("lit_room.glb") + " -o " + parent + "/out --max-page-size 64 --direct-only");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("radbake: plan: interreflection: skipped (asked for direct light only)"), std::string::npos);
  EXPECT_NE(r.out.find("energy balance not measured"), std::string::npos) << r.out;
  report = nlohmann::json::parse(slurp(parent + "/out/report.json"));
  EXPECT_FALSE(report["energy_balance"]["measured"].get<bool>());
  EXPECT_EQ(report["solver"]["channels"], 0);

  r = radbake("bake " + fixture("lit_room.glb") + " -o " + parent + "/out --direct-only --simulate-everything");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("contradict"), std::string::npos) << r.err;
}

TEST(Cli, QualityPresetSetsTheRayCountsAndGivenOptionsOverrideIt) {
  std::string parent = test::fresh_folder("cli_quality");
  // The preset applies first wherever it stands on the command line.
  for (std::string args : {"--quality draft --gather-rays 100", "--gather-rays 100 --quality draft"}) {
    Outcome r = radbake("bake " + fixture("lit_room.glb") + " -o " + parent + "/out --max-page-size 64 " + args);
    ASSERT_EQ(r.status, 0) << r.err;
    nlohmann::json options = nlohmann::json::parse(slurp(parent + "/out/report.json"))["options"];
    EXPECT_EQ(options["quality"], "draft") << args;
    EXPECT_EQ(options["gather-rays"], "100") << args;
    EXPECT_EQ(options["patch-rays"], "512") << args;
    EXPECT_EQ(options["tolerance"], "0.01") << args;
  }
}

TEST(Cli, HemicubeSubdivisionAndPreviewsFromTheCommandLine) {
  std::string parent = test::fresh_folder("cli_methods");
  Outcome r = radbake("bake " + test::source_path("samples/cornell_box/cornell_box.gltf") + " -o " + parent +
                      "/out --max-page-size 64 --form-factors hemicube --hemicube-resolution 16 --subdivide 0.5 "
                      "--preview-every 50");
  ASSERT_EQ(r.status, 0) << r.err;
  nlohmann::json report = nlohmann::json::parse(slurp(parent + "/out/report.json"));
  EXPECT_EQ(report["options"]["form-factors"], "hemicube");
  ASSERT_GE(report["subdivision"].size(), 2u);
  EXPECT_GT(report["subdivision"][0]["split_after_solve"].get<int>(), 0);
  EXPECT_GT(report["subdivision"][1]["patches"].get<int>(), report["subdivision"][0]["patches"].get<int>());
  EXPECT_TRUE(report["solver"]["converged"].get<bool>());
  size_t previews = 0;
  for (const auto& entry : fs::directory_iterator(parent + "/out/preview"))
    previews += entry.path().extension() == ".png";
  EXPECT_GE(previews, 2u);
  EXPECT_NE(r.err.find("radbake: previews in"), std::string::npos);
}

TEST(Cli, OnATerminalProgressIsOneRedrawnBar) {
  // script(1) gives radbake a pseudo-terminal for stderr.
  std::string parent = test::fresh_folder("cli_tty");
  Outcome r = run("script -qec '" + std::string(RADBAKE_BINARY) + " bake " + fixture("lit_room.glb") + " -o " + parent +
                  "/out --max-page-size 64' /dev/null");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("\r["), std::string::npos);        // redrawn in place
  EXPECT_NE(r.out.find("100% final gather"), std::string::npos);
  EXPECT_EQ(r.out.find("radbake: final gather"), std::string::npos);  // no plain lines
}

TEST(Cli, QuietMeansNothingOnStderr) {
  std::string parent = test::fresh_folder("cli_quiet");
  Outcome r = radbake("bake " + fixture("lit_room.glb") + " -o " + parent + "/out --max-page-size 64 --quiet");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.err, "");
}

TEST(Cli, OutputFolderIsReplacedOnlyWhenRadbakeWroteIt) {
  std::string parent = test::fresh_folder("cli_replace");
  fs::create_directories(parent + "/precious");
  std::ofstream(parent + "/precious/thesis.tex") << "do not delete";
  Outcome refused = radbake("bake " + fixture("lit_room.glb") + " -o " + parent + "/precious --max-page-size 64");
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find("is not a radbake output"), std::string::npos);
  EXPECT_EQ(slurp(parent + "/precious/thesis.tex"), "do not delete");

  std::string args = "bake " + fixture("lit_room.glb") + " -o " + parent + "/out --max-page-size 64 --quiet";
  ASSERT_EQ(radbake(args + " --debug-dumps").status, 0);
  ASSERT_EQ(radbake(args).status, 0);
  EXPECT_FALSE(fs::exists(parent + "/out/debug"));  // replaced whole, not merged (a user's files: output_folder_test)
  EXPECT_TRUE(fs::exists(parent + "/out/report.json"));
  EXPECT_EQ(leftovers(parent), 0u);
}

TEST(Cli, InterruptCancelsAndLeavesNothing) {
  std::string parent = test::fresh_folder("cli_interrupt");
  pid_t pid = fork();
  if (pid == 0) {
    std::string out = parent + "/out", input = test::source_path("samples/ferren/ferren.gltf");
    freopen("/dev/null", "w", stdout);
    freopen("/dev/null", "w", stderr);
    execl(RADBAKE_BINARY, RADBAKE_BINARY, "bake", input.c_str(), "-o", out.c_str(), "--gather-rays", "4096", nullptr);
    _exit(127);
  }
  // Wait until the bake is under way (its staging folder exists), then interrupt it.
  for (int i = 0; i < 200 && leftovers(parent) == 0; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  kill(pid, SIGINT);
  int raw;
  waitpid(pid, &raw, 0);
  EXPECT_TRUE(WIFEXITED(raw));
  EXPECT_EQ(WEXITSTATUS(raw), 130);  // 128 + SIGINT, as a shell reports it
  EXPECT_FALSE(fs::exists(parent + "/out"));
  EXPECT_EQ(leftovers(parent), 0u);
}

TEST(Cli, UvPrintsTheAtlasStatistics) {
  Outcome r = radbake("uv " + test::source_path("samples/cornell_box/cornell_box.gltf") + " --stats");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* line : {"utilisation", "centres covered", "L2 stretch", "seam length", "overlapping texels  0", "flipped triangles   0",
                           "padding violations  0"})
    EXPECT_NE(r.out.find(line), std::string::npos) << line << "\n" << r.out;

  Outcome j = radbake("uv " + fixture("uv/uv_sphere.gltf") + " --json --max-page-size 512 --padding 3");
  ASSERT_EQ(j.status, 0) << j.err;
  nlohmann::json s = nlohmann::json::parse(j.out);
  EXPECT_EQ(s["overlapping_texels"], 0);
  EXPECT_EQ(s["flipped_triangles"], 0);
  EXPECT_EQ(s["padding_violations"], 0);
  EXPECT_EQ(s["padding"], 3);
  EXPECT_GT(s["utilisation"].get<double>(), 0.3);
  // A texel whose centre a triangle covers is touched by it: the stricter count is the smaller,
  // and on a padded sphere's charts most touched texels have their centres covered.
  EXPECT_LE(s["utilisation_centres"].get<double>(), s["utilisation"].get<double>());
  EXPECT_GT(s["utilisation_centres"].get<double>(), 0.8 * s["utilisation"].get<double>());
  EXPECT_LT(s["stretch_l2"].get<double>(), 1.05);
}

TEST(Cli, PagesArePowersOfTwoUnlessAnyPageSizeIsGiven) {
  // --texels without bound: the automatic density fills the page, whose size is the point here.
  const std::string cornell = "uv " + test::source_path("samples/cornell_box/cornell_box.gltf") + " --stats --texels 4294967296 --max-page-size ";
  Outcome pow2 = radbake(cornell + "300");  // any value in range is accepted; pages stay within 256
  ASSERT_EQ(pow2.status, 0) << pow2.err;
  EXPECT_NE(pow2.out.find("(256x256)"), std::string::npos) << pow2.out;
  Outcome tight = radbake(cornell + "500 --any-page-size");
  ASSERT_EQ(tight.status, 0) << tight.err;
  int width = 0, height = 0;
  const size_t at = tight.out.find("pages               1 (");
  ASSERT_NE(at, std::string::npos) << tight.out;
  ASSERT_EQ(std::sscanf(tight.out.c_str() + at, "pages 1 (%dx%d)", &width, &height), 2) << tight.out;
  EXPECT_TRUE(width % 4 == 0 && height % 4 == 0 && width <= 500 && height <= 500) << width << "x" << height;
  EXPECT_FALSE((width & (width - 1)) == 0 && (height & (height - 1)) == 0) << width << "x" << height;
  EXPECT_NE(radbake("--help").out.find("--any-page-size"), std::string::npos);
}

TEST(Cli, UvEvaluatesALayoutMadeElsewhere) {
  // Six walls each filling their own [0, 1] square: measured as one page, they overlap.
  Outcome r = radbake("uv " + fixture("own_lightmap_uvs.gltf") + " --evaluate-texcoord 1 --max-page-size 128 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  nlohmann::json s = nlohmann::json::parse(r.out);
  EXPECT_EQ(s["charts"], 6);
  EXPECT_GT(s["overlapping_texels"].get<int>(), 5000);
  Outcome missing = radbake("uv " + fixture("own_lightmap_uvs.gltf") + " --evaluate-texcoord 3");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("has no TEXCOORD_3"), std::string::npos);
}

TEST(Cli, DensityIsLoweredToFitOnePageOnlyWhenAsked) {
  std::string cornell = test::source_path("samples/cornell_box/cornell_box.gltf");
  nlohmann::json pages = nlohmann::json::parse(radbake("uv " + cornell + " --density 400 --max-page-size 256 --json").out);
  EXPECT_GT(pages["pages"].get<int>(), 1);  // more pages, same texel size
  EXPECT_FLOAT_EQ(pages["texel_density_per_m"].get<float>(), 400.0f);
  EXPECT_FALSE(pages["density_lowered"].get<bool>());
  Outcome fitted = radbake("uv " + cornell + " --density 400 --max-page-size 256 --fit-page --json");
  nlohmann::json one = nlohmann::json::parse(fitted.out);
  EXPECT_EQ(one["pages"], 1);
  EXPECT_LT(one["texel_density_per_m"].get<float>(), 400.0f);
  EXPECT_TRUE(one["density_lowered"].get<bool>());
  ASSERT_EQ(one["warnings"].size(), 1u);  // and it says so
  EXPECT_NE(one["warnings"][0].get<std::string>().find("lowered from 400"), std::string::npos);
}

// The Khronos glTF-Validator (npm package gltf-validator, run by tests/tools/validate_gltf.mjs;
// `./dev test` installs it) must find no errors in what radbake writes for each sample.
class Validator : public ::testing::TestWithParam<const char*> {};

TEST_P(Validator, SampleOutputHasNoErrors) {
  std::string parent = test::fresh_folder(std::string("cli_validate_") + GetParam());
  std::string input = test::source_path(std::string("samples/") + GetParam() + "/" + GetParam() + ".gltf");
  // The classroom has no lamp: the sky lights it (through glazing, KHR_materials_transmission).
  const std::string light = std::string(GetParam()) == "classroom" ? " --sky cie-overcast" : "";
  ASSERT_EQ(radbake("bake " + input + " -o " + parent + "/out --max-page-size 128 --quiet" + light).status, 0);
  ASSERT_TRUE(fs::exists(test::source_path("tests/tools/node_modules/gltf-validator")))
      << "the validator is not installed: run ./dev test (npm ci in tests/tools)";
  Outcome v = run("node " + test::source_path("tests/tools/validate_gltf.mjs") + " " + parent + "/out/" + GetParam() + ".gltf");
  EXPECT_EQ(v.status, 0) << v.out << v.err;
  nlohmann::json summary = nlohmann::json::parse(v.out);
  EXPECT_EQ(summary["errors"], 0) << v.out;
  EXPECT_EQ(summary["warnings"], 0) << v.out;
  // UNUSED_OBJECT infos only where the validator cannot see MOZ_lightmap's references: the lightmap
  // UV sets (and the TEXCOORD_0 glTF requires beside them) and the page textures.
  for (const auto& code : summary["info_codes"]) {
    const std::string info = code.get<std::string>();
    if (info.rfind("UNUSED_OBJECT", 0) != 0) continue;
    EXPECT_TRUE(info.find("/attributes/TEXCOORD_") != std::string::npos || info.find("/textures/") != std::string::npos)
        << info;
  }
  // The display file: no error, warning or info at all.
  Outcome display = run("node " + test::source_path("tests/tools/validate_gltf.mjs") + " " + parent + "/out/" + GetParam() +
                        "_display.glb");
  nlohmann::json display_summary = nlohmann::json::parse(display.out);
  EXPECT_EQ(display_summary["errors"], 0) << display.out;
  EXPECT_EQ(display_summary["warnings"], 0) << display.out;
  EXPECT_EQ(display_summary["infos"], 0) << display.out;
  // Every primitive has its lightmap UVs (read from the file: loading it back drops the back-face
  // primitives of double-sided surfaces and their layout, to bake them afresh).
  const nlohmann::json written = nlohmann::json::parse(slurp(parent + "/out/" + GetParam() + ".gltf"));
  for (const auto& mesh : written["meshes"])
    for (const auto& primitive : mesh["primitives"]) EXPECT_TRUE(primitive["attributes"].contains("TEXCOORD_1")) << mesh["name"];
  // And it loads back with tinygltf; the baked light is in _BAKED_LIGHT, never in COLOR_0, so
  // nothing comes back as a base colour.
  LoadedScene back = load_gltf(parent + "/out/" + GetParam() + ".gltf");
  LoadedScene original = load_gltf(input);
  ASSERT_EQ(back.scene.instances.size(), original.scene.instances.size());
  for (const MeshInstance& inst : back.scene.instances) {
    EXPECT_FALSE(inst.color_0_was_light) << inst.name;
    EXPECT_TRUE(inst.colors.empty()) << inst.name;
  }
}

INSTANTIATE_TEST_SUITE_P(Samples, Validator, ::testing::Values("cornell_box", "ferren", "classroom"),
                         [](const ::testing::TestParamInfo<const char*>& info) { return std::string(info.param); });

}  // namespace
}  // namespace radbake
