#include "cli/share_folder.h"

#include <string>
#include <vector>

#include "base/errors.h"

namespace radbake {

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> share_folder_candidates() {
  std::error_code error;
  const fs::path executable = fs::read_symlink("/proc/self/exe", error);
  if (error) return {};
  const fs::path bin = executable.parent_path();
  return {bin.parent_path() / "share" / "radbake", bin / "share" / "radbake"};
}

}  // namespace

fs::path viewer_share_folder() {
  std::string looked;
  for (const fs::path& folder : share_folder_candidates()) {
    std::error_code error;
    if (fs::is_regular_file(folder / "web" / "viewer" / "index.html", error) &&
        fs::is_regular_file(folder / "web" / "three" / "build" / "three.module.js", error))
      return folder;
    looked += (looked.empty() ? "" : " or ") + folder.string();
  }
  throw InputError("the viewer's page and three.js are not beside radbake (looked in " + clipped(looked, 400) +
                   "): install it with cmake --install, or build it with three.js in web/node_modules (./dev sample)");
}

}  // namespace radbake
