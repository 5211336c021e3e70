// Internal to uv/: charts in their own plane before they are scaled and packed.
#pragma once

#include <cstdint>
#include <vector>

#include "baker/math.h"
#include "uv/atlas.h"

namespace radbake {

struct Chart {
  uint32_t mesh = 0;
  std::vector<uint32_t> triangles;  // triangle indices of the mesh
  std::vector<Vec2> corner_uv;      // three per triangle, metres, chart minimum at (0, 0)
  Vec2 extent;                      // metres
};

// Groups edge-connected coplanar triangles into charts, each flattened by projection onto its
// plane and turned so its bounding rectangle is smallest. Degenerate triangles get no chart.
std::vector<Chart> planar_charts(const MeshView& mesh, uint32_t mesh_index);

struct ChartPlacement {
  int page = -1;
  int x = 0, y = 0;  // texel offset of the chart's minimum corner
  float scale = 1;   // texels per metre for this chart
};

struct PackResult {
  std::vector<ChartPlacement> placements;  // parallel to the charts
  std::vector<AtlasPage> pages;
  std::vector<uint32_t> downscaled_meshes;  // meshes shrunk to fit one page
};

// Packs charts into pages of at most page_size texels, keeping all charts of one mesh on one page.
PackResult pack_charts(const std::vector<Chart>& charts, size_t mesh_count, float texel_density,
                       int page_size, int padding);

}  // namespace radbake
