#include "cli/view_command.h"

#include <httplib.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <thread>

#include "base/errors.h"
#include "cli/connection_guard.h"
#include "cli/interrupts.h"
#include "cli/served_files.h"
#include "cli/share_folder.h"
#include "io/files/regular_file.h"

extern char** environ;

namespace radbake {
namespace {

namespace fs = std::filesystem;

const char* content_type(const fs::path& file) {
  const std::string ext = file.extension().string();
  if (ext == ".html") return "text/html; charset=utf-8";
  if (ext == ".js" || ext == ".mjs") return "text/javascript; charset=utf-8";
  if (ext == ".json") return "application/json";
  if (ext == ".gltf") return "model/gltf+json";
  if (ext == ".glb") return "model/gltf-binary";
  if (ext == ".png") return "image/png";
  if (ext == ".csv") return "text/csv";
  if (ext == ".css") return "text/css";
  return "application/octet-stream";  // .bin, .exr
}

// One range a request, inside the file. Several ranges multiplied what one request cost (cpp-httplib
// 0.11 answered 200 ranges "0-" of a 5 MB file with 1 GB), and its multipart answers from a content
// provider are wrong besides (every part's total "/0", an open end sent as 2^64 - 1). Browsers and
// the page ask for one range at a time. An end past the file's is refused too, where RFC 9110 would
// cut it short: httplib 0.11 would promise the bytes up to it.
bool one_range_inside(const httplib::Ranges& asked, uint64_t size) {
  if (asked.size() != 1) return false;
  const auto [first, last] = asked.front();
  if (first < 0) return last > 0;  // "-N": the last N bytes
  return uint64_t(first) < size && (last < 0 || (last >= first && uint64_t(last) < size));
}

// A file as it is sent: opened as a regular file with one name (a hard link made in the folder to
// a file elsewhere would let the page read it), read in chunks as the connection takes them, never
// whole, and never compressed. The server listens on 127.0.0.1 only, where compressing costs the
// server more time than the bytes it saves (brotli took 2.35 CPU s for three.core.js, per
// request). Its ETag (size and modification time) lets a browser revalidate what it holds with one
// request; "no-cache" makes it ask, so a rebaked folder shows its new files.
void send_file(const fs::path& path, const httplib::Request& request, httplib::Response& response) {
  std::shared_ptr<RegularFile> file;
  try {
    file = std::make_shared<RegularFile>(path.string(), "served file");
  } catch (const InputError&) {
    response.status = 404;
    response.set_content("not found\n", "text/plain");
    return;
  }
  if (file->links() > 1) {
    response.status = 403;
    response.set_content("forbidden: the file has another name elsewhere (a hard link)\n", "text/plain");
    return;
  }
  const uint64_t size = file->size();
  std::error_code error;
  const auto modified = fs::last_write_time(path, error).time_since_epoch().count();
  const std::string tag = "\"" + std::to_string(size) + "-" + std::to_string(modified) + "\"";
  response.set_header("ETag", tag);
  response.set_header("Cache-Control", "no-cache");
  if (request.get_header_value("If-None-Match") == tag) {
    response.status = 304;
    return;
  }
  if (!request.ranges.empty() && !one_range_inside(request.ranges, size)) {
    response.status = 416;
    response.set_header("Content-Range", "bytes */" + std::to_string(size));
    return;
  }
  if (size == 0) {
    response.set_content("", content_type(path));
    return;
  }
  response.set_content_provider(size_t(size), content_type(path),
                                [file](size_t offset, size_t length, httplib::DataSink& sink) {
                                  char chunk[1 << 16];
                                  const size_t bytes = std::min(length, sizeof chunk);
                                  return file->read_at(offset, chunk, bytes) && sink.write(chunk, bytes);
                                });
}

// A route that serves what served_file allows under `root`, the rest of the path being the file.
void serve_folder(httplib::Server& server, const std::string& prefix, const fs::path& root) {
  server.Get(prefix + "(.*)", [root](const httplib::Request& request, httplib::Response& response) {
    const ServedFile file = served_file(root, request.matches[1].str());
    if (file.refusal != Refusal::None) {
      response.status = file.refusal == Refusal::Forbidden ? 403 : 404;
      response.set_content(file.refusal == Refusal::Forbidden ? "forbidden\n" : "not found\n", "text/plain");
      return;
    }
    send_file(file.path, request, response);
  });
}

// What the page needs to know of each bake: its name and its report.json.
nlohmann::json bakes_json(const std::vector<fs::path>& folders) {
  nlohmann::json out = nlohmann::json::array();
  for (size_t k = 0; k < folders.size(); ++k) {
    nlohmann::json report = nlohmann::json::parse(
        read_regular_file((folders[k] / "report.json").string(), "report", kMostReportBytes), nullptr, false);
    if (!report.is_object())
      throw InputError("'" + clipped(folders[k].string()) + "/report.json' is not a radbake report (not a JSON object)");
    std::string name;
    for (const auto& f : report.value("files", nlohmann::json::array()))
      if (f.is_string() && f.get<std::string>().size() > 5 &&
          f.get<std::string>().compare(f.get<std::string>().size() - 5, 5, ".gltf") == 0)
        name = f.get<std::string>();
    out.push_back({{"url", k == 0 ? "/a/" : "/b/"}, {"folder", folders[k].filename().string()}, {"gltf", name},
                   {"report", report}});
  }
  return out;
}

void open_in_browser(const std::string& url) {
  pid_t pid = 0;
  const char* argv[] = {"xdg-open", url.c_str(), nullptr};
  if (posix_spawnp(&pid, "xdg-open", nullptr, nullptr, const_cast<char* const*>(argv), environ) != 0) {
    std::fprintf(stderr, "radbake: could not start xdg-open: open %s yourself\n", url.c_str());
    return;
  }
  std::thread([pid] { waitpid(pid, nullptr, 0); }).detach();
}

}  // namespace

int run_view(const ViewCommand& command) {
  std::vector<fs::path> folders;
  for (const std::string& folder : command.folders) {
    std::error_code error;
    if (!fs::is_regular_file(fs::path(folder) / "report.json", error))
      throw InputError("'" + clipped(folder) + "' is not a radbake output folder (it has no report.json)");
    folders.push_back(fs::canonical(folder));
  }
  const fs::path web = viewer_share_folder() / "web";

  httplib::Server server;
  ConnectionGuard(ConnectionLimits{}).guard(server);
  server.set_payload_max_length(1 << 16);  // the page only asks: no request carries a body
  server.Get("/favicon.ico", [](const httplib::Request&, httplib::Response& response) { response.status = 204; });
  server.Get("/", [&](const httplib::Request& request, httplib::Response& response) {
    send_file(web / "viewer" / "index.html", request, response);
  });
  const nlohmann::json bakes = bakes_json(folders);
  for (const auto& bake : bakes)
    if (bake["gltf"].get<std::string>().empty())
      throw InputError("'" + clipped(bake["folder"].get<std::string>()) + "' lists no .gltf in its report.json");
  server.Get("/api/bakes", [&](const httplib::Request&, httplib::Response& response) {
    response.set_content(bakes.dump(), "application/json");
  });
  serve_folder(server, "/viewer/", web / "viewer");
  server.Get("/radbake-lightmap.js", [&](const httplib::Request& request, httplib::Response& response) {
    send_file(web / "radbake-lightmap.js", request, response);
  });
  serve_folder(server, "/three/", web / "three");
  serve_folder(server, "/a/", folders[0]);
  if (folders.size() > 1) serve_folder(server, "/b/", folders[1]);

  // Only this machine: the page reads the folders' files, which are nobody else's business.
  const char* host = "127.0.0.1";
  int port = command.port;
  if (port > 0) {
    if (!server.bind_to_port(host, port)) throw InputError("cannot listen on 127.0.0.1:" + std::to_string(port) + " (in use?)");
  } else {
    port = server.bind_to_any_port(host);
    if (port <= 0) throw InputError("cannot listen on 127.0.0.1");
  }
  const std::string url = "http://127.0.0.1:" + std::to_string(port) + "/";
  std::printf("radbake: viewing at %s (Ctrl-C stops)\n", url.c_str());
  std::fflush(stdout);
  if (command.open) open_in_browser(url);

  std::atomic<bool> done{false};
  std::thread watcher([&] {
    while (!done && !interrupted()) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    server.stop();
  });
  server.listen_after_bind();
  done = true;
  watcher.join();
  return interrupted() ? interrupted_exit_status() : 0;
}

}  // namespace radbake
