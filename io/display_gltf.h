// The display file: the bake as it looks, for any glTF viewer with no plugin and no lights.
// Every baked primitive is a node of world-space geometry with a KHR_materials_unlit material
// whose base colour is its pre-lit light (baker/prelit_pages.h) exposed to display range
// (baker/exposure.h) and sRGB-encoded: either a pre-lit page on the lightmap UVs (TEXCOORD_0
// here), or, with `vertex_lit`, the surface's own base colour times a pre-lit COLOR_0.
#pragma once

#include <string>
#include <vector>

#include "baker/exposure.h"
#include "baker/prelit_pages.h"
#include "baker/scene.h"
#include "uv/atlas.h"

namespace radbake {

// One vertex of a display mesh: a blend of up to three atlas output vertices of one triangle
// (weights sum to 1), so every attribute is interpolated the same way.
struct BlendedVertex {
  uint32_t corner[3] = {0, 0, 0};
  float weight[3] = {1, 0, 0};
};

// A display mesh per instance; its vertices blend the instance's atlas vertices.
struct DisplayMesh {
  std::vector<BlendedVertex> vertices;
  std::vector<uint32_t> triangles;  // three per triangle, the atlas mesh's winding
  std::vector<Rgb> light;           // vertex_lit only: per vertex, the stored quantity (lux or lm/m2)
};

// The atlas's own meshes, with the vertex light per atlas output vertex.
std::vector<DisplayMesh> atlas_display_meshes(const Atlas& atlas, const std::vector<std::vector<Rgb>>& vertex_values);

struct DisplayInput {
  const Scene* scene = nullptr;
  const Atlas* atlas = nullptr;
  const PrelitPages* pages = nullptr;       // page-lit: the pre-lit pages (cd/m2)
  const std::vector<DisplayMesh>* meshes = nullptr;  // per instance
  bool vertex_lit = false;
  bool lightmap_is_irradiance = true;
  float emission_scale = 1;
  Exposure exposure;
};

struct DisplayOutput {
  std::string file;  // NAME_display.glb
  size_t triangles = 0;
};

// Writes FOLDER/NAME_display.glb, self-contained (geometry and images in its BIN chunk).
DisplayOutput write_display_gltf(const DisplayInput& input, const std::string& folder, const std::string& name);

}  // namespace radbake
