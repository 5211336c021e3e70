// Bakes across processes and machines (docs/distributed.md): under mpirun with 1 to 4
// ranks, resumed after being killed, and as slices joined by radbake merge, radbake writes the
// same files as one process baking alone, bit for bit. A checkpoint of another bake is refused.
#include <gtest/gtest.h>

#include <cstring>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/commands.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

namespace fs = std::filesystem;
using test::Outcome;
using test::radbake;

const std::string kCornell = test::source_path("samples/cornell_box/cornell_box.gltf");
const std::string kOptions = " --max-page-size 256 --quiet";

// Open MPI's launcher, allowed to run as root (CI containers do), on more ranks than cores. In the
// sanitizer build (./dev asan) the leak checker is off for ranks: Open MPI's own start-up keeps
// allocations to the end; the same code run alone is still leak-checked.
std::string mpirun(int ranks) {
  return "ASAN_OPTIONS=detect_leaks=0 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
         "OMPI_MCA_rmaps_base_oversubscribe=1 mpirun -np " +
         std::to_string(ranks) + " " + RADBAKE_BINARY + " ";
}

// Every file of `reference` is in `candidate`, byte for byte (EXR pages carry no time stamp);
// report.json differs (times, processes) and is left out.
void expect_same_output(const std::string& reference, const std::string& candidate) {
  size_t compared = 0;
  for (const auto& entry : fs::directory_iterator(reference)) {
    const std::string name = entry.path().filename().string();
    if (name == "report.json") continue;
    const std::string other = candidate + "/" + name;
    ASSERT_TRUE(fs::exists(other)) << other;
    EXPECT_TRUE(test::slurp(entry.path().string()) == test::slurp(other)) << other;
    ++compared;
  }
  EXPECT_GE(compared, 5u) << reference;  // glTF, its .bin, EXR and PNG pages, the display file
}

nlohmann::json report(const std::string& folder) { return nlohmann::json::parse(test::slurp(folder + "/report.json")); }

// The bake of one process alone, once per test program (ctest runs each test as a program of
// its own, two at a time: each has its own folder).
const std::string& alone() {
  static const std::string folder = [] {
    const std::string f =
        test::fresh_folder(std::string("distributed_alone_") + ::testing::UnitTest::GetInstance()->current_test_info()->name()) +
        "/out";
    Outcome r = radbake("bake " + kCornell + " -o " + f + kOptions);
    EXPECT_EQ(r.status, 0) << r.err;
    return f;
  }();
  return folder;
}

TEST(Distributed, OneToFourRanksWriteWhatOneProcessWrites) {
  for (int ranks : {1, 2, 3, 4}) {
    const std::string out = test::fresh_folder("distributed_ranks_" + std::to_string(ranks)) + "/out";
    Outcome r = test::run(mpirun(ranks) + "bake " + kCornell + " -o " + out + kOptions);
    ASSERT_EQ(r.status, 0) << r.err;
    expect_same_output(alone(), out);
    const nlohmann::json d = report(out)["distribution"];
    EXPECT_EQ(d["processes"], ranks);
    EXPECT_EQ(d["peak_memory_bytes_per_process"].size(), size_t(ranks));
    // The shared stages exchanged results (direct light to all, rows and texels to the first).
    uint64_t bytes = 0;
    for (const auto& stage : d["stages"]) bytes += stage["bytes_exchanged"].get<uint64_t>();
    if (ranks > 1) EXPECT_GT(bytes, 100000u) << d.dump();
    else EXPECT_EQ(bytes, 0u) << d.dump();
  }
  // Alone, without mpirun, nothing is exchanged.
  const nlohmann::json solo = report(alone());
  EXPECT_EQ(solo["distribution"]["processes"], 1);
  for (const auto& stage : solo["distribution"]["stages"]) EXPECT_EQ(stage["bytes_exchanged"], 0);
}

TEST(Distributed, DirectionalPagesAndProbesAreTheSameOnTwoRanks) {
  // The light's directions travel with the direct light and the gather; the probes are the first's.
  const std::string dir = test::fresh_folder("distributed_directional");
  const std::string options = kOptions + " --directional sh --probes 0.2";
  Outcome one = radbake("bake " + kCornell + " -o " + dir + "/one" + options);
  ASSERT_EQ(one.status, 0) << one.err;
  Outcome two = test::run(mpirun(2) + "bake " + kCornell + " -o " + dir + "/two" + options);
  ASSERT_EQ(two.status, 0) << two.err;
  expect_same_output(dir + "/one", dir + "/two");
  EXPECT_TRUE(fs::exists(dir + "/two/cornell_box_sh_c1z_0.exr"));
}

TEST(Distributed, AStoppedTeamResumesOnAnotherNumberOfRanks) {
  const std::string dir = test::fresh_folder("distributed_resume_ranks");
  Outcome stop = test::run(mpirun(2) + "bake " + kCornell + kOptions + " --checkpoint " + dir + "/ckpt --stop-after form-factors");
  ASSERT_EQ(stop.status, 0) << stop.err;
  EXPECT_NE(stop.out.find("stopped after the form factors"), std::string::npos) << stop.out;
  EXPECT_FALSE(fs::exists(dir + "/out"));
  Outcome resume = test::run(mpirun(3) + "bake " + kCornell + " -o " + dir + "/out" + kOptions + " --checkpoint " + dir +
                             "/ckpt --resume");
  ASSERT_EQ(resume.status, 0) << resume.err;
  expect_same_output(alone(), dir + "/out");
}

TEST(Distributed, ABakeKilledAfterTheFormFactorsResumesToTheSameOutput) {
  const std::string dir = test::fresh_folder("distributed_kill");
  // Killed (SIGKILL, as a preempted node) once the gather has saved its first wave: the form
  // factors and the solve are behind it, in the checkpoint.
  const std::string bake = std::string(RADBAKE_BINARY) + " bake " + kCornell + " -o " + dir + "/out" + kOptions +
                           " --checkpoint " + dir + "/ckpt";
  Outcome killed = test::run(bake + " & pid=$!; while [ ! -e " + dir +
                             "/ckpt/final_gather_waves.stage ] && kill -0 $pid 2>/dev/null; do sleep 0.01; done; "
                             "kill -9 $pid; wait $pid; echo status $?");
  ASSERT_NE(killed.out.find("status 137"), std::string::npos) << "not killed mid-bake: " << killed.out << killed.err;
  EXPECT_FALSE(fs::exists(dir + "/out")) << "a killed bake left output";
  for (const char* stage : {"direct_light_waves", "form_factors_waves", "radiosity"})
    EXPECT_TRUE(fs::exists(dir + "/ckpt/" + stage + ".stage")) << stage;
  Outcome resume = test::run(bake + " --resume");
  ASSERT_EQ(resume.status, 0) << resume.err;
  expect_same_output(alone(), dir + "/out");
}

TEST(Distributed, ACheckpointOfAnotherBakeOrADamagedOneIsRefused) {
  const std::string dir = test::fresh_folder("distributed_refused");
  Outcome first = radbake("bake " + kCornell + kOptions + " --checkpoint " + dir + "/ckpt --stop-after direct-light");
  ASSERT_EQ(first.status, 0) << first.err;
  // Another scene, and the same scene with another seed.
  const std::string ferren = test::source_path("samples/ferren/ferren.gltf");
  test::expect_one_line_refusal(radbake("bake " + ferren + " -o " + dir + "/a" + kOptions + " --checkpoint " + dir + "/ckpt --resume"),
                                "another scene or other options", dir + "/a");
  test::expect_one_line_refusal(radbake("bake " + kCornell + " -o " + dir + "/b" + kOptions + " --seed 2 --checkpoint " + dir +
                                        "/ckpt --resume"),
                                "another scene or other options", dir + "/b");
  // A stage file with one byte changed fails its checksum.
  const std::string stage = dir + "/ckpt/direct_light_waves.stage";
  std::string bytes = test::slurp(stage);
  bytes[bytes.size() / 2] ^= 0x40;
  std::ofstream(stage, std::ios::binary) << bytes;
  test::expect_one_line_refusal(radbake("bake " + kCornell + " -o " + dir + "/c" + kOptions + " --checkpoint " + dir + "/ckpt --resume"),
                                "damaged: its checksum does not match", dir + "/c");
  // Headers whose two sizes sum, wrapping past 2^64, to the bytes that follow them: a
  // name of 0xffffffff bytes, a payload of 2^64 - 1000. Refused before anything is allocated.
  const uint64_t body = bytes.size() - 40;  // after the 40-byte header
  const auto forged = [&](uint32_t name_size, uint64_t payload_size, const std::string& out) {
    std::string copy = bytes;
    std::memcpy(&copy[12], &name_size, 4);      // Header::name_size
    std::memcpy(&copy[24], &payload_size, 8);   // Header::payload_size
    std::ofstream(stage, std::ios::binary) << copy;
    test::expect_one_line_refusal(radbake("bake " + kCornell + " -o " + out + kOptions + " --checkpoint " + dir + "/ckpt --resume"),
                                  "damaged: its size is not what its header says", out);
  };
  forged(0xffffffffu, body - 0xffffffffu, dir + "/name_size");
  forged(uint32_t(body + 1000), ~uint64_t(0) - 999, dir + "/payload_size");
  std::ofstream(stage, std::ios::binary) << bytes;
  // Under mpirun too: one line from the first rank, a non-zero exit, no hang.
  Outcome team = test::run(mpirun(2) + "bake " + kCornell + " -o " + dir + "/d" + kOptions + " --checkpoint " + dir + "/ckpt --resume");
  EXPECT_NE(team.status, 0);
  EXPECT_NE(team.err.find("radbake: error: checkpoint"), std::string::npos) << team.err;
  EXPECT_FALSE(fs::exists(dir + "/d"));
}

// A FIFO where a checkpoint's file should be: opened for reading, it would wait
// for a writer for ever. --resume and merge refuse it in one line instead (timeout 60 turns a hang
// into status 124).
TEST(Distributed, ACheckpointFileThatIsAFifoIsRefusedNotWaitedOn) {
  const std::string dir = test::fresh_folder("distributed_fifo");
  const std::string ckpt = " --checkpoint " + dir + "/ckpt";
  Outcome first = radbake("bake " + kCornell + kOptions + ckpt + " --stop-after direct-light");
  ASSERT_EQ(first.status, 0) << first.err;
  const std::string stage = dir + "/ckpt/direct_light_waves.stage";
  fs::remove(stage);
  ASSERT_EQ(mkfifo(stage.c_str(), 0600), 0);
  const std::string bake = std::string("timeout 60 ") + RADBAKE_BINARY + " bake " + kCornell + kOptions + ckpt + " --resume -o ";
  test::expect_one_line_refusal(test::run(bake + dir + "/a"), "is not a regular file", dir + "/a");
  test::expect_one_line_refusal(test::run(std::string("timeout 60 ") + RADBAKE_BINARY + " merge " + kCornell + kOptions + ckpt +
                                          " -o " + dir + "/m"),
                                "", dir + "/m");
  fs::remove(stage);
  const std::string manifest = dir + "/ckpt/checkpoint.json";
  fs::remove(manifest);
  ASSERT_EQ(mkfifo(manifest.c_str(), 0600), 0);
  test::expect_one_line_refusal(test::run(bake + dir + "/b"), "checkpoint manifest", dir + "/b");
}

// The checkpoint fuzzer's finding (tests/fuzz/findings/checkpoint.manifest_*): a checkpoint.json
// whose members are of another type ended --resume with json's type_error and exit 1. Each is now
// a manifest of some other bake, refused in one line.
TEST(Distributed, AManifestWhoseMembersAreOfAnotherTypeIsRefusedInOneLine) {
  const std::string dir = test::fresh_folder("distributed_manifest_types");
  const std::string ckpt = " --checkpoint " + dir + "/ckpt";
  Outcome first = radbake("bake " + kCornell + kOptions + ckpt + " --stop-after direct-light");
  ASSERT_EQ(first.status, 0) << first.err;
  for (const char* finding : {"fingerprint_not_a_string", "scene_not_a_string"}) {
    fs::copy_file(test::source_path(std::string("tests/fuzz/findings/checkpoint.manifest_") + finding + ".json"),
                  dir + "/ckpt/checkpoint.json", fs::copy_options::overwrite_existing);
    const std::string out = dir + "/" + finding;
    test::expect_one_line_refusal(radbake("bake " + kCornell + kOptions + ckpt + " --resume -o " + out),
                                  "was saved by a bake of another scene or other options", out);
  }
}

TEST(Distributed, SlicesOfTheGatherJoinedByMergeAreTheWholeBake) {
  const std::string dir = test::fresh_folder("distributed_slices");
  const std::string ckpt = " --checkpoint " + dir + "/ckpt";
  Outcome solve = radbake("bake " + kCornell + kOptions + ckpt + " --stop-after radiosity");
  ASSERT_EQ(solve.status, 0) << solve.err;
  // As a job array would: each slice alone, one of them on two ranks.
  for (int k = 1; k <= 3; ++k) {
    const std::string command = "bake " + kCornell + kOptions + ckpt + " --resume --texel-range " + std::to_string(k) + "/3";
    Outcome slice = k == 2 ? test::run(mpirun(2) + command) : radbake(command);
    ASSERT_EQ(slice.status, 0) << slice.err;
  }
  Outcome merge = radbake("merge " + kCornell + " -o " + dir + "/out" + kOptions + ckpt);
  ASSERT_EQ(merge.status, 0) << merge.err;
  expect_same_output(alone(), dir + "/out");
  // A merge missing a slice is refused, naming it.
  fs::remove(dir + "/ckpt/final_gather__slice_3_of_3_waves.stage");
  test::expect_one_line_refusal(radbake("merge " + kCornell + " -o " + dir + "/again" + kOptions + ckpt),
                                "no final gather, slice 3 of 3", dir + "/again");
}

}  // namespace
}  // namespace radbake
