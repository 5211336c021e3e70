#include "io/run/output_folder.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "base/errors.h"
#include "io/files/regular_file.h"

namespace radbake {
namespace fs = std::filesystem;
namespace {

// Why `target` must not be replaced, or "" when it may: it is absent, empty, or holds only what an
// earlier radbake wrote there. `-o ~` must never delete someone's home, nor a re-bake the notes a
// user put beside the lightmaps.
std::string obstacle(const fs::path& target, const std::string& shown) {
  std::error_code ec;
  if (!fs::exists(target, ec)) return "";
  const std::string not_ours = "output folder " + shown + " exists and is not a radbake output; choose another or remove it";
  if (!fs::is_directory(target, ec)) return not_ours;
  if (fs::is_empty(target, ec)) return "";
  nlohmann::json report;
  try {
    report = nlohmann::json::parse(read_regular_file((target / "report.json").string(), "report", kMostReportBytes), nullptr,
                                   false);
  } catch (const InputError&) {
    return not_ours;  // none, or not a regular file
  }
  if (!report.is_object() || !report.contains("generator") || report["generator"] != "radbake") return not_ours;
  if (!report.contains("files") || !report["files"].is_array())
    return "output folder " + shown + " is from a radbake that did not list the files it wrote; remove it or choose another";

  std::set<std::string> ours, our_folders;
  for (const auto& f : report["files"]) {
    if (!f.is_string()) continue;
    fs::path p = f.get<std::string>();
    ours.insert(p.generic_string());
    for (p = p.parent_path(); !p.empty(); p = p.parent_path()) our_folders.insert(p.generic_string());
  }
  std::vector<std::string> foreign;
  for (auto it = fs::recursive_directory_iterator(target, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    const std::string name = it->path().lexically_relative(target).generic_string();
    if (it->is_directory(ec) && !it->is_symlink(ec)) {
      if (our_folders.count(name)) continue;
      it.disable_recursion_pending();
      foreign.push_back(name + "/");
    } else if (!ours.count(name)) {
      foreign.push_back(name);
    }
  }
  if (ec) return "cannot read output folder " + shown + ": " + ec.message();
  if (foreign.empty()) return "";
  std::sort(foreign.begin(), foreign.end());
  std::string list;
  for (size_t k = 0; k < foreign.size() && k < 3; ++k) list += (k ? ", " : "") + clipped(foreign[k]);
  if (foreign.size() > 3) list += " and " + std::to_string(foreign.size() - 3) + " more";
  return "output folder " + shown + " holds files radbake did not write (" + list +
         "); move them out or choose another folder";
}

// Takes the lock on `path` (created if need be) and returns its descriptor.
int take_lock(const std::string& path, const std::string& shown) {
  for (;;) {
    const int fd = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) throw InputError("cannot create " + clipped(path) + ": " + std::strerror(errno));
    struct flock want {};
    want.l_type = F_WRLCK;
    want.l_whence = SEEK_SET;
    if (fcntl(fd, F_SETLK, &want) != 0) {
      const int error = errno;
      // POSIX record locks (unlike flock) say who holds them.
      struct flock holder = want;
      const bool known = fcntl(fd, F_GETLK, &holder) == 0 && holder.l_type != F_UNLCK && holder.l_pid > 0;
      close(fd);
      if (error != EACCES && error != EAGAIN)
        throw InputError("cannot lock " + clipped(path) + ": " + std::strerror(error));
      throw InputError("output folder " + shown + " is being written by another bake (" +
                       (known ? "radbake process " + std::to_string(holder.l_pid) : std::string("another process")) +
                       "); wait for it to finish or choose another folder");
    }
    // The bake before us removes the file just before it lets go of the lock; if that happened
    // between our open and our lock, we hold a file no one else can find: lock the new one.
    struct stat held {}, named {};
    if (fstat(fd, &held) == 0 && stat(path.c_str(), &named) == 0 && held.st_dev == named.st_dev &&
        held.st_ino == named.st_ino)
      return fd;
    close(fd);
  }
}

// Staging folders of `target` (".NAME.radbake-PID", and "-old" for the output a commit replaces).
bool is_staging_of(const std::string& entry, const std::string& prefix) {
  if (entry.compare(0, prefix.size(), prefix) != 0) return false;
  std::string rest = entry.substr(prefix.size());
  if (rest.size() > 4 && rest.compare(rest.size() - 4, 4, "-old") == 0) rest.resize(rest.size() - 4);
  return !rest.empty() && rest.find_first_not_of("0123456789") == std::string::npos;
}

// Removes `folder` even while another thread may still be creating files in it.
void remove_folder(const fs::path& folder) {
  std::error_code ec;
  for (int attempt = 0; attempt < 20 && fs::exists(folder, ec); ++attempt) fs::remove_all(folder, ec);
}

}  // namespace

StagedFolder::Lock::~Lock() {
  if (fd < 0) return;
  unlink(path.c_str());
  close(fd);
}

StagedFolder::StagedFolder(const std::string& target) {
  // Normalised after making it absolute, so `-o .` names the current folder, not a "." in it.
  fs::path t = fs::absolute(fs::path(target)).lexically_normal();
  if (!t.has_filename()) t = t.parent_path();
  const std::string shown = clipped(target);
  std::error_code ec;
  fs::create_directories(t.parent_path(), ec);
  if (ec) throw InputError("cannot create " + clipped(t.parent_path().string()) + ": " + ec.message());
  const std::string prefix = "." + t.filename().string() + ".radbake-";
  lock_.path = (t.parent_path() / (prefix + "lock")).string();
  lock_.fd = take_lock(lock_.path, shown);
  if (std::string why = obstacle(t, shown); !why.empty()) throw InputError(why);
  for (const auto& entry : fs::directory_iterator(t.parent_path(), ec))
    if (is_staging_of(entry.path().filename().string(), prefix)) remove_folder(entry.path());
  const fs::path staging = t.parent_path() / (prefix + std::to_string(getpid()));
  fs::create_directory(staging, ec);
  if (ec) throw InputError("cannot create " + clipped(staging.string()) + ": " + ec.message());
  given_ = target;
  target_ = t.string();
  staging_ = staging.string();
}

std::string StagedFolder::as_committed(const std::string& file) const {
  const fs::path inside = fs::path(file).lexically_relative(staging_);
  if (inside.empty() || *inside.begin() == "..") return file;
  return (fs::path(given_) / inside).string();
}

StagedFolder::~StagedFolder() {
  if (!committed_) remove_folder(staging_);
}

std::vector<std::string> StagedFolder::files() const {
  std::vector<std::string> out;
  for (const auto& entry : fs::recursive_directory_iterator(staging_))
    if (!entry.is_directory()) out.push_back(entry.path().lexically_relative(staging_).generic_string());
  std::sort(out.begin(), out.end());
  return out;
}

void StagedFolder::commit() {
  const fs::path old = staging_ + "-old";
  {
    std::lock_guard<std::mutex> lock(mutex_);
    std::error_code ec;
    const bool had_old = fs::exists(target_, ec);
    if (had_old) fs::rename(target_, old);
    fs::rename(staging_, target_, ec);
    if (ec) {
      if (had_old) fs::rename(old, target_);
      throw fs::filesystem_error("cannot move the bake into place", staging_, target_, ec);
    }
    committed_ = true;
  }
  remove_folder(old);
}

bool StagedFolder::abandon() noexcept {
  std::lock_guard<std::mutex> lock(mutex_);
  if (committed_) return false;
  remove_folder(staging_);
  unlink(lock_.path.c_str());
  return true;
}

}  // namespace radbake
