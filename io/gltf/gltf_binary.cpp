#include "io/gltf/gltf_binary.h"

#include <algorithm>
#include <cmath>

#include "io/gltf/gltf_source.h"

namespace radbake {
namespace {

using json = nlohmann::ordered_json;

double component(const uint8_t* p, int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: { int8_t v; std::memcpy(&v, p, 1); return v; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return *p;
    case TINYGLTF_COMPONENT_TYPE_SHORT: { int16_t v; std::memcpy(&v, p, 2); return v; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { uint16_t v; std::memcpy(&v, p, 2); return v; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { uint32_t v; std::memcpy(&v, p, 4); return v; }
    default: { float v; std::memcpy(&v, p, 4); return v; }
  }
}

}  // namespace

void add_bounds(json& accessor, const std::vector<uint8_t>& bytes, size_t count, int component_type) {
  const size_t cs = component_size(component_type);
  const size_t n = bytes.size() / count / cs;
  std::vector<double> lo(n, INFINITY), hi(n, -INFINITY);
  for (size_t i = 0; i < count; ++i)
    for (size_t c = 0; c < n; ++c) {
      double v = component(&bytes[(i * n + c) * cs], component_type);
      if (!std::isfinite(v)) continue;  // JSON has no NaN or infinity (nlohmann would write null)
      lo[c] = std::min(lo[c], v);
      hi[c] = std::max(hi[c], v);
    }
  accessor["min"] = json::array();
  accessor["max"] = json::array();
  for (size_t c = 0; c < n; ++c) {
    if (lo[c] > hi[c]) lo[c] = hi[c] = 0;
    accessor["min"].push_back(component_type == TINYGLTF_COMPONENT_TYPE_FLOAT ? json(float(lo[c])) : json(lo[c]));
    accessor["max"].push_back(component_type == TINYGLTF_COMPONENT_TYPE_FLOAT ? json(float(hi[c])) : json(hi[c]));
  }
}

int BinaryWriter::add_view(const std::vector<uint8_t>& bytes) {
  while (data_.size() % 4) data_.push_back(0);
  doc_["bufferViews"].push_back({{"buffer", buffer_}, {"byteOffset", data_.size()}, {"byteLength", bytes.size()}});
  data_.insert(data_.end(), bytes.begin(), bytes.end());
  return int(doc_["bufferViews"].size() - 1);
}

int BinaryWriter::add(const std::vector<uint8_t>& bytes, size_t count, const char* type, int component_type,
                      bool normalized, int target, bool with_bounds) {
  const int view = add_view(bytes);
  if (target) doc_["bufferViews"][size_t(view)]["target"] = target;
  json accessor = {{"bufferView", view}, {"componentType", component_type}, {"count", count}, {"type", type}};
  if (normalized) accessor["normalized"] = true;
  if (with_bounds && count > 0) add_bounds(accessor, bytes, count, component_type);
  doc_["accessors"].push_back(accessor);
  return int(doc_["accessors"].size() - 1);
}

std::pair<std::vector<uint8_t>, int> index_bytes(const std::vector<uint32_t>& triangles, size_t vertex_count) {
  if (vertex_count < 65536) {
    std::vector<uint16_t> narrow(triangles.begin(), triangles.end());
    return {as_bytes(narrow), kUnsignedShort};
  }
  return {as_bytes(triangles), kUnsignedInt};
}

}  // namespace radbake
