// Lightmap UVs for every mesh instance: the scene's own TEXCOORD_1 when it is usable, otherwise
// an atlas generated here (charts grown on a half-edge mesh, flattened by least-squares conformal
// maps, packed into pages). Takes pointers and counts, as xatlas's MeshDecl does, never a file
// format's types.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/math.h"
#include "base/progress.h"
#include "uv/atlas_page.h"
#include "uv/mesh_view.h"

namespace radbake {

enum class InputUvPolicy {
  KeepValid,  // use the input's TEXCOORD_1 where it is valid; generate (and report) where it is not
  KeepAll,    // use it even where it is not valid (reported); generate only where there is none
  Generate,   // ignore it and generate everywhere
};

struct AtlasOptions {
  float texel_density = 0;   // texels per metre; 0: automatic, about automatic_texels texels over
                             // the scene's surface, fewer if that many do not fit one page
  int max_page_size = 1024;  // texels per page side, 16..16384; generated pages stay within the
                             // largest power of two at most this unless any_page_size
  int padding = 2;           // empty texels kept between charts (bilinear reads one, dilation fills)
  bool rotate_charts = true; // charts may turn (to their smallest rectangle, and by 90 degrees to pack)
  bool fit_one_page = false; // with a density given: lower it until everything fits one page
  InputUvPolicy input_uvs = InputUvPolicy::KeepValid;
  float max_chart_normal_deviation = 50;  // degrees: a chart's faces stay within this cone
  float hard_edge_angle = 40;             // degrees: edges folding more are always seams
  // Generated pages are powers of two on each side by default, as engines and mipmapped samplers
  // want (a side of 508 is padded or resampled by many of them); true gives the tight page instead,
  // a multiple of 4 up to max_page_size. A kept TEXCOORD_1 keeps its own page size either way.
  bool any_page_size = false;
  // The automatic density's budget: texels over the scene's whole surface area. 50,000 bake in a
  // few seconds at the default preset on 2 cores, whatever the scene's size (a plain room at one
  // page of 1024 was 828,000 texels and 20 s); a larger model gets larger texels, reported.
  size_t automatic_texels = 50000;
  // Called with the stage "lightmap uvs" and the fraction done, at least every few tenths of a
  // second of work; returning false stops the unwrap, which throws Cancelled (base/errors.h), as
  // a bake's callback stops a bake. A large mesh can take minutes to unwrap.
  ProgressCallback progress = {};
};

// One mesh's lightmap parameterisation. Vertices are split along chart seams, so the output has
// its own vertex list; `source_vertex` says which input vertex each one copies.
struct AtlasMesh {
  std::vector<uint32_t> source_vertex;   // output vertex -> input vertex
  std::vector<uint32_t> triangles;       // same triangle order as the input, into output vertices
  std::vector<Vec2> uvs;                 // per output vertex, page coordinates in [0, 1]
  std::vector<uint32_t> triangle_chart;  // chart of each triangle, unique across the atlas; UINT32_MAX
                                         // for triangles that cover nothing (zero area)
  int page = 0;
  bool kept_input_uvs = false;  // the input's TEXCOORD_1 is used unchanged
};

// What the atlas is worth, measured (uv/atlas_stats.cpp).
struct AtlasStats {
  size_t charts = 0;
  double utilisation = 0;      // covered texels / page texels, over all pages
  // Texels whose centre a triangle covers / page texels: the stricter count (a texel a chart only
  // grazes is not counted), comparable with tools that count so.
  double utilisation_centres = 0;
  double stretch_l2 = 0;       // Sander et al. 2001 L2 stretch over the whole atlas, 1 = none
  double stretch_max = 0;      // the worst triangle's L2 stretch, same normalisation
  double seam_length = 0;      // metres of edges where charts meet
  size_t overlapping_texels = 0;   // texels covered by two charts
  size_t flipped_triangles = 0;    // triangles wound against the rest of their chart
  size_t padding_violations = 0;   // texels with another chart's texel closer than the padding
  size_t covered_texels = 0, page_texels = 0;  // covered: touched by a triangle (any area)
  size_t centre_covered_texels = 0;
  double seconds = 0;
};

struct Atlas {
  std::vector<AtlasPage> pages;
  std::vector<AtlasMesh> meshes;  // parallel to the input meshes
  float texel_density = 0;        // texels per metre used for generated charts
  float requested_density = 0;    // what the options asked for (0: automatic)
  bool density_lowered = false;   // fit_one_page lowered the density
  double surface_area = 0;        // m^2, every mesh's
  std::string density_choice;     // how the density was chosen, for the report
  size_t chart_count = 0;
  AtlasStats stats;
  std::vector<std::string> warnings;
};

// Throws InputError for options out of their range (a page size outside 16..16384, padding outside
// 0..64, a negative density), and Cancelled when options.progress asks to stop.
Atlas ensure_lightmap_uvs(const std::vector<MeshView>& meshes, const AtlasOptions& options);

// Why a mesh's own TEXCOORD_1 cannot be used at a page of `resolution` texels, or "" when it can.
std::string lightmap_uv_problem(const MeshView& mesh, int resolution);
// The same for meshes sharing one width x height page: each must be valid, and no two charts, of
// one mesh or of two, may share a texel. Problems of one mesh among several name it.
std::string lightmap_uv_problem(const std::vector<const MeshView*>& meshes, int width, int height);

// Measures any layout (generated, kept, or a peer's) over these meshes; `padding` is what the
// layout promises. Chart ids come from the layout's triangle_chart.
AtlasStats measure_atlas(const std::vector<MeshView>& meshes, const Atlas& atlas, int padding);

// A layout made elsewhere, as an Atlas to measure: every mesh's `uvs` in one page_size page,
// charts from uv_islands.
Atlas layout_from_uvs(const std::vector<MeshView>& meshes, const std::vector<const Vec2*>& uvs, int page_size);

// Chart ids for a layout that has none: triangles joined by an edge whose ends agree in position
// and UV form one chart (for measuring UVs made elsewhere).
std::vector<uint32_t> uv_islands(const MeshView& mesh, const Vec2* uvs);

}  // namespace radbake
