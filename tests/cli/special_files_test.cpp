// Every file radbake reads must be a regular file, checked without
// blocking before a byte is read. Opening a FIFO to read waits for a writer for ever, and
// /dev/zero never ends: each reader is given one (or a link to one) and must refuse it in one line.
// Every command runs under `timeout 60`, so a reader that blocks fails the test (status 124)
// instead of hanging the suite.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/commands.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

namespace fs = std::filesystem;

// The Cornell box copied into `folder`, its .gltf edited by `edit`; returns the .gltf's path.
std::string cornell_copy(const std::string& folder, const std::function<void(nlohmann::json&)>& edit = {}) {
  std::ifstream in(test::source_path("samples/cornell_box/cornell_box.gltf"));
  nlohmann::json gltf = nlohmann::json::parse(in);
  if (edit) edit(gltf);
  std::ofstream(folder + "/cornell_box.gltf") << gltf.dump();
  fs::copy_file(test::source_path("samples/cornell_box/cornell_box.bin"), folder + "/cornell_box.bin",
                fs::copy_options::overwrite_existing);
  return folder + "/cornell_box.gltf";
}

struct SpecialFileCase {
  std::string name;
  // Sets the special file up in `folder` and returns radbake's arguments (without -o).
  std::function<std::string(const std::string& folder)> arguments;
  std::string says;
};

// gtest prints a parameter it cannot format as its bytes; the case's name says it.
void PrintTo(const SpecialFileCase& c, std::ostream* os) { *os << c.name; }

class EveryReader : public ::testing::TestWithParam<SpecialFileCase> {};

TEST_P(EveryReader, RefusesAFileThatIsNotARegularFileWithoutWaiting) {
  const std::string folder = test::fresh_folder("special_" + GetParam().name);
  const std::string out = folder + "/out";
  const test::Outcome r = test::run("timeout 60 " + std::string(RADBAKE_BINARY) + " " + GetParam().arguments(folder) +
                                    " -o " + out + " --quiet");
  ASSERT_NE(r.status, 124) << "radbake waited on the special file";
  test::expect_one_line_refusal(r, GetParam().says, out);
}

INSTANTIATE_TEST_SUITE_P(
    Files, EveryReader,
    ::testing::Values(
        SpecialFileCase{"scene_fifo", [](const std::string& f) { return "bake " + test::make_fifo(f + "/scene.gltf"); },
                        "scene.gltf: not a regular file"},
        SpecialFileCase{"scene_link_to_dev_zero",
                        [](const std::string& f) {
                          fs::create_symlink("/dev/zero", f + "/scene.glb");
                          return "bake " + f + "/scene.glb";
                        },
                        "scene.glb: not a regular file"},
        SpecialFileCase{"buffer_fifo",
                        [](const std::string& f) {
                          const std::string scene = cornell_copy(f);
                          fs::remove(f + "/cornell_box.bin");
                          test::make_fifo(f + "/cornell_box.bin");
                          return "bake " + scene;
                        },
                        "/buffers/0/uri: URI 'cornell_box.bin' is not a regular file"},
        SpecialFileCase{"image_fifo",
                        [](const std::string& f) {
                          const std::string scene = cornell_copy(f, [](nlohmann::json& g) {
                            g["images"] = {{{"uri", "texture.png"}}};
                            g["textures"] = {{{"source", 0}}};
                          });
                          test::make_fifo(f + "/texture.png");
                          return "bake " + scene;
                        },
                        "/images/0/uri: URI 'texture.png' is not a regular file"},
        SpecialFileCase{"sensors_fifo",
                        [](const std::string& f) {
                          return "bake " + cornell_copy(f) + " --sensors " + test::make_fifo(f + "/sensors.csv");
                        },
                        "sensor file '"},
        SpecialFileCase{"weather_fifo",
                        [](const std::string& f) {
                          return "bake " + test::source_path("samples/classroom/classroom.gltf") +
                                 " --work-plane --weather " + test::make_fifo(f + "/year.epw");
                        },
                        "weather file '"},
        SpecialFileCase{"weather_dev_zero",
                        [](const std::string& f) {
                          fs::create_symlink("/dev/zero", f + "/year.epw");
                          return "bake " + test::source_path("samples/classroom/classroom.gltf") +
                                 " --work-plane --weather " + f + "/year.epw";
                        },
                        "year.epw' is not a regular file"}),
    [](const auto& info) { return info.param.name; });

// An output folder's report.json says whether radbake may replace the folder; one that is a FIFO
// makes it someone else's folder, said at once.
TEST(SpecialFiles, AnOutputFolderWhoseReportIsAFifoIsNotOurs) {
  const std::string folder = test::fresh_folder("special_output_report");
  const std::string out = folder + "/out";
  fs::create_directories(out);
  test::make_fifo(out + "/report.json");
  const test::Outcome r = test::run("timeout 60 " + std::string(RADBAKE_BINARY) + " bake " + cornell_copy(folder) +
                                    " -o " + out + " --quiet");
  ASSERT_NE(r.status, 124) << "radbake waited on the report";
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("exists and is not a radbake output"), std::string::npos) << r.err;
  EXPECT_EQ(fs::status(out + "/report.json").type(), fs::file_type::fifo) << "the folder was touched";
}

}  // namespace
}  // namespace radbake
