// The display file's light, ready to write: what a glTF viewer that knows nothing of lightmaps
// shows (pre-lit pages on unlit materials, or pre-lit vertex colours on a refined mesh), and the
// exposure both the display file and the engine file record. io/gltf/display_gltf.h writes it.
#pragma once

#include <cstddef>
#include <vector>

#include "baker/finish/exposure.h"
#include "baker/finish/finish.h"
#include "baker/finish/prelit_pages.h"
#include "baker/finish/vertex_refinement.h"
#include "base/scene.h"
#include "uv/atlas.h"

namespace radbake {

// What the display file (NAME_display.glb) shows its light with.
enum class DisplayMode {
  Page,    // pre-lit pages on the lightmap UVs
  Vertex,  // the surface's base colour times pre-lit COLOR_0
  None,    // no display file (the exposure is still chosen, for the engine file)
};

struct DisplayOptions {
  DisplayMode mode = DisplayMode::Page;
  int detail = 0;                      // pre-lit texels per lightmap texel along a side (1, 2, 4); 0: automatic
  ExposureOptions exposure;            // display units per cd/m2; automatic by default
  size_t vertex_refine_triangles = 0;  // DisplayMode::Vertex: refine the mesh up to this many triangles; 0: as it is
};

struct DisplayLight {
  Exposure exposure;          // metered on the flat pre-lit pages, as the display camera sees them
  PrelitPages pages;          // what the pages show, normal maps applied with `sh`; empty with DisplayMode::None
  VertexRefinement refined;   // the meshes they are shown on (refined only for vertex light)
};

// `pages` and `vertex_values` are the bake's (BakeResult); `sh`, when not null, its --directional sh
// pages, so normal maps show. `emission_scale`, `lightmap_is_irradiance` and
// `glazing` as the bake had them (BakeOptions). `seen`, when not null: the bake's
// display_view (per page, per lightmap texel), which the exposure meters on.
DisplayLight display_light(const Scene& scene, const Atlas& atlas, const std::vector<LightmapPage>& pages,
                           const std::vector<std::vector<Rgb>>& vertex_values,
                           const std::vector<std::vector<LightmapPage>>* sh, float emission_scale,
                           bool lightmap_is_irradiance, const Glazing& glazing,
                           const std::vector<std::vector<float>>* seen, const DisplayOptions& options);

}  // namespace radbake
