#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

#include "uv/atlas.h"
#include "uv/texel_coverage.h"

namespace radbake {
namespace {

struct UnionFind {
  std::vector<uint32_t> parent;
  explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  uint32_t find(uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(uint32_t a, uint32_t b) { parent[find(a)] = find(b); }
};

// Triangles joined by an edge whose two ends agree in position and UV belong to one UV chart;
// texels may be shared within a chart but not between charts.
std::vector<uint32_t> uv_charts(const MeshView& mesh) {
  using CornerKey = std::tuple<float, float, float, float, float>;
  std::map<CornerKey, uint32_t> welded;
  std::vector<uint32_t> corner_id(mesh.vertex_count);
  for (size_t v = 0; v < mesh.vertex_count; ++v) {
    Vec3 p = mesh.positions[v];
    Vec2 uv = mesh.lightmap_uvs[v];
    corner_id[v] = welded.emplace(CornerKey{p.x, p.y, p.z, uv.x, uv.y}, uint32_t(welded.size())).first->second;
  }
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> edge_owner;
  UnionFind charts(mesh.triangle_count);
  for (uint32_t t = 0; t < mesh.triangle_count; ++t)
    for (int e = 0; e < 3; ++e) {
      uint32_t a = corner_id[mesh.triangles[3 * t + e]], b = corner_id[mesh.triangles[3 * t + (e + 1) % 3]];
      auto [it, inserted] = edge_owner.emplace(std::minmax(a, b), t);
      if (!inserted) charts.unite(t, it->second);
    }
  std::vector<uint32_t> chart(mesh.triangle_count);
  for (uint32_t t = 0; t < mesh.triangle_count; ++t) chart[t] = charts.find(t);
  return chart;
}

}  // namespace

std::string lightmap_uv_problem(const MeshView& mesh, int resolution) {
  if (!mesh.lightmap_uvs) return "it has no TEXCOORD_1";
  for (size_t v = 0; v < mesh.vertex_count; ++v) {
    Vec2 uv = mesh.lightmap_uvs[v];
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return "TEXCOORD_1 has non-finite values";
    const float slack = 1e-5f;
    if (uv.x < -slack || uv.x > 1 + slack || uv.y < -slack || uv.y > 1 + slack)
      return "TEXCOORD_1 leaves the [0, 1] square";
  }
  size_t flat_in_uv = 0;
  for (size_t t = 0; t < mesh.triangle_count; ++t) {
    const uint32_t* tri = mesh.triangles + 3 * t;
    Vec3 p0 = mesh.positions[tri[0]];
    float world = length(cross(mesh.positions[tri[1]] - p0, mesh.positions[tri[2]] - p0));
    Vec2 u0 = mesh.lightmap_uvs[tri[0]];
    float uv = std::fabs(cross2(mesh.lightmap_uvs[tri[1]] - u0, mesh.lightmap_uvs[tri[2]] - u0));
    if (world > 0 && !(uv > 0)) ++flat_in_uv;
  }
  if (flat_in_uv) return "TEXCOORD_1 gives " + std::to_string(flat_in_uv) + " triangles no area";

  // Texels may be shared by the triangles of one chart (they meet inside them), never by two
  // charts; and the pieces in one texel may not add up to more than the texel (a fold).
  std::vector<uint32_t> chart = uv_charts(mesh);
  std::vector<int64_t> owner(size_t(resolution) * resolution, -1);
  std::vector<float> covered(owner.size(), 0.0f);
  size_t shared_texels = 0, folded_texels = 0;
  auto texel = [&](Vec2 uv) { return Vec2{uv.x * resolution, uv.y * resolution}; };
  for (size_t t = 0; t < mesh.triangle_count; ++t) {
    const uint32_t* tri = mesh.triangles + 3 * t;
    for_each_covered_texel(texel(mesh.lightmap_uvs[tri[0]]), texel(mesh.lightmap_uvs[tri[1]]),
                           texel(mesh.lightmap_uvs[tri[2]]), resolution, resolution, [&](const TexelPiece& piece) {
                             size_t at = size_t(piece.y) * resolution + piece.x;
                             int64_t& o = owner[at];
                             if (o < 0) o = chart[t];
                             else if (o != chart[t] && o != INT64_MAX) o = INT64_MAX, ++shared_texels;
                             float before = covered[at];
                             covered[at] += piece.area;
                             folded_texels += before <= 1.01f && covered[at] > 1.01f;
                           });
  }
  std::string at = " at " + std::to_string(resolution) + "x" + std::to_string(resolution);
  if (shared_texels) return "TEXCOORD_1 charts overlap or touch in " + std::to_string(shared_texels) + " texels" + at;
  if (folded_texels) return "TEXCOORD_1 folds over itself in " + std::to_string(folded_texels) + " texels" + at;
  return "";
}

}  // namespace radbake
