#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

#include "uv/atlas.h"
#include "uv/texel_coverage.h"

namespace radbake {

std::vector<uint32_t> uv_islands(const MeshView& mesh, const Vec2* uvs) {
  using CornerKey = std::tuple<float, float, float, float, float>;
  std::map<CornerKey, uint32_t> welded;
  std::vector<uint32_t> corner_id(mesh.vertex_count);
  for (size_t v = 0; v < mesh.vertex_count; ++v) {
    Vec3 p = mesh.positions[v];
    corner_id[v] = welded.emplace(CornerKey{p.x, p.y, p.z, uvs[v].x, uvs[v].y}, uint32_t(welded.size())).first->second;
  }
  std::vector<uint32_t> parent(mesh.triangle_count);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> edge_owner;
  for (uint32_t t = 0; t < mesh.triangle_count; ++t)
    for (int e = 0; e < 3; ++e) {
      uint32_t a = corner_id[mesh.triangles[3 * t + e]], b = corner_id[mesh.triangles[3 * t + (e + 1) % 3]];
      auto [it, inserted] = edge_owner.emplace(std::minmax(a, b), t);
      if (!inserted) parent[find(t)] = find(it->second);
    }
  // Dense numbering in order of first appearance.
  std::vector<uint32_t> island(mesh.triangle_count), number(mesh.triangle_count, UINT32_MAX);
  uint32_t next = 0;
  for (uint32_t t = 0; t < mesh.triangle_count; ++t) {
    uint32_t r = find(t);
    if (number[r] == UINT32_MAX) number[r] = next++;
    island[t] = number[r];
  }
  return island;
}

Atlas layout_from_uvs(const std::vector<MeshView>& meshes, const std::vector<const Vec2*>& uvs, int page_size) {
  Atlas atlas;
  atlas.pages.push_back({page_size, page_size});
  uint32_t next_chart = 0;
  for (size_t m = 0; m < meshes.size(); ++m) {
    const MeshView& mesh = meshes[m];
    AtlasMesh am;
    am.kept_input_uvs = true;
    am.source_vertex.resize(mesh.vertex_count);
    std::iota(am.source_vertex.begin(), am.source_vertex.end(), 0u);
    am.triangles.assign(mesh.triangles, mesh.triangles + 3 * mesh.triangle_count);
    am.uvs.assign(uvs[m], uvs[m] + mesh.vertex_count);
    am.triangle_chart = uv_islands(mesh, uvs[m]);
    uint32_t largest = 0;
    for (size_t t = 0; t < mesh.triangle_count; ++t) {
      largest = std::max(largest, am.triangle_chart[t]);
      am.triangle_chart[t] += next_chart;
    }
    next_chart += mesh.triangle_count ? largest + 1 : 0;
    atlas.meshes.push_back(std::move(am));
  }
  atlas.chart_count = next_chart;
  return atlas;
}

namespace {

// Whether p lies in the triangle (either winding), edges included.
bool contains_point(const Vec2 (&c)[3], Vec2 p) {
  const float d0 = cross2(c[1] - c[0], p - c[0]), d1 = cross2(c[2] - c[1], p - c[1]), d2 = cross2(c[0] - c[2], p - c[2]);
  return (d0 >= 0 && d1 >= 0 && d2 >= 0) || (d0 <= 0 && d1 <= 0 && d2 <= 0);
}

}  // namespace

AtlasStats measure_atlas(const std::vector<MeshView>& meshes, const Atlas& atlas, int padding) {
  AtlasStats s;
  s.charts = atlas.chart_count;
  // Per page, per texel: the chart covering it (-1 none, -2 several), and whether a triangle covers
  // its centre.
  std::vector<std::vector<int64_t>> owner;
  std::vector<std::vector<uint8_t>> centre_covered;
  for (const AtlasPage& p : atlas.pages) {
    owner.emplace_back(size_t(p.width) * p.height, -1);
    centre_covered.emplace_back(size_t(p.width) * p.height, 0);
    s.page_texels += size_t(p.width) * p.height;
  }
  double sum_l2_area = 0, area_3d = 0, area_uv = 0, worst = 0;
  std::map<uint32_t, double> chart_orientation;  // signed UV area per chart
  for (size_t m = 0; m < meshes.size(); ++m) {
    const AtlasMesh& am = atlas.meshes[m];
    for (size_t t = 0; t < am.triangle_chart.size(); ++t) {
      if (am.triangle_chart[t] == UINT32_MAX) continue;
      Vec2 a = am.uvs[am.triangles[3 * t]], b = am.uvs[am.triangles[3 * t + 1]], c = am.uvs[am.triangles[3 * t + 2]];
      chart_orientation[am.triangle_chart[t]] += 0.5 * double(cross2(b - a, c - a));
    }
  }
  for (size_t m = 0; m < meshes.size(); ++m) {
    const AtlasMesh& am = atlas.meshes[m];
    const AtlasPage& page = atlas.pages[size_t(am.page)];
    std::vector<int64_t>& grid = owner[size_t(am.page)];
    for (size_t t = 0; t < am.triangle_chart.size(); ++t) {
      const uint32_t chart = am.triangle_chart[t];
      if (chart == UINT32_MAX) continue;
      Vec2 uv[3];
      Vec3 q[3];
      for (int k = 0; k < 3; ++k) {
        uint32_t v = am.triangles[3 * t + size_t(k)];
        uv[k] = {am.uvs[v].x * page.width, am.uvs[v].y * page.height};
        q[k] = meshes[m].positions[am.source_vertex[v]];
      }
      std::vector<uint8_t>& centres = centre_covered[size_t(am.page)];
      for_each_covered_texel(uv[0], uv[1], uv[2], page.width, page.height, [&](const TexelPiece& piece) {
        int64_t& o = grid[size_t(piece.y) * page.width + piece.x];
        if (o == -1) o = chart;
        else if (o != int64_t(chart) && o != -2) o = -2;
        if (contains_point(uv, {float(piece.x) + 0.5f, float(piece.y) + 0.5f}))
          centres[size_t(piece.y) * page.width + piece.x] = 1;
      });
      // Sander et al. 2001: singular values of the map from the texture to the surface.
      double signed_area = 0.5 * double(cross2(uv[1] - uv[0], uv[2] - uv[0]));
      double a3 = 0.5 * double(length(cross(q[1] - q[0], q[2] - q[0])));
      if (signed_area == 0 || !(a3 > 0)) continue;
      if ((signed_area > 0) != (chart_orientation[chart] > 0)) ++s.flipped_triangles;
      double A = signed_area;
      Vec3 ss = (q[0] * (uv[1].y - uv[2].y) + q[1] * (uv[2].y - uv[0].y) + q[2] * (uv[0].y - uv[1].y)) / float(2 * A);
      Vec3 st = (q[0] * (uv[2].x - uv[1].x) + q[1] * (uv[0].x - uv[2].x) + q[2] * (uv[1].x - uv[0].x)) / float(2 * A);
      double l2 = std::sqrt((double(dot(ss, ss)) + double(dot(st, st))) / 2);
      sum_l2_area += l2 * l2 * a3;
      area_3d += a3;
      area_uv += std::fabs(A);
      worst = std::max(worst, l2);
    }
  }
  // Normalised so that scaling the whole layout does not change the measure.
  double normaliser = area_3d > 0 ? std::sqrt(area_uv / area_3d) : 0;
  s.stretch_l2 = area_3d > 0 ? std::sqrt(sum_l2_area / area_3d) * normaliser : 0;
  s.stretch_max = worst * normaliser;

  for (size_t p = 0; p < atlas.pages.size(); ++p) {
    const int w = atlas.pages[p].width, h = atlas.pages[p].height;
    const std::vector<int64_t>& grid = owner[p];
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        int64_t o = grid[size_t(y) * w + x];
        if (o == -1) continue;
        ++s.covered_texels;
        if (o == -2) {
          ++s.overlapping_texels;
          continue;
        }
        bool crowded = false;
        for (int dy = -padding; dy <= padding && !crowded; ++dy)
          for (int dx = -padding; dx <= padding && !crowded; ++dx) {
            int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
            int64_t n = grid[size_t(ny) * w + nx];
            crowded = n >= 0 && n != o;
          }
        s.padding_violations += crowded;
      }
  }
  for (const std::vector<uint8_t>& centres : centre_covered)
    for (uint8_t c : centres) s.centre_covered_texels += c;
  s.utilisation = s.page_texels ? double(s.covered_texels) / double(s.page_texels) : 0;
  s.utilisation_centres = s.page_texels ? double(s.centre_covered_texels) / double(s.page_texels) : 0;
  return s;
}

}  // namespace radbake
