// The display file: the bake as it looks, for any glTF viewer with no plugin and no lights.
// Every baked primitive is a node of world-space geometry with a KHR_materials_unlit material
// whose base colour is its pre-lit light (baker/finish/prelit_pages.h) exposed to display range
// (baker/finish/exposure.h) and sRGB-encoded: either a pre-lit page on the lightmap UVs (TEXCOORD_0
// here), or, with `vertex_lit`, the surface's own base colour times a pre-lit COLOR_0.
// It keeps the input's cameras, each a root node at its world position and orientation, so a
// viewer opens where the author looked; with none, it adds the bake's DisplayCamera.
#pragma once

#include <string>
#include <vector>

#include "baker/finish/exposure.h"
#include "baker/finish/prelit_pages.h"
#include "baker/finish/vertex_refinement.h"
#include "baker/readings/display_camera.h"
#include "base/scene.h"
#include "io/gltf/gltf_loader.h"
#include "uv/atlas.h"

namespace radbake {

struct DisplayInput {
  const Scene* scene = nullptr;
  const Atlas* atlas = nullptr;
  const PrelitPages* pages = nullptr;       // page-lit: the pre-lit pages (cd/m2)
  const std::vector<RefinedMesh>* meshes = nullptr;  // per instance; vertex values in the stored quantity
  bool vertex_lit = false;
  bool lightmap_is_irradiance = true;
  float emission_scale = 1;
  Exposure exposure;
  const GltfSource* source = nullptr;          // the input, whose cameras are kept; none: no cameras
  const DisplayCamera* camera = nullptr;       // added when the input has no camera; none: no camera
};

struct DisplayOutput {
  std::string file;  // NAME_display.glb
  size_t triangles = 0;
  std::string camera;  // which camera the file opens on, and why
  bool camera_added = false;  // it opens on DisplayInput::camera, the input having none
};

// Writes FOLDER/NAME_display.glb, self-contained (geometry and images in its BIN chunk).
DisplayOutput write_display_gltf(const DisplayInput& input, const std::string& folder, const std::string& name);

}  // namespace radbake
