#include <algorithm>
#include <cstring>
#include <string>

#include "base/errors.h"
#include "io/gltf/gltf_source.h"

namespace radbake {

size_t component_count(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
  }
}

size_t component_size(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

namespace {

[[noreturn]] void bad(int accessor, const std::string& what) {
  throw InputError("accessor " + std::to_string(accessor) + " " + what);
}

// Bytes of a buffer view, checked against its buffer.
const uint8_t* view_data(const tinygltf::Model& model, int view_index, int accessor, size_t* length) {
  if (view_index < 0 || size_t(view_index) >= model.bufferViews.size()) bad(accessor, "names a missing bufferView");
  const tinygltf::BufferView& view = model.bufferViews[size_t(view_index)];
  if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size()) bad(accessor, "uses a bufferView with a missing buffer");
  const tinygltf::Buffer& buffer = model.buffers[size_t(view.buffer)];
  if (view.byteOffset > buffer.data.size() || view.byteLength > buffer.data.size() - view.byteOffset)
    bad(accessor, "uses bufferView " + std::to_string(view_index) + ", which runs past the end of buffer " +
                      std::to_string(view.buffer));
  *length = view.byteLength;
  return buffer.data.data() + view.byteOffset;
}

// Reads `count` elements of `element_size` bytes at `stride` from a view, bounds-checked.
void copy_elements(const uint8_t* data, size_t length, size_t offset, size_t stride, size_t count,
                   size_t element_size, uint8_t* out, int accessor) {
  if (count == 0) return;
  if (offset > length || (count - 1) > (length - offset) / stride || (count - 1) * stride + element_size > length - offset)
    bad(accessor, "reads past the end of its bufferView");
  for (size_t i = 0; i < count; ++i) std::memcpy(out + i * element_size, data + offset + i * stride, element_size);
}

}  // namespace

std::vector<uint8_t> accessor_bytes(const tinygltf::Model& model, int index, size_t* element_size_out) {
  if (index < 0 || size_t(index) >= model.accessors.size()) bad(index, "does not exist");
  const tinygltf::Accessor& a = model.accessors[size_t(index)];
  const size_t element_size = component_count(a.type) * component_size(a.componentType);
  if (element_size == 0) bad(index, "has an unknown type or component type");
  *element_size_out = element_size;
  std::vector<uint8_t> out(a.count * element_size, 0);  // no bufferView: zeros (glTF 2.0 section 3.6.2.3)
  if (a.bufferView >= 0) {
    size_t length;
    const uint8_t* data = view_data(model, a.bufferView, index, &length);
    size_t stride = model.bufferViews[size_t(a.bufferView)].byteStride;
    copy_elements(data, length, a.byteOffset, stride ? stride : element_size, a.count, element_size, out.data(), index);
  }
  if (a.sparse.isSparse && a.sparse.count > 0) {
    const size_t count = size_t(a.sparse.count);
    const size_t index_size = component_size(a.sparse.indices.componentType);
    if (index_size == 0) bad(index, "has sparse indices of an unknown type");
    std::vector<uint8_t> indices(count * index_size), values(count * element_size);
    size_t length;
    const uint8_t* data = view_data(model, a.sparse.indices.bufferView, index, &length);
    copy_elements(data, length, size_t(a.sparse.indices.byteOffset), index_size, count, index_size, indices.data(), index);
    data = view_data(model, a.sparse.values.bufferView, index, &length);
    copy_elements(data, length, size_t(a.sparse.values.byteOffset), element_size, count, element_size, values.data(), index);
    for (size_t k = 0; k < count; ++k) {
      uint32_t target = 0;
      if (index_size == 1) target = indices[k];
      else if (index_size == 2) { uint16_t v; std::memcpy(&v, &indices[2 * k], 2); target = v; }
      else std::memcpy(&target, &indices[4 * k], 4);
      if (target >= a.count) bad(index, "has a sparse index out of range");
      std::memcpy(&out[target * element_size], &values[k * element_size], element_size);
    }
  }
  return out;
}

std::vector<float> accessor_floats(const tinygltf::Model& model, int index, int* components) {
  size_t element_size;
  std::vector<uint8_t> bytes = accessor_bytes(model, index, &element_size);
  const tinygltf::Accessor& a = model.accessors[size_t(index)];
  const size_t n = component_count(a.type);
  *components = int(n);
  std::vector<float> out(a.count * n);
  for (size_t i = 0; i < out.size(); ++i) {
    const uint8_t* p = bytes.data() + i * component_size(a.componentType);
    float v = 0;
    switch (a.componentType) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: std::memcpy(&v, p, 4); break;
      case TINYGLTF_COMPONENT_TYPE_BYTE: { int8_t x; std::memcpy(&x, p, 1); v = a.normalized ? std::max(x / 127.0f, -1.0f) : x; break; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: v = a.normalized ? *p / 255.0f : *p; break;
      case TINYGLTF_COMPONENT_TYPE_SHORT: { int16_t x; std::memcpy(&x, p, 2); v = a.normalized ? std::max(x / 32767.0f, -1.0f) : x; break; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { uint16_t x; std::memcpy(&x, p, 2); v = a.normalized ? x / 65535.0f : x; break; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { uint32_t x; std::memcpy(&x, p, 4); v = float(x); break; }
    }
    out[i] = v;
  }
  return out;
}

std::vector<uint32_t> accessor_indices(const tinygltf::Model& model, int index) {
  size_t element_size;
  std::vector<uint8_t> bytes = accessor_bytes(model, index, &element_size);
  const tinygltf::Accessor& a = model.accessors[size_t(index)];
  if (a.type != TINYGLTF_TYPE_SCALAR) bad(index, "holds indices but is not SCALAR");
  std::vector<uint32_t> out(a.count);
  for (size_t i = 0; i < a.count; ++i) {
    switch (a.componentType) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: out[i] = bytes[i]; break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { uint16_t v; std::memcpy(&v, &bytes[2 * i], 2); out[i] = v; break; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: std::memcpy(&out[i], &bytes[4 * i], 4); break;
      default: bad(index, "holds indices of a type other than unsigned byte, short or int");
    }
  }
  return out;
}

std::vector<uint32_t> triangle_list(const std::vector<uint32_t>& idx, int mode) {
  std::vector<uint32_t> tri;
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    tri.assign(idx.begin(), idx.begin() + long(idx.size() / 3 * 3));
  } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    for (size_t i = 0; i + 2 < idx.size(); ++i) tri.insert(tri.end(), {idx[i], idx[i + 1 + i % 2], idx[i + 2 - i % 2]});
  } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
    for (size_t i = 1; i + 1 < idx.size(); ++i) tri.insert(tri.end(), {idx[i], idx[i + 1], idx[0]});
  }
  return tri;
}

}  // namespace radbake
