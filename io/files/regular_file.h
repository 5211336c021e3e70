// Every file radbake reads must be a regular file, checked before anything is read from it: it is
// opened without blocking (a FIFO opened for reading waits for a writer for ever) and looked at
// with fstat on that very descriptor, so a FIFO, a device (/dev/zero) or a folder, also behind a
// symbolic link, is refused with one line and no swap between the check and the read can slip in.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace radbake {

// The most radbake reads of the files it reads back whole (their sizes are facts of the file, but
// a file radbake did not write can be any size).
constexpr uint64_t kMostReportBytes = uint64_t(64) << 20;  // a report.json: kilobytes; with a million sensors, a few MB
constexpr uint64_t kMostSensorFileBytes = uint64_t(256) << 20;  // a million sensors at full precision: about 100 MB

class RegularFile {
 public:
  // Throws InputError naming `what` and the path when it cannot be opened or is not a regular file.
  RegularFile(const std::string& path, const std::string& what);
  ~RegularFile();
  RegularFile(const RegularFile&) = delete;
  RegularFile& operator=(const RegularFile&) = delete;

  uint64_t size() const { return size_; }
  // How many names the file has: a hard link made elsewhere counts.
  uint64_t links() const { return links_; }
  // Reads exactly `bytes` bytes, or returns false (the file ended first, or a read failed).
  bool read(void* into, uint64_t bytes);
  // The same from byte `offset`, without moving where read() goes on from.
  bool read_at(uint64_t offset, void* into, uint64_t bytes);

 private:
  int fd_ = -1;
  uint64_t size_ = 0;
  uint64_t links_ = 0;
};

// The whole of a regular file of at most `most_bytes` bytes (else InputError).
std::string read_regular_file(const std::string& path, const std::string& what, uint64_t most_bytes);
std::vector<uint8_t> read_regular_bytes(const std::string& path, const std::string& what, uint64_t most_bytes);

}  // namespace radbake
