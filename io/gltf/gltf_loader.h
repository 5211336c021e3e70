// glTF in. io/ is the only part of radbake that knows the file format: load_gltf checks a
// .gltf/.glb and turns it into the plain Scene (io/gltf/gltf_writer.h writes it back with the bake).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "base/math.h"
#include "base/scene.h"
#include "uv/atlas.h"

namespace radbake {

// The parsed file, kept so the writer can reproduce everything the core does not model.
struct GltfSource;

// What a file may make radbake read and hold. The file's claims (counts, lengths, image sizes) are
// checked against these before anything sized from them is allocated.
struct LoadOptions {
  bool allow_external_files = false;   // follow URIs out of the scene's folder (absolute, ../, symlinks)
  uint64_t max_triangles = 20000000;   // triangles after instancing
  uint64_t max_memory_bytes = 0;       // estimated peak of the whole bake; 0: half the physical memory
};

// What a bake of the file will hold, estimated before it is read (see resource_budget.cpp).
struct ResourceEstimate {
  uint64_t triangles = 0;  // after instancing
  uint64_t vertices = 0;   // after instancing
  uint64_t texels = 0;     // lightmap page texels; 0 until the atlas options are known
  uint64_t data_bytes = 0; // the file, its buffers and decoded images, held while baking

  uint64_t bytes() const;  // estimated peak memory of the bake
};

struct LoadedScene {
  Scene scene;
  std::shared_ptr<const GltfSource> source;
  ResourceEstimate estimate;  // the file's part: geometry, buffers and images
};

// Throws InputError with a one-line message for anything wrong with the file, of the form
// "FILE: /json/pointer/of/the/object: what is wrong".
LoadedScene load_gltf(const std::string& path, const LoadOptions& options = {});

// What a bake of the loaded file depends on, as bytes: the JSON document, each buffer and each
// decoded image, in that order (for a checkpoint's fingerprint). Valid while `loaded` lives.
std::vector<std::string_view> scene_contents(const LoadedScene& loaded);

// The lightmap's part of the estimate (from the page size, or the surface area at a given density),
// added to the file's; throws InputError, naming the estimate and the option that would allow it,
// when the total passes the limits.
ResourceEstimate check_bake_budget(const LoadedScene& loaded, const AtlasOptions& atlas, const LoadOptions& options,
                                   const std::string& path);

}  // namespace radbake
