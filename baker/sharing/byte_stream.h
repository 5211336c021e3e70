// Plain data to bytes and back, for what processes exchange (team.h) and what checkpoints keep
// (stage_store.h). Only trivially copyable values and vectors of them, in this machine's byte
// order: a team runs one build on one kind of machine. Reading past the end throws, so a
// truncated checkpoint is an error, never a read out of bounds.
#pragma once

#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "baker/sharing/team.h"

namespace radbake {

class ByteWriter {
 public:
  template <typename T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* p = reinterpret_cast<const uint8_t*>(&value);
    bytes_.insert(bytes_.end(), p, p + sizeof(T));
  }
  template <typename T>
  void put_vector(const std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>);
    put(uint64_t(values.size()));
    const auto* p = reinterpret_cast<const uint8_t*>(values.data());
    bytes_.insert(bytes_.end(), p, p + values.size() * sizeof(T));
  }
  void put_bytes(const Bytes& b) { put_vector(b); }
  Bytes& bytes() { return bytes_; }

 private:
  Bytes bytes_;
};

// Thrown when bytes end before what they should hold; the checkpoint reader names the file.
struct TruncatedBytes : std::runtime_error {
  TruncatedBytes() : std::runtime_error("the data ends early") {}
};

class ByteReader {
 public:
  explicit ByteReader(const Bytes& bytes) : data_(bytes.data()), size_(bytes.size()) {}

  template <typename T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    T value;
    take(&value, sizeof(T));
    return value;
  }
  template <typename T>
  std::vector<T> get_vector() {
    static_assert(std::is_trivially_copyable_v<T>);
    const uint64_t count = get<uint64_t>();
    // Sized from what is left, never from what the bytes claim.
    if (count > (size_ - at_) / sizeof(T)) throw TruncatedBytes();
    std::vector<T> values(count);
    take(values.data(), count * sizeof(T));
    return values;
  }
  Bytes get_bytes() { return get_vector<uint8_t>(); }
  bool done() const { return at_ == size_; }

 private:
  void take(void* to, size_t n) {
    if (n > size_ - at_) throw TruncatedBytes();
    if (n > 0) std::memcpy(to, data_ + at_, n);
    at_ += n;
  }
  const uint8_t* data_;
  size_t size_, at_ = 0;
};

}  // namespace radbake
