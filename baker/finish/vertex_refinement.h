// Vertex light that keeps the shadows: the output mesh refined where the baked light varies, so
// light interpolated between vertices follows the lightmap (Lightscape's meshed solution: split
// triangles along shadow edges and gradients, within a triangle budget). The lightmap stays the
// reference; this stage only decides where vertices go and samples the lightmap there.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "baker/finish/finish.h"
#include "base/math.h"
#include "base/progress.h"
#include "base/scene.h"
#include "uv/atlas.h"

namespace radbake {

struct RefinementOptions {
  // Triangles over all instances when refinement stops; 0, or fewer than the input has, leaves the
  // mesh as it is. A split is never made that would pass the budget.
  size_t max_triangles = 0;
  // Unitless: a triangle is not split once the RMS difference between its interpolated light and
  // the lightmap texels it covers, divided by the scene's mean light, is below this.
  float tolerance = 0.02f;
  // Texels^2 of lightmap a triangle must cover to be split for its own error: the halves of a
  // smaller one would be under a texel, finer than any detail the lightmap holds. Splits that
  // keep the mesh conforming ignore it.
  float min_footprint = 2.0f;
  // Called with the stage "vertex refinement" and the fraction of the budget used; returning false
  // throws Cancelled (base/errors.h).
  ProgressCallback progress = {};
};

// A vertex of the refined mesh as a blend of atlas output vertices (AtlasMesh vertex indices) of
// one input triangle, so every attribute the input has (position, normal, UVs, colour) is
// interpolated the same way. Weights are non-negative, sum to 1 and are dyadic fractions (exact
// in float); corners with weight 0 are placeholders. An original vertex is {v, v, v}, {1, 0, 0}.
struct RefinedVertex {
  uint32_t corner[3];
  float weight[3];
};

// Any per-atlas-vertex attribute at a refined vertex: sum of weight x attribute over the corners
// with non-zero weight, in corner order. A vertex on an edge has two such corners, so both sides
// of a chart seam compute bit-identical positions (a + b == b + a in floating point) and the
// refined mesh has no cracks there.
template <typename T, typename AttributeOf>
T blend(const RefinedVertex& v, AttributeOf&& attribute_of_atlas_vertex) {
  T sum{};
  bool first = true;
  for (int k = 0; k < 3; ++k) {
    if (v.weight[k] == 0) continue;
    T term = attribute_of_atlas_vertex(v.corner[k]) * v.weight[k];
    sum = first ? term : sum + term;
    first = false;
  }
  return sum;
}

struct RefinedMesh {  // per instance, parallel to Atlas::meshes
  // The atlas output vertices first (same indices, weight 1), then the added ones.
  std::vector<RefinedVertex> vertices;
  std::vector<uint32_t> triangles;        // three per triangle, wound as the input triangle they lie in
  std::vector<uint32_t> source_triangle;  // per triangle: the input triangle it lies in
  // Light at each vertex, in the page's unit: the bake's vertex value for an original vertex (what
  // the writer writes without refinement), the lightmap sampled bilinearly at the vertex's
  // lightmap UV for an added one.
  std::vector<Rgb> values;

  size_t triangle_count() const { return triangles.size() / 3; }
};

// The error as refinement proceeds: at the start, each time the triangle count has doubled, and at
// the end. rms_relative = area-weighted RMS difference between vertex-interpolated light and the
// lightmap texels (mean of the RGB channels' squared differences) / area-weighted mean light.
struct RefinementCurve {
  std::vector<size_t> triangles;
  std::vector<double> rms_relative;
};

struct VertexRefinement {
  std::vector<RefinedMesh> meshes;
  RefinementCurve curve;
  double mean_light = 0;  // area-weighted mean of the covered texels (mean of RGB), the page's unit
};

// `vertex_values` are BakeResult::vertex_values (per instance, per atlas output vertex); `pages`
// the bake's dilated pages in the same unit. Only texels marked `valid` are measured (a buried
// texel under a block is seen by nobody); a page with an empty mask counts all of them.
// Deterministic: same input, same output.
VertexRefinement refine_vertex_light(const Scene& scene, const Atlas& atlas, const std::vector<LightmapPage>& pages,
                                     const std::vector<std::vector<Rgb>>& vertex_values,
                                     const RefinementOptions& options);

// The lightmap at `texel` (page texel units: texel (x, y) spans [x, x + 1) x [y, y + 1)),
// bilinear between texel centres and clamped at the page's edges, as a LINEAR/CLAMP sampler reads it.
Rgb sample_bilinear(const LightmapPage& page, Vec2 texel);

}  // namespace radbake
