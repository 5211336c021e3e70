#include <algorithm>
#include <cmath>

#include "uv/atlas.h"
#include "uv/texel_coverage.h"

namespace radbake {
namespace {

// What is wrong with one mesh's TEXCOORD_1 wherever it is placed, or "".
std::string mesh_uv_problem(const MeshView& mesh) {
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
  return "";
}

}  // namespace

std::string lightmap_uv_problem(const MeshView& mesh, int resolution) {
  return lightmap_uv_problem(std::vector<const MeshView*>{&mesh}, resolution, resolution);
}

std::string lightmap_uv_problem(const std::vector<const MeshView*>& meshes, int width, int height) {
  for (const MeshView* mesh : meshes) {
    std::string problem = mesh_uv_problem(*mesh);
    if (!problem.empty()) return meshes.size() > 1 ? "mesh '" + mesh->name + "': " + problem : problem;
  }
  // Texels may be shared by the triangles of one chart (they meet inside them), never by two
  // charts, of one mesh or of two; and the pieces in one texel may not add up to more than the
  // texel (a fold).
  std::vector<int64_t> owner(size_t(width) * size_t(height), -1);
  std::vector<float> covered(owner.size(), 0.0f);
  size_t shared_texels = 0, folded_texels = 0;
  int64_t first_chart = 0;
  for (const MeshView* mesh : meshes) {
    std::vector<uint32_t> chart = uv_islands(*mesh, mesh->lightmap_uvs);
    auto texel = [&](Vec2 uv) { return Vec2{uv.x * float(width), uv.y * float(height)}; };
    int64_t charts = 0;
    for (size_t t = 0; t < mesh->triangle_count; ++t) {
      const uint32_t* tri = mesh->triangles + 3 * t;
      const int64_t id = first_chart + chart[t];
      charts = std::max(charts, int64_t(chart[t]) + 1);
      for_each_covered_texel(texel(mesh->lightmap_uvs[tri[0]]), texel(mesh->lightmap_uvs[tri[1]]),
                             texel(mesh->lightmap_uvs[tri[2]]), width, height, [&](const TexelPiece& piece) {
                               size_t at = size_t(piece.y) * size_t(width) + size_t(piece.x);
                               int64_t& o = owner[at];
                               if (o < 0) o = id;
                               else if (o != id && o != INT64_MAX) o = INT64_MAX, ++shared_texels;
                               float before = covered[at];
                               covered[at] += piece.area;
                               folded_texels += before <= 1.01f && covered[at] > 1.01f;
                             });
    }
    first_chart += charts;
  }
  std::string at = " at " + std::to_string(width) + "x" + std::to_string(height);
  if (shared_texels) return "TEXCOORD_1 charts overlap or touch in " + std::to_string(shared_texels) + " texels" + at;
  if (folded_texels) return "TEXCOORD_1 folds over itself in " + std::to_string(folded_texels) + " texels" + at;
  return "";
}

}  // namespace radbake
