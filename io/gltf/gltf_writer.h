// glTF out: the engine file, the input written back with the bake added.
#pragma once

#include <string>
#include <vector>

#include "base/math.h"
#include "base/scene.h"
#include "baker/readings/light_probes.h"
#include "io/gltf/gltf_loader.h"
#include "io/lightmaps/directional_outputs.h"
#include "io/lightmaps/page_encodings.h"
#include "uv/atlas.h"

namespace radbake {

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
