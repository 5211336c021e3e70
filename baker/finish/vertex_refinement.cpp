#include "baker/finish/vertex_refinement.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <map>
#include <queue>
#include <unordered_map>

#include "uv/texel_coverage.h"

namespace radbake {

Rgb sample_bilinear(const LightmapPage& page, Vec2 texel) {
  if (page.width <= 0 || page.height <= 0) return {};
  const float fx = texel.x - 0.5f, fy = texel.y - 0.5f;
  const float x_floor = std::floor(fx), y_floor = std::floor(fy);
  const float ax = fx - x_floor, ay = fy - y_floor;
  auto at = [&](float x, float y) {
    int xi = int(std::clamp(x, 0.0f, float(page.width - 1)));
    int yi = int(std::clamp(y, 0.0f, float(page.height - 1)));
    return page.texels[size_t(yi) * size_t(page.width) + size_t(xi)];
  };
  Rgb top = at(x_floor, y_floor) * (1 - ax) + at(x_floor + 1, y_floor) * ax;
  Rgb bottom = at(x_floor, y_floor + 1) * (1 - ax) + at(x_floor + 1, y_floor + 1) * ax;
  return top * (1 - ay) + bottom * ay;
}

namespace {

// The pieces for_each_covered_texel (uv/texel_coverage.h) gives, but a texel wholly inside the
// triangle is taken whole without clipping: most texels of a large triangle are, and refinement
// measures every covered texel again at each level of splitting.
template <typename Visit>
void for_each_texel_piece(Vec2 a, Vec2 b, Vec2 c, int width, int height, Visit&& visit) {
  const float min_x = std::min({a.x, b.x, c.x}), max_x = std::max({a.x, b.x, c.x});
  const float min_y = std::min({a.y, b.y, c.y}), max_y = std::max({a.y, b.y, c.y});
  if (!(min_x < max_x) || !(min_y < max_y)) return;  // degenerate or non-finite
  const int x0 = std::max(0, int(std::floor(min_x))), x1 = std::min(width - 1, int(std::floor(max_x)));
  const int y0 = std::max(0, int(std::floor(min_y))), y1 = std::min(height - 1, int(std::floor(max_y)));
  // Edge functions, positive inside whatever the winding.
  const double sign = cross2(b - a, c - a) > 0 ? 1.0 : -1.0;
  const Vec2 tri[3] = {a, b, c};
  double nx[3], ny[3], d[3];
  for (int k = 0; k < 3; ++k) {
    const Vec2 p = tri[k], q = tri[(k + 1) % 3];
    nx[k] = -sign * (double(q.y) - p.y);
    ny[k] = sign * (double(q.x) - p.x);
    d[k] = -(nx[k] * p.x + ny[k] * p.y);
  }
  Vec2 tmp[8], out[8];
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      bool whole = true, outside = false;
      for (int k = 0; k < 3 && !outside; ++k) {
        const double e00 = nx[k] * x + ny[k] * y + d[k];
        const double e10 = e00 + nx[k], e01 = e00 + ny[k], e11 = e10 + ny[k];
        if (e00 < 0 && e10 < 0 && e01 < 0 && e11 < 0) outside = true;
        else if (e00 < 0 || e10 < 0 || e01 < 0 || e11 < 0) whole = false;
      }
      if (outside) continue;
      if (whole) {
        visit(TexelPiece{x, y, 1.0f, {x + 0.5f, y + 0.5f}});
        continue;
      }
      int n = detail::clip_polygon(tri, 3, tmp, 0, float(x), 1.0f);
      n = detail::clip_polygon(tmp, n, out, 0, float(x + 1), -1.0f);
      n = detail::clip_polygon(out, n, tmp, 1, float(y), 1.0f);
      n = detail::clip_polygon(tmp, n, out, 1, float(y + 1), -1.0f);
      if (n < 3) continue;
      Vec2 centroid{x + 0.5f, y + 0.5f};
      const float area = std::fabs(detail::polygon_area_centroid(out, n, centroid));
      if (area > 1e-7f) visit(TexelPiece{x, y, std::min(area, 1.0f), centroid});
    }
}

// An edge by the welded ids of its ends (vertices at one position share an id), either order.
uint64_t edge_key(uint32_t a, uint32_t b) {
  if (a > b) std::swap(a, b);
  return (uint64_t(a) << 32) | b;
}

struct Vertex {
  Vec3 position;  // world, metres
  Vec2 texel;     // page texel units
  uint32_t weld;  // same id for every vertex of the instance at this position
};

struct Triangle {
  uint32_t v[3];
  uint32_t source;       // input triangle
  uint32_t version = 0;  // bumped whenever the triangle changes, so stale queue entries are skipped
  double error = 0;      // sum over covered valid texels of world area x mean squared difference
  double weight = 0;     // world area of the covered valid texels, m^2
  double light = 0;      // sum of world area x texel light (mean of RGB)
  float footprint = 0;   // texels^2
};

struct Candidate {
  double error;
  uint32_t instance, triangle, version;
  // Largest error first; ties by position in the scene, so the order never depends on the heap.
  bool operator<(const Candidate& o) const {
    if (error != o.error) return error < o.error;
    if (instance != o.instance) return instance > o.instance;
    return triangle > o.triangle;
  }
};

// One instance's mesh while it is refined.
struct Refiner {
  const AtlasMesh* atlas = nullptr;
  const LightmapPage* page = nullptr;
  RefinedMesh out;  // vertices and values grow here; triangles are written at the end
  std::vector<Vertex> vertices;
  std::vector<Triangle> triangles;
  std::unordered_map<uint64_t, std::vector<uint32_t>> edges;  // welded edge -> triangles using it
  uint32_t next_weld = 0;

  bool splittable(const Triangle& t) const {
    uint32_t a = vertices[t.v[0]].weld, b = vertices[t.v[1]].weld, c = vertices[t.v[2]].weld;
    return a != b && b != c && c != a;
  }

  // The triangle's edges by welded ends, in corner order (edge k runs from v[k] to v[k + 1]).
  std::array<uint64_t, 3> edge_keys(const Triangle& t) const {
    std::array<uint64_t, 3> keys;
    for (int k = 0; k < 3; ++k) keys[size_t(k)] = edge_key(vertices[t.v[k]].weld, vertices[t.v[(k + 1) % 3]].weld);
    return keys;
  }

  // The longest edge in world space; equal lengths are ordered by key, so every triangle sharing
  // an edge ranks it the same way (the ends' positions are bit-identical on both sides).
  int longest_edge(const Triangle& t) const {
    int best = 0;
    double best_length = -1;
    uint64_t best_key = 0;
    std::array<uint64_t, 3> keys = edge_keys(t);
    for (int k = 0; k < 3; ++k) {
      Vec3 d = vertices[t.v[(k + 1) % 3]].position - vertices[t.v[k]].position;
      double length = double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z;
      if (length > best_length || (length == best_length && keys[size_t(k)] > best_key)) {
        best = k;
        best_length = length;
        best_key = keys[size_t(k)];
      }
    }
    return best;
  }

  void measure(Triangle& t) const {
    t.error = t.weight = t.light = 0;
    const Vec2 a = vertices[t.v[0]].texel, b = vertices[t.v[1]].texel, c = vertices[t.v[2]].texel;
    const float doubled = cross2(b - a, c - a);
    t.footprint = 0.5f * std::fabs(doubled);
    if (!(t.footprint > 0)) return;
    const Vec3 pa = vertices[t.v[0]].position;
    const float world_area = 0.5f * length(cross(vertices[t.v[1]].position - pa, vertices[t.v[2]].position - pa));
    const double area_per_texel = double(world_area) / t.footprint;  // affine within a triangle
    const Rgb va = out.values[t.v[0]], vb = out.values[t.v[1]], vc = out.values[t.v[2]];
    for_each_texel_piece(a, b, c, page->width, page->height, [&](const TexelPiece& p) {
      const size_t index = size_t(p.y) * size_t(page->width) + size_t(p.x);
      // Buried or outside any chart: nobody sees it. A page without the mask counts every texel.
      if (!page->valid.empty() && !page->valid[index]) return;
      // Interpolated at the piece's centroid, which lies inside the triangle.
      const float wb = cross2(p.centroid - a, c - a) / doubled, wc = cross2(b - a, p.centroid - a) / doubled;
      const Rgb interpolated = va * (1 - wb - wc) + vb * wb + vc * wc;
      const Rgb texel = page->texels[index];
      const Rgb d = interpolated - texel;
      const double w = p.area * area_per_texel;
      t.error += w * (double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z) / 3;
      t.weight += w;
      t.light += w * (double(texel.x) + texel.y + texel.z) / 3;
    });
  }

  // Where the input triangle `source` holds refined vertex v: its barycentric weights there.
  std::array<float, 3> weights_in(uint32_t source, uint32_t v) const {
    std::array<float, 3> w{0, 0, 0};
    const RefinedVertex& r = out.vertices[v];
    for (int k = 0; k < 3; ++k) {
      if (r.weight[k] == 0) continue;
      int slot = 0;
      while (slot < 3 && atlas->triangles[3 * size_t(source) + size_t(slot)] != r.corner[k]) ++slot;
      assert(slot < 3);  // a vertex of a sub-triangle lies in its input triangle
      if (slot < 3) w[size_t(slot)] += r.weight[k];
    }
    return w;
  }

  uint32_t add_midpoint(uint32_t source, uint32_t u, uint32_t v, uint32_t weld) {
    std::array<float, 3> wu = weights_in(source, u), wv = weights_in(source, v);
    RefinedVertex r;
    for (int k = 0; k < 3; ++k) {
      r.corner[k] = atlas->triangles[3 * size_t(source) + size_t(k)];
      r.weight[k] = 0.5f * (wu[size_t(k)] + wv[size_t(k)]);  // halves of dyadic fractions: exact
    }
    Vertex x;
    x.position = blend<Vec3>(r, [&](uint32_t a) { return (*positions)[atlas->source_vertex[a]]; });
    x.texel = blend<Vec2>(r, [&](uint32_t a) { return Vec2{atlas->uvs[a].x * page->width, atlas->uvs[a].y * page->height}; });
    x.weld = weld;
    out.vertices.push_back(r);
    out.values.push_back(sample_bilinear(*page, x.texel));
    vertices.push_back(x);
    return uint32_t(vertices.size() - 1);
  }

  void replace_on_edge(uint64_t key, uint32_t from, uint32_t to) {
    for (uint32_t& t : edges[key])
      if (t == from) t = to;
  }

  // Splits welded edge `key` at its midpoint in every triangle that uses it, so the mesh stays
  // conforming: one new vertex per distinct pair of ends (triangles of one chart share it; the
  // other side of a seam gets its own, at the same position). Returns the triangles changed or made.
  std::vector<uint32_t> split_edge(uint64_t key) {
    std::vector<uint32_t> users = edges[key];
    edges.erase(key);
    const uint32_t weld = next_weld++;
    std::vector<std::array<uint32_t, 3>> made;  // (end, end, midpoint) for this split
    std::vector<uint32_t> touched;
    for (uint32_t ti : users) {
      // Rotate so the split edge runs from corner 0 to corner 1.
      Triangle& t0 = triangles[ti];
      std::array<uint64_t, 3> keys = edge_keys(t0);
      int k = 0;
      while (k < 3 && keys[size_t(k)] != key) ++k;
      assert(k < 3);
      const uint32_t a = t0.v[k], b = t0.v[(k + 1) % 3], c = t0.v[(k + 2) % 3];
      uint32_t m = UINT32_MAX;
      for (const auto& e : made)
        if ((e[0] == a && e[1] == b) || (e[0] == b && e[1] == a)) m = e[2];
      if (m == UINT32_MAX) {
        m = add_midpoint(t0.source, a, b, weld);
        made.push_back({a, b, m});
      }
      const uint32_t ni = uint32_t(triangles.size());
      Triangle n;
      n.v[0] = m, n.v[1] = b, n.v[2] = c;
      n.source = t0.source;
      triangles.push_back(n);  // t0 may dangle from here on
      Triangle& t = triangles[ti];
      t.v[0] = a, t.v[1] = m, t.v[2] = c;
      ++t.version;
      const uint32_t wa = vertices[a].weld, wb = vertices[b].weld, wc = vertices[c].weld;
      replace_on_edge(edge_key(wb, wc), ti, ni);
      edges[edge_key(wa, weld)].push_back(ti);
      edges[edge_key(weld, wb)].push_back(ni);
      std::vector<uint32_t>& middle = edges[edge_key(weld, wc)];
      middle.push_back(ti);
      middle.push_back(ni);
      touched.push_back(ti);
      touched.push_back(ni);
    }
    for (uint32_t ti : touched) measure(triangles[ti]);
    return touched;
  }

  const std::vector<Vec3>* positions = nullptr;
};

}  // namespace

VertexRefinement refine_vertex_light(const Scene& scene, const Atlas& atlas, const std::vector<LightmapPage>& pages,
                                     const std::vector<std::vector<Rgb>>& vertex_values,
                                     const RefinementOptions& options) {
  assert(atlas.meshes.size() == scene.instances.size() && vertex_values.size() == atlas.meshes.size());
  std::vector<Refiner> refiners(atlas.meshes.size());
  size_t total = 0;
  for (size_t m = 0; m < atlas.meshes.size(); ++m) {
    Refiner& r = refiners[m];
    const AtlasMesh& mesh = atlas.meshes[m];
    r.atlas = &mesh;
    r.page = &pages[size_t(mesh.page)];
    r.positions = &scene.instances[m].positions;
    // Weld by exact position (value comparison, so -0 and +0 agree): the sides of a chart seam and
    // of a hard edge (vertices split for their normals) then split together, without T-junctions.
    std::map<std::array<float, 3>, uint32_t> weld_of;
    const size_t n = mesh.uvs.size();
    r.vertices.resize(n);
    r.out.vertices.resize(n);
    r.out.values.assign(vertex_values[m].begin(), vertex_values[m].end());
    for (size_t v = 0; v < n; ++v) {
      const Vec3 p = scene.instances[m].positions[mesh.source_vertex[v]];
      auto inserted = weld_of.emplace(std::array<float, 3>{p.x, p.y, p.z}, r.next_weld);
      if (inserted.second) ++r.next_weld;
      r.vertices[v] = {p, {mesh.uvs[v].x * r.page->width, mesh.uvs[v].y * r.page->height}, inserted.first->second};
      r.out.vertices[v] = RefinedVertex{{uint32_t(v), uint32_t(v), uint32_t(v)}, {1, 0, 0}};
    }
    const size_t count = mesh.triangles.size() / 3;
    r.triangles.resize(count);
    for (size_t t = 0; t < count; ++t) {
      Triangle& tri = r.triangles[t];
      for (int k = 0; k < 3; ++k) tri.v[k] = mesh.triangles[3 * t + size_t(k)];
      tri.source = uint32_t(t);
      r.measure(tri);
      // A triangle with two ends welded together has no area to refine; it stays out of the
      // adjacency, so no split ever reaches it.
      if (!r.splittable(tri)) continue;
      for (uint64_t key : r.edge_keys(tri)) r.edges[key].push_back(uint32_t(t));
    }
    total += count;
  }

  VertexRefinement result;
  double light = 0, weight = 0;
  for (const Refiner& r : refiners)
    for (const Triangle& t : r.triangles) light += t.light, weight += t.weight;
  result.mean_light = weight > 0 ? light / weight : 0;

  auto relative_rms = [&] {
    double error = 0, w = 0;
    for (const Refiner& r : refiners)
      for (const Triangle& t : r.triangles) error += t.error, w += t.weight;
    return w > 0 && result.mean_light > 0 ? std::sqrt(error / w) / result.mean_light : 0.0;
  };
  auto record = [&] {
    result.curve.triangles.push_back(total);
    result.curve.rms_relative.push_back(relative_rms());
  };
  record();

  const double mean = result.mean_light;
  const double tolerance = double(options.tolerance) * mean;
  std::priority_queue<Candidate> queue;
  auto offer = [&](uint32_t m, uint32_t ti) {
    const Triangle& t = refiners[m].triangles[ti];
    if (t.footprint < options.min_footprint || !(t.weight > 0) || !refiners[m].splittable(t)) return;
    if (!(std::sqrt(t.error / t.weight) > tolerance)) return;
    queue.push({t.error, m, ti, t.version});
  };
  const bool refine = options.max_triangles > total && mean > 0;
  if (refine)
    for (uint32_t m = 0; m < refiners.size(); ++m)
      for (uint32_t t = 0; t < refiners[m].triangles.size(); ++t) offer(m, t);

  Progress progress(options.progress);
  if (refine) progress.begin("vertex refinement", options.max_triangles - total);
  size_t next_record = 2 * total;
  bool budget_left = true;
  while (budget_left && !queue.empty()) {
    const Candidate top = queue.top();
    queue.pop();
    Refiner& r = refiners[top.instance];
    if (r.triangles[top.triangle].version != top.version) continue;
    // Longest-edge bisection (Rivara's LEPP): to halve this triangle along its longest edge, first
    // walk to neighbours whose own longest edge is longer and halve those, so every split is of an
    // edge that is longest on both sides and angles never degrade. The walk climbs strictly longer
    // edges, so it ends; each split keeps the mesh conforming, so stopping anywhere is safe.
    const Triangle& target = r.triangles[top.triangle];
    const uint64_t goal = r.edge_keys(target)[size_t(r.longest_edge(target))];
    while (budget_left && r.edges.count(goal)) {
      uint64_t key = goal;
      uint32_t from = top.triangle;
      for (;;) {
        uint32_t next = UINT32_MAX;
        for (uint32_t n : r.edges[key]) {
          if (n == from) continue;
          const Triangle& t = r.triangles[n];
          if (r.edge_keys(t)[size_t(r.longest_edge(t))] != key) {
            next = n;
            break;
          }
        }
        if (next == UINT32_MAX) break;
        from = next;
        key = r.edge_keys(r.triangles[next])[size_t(r.longest_edge(r.triangles[next]))];
      }
      const size_t adds = r.edges[key].size();
      if (total + adds > options.max_triangles) {
        budget_left = false;
        break;
      }
      for (uint32_t t : r.split_edge(key)) offer(top.instance, t);
      total += adds;
      progress.advance(adds);
      if (total >= next_record) {
        record();
        next_record = 2 * total;
      }
    }
  }
  if (refine) progress.end();
  if (result.curve.triangles.back() != total) record();

  result.meshes.resize(refiners.size());
  for (size_t m = 0; m < refiners.size(); ++m) {
    Refiner& r = refiners[m];
    RefinedMesh& out = result.meshes[m];
    out.vertices = std::move(r.out.vertices);
    out.values = std::move(r.out.values);
    out.triangles.reserve(3 * r.triangles.size());
    out.source_triangle.reserve(r.triangles.size());
    for (const Triangle& t : r.triangles) {
      out.triangles.insert(out.triangles.end(), t.v, t.v + 3);
      out.source_triangle.push_back(t.source);
    }
  }
  return result;
}

}  // namespace radbake
