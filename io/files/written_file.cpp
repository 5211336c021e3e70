#include "io/files/written_file.h"

#include <sys/statvfs.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "base/errors.h"

namespace radbake {
namespace {

// Below this much free space a failed write is put down to a full disk: a page, a glTF or a
// debug dump each needs more than this, and what is written when the disk is full fails here.
constexpr unsigned long long kNearlyFullBytes = 16ull << 20;

}  // namespace

void refuse_unwritten(const std::string& path) {
  const int error = errno;
  std::string reason;
  struct statvfs disk {};
  const std::string folder = std::filesystem::path(path).parent_path().string();
  if (::statvfs(folder.empty() ? "." : folder.c_str(), &disk) == 0 &&
      (unsigned long long)disk.f_bavail * disk.f_frsize < kNearlyFullBytes) {
    char free[64];
    std::snprintf(free, sizeof free, "%.1f MB", double(disk.f_bavail) * double(disk.f_frsize) / 1e6);
    reason = "the disk is full (" + std::string(free) + " free)";
  } else if (error == ENOSPC || error == EDQUOT) {
    reason = "the disk is full";
  } else if (error == EROFS || error == EACCES || error == EPERM || error == EIO || error == EFBIG) {
    reason = std::strerror(error);
  } else {
    reason = "the write failed";
  }
  throw OutputError(path, reason);
}

void close_written(std::ofstream& out, const std::string& path) {
  errno = 0;
  out.close();
  if (out.fail()) refuse_unwritten(path);
}

}  // namespace radbake
