// Building a glTF's binary data: accessors and buffer views appended to one new buffer, with the
// bounds validators expect. Shared by the engine file's writer and the display file's.
#pragma once

#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <vector>

namespace radbake {

constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;
constexpr int kUnsignedShort = 5123, kUnsignedInt = 5125, kFloat = 5126;

// min and max of each component, written as values of the component type (floats as the float
// values themselves, so validators compare like with like). NaN and infinities are left out (a
// component with no finite value gets 0): the bounds are never non-finite.
void add_bounds(nlohmann::ordered_json& accessor, const std::vector<uint8_t>& bytes, size_t count, int component_type);

class BinaryWriter {
 public:
  BinaryWriter(nlohmann::ordered_json& doc, int buffer_index) : doc_(doc), buffer_(buffer_index) {}

  // A buffer view over `bytes` (aligned to 4) and an accessor over it; returns the accessor.
  int add(const std::vector<uint8_t>& bytes, size_t count, const char* type, int component_type, bool normalized,
          int target, bool with_bounds);
  // A buffer view alone (an image's bytes); returns its index.
  int add_view(const std::vector<uint8_t>& bytes);

  const std::vector<uint8_t>& data() const { return data_; }

 private:
  nlohmann::ordered_json& doc_;
  int buffer_;
  std::vector<uint8_t> data_;
};

template <typename T>
std::vector<uint8_t> as_bytes(const std::vector<T>& v) {
  std::vector<uint8_t> out(v.size() * sizeof(T));
  if (!out.empty()) std::memcpy(out.data(), v.data(), out.size());
  return out;
}

// Triangle indices as the narrowest type that holds them: (bytes, component type).
std::pair<std::vector<uint8_t>, int> index_bytes(const std::vector<uint32_t>& triangles, size_t vertex_count);

}  // namespace radbake
