// Internal to io/: the file as tinygltf parsed it, plus its JSON text for faithful rewriting.
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <vector>

#include "io/gltf.h"

namespace radbake {

struct GltfSource {
  std::string path;
  std::string base_dir;
  bool binary = false;
  tinygltf::Model model;
  std::string json_text;          // the JSON document (the JSON chunk of a .glb)
  std::vector<uint8_t> glb_bin;   // the BIN chunk of a .glb
};

// Packed elements of an accessor (sparse substitution applied), byteStride removed.
// Throws InputError when it reads outside its buffer.
std::vector<uint8_t> accessor_bytes(const tinygltf::Model& model, int accessor_index, size_t* element_size);

// Accessor values as floats (normalized integers mapped to [0,1] / [-1,1]), `components` per element.
std::vector<float> accessor_floats(const tinygltf::Model& model, int accessor_index, int* components);

std::vector<uint32_t> accessor_indices(const tinygltf::Model& model, int accessor_index);

size_t component_count(int type);
size_t component_size(int component_type);

}  // namespace radbake
