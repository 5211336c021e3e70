#include "io/files/regular_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "base/errors.h"

namespace radbake {

RegularFile::RegularFile(const std::string& path, const std::string& what) {
  fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) throw InputError(what + " '" + clipped(path) + "' cannot be opened: " + std::strerror(errno));
  struct stat st {};
  if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd_);
    fd_ = -1;
    throw InputError(what + " '" + clipped(path) + "' is not a regular file (a FIFO, a device or a folder)");
  }
  size_ = uint64_t(st.st_size);
  links_ = uint64_t(st.st_nlink);
  // Reads of a regular file never block; the flag goes for plain semantics all the same.
  ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) & ~O_NONBLOCK);
}

RegularFile::~RegularFile() {
  if (fd_ >= 0) ::close(fd_);
}

bool RegularFile::read(void* into, uint64_t bytes) {
  char* at = static_cast<char*>(into);
  while (bytes > 0) {
    const ssize_t got = ::read(fd_, at, size_t(std::min<uint64_t>(bytes, uint64_t(1) << 30)));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return false;
    at += got;
    bytes -= uint64_t(got);
  }
  return true;
}

bool RegularFile::read_at(uint64_t offset, void* into, uint64_t bytes) {
  char* at = static_cast<char*>(into);
  while (bytes > 0) {
    const ssize_t got = ::pread(fd_, at, size_t(std::min<uint64_t>(bytes, uint64_t(1) << 30)), off_t(offset));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return false;
    at += got;
    offset += uint64_t(got);
    bytes -= uint64_t(got);
  }
  return true;
}

namespace {

template <typename Bytes>
Bytes read_whole(const std::string& path, const std::string& what, uint64_t most_bytes) {
  RegularFile file(path, what);
  if (file.size() > most_bytes)
    throw InputError(what + " '" + clipped(path) + "' holds " + std::to_string(file.size()) + " bytes, more than the " +
                     std::to_string(most_bytes) + " it may");
  Bytes bytes(size_t(file.size()), 0);
  if (!file.read(bytes.data(), bytes.size())) throw InputError(what + " '" + clipped(path) + "' could not be read whole");
  return bytes;
}

}  // namespace

std::string read_regular_file(const std::string& path, const std::string& what, uint64_t most_bytes) {
  return read_whole<std::string>(path, what, most_bytes);
}

std::vector<uint8_t> read_regular_bytes(const std::string& path, const std::string& what, uint64_t most_bytes) {
  return read_whole<std::vector<uint8_t>>(path, what, most_bytes);
}

}  // namespace radbake
