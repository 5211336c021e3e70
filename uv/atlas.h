// Lightmap UVs for every mesh instance: the scene's own TEXCOORD_1 when it is usable, otherwise
// charts generated here and packed into pages. Takes pointers and counts (as xatlas's MeshDecl
// does), never a file format's types.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "baker/math.h"

namespace radbake {

struct MeshView {
  const Vec3* positions = nullptr;  // world space, metres
  size_t vertex_count = 0;
  const uint32_t* triangles = nullptr;  // three indices per triangle
  size_t triangle_count = 0;
  const Vec2* lightmap_uvs = nullptr;  // the input's TEXCOORD_1, or null
  std::string name;                    // for messages
};

struct AtlasOptions {
  float texel_density = 0;   // texels per metre; 0 picks the density that fills one page
  int max_page_size = 1024;  // texels per page side, 16..16384
  int padding = 2;           // empty texels kept between charts (bilinear reads one, dilation fills)
};

struct AtlasPage {
  int width = 0, height = 0;  // texels
};

// One mesh's lightmap parameterisation. Vertices are split along chart seams, so the output has
// its own vertex list; `source_vertex` says which input vertex each one copies.
struct AtlasMesh {
  std::vector<uint32_t> source_vertex;   // output vertex -> input vertex
  std::vector<uint32_t> triangles;       // same triangle order as the input, into output vertices
  std::vector<Vec2> uvs;                 // per output vertex, page coordinates in [0, 1]
  std::vector<uint32_t> triangle_chart;  // chart of each triangle, unique across the atlas
  int page = 0;
  bool kept_input_uvs = false;  // the input's TEXCOORD_1 was valid and is used unchanged
};

struct Atlas {
  std::vector<AtlasPage> pages;
  std::vector<AtlasMesh> meshes;  // parallel to the input meshes
  float texel_density = 0;        // texels per metre used for generated charts
  size_t chart_count = 0;
  std::vector<std::string> warnings;
};

Atlas ensure_lightmap_uvs(const std::vector<MeshView>& meshes, const AtlasOptions& options);

// Why a mesh's own TEXCOORD_1 cannot be used at a page of `resolution` texels, or "" when it can.
std::string lightmap_uv_problem(const MeshView& mesh, int resolution);

}  // namespace radbake
