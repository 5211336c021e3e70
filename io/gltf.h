// glTF in and out. io/ is the only part of radbake that knows the file format: load_gltf turns a
// .gltf/.glb into the plain Scene, and write_gltf writes the input back with the bake added.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "baker/math.h"
#include "baker/scene.h"
#include "baker/light_probes.h"
#include "io/directional_outputs.h"
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

// The lightmap's part of the estimate (from the page size, or the surface area at a given density),
// added to the file's; throws InputError, naming the estimate and the option that would allow it,
// when the total passes the limits.
ResourceEstimate check_bake_budget(const LoadedScene& loaded, const AtlasOptions& atlas, const LoadOptions& options,
                                   const std::string& path);

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

// What COLOR_0 holds in the engine file. glTF defines COLOR_0 as a base colour multiplier, and
// loaders apply it so; baked light there darkens every surface that shows it.
enum class Color0 {
  Source,  // the input's own COLOR_0, if it had one (the baked light is in _BAKED_LIGHT)
  Light,   // the baked light / extras.radbake.color_0_intensity, as radbake 0.1 wrote it
  Prelit,  // the exposed display colour of a white surface (for vertex-lit pipelines)
};

struct EngineFileOptions {
  Color0 color_0 = Color0::Source;
  float display_exposure = 0;   // display units per cd/m2, recorded for viewers and the three.js plugin
  std::string display_file;     // the display file beside it, recorded in extras; empty: none
  DirectionalFiles directional; // --directional's pages, recorded in extras.radbake.directional
  const LightProbes* probes = nullptr;  // --probes: recorded in extras.radbake.probes, with their file
  std::string probes_file;
};

// Writes NAME.gltf (+ buffers and copies of the input's images) into `folder`: the input with, for
// every baked primitive, lightmap UVs (TEXCOORD_1), the vertex light in `_BAKED_LIGHT` (float RGB,
// the stored quantity's unit), COLOR_0 as `options.color_0` says, and a material carrying
// MOZ_lightmap for its page; the lights that were baked marked `extras.radbake.baked`; objects
// nothing references any more removed. Meshes used by several nodes are copied per node.
GltfOutput write_gltf(const GltfSource& source, const Scene& scene, const Atlas& atlas,
                      const std::vector<std::vector<Rgb>>& vertex_values, const LightmapFiles& lightmaps,
                      const std::string& folder, const std::string& name, const EngineFileOptions& options = {});

}  // namespace radbake
