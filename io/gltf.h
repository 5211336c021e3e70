// glTF in and out. io/ is the only part of radbake that knows the file format: load_gltf turns a
// .gltf/.glb into the plain Scene, and write_gltf writes the input back with the bake added.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "baker/math.h"
#include "baker/scene.h"
#include "uv/atlas.h"

namespace radbake {

// The parsed file, kept so the writer can reproduce everything the core does not model.
struct GltfSource;

struct LoadedScene {
  Scene scene;
  std::shared_ptr<const GltfSource> source;
};

// Throws InputError with a one-line message for anything wrong with the file.
LoadedScene load_gltf(const std::string& path);

// What the lightmap files are and how their values read back.
struct LightmapFiles {
  std::vector<std::string> png, exr;  // file names inside the output folder, one per page
  float png_scale = 1;                // linear value = sRGB-decoded PNG value * png_scale
  std::string quantity;               // "irradiance" or "radiosity"
  std::string unit;                   // "lx" or "lm/m2"
};

struct GltfOutput {
  std::string gltf_file;                      // NAME.gltf
  std::vector<std::string> written_files;     // everything written, relative to the folder
  std::vector<std::string> warnings;
};

// Writes NAME.gltf (+ buffers and copies of the input's images) into `folder`: the input with, for
// every baked primitive, lightmap UVs (TEXCOORD_1), COLOR_0 = vertex values / a scale recorded in
// extras.radbake.color_0_intensity (the PNG's, or the brightest vertex's if higher), and a
// material carrying MOZ_lightmap for its page. Meshes used by several nodes are copied per node.
GltfOutput write_gltf(const GltfSource& source, const Scene& scene, const Atlas& atlas,
                      const std::vector<std::vector<Rgb>>& vertex_values, const LightmapFiles& lightmaps,
                      const std::string& folder, const std::string& name);

}  // namespace radbake
