// Internal to io/: the glTF 2.0 schema enforced on a file before tinygltf reads it, so that what the
// writer copies from the input is valid glTF (the writer rewrites the input's JSON text).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace radbake {

// `bytes` is the whole file (.gltf text or .glb). Checks the types, required properties, enums,
// ranges and indices of the core glTF 2.0 schema and of the extensions radbake reads.
// - What radbake reads (scenes, nodes, meshes, accessors, materials, lights...) must be valid: it
//   throws InputError "FILE: /json/pointer: what is wrong".
// - What it only copies (cameras, skins, animations, names, normal and occlusion textures, sampler
//   filters, extensions it does not read) is dropped when invalid, with a warning naming its
//   pointer; extras are kept whatever they hold (glTF allows any JSON there).
// - Extension declarations are made to match use (extensionsUsed deduplicated and completed,
//   unused entries of extensionsRequired removed), each change warned.
// Returns the file with the drops applied (a .glb reassembled around the new JSON chunk), or the
// bytes unchanged when nothing was dropped or the JSON does not parse (tinygltf then says why).
std::vector<uint8_t> enforce_gltf_schema(const std::string& file, std::vector<uint8_t> bytes,
                                         std::vector<std::string>& warnings);

}  // namespace radbake
