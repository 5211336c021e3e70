// `radbake view` against the real server: it serves the page, three.js and the output
// folders' files and nothing else, on 127.0.0.1 only, and the page in headless Chromium reads the
// bake's EXR where it is clicked.
#include <gtest/gtest.h>

#include <algorithm>
#include <httplib.h>
#include <signal.h>
#include <spawn.h>
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "io/analysis/false_colour.h"
#include "io/lightmaps/lightmap_images.h"
#include "support/commands.h"
#include "support/scene_builders.h"

extern char** environ;

namespace radbake {
namespace {

namespace fs = std::filesystem;

// `radbake view FOLDER --no-open` in the background, until destroyed (SIGTERM).
class ViewServer {
 public:
  explicit ViewServer(const std::vector<std::string>& folders) {
    int out[2];
    if (pipe(out) != 0) return;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, out[0]);
    std::vector<std::string> args = {RADBAKE_BINARY, "view"};
    args.insert(args.end(), folders.begin(), folders.end());
    args.push_back("--no-open");
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    if (posix_spawn(&pid_, RADBAKE_BINARY, &actions, nullptr, argv.data(), environ) != 0) pid_ = -1;
    posix_spawn_file_actions_destroy(&actions);
    close(out[1]);
    // Its first line: "radbake: viewing at http://127.0.0.1:PORT/ (Ctrl-C stops)".
    std::string line;
    char c;
    while (read(out[0], &c, 1) == 1 && c != '\n') line += c;
    close(out[0]);
    const size_t at = line.find("http://127.0.0.1:");
    if (at != std::string::npos) {
      url_ = line.substr(at, line.find(' ', at) - at);
      port_ = std::stoi(line.substr(at + 17));
    }
  }
  ~ViewServer() {
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      waitpid(pid_, &status_, 0);
    }
  }
  const std::string& url() const { return url_; }
  int port() const { return port_; }
  pid_t pid() const { return pid_; }

 private:
  pid_t pid_ = -1;
  int status_ = 0;
  std::string url_;
  int port_ = 0;
};

// The Cornell box on a 256 page in a folder of the test's own: with no options a copy of the bake
// ctest's fixture.cornell_box_256 made (a test may add files to its copy), else baked with them.
std::string cornell_bake(const std::string& name, const std::string& options = "") {
  const std::string out = test::fresh_folder(name) + "/out";
  if (options.empty()) {
    std::error_code failed;
    fs::copy(RADBAKE_CORNELL_BOX_256, out, fs::copy_options::recursive, failed);
    EXPECT_FALSE(failed) << RADBAKE_CORNELL_BOX_256 << ": " << failed.message()
                         << " (ctest bakes it first: run view_tests through ctest)";
    return out;
  }
  const test::Outcome r = test::radbake("bake " + test::source_path("samples/cornell_box/cornell_box.gltf") + " -o " + out +
                                        " --max-page-size 256 --quiet " + options);
  EXPECT_EQ(r.status, 0) << r.err;
  return out;
}

TEST(View, ServesTheFoldersFilesAndNothingElseOnLocalhostOnly) {
  const std::string folder = cornell_bake("view_serves");
  // A link in the folder that leads out of it, and a file beside the folder.
  fs::create_symlink("/etc/passwd", folder + "/escape.txt");
  std::ofstream(fs::path(folder).parent_path() / "secret.txt") << "not for the page\n";
  ViewServer server({folder});
  ASSERT_GT(server.port(), 0) << "no address printed";
  httplib::Client client("127.0.0.1", server.port());
  auto status = [&](const std::string& path) {
    const auto r = client.Get(path.c_str());
    return r ? r->status : -1;
  };
  EXPECT_EQ(status("/"), 200);
  EXPECT_EQ(status("/a/cornell_box.gltf"), 200);
  EXPECT_EQ(status("/a/cornell_box_lightmap_0.exr"), 200);
  EXPECT_EQ(status("/three/build/three.module.js"), 200);
  const auto bakes = client.Get("/api/bakes");
  ASSERT_TRUE(bakes);
  EXPECT_EQ(nlohmann::json::parse(bakes->body)[0]["gltf"], "cornell_box.gltf");
  // Ways out: 403; what is not there: 404.
  EXPECT_EQ(status("/a/escape.txt"), 403);
  EXPECT_EQ(status("/a/%2e%2e/secret.txt"), 403);
  EXPECT_EQ(status("/a/..%2fsecret.txt"), 403);
  EXPECT_EQ(status("/a//etc/passwd"), 403);
  EXPECT_EQ(status("/three/%2e%2e/package.json"), 403);
  EXPECT_EQ(status("/a/nothing.txt"), 404);
  EXPECT_EQ(status("/b/cornell_box.gltf"), 404);  // no second folder
  EXPECT_EQ(status("/etc/passwd"), 404);
  // It listens on 127.0.0.1 only: the kernel's table of listening TCP sockets (state 0A) gives
  // the port's local address, 0100007F in /proc/net/tcp's byte order; none listens on IPv6.
  char port_hex[8];
  std::snprintf(port_hex, sizeof port_hex, "%04X", server.port());
  std::vector<std::string> listening;
  for (const char* table : {"/proc/net/tcp", "/proc/net/tcp6"}) {
    std::ifstream in(table);
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
      std::istringstream fields(line);
      std::string slot, local, remote, state;
      fields >> slot >> local >> remote >> state;
      if (state == "0A" && local.size() > 5 && local.substr(local.size() - 4) == port_hex) listening.push_back(local);
    }
  }
  EXPECT_EQ(listening, std::vector<std::string>{"0100007F:" + std::string(port_hex)});
}

// Files go out as they are on disk, never compressed (the server is on 127.0.0.1 only, where
// brotli cost 2.35 CPU s a request for three.core.js and saved nothing), with a validator: a
// browser holding the file revalidates it with one empty 304. Ranges are honoured.
TEST(View, FilesAreSentPlainWithAValidatorAndRanges) {
  const std::string folder = cornell_bake("view_plain");
  ViewServer server({folder});
  ASSERT_GT(server.port(), 0);
  httplib::Client client("127.0.0.1", server.port());
  std::ifstream in(test::source_path("web/node_modules/three/build/three.core.js"), std::ios::binary);
  const std::string pinned((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(pinned.size(), 100000u);
  const auto full = client.Get("/three/build/three.core.js", {{"Accept-Encoding", "br, gzip, deflate"}});
  ASSERT_TRUE(full);
  EXPECT_EQ(full->status, 200);
  EXPECT_FALSE(full->has_header("Content-Encoding")) << full->get_header_value("Content-Encoding");
  EXPECT_EQ(full->body, pinned);
  EXPECT_EQ(full->get_header_value("Cache-Control"), "no-cache");
  const std::string tag = full->get_header_value("ETag");
  ASSERT_FALSE(tag.empty());
  const auto again = client.Get("/three/build/three.core.js", {{"If-None-Match", tag}});
  ASSERT_TRUE(again);
  EXPECT_EQ(again->status, 304);
  EXPECT_TRUE(again->body.empty());
  const auto part = client.Get("/three/build/three.core.js", {{"Range", "bytes=100-199"}});
  ASSERT_TRUE(part);
  EXPECT_EQ(part->status, 206);
  EXPECT_EQ(part->body, pinned.substr(100, 100));
  // A bake's own files alike, and the page.
  const auto page = client.Get("/", {{"Accept-Encoding", "gzip"}});
  ASSERT_TRUE(page);
  EXPECT_FALSE(page->has_header("Content-Encoding"));
  EXPECT_NE(page->body.find("radbake view"), std::string::npos);
  const auto exr = client.Get("/a/cornell_box_lightmap_0.exr");
  ASSERT_TRUE(exr);
  EXPECT_EQ(exr->body.size(), fs::file_size(folder + "/cornell_box_lightmap_0.exr"));
}

// A connection of its own to the server, spoken to byte by byte.
class RawConnection {
 public:
  explicit RawConnection(int port) {
    socket_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(uint16_t(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(socket_, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
      ::close(socket_);
      socket_ = -1;
    }
  }
  ~RawConnection() {
    if (socket_ >= 0) ::close(socket_);
  }
  bool send(const std::string& bytes) {
    return socket_ >= 0 && ::send(socket_, bytes.data(), bytes.size(), MSG_NOSIGNAL) == ssize_t(bytes.size());
  }
  // Whether the server has closed its side: a read that finds the end (or a reset) at once.
  bool closed_by_server() {
    char c;
    const ssize_t got = ::recv(socket_, &c, 1, MSG_DONTWAIT);
    return got == 0 || (got < 0 && errno != EAGAIN && errno != EWOULDBLOCK);
  }
  // Reads until the server closes; returns how many bytes came.
  uint64_t drain() {
    char chunk[1 << 16];
    uint64_t total = 0;
    for (ssize_t got; (got = ::recv(socket_, chunk, sizeof chunk, 0)) > 0;) total += uint64_t(got);
    return total;
  }

 private:
  int socket_ = -1;
};

uint64_t status_kib(pid_t pid, const std::string& field) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind(field + ":", 0) == 0) return std::stoull(line.substr(field.size() + 1));
  return 0;
}

// A request with 200 ranges "0-" of a 5 MB file came back as 1 GB. Now a request
// may ask for one range inside the file (cpp-httplib 0.11's multipart answers are wrong besides);
// anything else is refused with 416, no body.
TEST(View, ARequestMayAskForOneRangeAndNoMore) {
  const std::string folder = cornell_bake("view_ranges");
  std::string bytes(5 << 20, '\0');
  for (size_t k = 0; k < bytes.size(); ++k) bytes[k] = char(k * 2654435761u >> 24);
  std::ofstream(folder + "/five_megabytes.bin", std::ios::binary) << bytes;
  ViewServer server({folder});
  ASSERT_GT(server.port(), 0);
  httplib::Client client("127.0.0.1", server.port());
  auto ranged = [&](const std::string& ranges) { return client.Get("/a/five_megabytes.bin", {{"Range", "bytes=" + ranges}}); };
  std::string two_hundred_whole = "0-";
  for (int k = 1; k < 200; ++k) two_hundred_whole += ",0-";
  const auto whole_times_200 = ranged(two_hundred_whole);
  ASSERT_TRUE(whole_times_200);
  EXPECT_EQ(whole_times_200->status, 416);
  EXPECT_TRUE(whole_times_200->body.empty());
  EXPECT_EQ(whole_times_200->get_header_value("Content-Range"), "bytes */5242880");
  EXPECT_EQ(ranged("0-9,20-29")->status, 416) << "two, apart";
  EXPECT_EQ(ranged("6000000-")->status, 416) << "past the end";
  EXPECT_EQ(ranged("5242870-9999999")->status, 416) << "ending past the end (httplib 0.11 would promise 4.7 MB more)";
  const std::vector<std::pair<std::string, std::string>> singles = {
      {"1000-1999", bytes.substr(1000, 1000)},
      {"5242000-", bytes.substr(5242000)},
      {"-100", bytes.substr(bytes.size() - 100)}};
  for (const auto& [range, expected] : singles) {
    const auto part = ranged(range);
    ASSERT_TRUE(part) << range;
    EXPECT_EQ(part->status, 206) << range;
    EXPECT_EQ(part->body, expected) << range;
  }
}

// A hard link made in the folder to a file elsewhere was served (symbolic links
// were already refused); a FIFO must not hold a request.
TEST(View, AFileWithAnotherNameElsewhereOrThatIsNotAFileIsNotServed) {
  const std::string folder = cornell_bake("view_links");
  const std::string elsewhere = fs::path(folder).parent_path().string() + "/elsewhere.txt";
  std::ofstream(elsewhere) << "not for the page\n";
  fs::create_hard_link(elsewhere, folder + "/linked.txt");
  ASSERT_EQ(mkfifo((folder + "/pipe.bin").c_str(), 0600), 0);
  ViewServer server({folder});
  ASSERT_GT(server.port(), 0);
  httplib::Client client("127.0.0.1", server.port());
  client.set_read_timeout(30, 0);  // guards against a hang: a FIFO opened for reading waits for a writer
  const auto linked = client.Get("/a/linked.txt");
  ASSERT_TRUE(linked);
  EXPECT_EQ(linked->status, 403);
  EXPECT_EQ(linked->body.find("not for the page"), std::string::npos);
  const auto pipe = client.Get("/a/pipe.bin");
  ASSERT_TRUE(pipe) << "the FIFO held the request";
  EXPECT_EQ(pipe->status, 404);
  EXPECT_EQ(client.Get("/a/cornell_box.gltf")->status, 200);
}

// 40 connections that each sent a header line every 2 s stalled everyone
// else's requests for 12-25 s. Now each is served on its own worker, so a request from elsewhere
// is answered while all 40 are still open, and the server closes each when its header's deadline
// (8 s) passes.
TEST(View, SlowClientsHoldNobodyElseUpAndAreCutOff) {
  const std::string folder = cornell_bake("view_slow");
  ViewServer server({folder});
  ASSERT_GT(server.port(), 0);
  std::vector<std::unique_ptr<RawConnection>> slow;
  for (int k = 0; k < 40; ++k) {
    slow.push_back(std::make_unique<RawConnection>(server.port()));
    ASSERT_TRUE(slow.back()->send("GET /a/report.json HTTP/1.1\r\nHost: 127.0.0.1\r\n"));
  }
  for (int round = 0; round < 2; ++round) {
    std::this_thread::sleep_for(std::chrono::seconds(2));
    for (auto& connection : slow) connection->send("X-Slow: " + std::to_string(round) + "\r\n");
  }
  httplib::Client client("127.0.0.1", server.port());
  client.set_read_timeout(60, 0);
  const auto answered = client.Get("/a/report.json");
  ASSERT_TRUE(answered);
  EXPECT_EQ(answered->status, 200);
  int still_open = 0;
  for (auto& connection : slow) still_open += connection->closed_by_server() ? 0 : 1;
  EXPECT_EQ(still_open, 40) << "the answer came only after slow connections were let go";
  // They keep trickling, a line every 2 s; within 30 s (the deadline and a worker's sweep, with room
  // for a loaded machine) the server has closed every one.
  int closed = 0;
  for (int round = 0; round < 15 && closed < 40; ++round) {
    std::this_thread::sleep_for(std::chrono::seconds(2));
    closed = 0;
    for (auto& connection : slow) closed += connection->send("X-Slow: more\r\n") && !connection->closed_by_server() ? 0 : 1;
  }
  EXPECT_EQ(closed, 40);
}

// One GET of a 2 GB file took the server from 154 MB to 4.3 GB. Files are now
// read in 64 KiB chunks as each connection takes them, and at most 128 connections are served at
// once: 200 clients that each fetch a 16 MB file grow the server's peak memory by a few MB, not
// by what they fetch (3.2 GB in all).
TEST(View, TwoHundredClientsAtOnceKeepTheServerWithinAFixedMemoryBudget) {
  const std::string folder = cornell_bake("view_memory");
  const uint64_t file_bytes = 16u << 20;
  {
    std::ofstream out(folder + "/sixteen_megabytes.bin", std::ios::binary);
    const std::string block(1 << 20, 'x');
    for (uint64_t k = 0; k < file_bytes; k += block.size()) out << block;
  }
  ViewServer server({folder});
  ASSERT_GT(server.port(), 0);
  {
    httplib::Client warm("127.0.0.1", server.port());
    ASSERT_EQ(warm.Get("/a/cornell_box.gltf")->status, 200);
  }
  const uint64_t resident_before_kib = status_kib(server.pid(), "VmRSS");
  ASSERT_GT(resident_before_kib, 0u);
  std::vector<std::thread> clients;
  std::vector<uint64_t> received(200, 0);
  for (size_t k = 0; k < received.size(); ++k)
    clients.emplace_back([&, k] {
      RawConnection connection(server.port());
      if (connection.send("GET /a/sixteen_megabytes.bin HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n"))
        received[k] = connection.drain();
    });
  for (std::thread& client : clients) client.join();
  const uint64_t peak_kib = status_kib(server.pid(), "VmHWM");
  for (size_t k = 0; k < received.size(); ++k) EXPECT_GT(received[k], file_bytes) << "client " << k;  // body and header
  const double growth_mb = double(peak_kib - std::min(peak_kib, resident_before_kib)) / 1024.0;
  std::printf("200 clients, 16 MB each: server resident %.1f MB before, peak %.1f MB (+%.1f MB)\n",
              resident_before_kib / 1024.0, peak_kib / 1024.0, growth_mb);
  // Bounds 128 workers' chunk buffers (8 MB) and thread stacks touched; whole files would be 3.2 GB.
  EXPECT_LT(growth_mb, 64.0);
}

TEST(View, AFolderThatIsNotABakeIsRefusedWithOneLine) {
  const std::string empty = test::fresh_folder("view_not_a_bake");
  const std::string garbled = test::fresh_folder("view_garbled_report");
  std::ofstream(garbled + "/report.json") << "[1, 2";
  for (const auto& [folder, says] : {std::pair<std::string, std::string>{empty, "is not a radbake output folder"},
                                     {garbled, "is not a radbake report"}}) {
    const test::Outcome r = test::radbake("view " + folder + " --no-open");
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

// The page in headless Chromium at 256 x 256 through the sample's own camera, running `steps`
// (tests/web/viewer_modes.mjs).
nlohmann::json drive_page(const ViewServer& server, const nlohmann::json& steps) {
  EXPECT_TRUE(fs::exists(test::source_path("web/node_modules/playwright-core")))
      << "web/'s packages are not installed: run ./dev test (npm ci in web/)";
  const std::string steps_file = test::write_text_file("view_steps.json", steps.dump());
  const test::Outcome r = test::run("node " + test::source_path("tests/web/viewer_modes.mjs") + " " + server.url() +
                                    " 256 256 \"$(cat " + steps_file + ")\"");
  EXPECT_EQ(r.status, 0) << r.err;
  if (r.status != 0) return nullptr;
  const nlohmann::json result = nlohmann::json::parse(r.out);
  EXPECT_TRUE(result["consoleErrors"].empty()) << result["consoleErrors"].dump();
  return result;
}

// The back wall, the red wall and the floor, seen through the sample's camera at 256 x 256.
const std::vector<std::vector<int>> kWalls = {{128, 62}, {25, 100}, {100, 238}};

TEST(View, AClickReadsTheIlluminanceTheExrHoldsThere) {
  const std::string folder = cornell_bake("view_click");
  ViewServer server({folder});
  ASSERT_GT(server.port(), 0);
  const nlohmann::json result = drive_page(server, nlohmann::json::array({{{"mode", "baked"}, {"pixels", kWalls}}}));
  ASSERT_FALSE(result.is_null());
  const LightmapPage page = read_lightmap_exr(folder + "/cornell_box_lightmap_0.exr");
  const char* expected_surface[] = {"back_wall", "left_wall_red", "floor"};
  const nlohmann::json& pixels = result["steps"][0]["pixels"];
  ASSERT_EQ(pixels.size(), 3u);
  for (size_t k = 0; k < 3; ++k) {
    const nlohmann::json& pick = pixels[k]["pick"];
    ASSERT_FALSE(pick.is_null()) << k;
    EXPECT_NE(pick["surface"].get<std::string>().find(expected_surface[k]), std::string::npos) << pick.dump();
    const int x = pick["texel"][0], y = pick["texel"][1];
    // The reading is photopic, as every lux radbake prints (on the red wall a third of the RGB
    // mean would be 10% off).
    const double exr = photopic(page.texels[size_t(y) * size_t(page.width) + size_t(x)]);
    // 1%: both read the same half floats (OpenEXR here, three.js's
    // EXRLoader in the page), so only a wrong texel or a wrong page would differ.
    EXPECT_NEAR(double(pick["value"]), exr, 0.01 * exr) << pick.dump();
    EXPECT_GT(exr, 1.0) << pick.dump();  // a lit texel, not padding
  }
}

TEST(View, FalseColourPaintsEachTexelAsTheLegendSays) {
  const std::string folder = cornell_bake("view_false_colour");
  ViewServer server({folder});
  ASSERT_GT(server.port(), 0);
  // The ceiling by the lamp (bright) and the floor in the short block's shadow (dark), and the
  // three walls; a fixed top of the scale, linear, then logarithmic.
  std::vector<std::vector<int>> pixels = kWalls;
  pixels.push_back({128, 20});
  pixels.push_back({150, 225});
  const nlohmann::json result = drive_page(server, nlohmann::json::array({
      {{"mode", "falsecolour"}, {"scale", "linear"}, {"max", 2000}, {"pixels", pixels}},
      {{"mode", "falsecolour"}, {"scale", "log"}, {"max", 2000}, {"pixels", pixels}},
  }));
  ASSERT_FALSE(result.is_null());
  for (size_t s = 0; s < 2; ++s) {
    double brightest = 0, darkest = INFINITY;
    for (const nlohmann::json& p : result["steps"][s]["pixels"]) {
      ASSERT_FALSE(p["pick"].is_null()) << p.dump();
      const double value = p["pick"]["value"];
      brightest = std::max(brightest, value), darkest = std::min(darkest, value);
      FalseColourScale scale;
      scale.logarithmic = s == 1;
      scale.max = 2000;
      // The legend's colour for the texel's value (io/false_colour: radbake's own images). 3 of 255
      // bounds the page's round trip from sRGB to linear and back.
      const auto expected = turbo_colour(scale_fraction(value, scale, 2000));
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(int(p["rgb"][c]), int(expected[size_t(c)]), 3) << p.dump();
    }
    EXPECT_GT(brightest, 3 * darkest);  // a known-bright and a known-dark texel among them
  }
}

TEST(View, EveryDisplayModeDrawsTheBakeWithoutAnError) {
  // The classroom under the CIE overcast sky, with a daylight factor and a work plane: every mode
  // it offers.
  const std::string folder = test::fresh_folder("view_modes") + "/out";
  const test::Outcome bake = test::radbake("bake " + test::source_path("samples/classroom/classroom.gltf") + " -o " + folder +
                                           " --quiet --sky cie-overcast --daylight-factor --max-page-size 256 --work-plane "
                                           "--work-plane-over floor --work-plane-spacing 1");
  ASSERT_EQ(bake.status, 0) << bake.err;
  ViewServer server({folder});
  ASSERT_GT(server.port(), 0);
  nlohmann::json steps = nlohmann::json::array();
  for (const char* mode : {"baked", "lightmap", "vertex", "falsecolour", "daylight"})
    steps.push_back({{"mode", mode}, {"pixels", {{128, 128}, {120, 136}}}});
  // Three points of the grid's last row (9 x 7 points at 1 m), drawn last, so no other point
  // covers them.
  steps.push_back({{"mode", "sensors"}, {"max", 2000}, {"sensors", {54, 58, 62}}, {"camera", -1}});
  const nlohmann::json result = drive_page(server, steps);
  ASSERT_FALSE(result.is_null());
  for (size_t s = 0; s + 1 < steps.size(); ++s)
    for (const nlohmann::json& p : result["steps"][s]["pixels"]) {
      // Something lit is drawn there, in every mode (the background is black).
      EXPECT_GT(int(p["rgb"][0]) + int(p["rgb"][1]) + int(p["rgb"][2]), 30) << steps[s]["mode"] << p.dump();
    }
  // The daylight factor's scale is in percent, and its top a daylight factor, not lux.
  EXPECT_EQ(result["steps"][4]["scale"]["unit"], "%");
  EXPECT_LE(double(result["steps"][4]["scale"]["max"]), 100);
  // The work plane's points, each drawn in the colour of its reading on the legend's scale (3 of
  // 255: sRGB to linear and back).
  FalseColourScale scale;
  scale.max = 2000;
  for (const nlohmann::json& s : result["steps"][5]["sensors"]) {
    const auto expected = turbo_colour(scale_fraction(double(s["lux"]), scale, 2000));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(int(s["rgb"][c]), int(expected[size_t(c)]), 3) << s.dump();
  }
}

// The pixel in the middle of the first frame (256 x 256), and the surface the page picks there.
const nlohmann::json kMiddle = nlohmann::json::array({{{"mode", "baked"}, {"pixels", {{128, 128}}}}});
std::string middle_surface(const nlohmann::json& result) {
  const nlohmann::json& pick = result["steps"][0]["pixels"][0]["pick"];
  return pick.is_null() ? "nothing" : pick["surface"].get<std::string>();
}

// The first view: the scene's own camera (the Cornell box's); for a scene without one
// (the classroom), the view radbake chose for the display file, inside the largest room.
TEST(View, TheFirstViewIsTheScenesCameraElseInsideItsLargestRoom) {
  const std::string cornell = cornell_bake("view_first_cornell");
  {
    ViewServer server({cornell});
    ASSERT_GT(server.port(), 0);
    const nlohmann::json result = drive_page(server, kMiddle);
    ASSERT_FALSE(result.is_null());
    const std::vector<double> eye = result["firstCamera"], expected = {0.278, 0.273, -0.8};
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(eye[size_t(k)], expected[size_t(k)], 1e-4) << result["firstCamera"];
    EXPECT_EQ(middle_surface(result), "tall_block") << "the Cornell box";  // its camera looks at it
  }
  const std::string classroom = test::fresh_folder("view_first_classroom") + "/out";
  const test::Outcome bake = test::radbake("bake " + test::source_path("samples/classroom/classroom.gltf") + " -o " +
                                           classroom + " --quiet --sky cie-overcast --max-page-size 256");
  ASSERT_EQ(bake.status, 0) << bake.err;
  std::ifstream report_file(classroom + "/report.json");
  const nlohmann::json report = nlohmann::json::parse(report_file);
  const nlohmann::json& view = report["display"]["camera_view"];
  ASSERT_TRUE(view.is_object()) << report["display"].dump();
  EXPECT_TRUE(view["in_room"].get<bool>());
  ViewServer server({classroom});
  ASSERT_GT(server.port(), 0);
  const nlohmann::json result = drive_page(server, kMiddle);
  ASSERT_FALSE(result.is_null());
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(double(result["firstCamera"][k]), double(view["eye"][k]), 1e-4) << result["firstCamera"];
  // Along its 9 m length from the west end, to the east wall.
  EXPECT_EQ(middle_surface(result), "wall_east") << "the classroom";
  // Inside the room (samples/classroom: 9 m x 7 m from the origin, 3 m high), not outside it as before.
  const std::vector<double> eye = result["firstCamera"];
  EXPECT_GT(eye[0], 0.0);
  EXPECT_LT(eye[0], 9.0);
  EXPECT_GT(eye[1], 0.5);
  EXPECT_LT(eye[1], 3.0);
  EXPECT_GT(eye[2], 0.0);
  EXPECT_LT(eye[2], 7.0);
  EXPECT_GT(int(result["steps"][0]["pixels"][0]["rgb"][1]), 20);  // a lit wall or floor ahead
  // A model that is no room and has no camera (tests/fixtures/open_floor.gltf under a sky): seen
  // from outside, the model in the middle.
  const std::string floor = test::fresh_folder("view_first_open_floor") + "/out";
  const test::Outcome floor_bake = test::radbake("bake " + test::source_path("tests/fixtures/open_floor.gltf") + " -o " +
                                                 floor + " --quiet --sky uniform");
  ASSERT_EQ(floor_bake.status, 0) << floor_bake.err;
  ViewServer floor_server({floor});
  ASSERT_GT(floor_server.port(), 0);
  const nlohmann::json outside = drive_page(floor_server, kMiddle);
  ASSERT_FALSE(outside.is_null());
  EXPECT_EQ(middle_surface(outside), "floor") << "the open floor";
}

// "Lightmap only" shows the page in colour (the red wall's bleeding is what a bake is about), and
// the exposure slider's range comes from the bake's light: at its lowest nothing the camera sees
// clips, at its highest the dim texels reach white.
TEST(View, TheLightmapIsShownInColourWithAnExposureRangeFromTheData) {
  const std::string folder = cornell_bake("view_colour");
  ViewServer server({folder});
  ASSERT_GT(server.port(), 0);
  const nlohmann::json result = drive_page(server, nlohmann::json::array({
      {{"mode", "lightmap"}, {"ev", -1}, {"pixels", kWalls}},
      {{"mode", "lightmap"}, {"ev", "lowest"}, {"pixels", kWalls}},
      {{"mode", "lightmap"}, {"ev", "highest"}, {"pixels", kWalls}},
  }));
  ASSERT_FALSE(result.is_null());
  // Each pixel's colour is its texel's: red over green as the EXR holds it, the pixel's sRGB
  // linearised (a grey view gave 1 everywhere).
  const LightmapPage page = read_lightmap_exr(folder + "/cornell_box_lightmap_0.exr");
  auto linear = [](int srgb) {
    const double c = srgb / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  double most_tinted = 0;
  for (const nlohmann::json& p : result["steps"][0]["pixels"]) {
    ASSERT_FALSE(p["pick"].is_null()) << p.dump();
    const Rgb texel = page.texels[size_t(p["pick"]["texel"][1]) * size_t(page.width) + size_t(p["pick"]["texel"][0])];
    const double expected = texel.x / texel.y, shown = linear(p["rgb"][0]) / linear(p["rgb"][1]);
    RecordProperty("texel_r_over_g_" + std::to_string(int(p["x"])), std::to_string(expected));
    // 4% bounds 8-bit rounding of two channels above 60 of 255.
    EXPECT_NEAR(shown / expected, 1.0, 0.04) << p.dump() << " texel " << texel.x << " " << texel.y << " " << texel.z;
    most_tinted = std::max(most_tinted, std::fabs(expected - 1));
  }
  EXPECT_GT(most_tinted, 0.1);  // some texel there is tinted, so a grey view would fail
  const std::vector<double> range = result["evRange"];
  EXPECT_LT(range[0], range[2]);
  EXPECT_GT(range[1], range[2]);
  for (const nlohmann::json& p : result["steps"][1]["pixels"])
    for (int c = 0; c < 3; ++c) EXPECT_LT(int(p["rgb"][c]), 200) << "clipped at the lowest EV " << range[0] << ": " << p.dump();
  for (const nlohmann::json& p : result["steps"][2]["pixels"])
    EXPECT_EQ(std::max({int(p["rgb"][0]), int(p["rgb"][1]), int(p["rgb"][2])}), 255) << "at the highest EV " << range[1] << ": " << p.dump();
}

TEST(View, ExposureWalkingAndTheScreenshotButtonDoWhatTheySay) {
  const std::string folder = cornell_bake("view_controls");
  ViewServer server({folder});
  ASSERT_GT(server.port(), 0);
  const nlohmann::json result = drive_page(server, nlohmann::json::array({
      {{"mode", "lightmap"}, {"ev", 0}, {"pixels", {{128, 62}}}},
      {{"mode", "lightmap"}, {"ev", -1}, {"pixels", {{128, 62}}}},
      {{"mode", "baked"}, {"ev", 0}, {"walk", true}, {"hold", "w"}, {"button", true}},
  }));
  ASSERT_FALSE(result.is_null());
  // One EV less halves the display value: the back wall's linear value, from its sRGB pixel.
  auto linear = [](int srgb) {
    const double c = srgb / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  const int at_0 = result["steps"][0]["pixels"][0]["rgb"][1], at_minus_1 = result["steps"][1]["pixels"][0]["rgb"][1];
  ASSERT_GT(at_0, 40);
  ASSERT_LT(at_0, 255);  // not clipped
  // 2/255 in sRGB bounds the rounding of both pixels.
  EXPECT_NEAR(linear(at_minus_1) / linear(at_0), 0.5, 0.03) << at_0 << " " << at_minus_1;
  // Walking forward (W) from the sample's camera, which looks along +z: it moved that way.
  const nlohmann::json &before = result["steps"][1]["camera"], &after = result["steps"][2]["camera"];
  EXPECT_GT(double(after[2]) - double(before[2]), 0.01) << before << " " << after;
  EXPECT_NEAR(double(after[1]), double(before[1]), 1e-6);  // along the ground
  // The screenshot button saves a PNG of the view.
  EXPECT_GT(int(result["steps"][2]["download"]), 1000);
}

TEST(View, ComparingABakeWithAFivePercentBrighterLampShowsTheDifference) {
  const std::string a = cornell_bake("view_compare_a");
  const std::string b = cornell_bake("view_compare_b", "--emission-scale 1.05");
  ViewServer server({a, b});
  ASSERT_GT(server.port(), 0);
  const nlohmann::json result = drive_page(server, nlohmann::json::array({
      {{"mode", "difference"}, {"pixels", kWalls}},
      {{"mode", "baked"}, {"compare", "split"}, {"split", 1.0}, {"pixels", kWalls}},
      {{"mode", "baked"}, {"compare", "split"}, {"split", 0.0}, {"pixels", kWalls}},
  }));
  ASSERT_FALSE(result.is_null());
  for (const nlohmann::json& p : result["steps"][0]["pixels"]) {
    // +5% against radbake diff's full colour at 10%: halfway from white to red, linear (1, 0.5,
    // 0.5), sRGB (255, 188, 188); 12 of 255 bounds the bakes' own noise (a seed's worth, ~1%).
    EXPECT_NEAR(int(p["rgb"][0]), 255, 2) << p.dump();
    EXPECT_NEAR(int(p["rgb"][1]), 188, 12) << p.dump();
    EXPECT_NEAR(int(p["rgb"][2]), 188, 12) << p.dump();
  }
  // Split all the way one way, then the other: A, then B, brighter.
  for (size_t k = 0; k < kWalls.size(); ++k) {
    const nlohmann::json &left = result["steps"][1]["pixels"][k]["rgb"], &right = result["steps"][2]["pixels"][k]["rgb"];
    EXPECT_GT(int(right[0]) + int(right[1]) + int(right[2]), int(left[0]) + int(left[1]) + int(left[2])) << k;
  }
}

TEST(View, LightProbesAreDrawnAsSpheresLitByTheirOwnLight) {
  const std::string folder = cornell_bake("view_probes", "--probes 0.15");
  const nlohmann::json probes = nlohmann::json::parse(test::slurp(folder + "/cornell_box_probes.json"));
  ASSERT_GT(probes["count"].get<int>(), 4);
  ViewServer server({folder});
  ASSERT_GT(server.port(), 0);
  // The three nearest the camera (it looks along +Z from z = -0.8), so no block hides them.
  std::vector<size_t> nearest(probes["probes"].size());
  for (size_t k = 0; k < nearest.size(); ++k) nearest[k] = k;
  std::sort(nearest.begin(), nearest.end(), [&](size_t a, size_t b) {
    return probes["probes"][a]["position"][2].get<double>() < probes["probes"][b]["position"][2].get<double>();
  });
  nearest.resize(3);
  const nlohmann::json result = drive_page(server, nlohmann::json::array({{{"mode", "baked"}, {"probes", nearest}}}));
  ASSERT_FALSE(result.is_null());
  const nlohmann::json& step = result["steps"][0];
  EXPECT_EQ(step["probeCount"], probes["count"]);
  ASSERT_EQ(step["probes"].size(), 3u);
  for (size_t k = 0; k < 3; ++k) {
    // Each sphere stands where its probe is, and showing it changes the pixel there.
    const nlohmann::json& p = step["probes"][k];
    for (size_t a = 0; a < 3; ++a)
      EXPECT_NEAR(p["position"][a].get<double>(), probes["probes"][nearest[k]]["position"][a].get<double>(), 1e-4);
    EXPECT_NE(p["shown"], p["hidden"]) << p.dump();
    // Lit, not black: a white sphere under the room's light.
    EXPECT_GT(p["shown"][0].get<int>() + p["shown"][1].get<int>() + p["shown"][2].get<int>(), 60) << p.dump();
  }
}

}  // namespace
}  // namespace radbake
