#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include "uv/charts.h"

namespace radbake {
namespace {

// Coincident positions become one vertex so that meshes exported with split vertices (flat
// shading, UV seams) still connect.
std::vector<uint32_t> weld_positions(const MeshView& mesh) {
  struct Key {
    uint32_t bits[3];
    bool operator==(const Key& o) const { return std::memcmp(bits, o.bits, sizeof bits) == 0; }
  };
  struct Hash {
    size_t operator()(const Key& k) const {
      return (size_t(k.bits[0]) * 73856093u) ^ (size_t(k.bits[1]) * 19349663u) ^
             (size_t(k.bits[2]) * 83492791u);
    }
  };
  std::unordered_map<Key, uint32_t, Hash> first;
  std::vector<uint32_t> canonical(mesh.vertex_count);
  for (size_t v = 0; v < mesh.vertex_count; ++v) {
    Vec3 p = mesh.positions[v];
    for (int i = 0; i < 3; ++i)
      if (p[i] == 0.0f) p[i] = 0.0f;  // -0 and +0 are the same place
    Key key;
    std::memcpy(key.bits, &p, sizeof key.bits);
    canonical[v] = first.emplace(key, uint32_t(v)).first->second;
  }
  return canonical;
}

struct DirectedEdge {
  uint64_t key;  // unordered pair of welded vertices
  uint32_t triangle;
  bool forward;  // lower vertex id first in the triangle's winding
};

// For each triangle edge, the triangle across it when the edge is manifold and consistently
// wound, else -1.
std::vector<int64_t> manifold_neighbours(const MeshView& mesh, const std::vector<uint32_t>& canonical) {
  std::vector<DirectedEdge> edges;
  edges.reserve(mesh.triangle_count * 3);
  for (uint32_t t = 0; t < mesh.triangle_count; ++t)
    for (int e = 0; e < 3; ++e) {
      uint32_t a = canonical[mesh.triangles[3 * t + e]], b = canonical[mesh.triangles[3 * t + (e + 1) % 3]];
      if (a == b) continue;
      uint64_t lo = std::min(a, b), hi = std::max(a, b);
      edges.push_back({lo << 32 | hi, t * 3 + uint32_t(e), a < b});
    }
  std::sort(edges.begin(), edges.end(), [](const DirectedEdge& x, const DirectedEdge& y) {
    return x.key != y.key ? x.key < y.key : x.triangle < y.triangle;
  });
  std::vector<int64_t> neighbour(mesh.triangle_count * 3, -1);
  for (size_t i = 0; i < edges.size();) {
    size_t j = i;
    while (j < edges.size() && edges[j].key == edges[i].key) ++j;
    if (j - i == 2 && edges[i].forward != edges[i + 1].forward) {
      neighbour[edges[i].triangle] = edges[i + 1].triangle / 3;
      neighbour[edges[i + 1].triangle] = edges[i].triangle / 3;
    }
    i = j;
  }
  return neighbour;
}

std::vector<Vec2> convex_hull(std::vector<Vec2> points) {
  std::sort(points.begin(), points.end(), [](Vec2 a, Vec2 b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  if (points.size() < 3) return points;
  std::vector<Vec2> hull(2 * points.size());
  size_t k = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross2(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross2(hull[k - 1] - hull[k - 2], points[i - 1] - hull[k - 2]) <= 0) --k;
    hull[k++] = points[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

// Turns the chart so its bounding rectangle has the least area (one side of the best rectangle
// lies along a hull edge), then moves its minimum corner to the origin.
void fit_bounding_rectangle(Chart& chart) {
  std::vector<Vec2> hull = convex_hull(chart.corner_uv);
  Vec2 best_axis{1, 0};
  float best_area = INFINITY;
  for (size_t i = 0; i < hull.size(); ++i) {
    Vec2 e = hull[(i + 1) % hull.size()] - hull[i];
    float len = std::sqrt(e.x * e.x + e.y * e.y);
    if (len <= 0) continue;
    Vec2 u = e * (1 / len);
    float lo_u = INFINITY, hi_u = -INFINITY, lo_v = INFINITY, hi_v = -INFINITY;
    for (Vec2 p : hull) {
      float pu = p.x * u.x + p.y * u.y, pv = -p.x * u.y + p.y * u.x;
      lo_u = std::min(lo_u, pu), hi_u = std::max(hi_u, pu);
      lo_v = std::min(lo_v, pv), hi_v = std::max(hi_v, pv);
    }
    float area = (hi_u - lo_u) * (hi_v - lo_v);
    if (area < best_area * 0.9999f) best_area = area, best_axis = u;
  }
  Vec2 lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
  for (Vec2& p : chart.corner_uv) {
    p = {p.x * best_axis.x + p.y * best_axis.y, -p.x * best_axis.y + p.y * best_axis.x};
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  for (Vec2& p : chart.corner_uv) p = p - lo;
  chart.extent = hi - lo;
}

}  // namespace

std::vector<Chart> planar_charts(const MeshView& mesh, uint32_t mesh_index) {
  const size_t triangle_count = mesh.triangle_count;
  std::vector<uint32_t> canonical = weld_positions(mesh);
  std::vector<int64_t> neighbour = manifold_neighbours(mesh, canonical);

  auto corner = [&](size_t t, int k) { return mesh.positions[mesh.triangles[3 * t + k]]; };
  std::vector<Vec3> normal(triangle_count);
  std::vector<float> area(triangle_count);
  for (size_t t = 0; t < triangle_count; ++t) {
    Vec3 n = cross(corner(t, 1) - corner(t, 0), corner(t, 2) - corner(t, 0));
    area[t] = 0.5f * length(n);
    normal[t] = normalize(n);
  }

  const float kCosPlanar = 0.99985f;  // normals within 1 degree
  std::vector<char> assigned(triangle_count, 0);
  std::vector<Chart> charts;
  std::vector<uint32_t> stack;
  for (uint32_t seed = 0; seed < triangle_count; ++seed) {
    if (assigned[seed] || !(area[seed] > 0) || !std::isfinite(area[seed])) continue;
    Vec3 n = normal[seed], origin = corner(seed, 0);
    Vec3 t_axis = normalize(corner(seed, 1) - origin), b_axis = cross(n, t_axis);
    float size = std::sqrt(area[seed]);
    Chart chart;
    chart.mesh = mesh_index;
    stack.assign(1, seed);
    assigned[seed] = 1;
    while (!stack.empty()) {
      uint32_t t = stack.back();
      stack.pop_back();
      chart.triangles.push_back(t);
      for (int e = 0; e < 3; ++e) {
        int64_t u = neighbour[3 * t + e];
        if (u < 0 || assigned[u] || !(area[u] > 0) || dot(normal[u], n) < kCosPlanar) continue;
        bool in_plane = true;
        for (int k = 0; k < 3; ++k)
          in_plane &= std::fabs(dot(corner(size_t(u), k) - origin, n)) <= 1e-3f * (size + std::sqrt(area[u]));
        if (!in_plane) continue;
        assigned[u] = 1;
        stack.push_back(uint32_t(u));
      }
    }
    std::sort(chart.triangles.begin(), chart.triangles.end());
    for (uint32_t t : chart.triangles)
      for (int k = 0; k < 3; ++k) {
        Vec3 d = corner(t, k) - origin;
        chart.corner_uv.push_back({dot(d, t_axis), dot(d, b_axis)});
      }
    fit_bounding_rectangle(chart);
    charts.push_back(std::move(chart));
  }
  return charts;
}

}  // namespace radbake
