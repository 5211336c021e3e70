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
#include "io/gltf/load_limits.h"
#include "uv/atlas.h"

namespace radbake {

// The parsed file, kept so the writer can reproduce everything the core does not model.
struct GltfSource;

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
