// Which file a request of `radbake view` may read: one inside a folder it was given, named by a
// relative path with no way out of it (no "..", no absolute path, no symbolic link leading
// elsewhere), and nothing else.
#pragma once

#include <filesystem>
#include <string>

namespace radbake {

enum class Refusal {
  None,
  Forbidden,  // a way out of the folder: HTTP 403
  NotFound,   // nothing there, or not a regular file: HTTP 404
};

struct ServedFile {
  std::filesystem::path path;  // canonical, when served
  Refusal refusal = Refusal::None;
};

// `relative` as the request names it, URL-decoded, '/'-separated.
ServedFile served_file(const std::filesystem::path& root, const std::string& relative);

}  // namespace radbake
