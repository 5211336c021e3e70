#include "uv/atlas.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "uv/charts.h"

namespace radbake {
namespace {

double world_area(const MeshView& mesh) {
  double area = 0;
  for (size_t t = 0; t < mesh.triangle_count; ++t) {
    const uint32_t* tri = mesh.triangles + 3 * t;
    Vec3 p0 = mesh.positions[tri[0]];
    float a = length(cross(mesh.positions[tri[1]] - p0, mesh.positions[tri[2]] - p0));
    if (std::isfinite(a)) area += 0.5 * a;
  }
  return area;
}

double uv_area(const MeshView& mesh) {
  double area = 0;
  for (size_t t = 0; t < mesh.triangle_count; ++t) {
    const uint32_t* tri = mesh.triangles + 3 * t;
    Vec2 u0 = mesh.lightmap_uvs[tri[0]];
    area += 0.5 * std::fabs(cross2(mesh.lightmap_uvs[tri[1]] - u0, mesh.lightmap_uvs[tri[2]] - u0));
  }
  return area;
}

// A kept TEXCOORD_1 layout gets a page of its own, square, sized so its texels match the density.
int page_side_for_own_uvs(const MeshView& mesh, float density, int max_page_size) {
  double uv = uv_area(mesh);
  double side = uv > 0 ? density * std::sqrt(world_area(mesh) / uv) : 16;
  return std::clamp((int(std::ceil(side)) + 3) / 4 * 4, 16, max_page_size);
}

AtlasMesh keep_own_uvs(const MeshView& mesh, int page, uint32_t& next_chart) {
  AtlasMesh out;
  out.kept_input_uvs = true;
  out.page = page;
  out.source_vertex.resize(mesh.vertex_count);
  for (size_t v = 0; v < mesh.vertex_count; ++v) out.source_vertex[v] = uint32_t(v);
  out.triangles.assign(mesh.triangles, mesh.triangles + 3 * mesh.triangle_count);
  out.uvs.assign(mesh.lightmap_uvs, mesh.lightmap_uvs + mesh.vertex_count);
  // One chart per mesh is enough here: the overlap check already treats the layout as given.
  out.triangle_chart.assign(mesh.triangle_count, next_chart++);
  return out;
}

// Splits vertices along chart borders and writes each corner's page coordinates.
AtlasMesh lay_out_charts(const MeshView& mesh, const std::vector<const Chart*>& charts,
                         const std::vector<const ChartPlacement*>& placements, const AtlasPage& page,
                         int page_index, uint32_t first_chart) {
  AtlasMesh out;
  out.page = page_index;
  out.triangles.assign(3 * mesh.triangle_count, 0);
  out.triangle_chart.assign(mesh.triangle_count, UINT32_MAX);
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> vertex_of;  // (input vertex, chart) -> output
  auto emit = [&](uint32_t source, uint32_t chart, Vec2 uv) {
    auto [it, inserted] = vertex_of.emplace(std::make_pair(source, chart), uint32_t(out.source_vertex.size()));
    if (inserted) {
      out.source_vertex.push_back(source);
      out.uvs.push_back(uv);
    }
    return it->second;
  };
  for (size_t c = 0; c < charts.size(); ++c) {
    const Chart& chart = *charts[c];
    const ChartPlacement& at = *placements[c];
    for (size_t i = 0; i < chart.triangles.size(); ++i) {
      uint32_t t = chart.triangles[i];
      out.triangle_chart[t] = first_chart + uint32_t(c);
      for (int k = 0; k < 3; ++k) {
        Vec2 local = chart.corner_uv[3 * i + k];
        Vec2 uv{(at.x + local.x * at.scale) / page.width, (at.y + local.y * at.scale) / page.height};
        out.triangles[3 * t + k] = emit(mesh.triangles[3 * t + k], uint32_t(c), uv);
      }
    }
  }
  // Degenerate triangles cover no texel; their corners sit at the page origin, inside the padding.
  for (size_t t = 0; t < mesh.triangle_count; ++t)
    if (out.triangle_chart[t] == UINT32_MAX)
      for (int k = 0; k < 3; ++k) out.triangles[3 * t + k] = emit(mesh.triangles[3 * t + k], UINT32_MAX, {0, 0});
  return out;
}

}  // namespace

Atlas ensure_lightmap_uvs(const std::vector<MeshView>& meshes, const AtlasOptions& options) {
  if (options.max_page_size < 16 || options.max_page_size > 16384)
    throw std::invalid_argument("maximum page size must be 16..16384 texels");
  if (options.padding < 0 || options.padding > 64) throw std::invalid_argument("padding must be 0..64 texels");
  if (!(options.texel_density >= 0)) throw std::invalid_argument("texel density must be positive");

  Atlas atlas;
  atlas.meshes.resize(meshes.size());
  const int page_size = options.max_page_size;
  double total_area = 0;
  for (const MeshView& m : meshes) total_area += world_area(m);
  // Auto density aims for 60% of one page: what the shelf packer reaches on box-like scenes.
  const float auto_fill = 0.6f;
  const float auto_density = float(page_size * std::sqrt(auto_fill / std::max(total_area, 1e-12)));
  float density = options.texel_density > 0 ? options.texel_density : auto_density;

  std::vector<int> own_page_side(meshes.size(), 0);
  std::vector<Chart> charts;
  for (size_t m = 0; m < meshes.size(); ++m) {
    if (meshes[m].lightmap_uvs) {
      int side = page_side_for_own_uvs(meshes[m], density, page_size);
      std::string problem = lightmap_uv_problem(meshes[m], side);
      if (problem.empty()) {
        own_page_side[m] = side;
        continue;
      }
      atlas.warnings.push_back("mesh '" + meshes[m].name + "': " + problem + "; generating lightmap UVs");
    }
    std::vector<Chart> mine = planar_charts(meshes[m], uint32_t(m));
    charts.insert(charts.end(), std::make_move_iterator(mine.begin()), std::make_move_iterator(mine.end()));
  }

  PackResult packed = pack_charts(charts, meshes.size(), density, page_size, options.padding);
  // Auto density backs off until everything generated fits the one page it promised; when even
  // one-texel charts cannot share a page (more charts than the page has room for), it gives up
  // on one page rather than shrinking forever.
  for (int attempt = 0; options.texel_density <= 0 && packed.pages.size() > 1 && attempt < 200; ++attempt) {
    density *= 0.95f;
    packed = pack_charts(charts, meshes.size(), density, page_size, options.padding);
  }
  if (options.texel_density <= 0 && packed.pages.size() > 1) {
    density = auto_density;
    packed = pack_charts(charts, meshes.size(), density, page_size, options.padding);
    atlas.warnings.push_back("the charts do not fit one " + std::to_string(page_size) + "-texel page at any density; using " +
                             std::to_string(packed.pages.size()) + " pages");
  }
  atlas.texel_density = density;
  atlas.pages = packed.pages;
  for (uint32_t m : packed.downscaled_meshes)
    atlas.warnings.push_back("mesh '" + meshes[m].name + "' is too large for one " + std::to_string(page_size) +
                             "-texel page at " + std::to_string(density) + " texels/m and was scaled down");

  std::vector<std::vector<const Chart*>> charts_of(meshes.size());
  std::vector<std::vector<const ChartPlacement*>> placements_of(meshes.size());
  for (size_t c = 0; c < charts.size(); ++c) {
    charts_of[charts[c].mesh].push_back(&charts[c]);
    placements_of[charts[c].mesh].push_back(&packed.placements[c]);
  }
  uint32_t next_chart = 0;
  for (size_t m = 0; m < meshes.size(); ++m) {
    if (own_page_side[m]) {
      atlas.pages.push_back({own_page_side[m], own_page_side[m]});
      atlas.meshes[m] = keep_own_uvs(meshes[m], int(atlas.pages.size() - 1), next_chart);
      continue;
    }
    int page = placements_of[m].empty() ? 0 : placements_of[m][0]->page;
    if (atlas.pages.empty()) atlas.pages.push_back({16, 16});  // only degenerate triangles
    atlas.meshes[m] = lay_out_charts(meshes[m], charts_of[m], placements_of[m], atlas.pages[size_t(page)], page,
                                     next_chart);
    next_chart += uint32_t(charts_of[m].size());
  }
  atlas.chart_count = next_chart;
  return atlas;
}

}  // namespace radbake
