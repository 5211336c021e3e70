// Internal to io/: a file's document checked before tinygltf reads it, in two steps over one parsed
// document, so that what the writer copies is valid glTF and a file can only make radbake allocate
// what it really holds.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "io/gltf/load_limits.h"

namespace radbake {

// The one shape of every complaint about a file: "FILE: /json/pointer: what is wrong".
[[noreturn]] void refuse(const std::string& file, const std::string& pointer, const std::string& what);

// Step one (gltf_check.cpp), one pass over the document: the types, required members, enums,
// ranges and indices of the core glTF 2.0 schema and of the extensions radbake reads, and the
// bounds on what the bake multiplies.
// - What radbake reads (scenes, nodes, meshes, accessors, materials, lights...) must be valid: it
//   refuses the file, naming the pointer.
// - What it only copies (cameras, skins, animations, names, normal and occlusion textures, sampler
//   filters, extensions it does not read) is dropped when invalid, with a warning naming its
//   pointer; extras are kept whatever they hold (glTF allows any JSON there).
// - Extension declarations are made to match use (extensionsUsed deduplicated and completed,
//   unused entries of extensionsRequired removed), each change warned.
// Returns true when it changed the document, which must then be written anew for tinygltf.
bool check_document(nlohmann::ordered_json& doc, const std::string& file, std::vector<std::string>& warnings);

// Step two (gltf_claims.cpp), on the checked document: what it claims held against what the file
// holds (buffers against the .glb's BIN chunk, bufferViews against their buffers, accessors against
// their bufferViews, every attribute's count against POSITION), its nodes as disjoint trees, and what
// loading it costs. `glb_bin_size` is the BIN chunk's length, or SIZE_MAX when the file is no .glb.
ResourceEstimate check_claims(const nlohmann::ordered_json& doc, const std::string& file, size_t glb_bin_size);

}  // namespace radbake
