// The output folder under real use: bakes that die, are interrupted, run two at once,
// or find a user's files in OUTDIR. Each runs the radbake binary as a pipeline would.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <thread>

#include "io/gltf/gltf_loader.h"
#include "support/commands.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::string lit_room() { return test::source_path("tests/fixtures/lit_room.glb"); }

// Hidden entries radbake keeps beside OUTDIR while it bakes (staging folders, the lock).
std::vector<std::string> leftovers(const std::string& parent) {
  std::vector<std::string> out;
  for (const auto& entry : fs::directory_iterator(parent))
    if (entry.path().filename().string().find(".radbake-") != std::string::npos) out.push_back(entry.path().filename());
  return out;
}

bool staging_exists(const std::string& parent) {
  for (const std::string& name : leftovers(parent))
    if (name.find("-lock") == std::string::npos) return true;
  return false;
}

// Starts `radbake args...` in the background, stdout and stderr into `log`.
// `preload`: a library to load first; it makes the file `began` when it starts (slow_library_start.cpp).
pid_t start_radbake(const std::vector<std::string>& args, const std::string& log, const char* preload = nullptr,
                    const std::string& began = "") {
  pid_t pid = fork();
  if (pid == 0) {
    if (preload) {
      setenv("LD_PRELOAD", preload, 1);
      setenv("RADBAKE_TEST_LIBRARY_BEGAN", began.c_str(), 1);
      setenv("ASAN_OPTIONS", "verify_asan_link_order=0", 1);  // the sanitizer build's runtime is not first then
    }
    std::vector<char*> argv{const_cast<char*>(RADBAKE_BINARY)};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    if (!freopen(log.c_str(), "w", stdout) || dup2(STDOUT_FILENO, STDERR_FILENO) < 0) _exit(126);
    execv(RADBAKE_BINARY, argv.data());
    _exit(127);
  }
  return pid;
}

// Waits (up to a minute: loading is slow on a busy machine) until `ready` holds; false if the
// process ended first or it never did.
template <typename Ready>
bool wait_until(Ready ready, pid_t pid) {
  for (int i = 0; i < 1200; ++i) {
    if (ready()) return true;
    if (waitpid(pid, nullptr, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
}

// Until the bake has its staging folder.
bool wait_for_staging(const std::string& parent, pid_t pid) {
  return wait_until([&] { return staging_exists(parent); }, pid);
}

int exit_status(pid_t pid) {
  int raw = 0;
  waitpid(pid, &raw, 0);
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -WTERMSIG(raw);
}

// Every file report.json lists exists, and the glTF loads back.
void expect_complete_output(const std::string& folder, const std::string& name) {
  nlohmann::json report = nlohmann::json::parse(test::slurp(folder + "/report.json"));
  ASSERT_TRUE(report["files"].is_array());
  EXPECT_GE(report["files"].size(), 5u);
  for (const auto& file : report["files"]) EXPECT_TRUE(fs::is_regular_file(folder + "/" + file.get<std::string>())) << file;
  LoadedScene back = load_gltf(folder + "/" + name + ".gltf");
  for (const MeshInstance& inst : back.scene.instances) EXPECT_NE(inst.lightmap_uvs(), nullptr) << inst.name;
}

TEST(OutputFolder, AStagingFolderLeftByAKilledBakeIsRemovedByTheNext) {
  const std::string parent = test::fresh_folder("outdir_stale");
  // A bake killed outright (no chance to clean up) leaves its staging folder and its lock file.
  pid_t killed = start_radbake({"bake", lit_room(), "-o", parent + "/out", "--gather-rays", "65536"}, parent + "/log");
  ASSERT_TRUE(wait_for_staging(parent, killed));
  kill(killed, SIGKILL);
  exit_status(killed);
  ASSERT_TRUE(staging_exists(parent));
  // An older crash's half-finished commit, and another output folder's staging, which must stay.
  fs::create_directories(parent + "/.out.radbake-999999999-old/debug");
  fs::create_directories(parent + "/.other.radbake-999999999");

  test::Outcome r = test::radbake("bake " + lit_room() + " -o " + parent + "/out --max-page-size 64 --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(leftovers(parent), std::vector<std::string>{".other.radbake-999999999"});
  expect_complete_output(parent + "/out", "lit_room");
}

TEST(OutputFolder, ASecondBakeIntoAFolderInUseFailsNamingTheFirst) {
  const std::string parent = test::fresh_folder("outdir_concurrent");
  const std::string out = parent + "/out";
  pid_t first = start_radbake({"bake", lit_room(), "-o", out, "--max-page-size", "128", "--gather-rays", "2048"},
                              parent + "/first.log");
  ASSERT_TRUE(wait_for_staging(parent, first)) << test::slurp(parent + "/first.log");
  test::Outcome second = test::radbake("bake " + lit_room() + " -o " + out + " --max-page-size 64 --quiet");
  EXPECT_EQ(second.status, 2);
  EXPECT_EQ(second.err, "radbake: error: output folder " + out + " is being written by another bake (radbake process " +
                            std::to_string(first) + "); wait for it to finish or choose another folder\n");
  ASSERT_EQ(exit_status(first), 0) << test::slurp(parent + "/first.log");
  // The first bake's output, whole: the second touched nothing.
  expect_complete_output(out, "lit_room");
  EXPECT_EQ(nlohmann::json::parse(test::slurp(out + "/report.json"))["options"]["gather-rays"], "2048");
  EXPECT_TRUE(leftovers(parent).empty());
}

TEST(OutputFolder, AUsersFilesInAnEarlierOutputAreKeptAndTheBakeRefused) {
  const std::string parent = test::fresh_folder("outdir_foreign");
  const std::string out = parent + "/out", bake = "bake " + lit_room() + " -o " + out + " --max-page-size 64 --quiet";
  ASSERT_EQ(test::radbake(bake).status, 0);
  const std::string report = test::slurp(out + "/report.json");
  std::ofstream(out + "/notes.txt") << "mine";
  fs::create_directories(out + "/renders");

  test::Outcome r = test::radbake(bake);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "radbake: error: output folder " + out +
                       " holds files radbake did not write (notes.txt, renders/); move them out or choose another folder\n");
  EXPECT_EQ(test::slurp(out + "/notes.txt"), "mine");
  EXPECT_TRUE(fs::is_directory(out + "/renders"));
  EXPECT_EQ(test::slurp(out + "/report.json"), report);  // the earlier bake is left as it was
  EXPECT_TRUE(leftovers(parent).empty());

  fs::remove(out + "/notes.txt");
  fs::remove(out + "/renders");
  EXPECT_EQ(test::radbake(bake).status, 0);  // only radbake's own files: replaced
}

TEST(OutputFolder, AnOutputWhoseReportListsNoFilesIsNotReplaced) {
  // A radbake from before report.json listed its files: what else is in there cannot be told.
  const std::string parent = test::fresh_folder("outdir_unlisted");
  fs::create_directories(parent + "/out");
  std::ofstream(parent + "/out/report.json") << R"({"generator": "radbake"})";
  test::Outcome r = test::radbake("bake " + lit_room() + " -o " + parent + "/out --max-page-size 64");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("did not list the files it wrote"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(parent + "/out/report.json"));
}

// A glTF of one mesh lit by a point light, written as .gltf + .bin.
std::string write_lit_mesh(const std::string& folder, const MeshInstance& mesh) {
  std::ofstream bin(folder + "/mesh.bin", std::ios::binary);
  bin.write(reinterpret_cast<const char*>(mesh.positions.data()), std::streamsize(mesh.positions.size() * sizeof(Vec3)));
  bin.write(reinterpret_cast<const char*>(mesh.triangles.data()), std::streamsize(mesh.triangles.size() * 4));
  const size_t positions = mesh.positions.size() * sizeof(Vec3), indices = mesh.triangles.size() * 4;
  Vec3 lo{1e30f, 1e30f, 1e30f}, hi{-1e30f, -1e30f, -1e30f};
  for (Vec3 p : mesh.positions) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  nlohmann::json gltf = {
      {"asset", {{"version", "2.0"}}},
      {"extensionsUsed", {"KHR_lights_punctual"}},
      {"extensions", {{"KHR_lights_punctual", {{"lights", {{{"type", "point"}, {"intensity", 100}}}}}}}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0, 1}}}}},
      {"nodes", {{{"mesh", 0}}, {{"translation", {0, 2, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}}},
      {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}}}}}},
      {"buffers", {{{"uri", "mesh.bin"}, {"byteLength", positions + indices}}}},
      {"bufferViews", {{{"buffer", 0}, {"byteLength", positions}},
                       {{"buffer", 0}, {"byteOffset", positions}, {"byteLength", indices}}}},
      {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", mesh.positions.size()}, {"type", "VEC3"},
                      {"min", {lo.x, lo.y, lo.z}}, {"max", {hi.x, hi.y, hi.z}}},
                     {{"bufferView", 1}, {"componentType", 5125}, {"count", mesh.triangles.size()}, {"type", "SCALAR"}}}},
  };
  std::ofstream(folder + "/mesh.gltf") << gltf.dump();
  return folder + "/mesh.gltf";
}

TEST(Interrupt, SigtermDuringLightmapUvGenerationEndsTheBakeAndLeavesNothing) {
  const std::string parent = test::fresh_folder("outdir_sigterm_uv");
  fs::create_directories(parent + "/in");
  // 400,000 triangles: unwrapping alone took 10 s of CPU (25 s on the shared 2-core machine) when
  // measured; the bake would take minutes more.
  const std::string scene = write_lit_mesh(parent + "/in", test::bumpy_torus(500, 400));
  pid_t bake = start_radbake({"bake", scene, "-o", parent + "/out"}, parent + "/log");
  // The staging folder is made just before the unwrap starts.
  ASSERT_TRUE(wait_for_staging(parent, bake)) << test::slurp(parent + "/log");
  std::this_thread::sleep_for(std::chrono::seconds(1));
  const auto signalled = Clock::now();
  kill(bake, SIGTERM);
  const int status = exit_status(bake);
  const double seconds = std::chrono::duration<double>(Clock::now() - signalled).count();
  std::printf("exited %.2f s after SIGTERM\n", seconds);
  const std::string log = test::slurp(parent + "/log");
  EXPECT_EQ(status, 143) << log;
  EXPECT_LT(seconds, 10.0);  // 0.15 to 0.25 s measured; polls at least every 50 ms of unwrapping
  EXPECT_NE(log.find("radbake: lightmap uvs"), std::string::npos) << log;
  EXPECT_EQ(log.find("radbake: elements"), std::string::npos) << log;  // it was still unwrapping
  EXPECT_NE(log.find("radbake: cancelled; nothing was written"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(parent + "/out"));
  EXPECT_TRUE(leftovers(parent).empty());
}

// A signal in radbake's first moments once ended it by the signal's default action,
// with no "cancelled" line: its 272 shared libraries take about 0.2 s to start, and the signals
// were blocked only when main began. They are now blocked before any library starts. A library
// preloaded to take 2 s to start (tests/support/slow_library_start.cpp) makes that moment long
// enough to signal into. The signal goes once that library has begun (radbake blocks signals
// before it, from .preinit_array): after a fixed half second, a loaded machine had not yet loaded
// radbake that far, and the signal's default action ended it.
TEST(Interrupt, ASignalWhileTheLibrariesStartEndsWithTheCancelledLine) {
  const std::string parent = test::fresh_folder("outdir_sigterm_start");
  fs::create_directories(parent + "/in");
  const std::string scene = write_lit_mesh(parent + "/in", test::bumpy_torus(8, 6));
  const std::string began = parent + "/slow_library_began";
  pid_t bake = start_radbake({"bake", scene, "-o", parent + "/out"}, parent + "/log", SLOW_LIBRARY_START, began);
  ASSERT_TRUE(wait_until([&] { return fs::exists(began); }, bake)) << test::slurp(parent + "/log");
  ASSERT_EQ(test::slurp(parent + "/log"), "") << "radbake began before the slow library let it";
  kill(bake, SIGTERM);
  const int status = exit_status(bake);
  const std::string log = test::slurp(parent + "/log");
  EXPECT_EQ(status, 143) << log;  // -15 when the signal's default action ended it
  EXPECT_NE(log.find("radbake: cancelled; nothing was written"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(parent + "/out"));
  EXPECT_TRUE(leftovers(parent).empty());
}

// A full disk with --debug-dumps once ended the bake with exit status 1 and
// OpenEXR's words. A bake is written into disks of a twelfth, two twelfths ... of the space its
// output takes (tmpfs in a mount namespace of the test's own, `unshare`): each either writes
// everything or says in one line which file could not be written because the disk is full (named
// under the output folder as given, not the hidden staging folder it was written in), exits
// 2 and leaves nothing, whichever output kind (debug dump, page, display file, report) it was at.
TEST(DiskFull, EveryOutputKindFailsWithOneLineAndExitStatusTwo) {
  const std::string parent = test::fresh_folder("disk_full");
  const std::string bake = std::string(RADBAKE_BINARY) + " bake " + test::source_path("samples/cornell_box/cornell_box.gltf") +
                           " --max-page-size 256 --quiet --debug-dumps -o ";
  ASSERT_EQ(test::run(bake + parent + "/whole").status, 0);
  uint64_t whole = 0;
  for (const auto& entry : fs::recursive_directory_iterator(parent + "/whole"))
    if (entry.is_regular_file()) whole += entry.file_size();
  std::set<std::string> failed_at;
  for (int twelfths = 1; twelfths <= 12; ++twelfths) {
    const uint64_t kib = std::max<uint64_t>(16, whole * twelfths / 12 / 1024);
    const std::string disk = parent + "/disk_" + std::to_string(twelfths);
    fs::create_directories(disk);
    const test::Outcome r = test::run("unshare --user --map-root-user --mount sh -c 'mount -t tmpfs -o size=" +
                                      std::to_string(kib) + "k tmpfs " + disk + " && cd " + disk + " && " + bake +
                                      "out; status=$?; ls -A; exit $status'");
    SCOPED_TRACE(std::to_string(kib) + " KiB: " + r.err);
    ASSERT_EQ(r.err.find("unshare:"), std::string::npos) << "no mount namespace here";
    if (r.status == 0) {
      EXPECT_EQ(r.out, "out\n");
      continue;
    }
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err.rfind("radbake: error: cannot write out/", 0), 0u) << "not where the user looks";
    EXPECT_NE(r.err.find(": the disk is full"), std::string::npos);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
    EXPECT_EQ(r.out, "") << "left on the full disk";
    const size_t name = r.err.rfind('/'), end = r.err.find(':', name);
    if (name != std::string::npos && end != std::string::npos) failed_at.insert(r.err.substr(name + 1, end - name - 1));
  }
  std::string kinds;
  for (const std::string& f : failed_at) kinds += f + " ";
  std::printf("failed at: %s\n", kinds.c_str());
  EXPECT_TRUE(failed_at.count("cornell_box_irradiance_0.exr")) << kinds;  // the first debug dump
  EXPECT_TRUE(failed_at.count("cornell_box_lightmap_0.exr")) << kinds;
  EXPECT_GE(failed_at.size(), 3u) << kinds;
}

// The same for a checkpoint on a full disk: one line, exit 2, and no partial stage file left.
TEST(DiskFull, ACheckpointOnAFullDiskFailsWithOneLineAndLeavesNoPartialFile) {
  const std::string parent = test::fresh_folder("disk_full_checkpoint");
  const std::string disk = parent + "/disk";
  fs::create_directories(disk);
  const test::Outcome r = test::run(
      "unshare --user --map-root-user --mount sh -c 'mount -t tmpfs -o size=16k tmpfs " + disk + " && " +
      std::string(RADBAKE_BINARY) + " bake " + test::source_path("samples/cornell_box/cornell_box.gltf") +
      " --max-page-size 256 --quiet -o " + parent + "/out --checkpoint " + disk + "/checkpoint; status=$?; ls -A " +
      disk + "/checkpoint; exit $status'");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("cannot write " + disk + "/checkpoint/"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(": the disk is full"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.out.find(".partial"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(parent + "/out"));
}

}  // namespace
}  // namespace radbake
