// Internal to io/: the file as tinygltf parsed it, plus its JSON text for faithful rewriting.
#pragma once

#include <tiny_gltf.h>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "io/gltf/gltf_check.h"
#include "io/gltf/load_limits.h"

namespace radbake {

struct GltfSource {
  std::string path;
  std::string base_dir;
  bool binary = false;
  tinygltf::Model model;
  std::string json_text;          // the JSON document (the JSON chunk of a .glb)
  std::vector<uint8_t> glb_bin;   // the BIN chunk of a .glb
  std::vector<std::string> image_files;  // per image: the file its URI resolved to, empty if none
  std::vector<std::string> image_types;  // per image: its bytes' MIME type (image_type), empty if unread
};

// The external files a document's URIs name, resolved inside the scene's folder: the only files
// tinygltf is allowed to open (through FileAccess's callbacks) and the writer to copy.
struct FileAccess {
  std::map<std::string, std::string> by_uri;   // tinygltf's decoding of a URI -> canonical path
  std::set<std::string> allowed;               // canonical paths
  std::vector<std::string> image_files;        // per image, as GltfSource::image_files
  std::vector<std::string> image_types;        // per image, as GltfSource::image_types
  // Image decoding, checked as tinygltf hands each image over.
  std::string file;
  uint64_t max_memory_bytes = 0;
  ResourceEstimate* estimate = nullptr;
  std::string error;  // set by a callback that refused; tinygltf only sees "false"
};

FileAccess resolve_files(const nlohmann::ordered_json& doc, const std::string& file, const std::string& base_dir,
                         bool allow_external_files);

// Points tinygltf's file system and image decoding at `access`, which must outlive the load.
void restrict_file_access(tinygltf::TinyGLTF& loader, FileAccess& access);

// The MIME type of an image file's bytes, from their signature: image/png, image/jpeg or
// image/webp (the formats glTF and EXT_texture_webp allow), or empty for anything else.
std::string image_type(const unsigned char* bytes, size_t size);

// What --max-memory allows: its value, or half the physical memory when it is 0 (auto).
uint64_t memory_limit(uint64_t max_memory_bytes);

// Throws InputError naming the estimate and the option to raise when it passes a limit.
void check_budget(const ResourceEstimate& estimate, const LoadOptions& options, const std::string& file);

// Packed elements of an accessor (sparse substitution applied), byteStride removed.
// Throws InputError when it reads outside its buffer.
std::vector<uint8_t> accessor_bytes(const tinygltf::Model& model, int accessor_index, size_t* element_size);

// Accessor values as floats (normalized integers mapped to [0,1] / [-1,1]), `components` per element.
std::vector<float> accessor_floats(const tinygltf::Model& model, int accessor_index, int* components);

std::vector<uint32_t> accessor_indices(const tinygltf::Model& model, int accessor_index);

// Triangles (three indices each) of a primitive drawn as triangles, a strip or a fan (glTF 2.0
// section 3.7.2.1, windings kept); none for points and lines. A list's incomplete last triangle is left out.
std::vector<uint32_t> triangle_list(const std::vector<uint32_t>& indices, int mode);

size_t component_count(int type);
size_t component_size(int component_type);

}  // namespace radbake
