#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <tuple>
#include <unordered_map>

#include "uv/charts.h"
#include "uv/half_edge_mesh.h"
#include "uv/texel_coverage.h"

namespace radbake {
namespace {

using FaceList = std::vector<int>;

// A chart's vertices numbered locally, with their positions.
struct LocalChart {
  FaceList faces;
  std::unordered_map<int, int> local;  // OpenMesh vertex -> local index
  std::vector<int> vertex;             // local index -> OpenMesh vertex
  std::vector<Vec3> position;
  std::vector<Vec2> uv;                // metres
  Vec3 normal;                         // area-weighted mean, unit
};

LocalChart gather(const HalfEdgeMesh& hm, const FaceList& faces) {
  LocalChart c;
  c.faces = faces;
  Vec3 n{};
  for (int f : faces) {
    n += hm.face_normal[size_t(f)] * hm.face_area[size_t(f)];
    for (auto v : hm.mesh.fv_range(HalfEdgeTriMesh::FaceHandle(f))) {
      auto [it, inserted] = c.local.emplace(v.idx(), int(c.vertex.size()));
      if (inserted) {
        c.vertex.push_back(v.idx());
        c.position.push_back(to_vec3(hm.mesh.point(v)));
      }
    }
  }
  c.normal = normalize(n);
  if (!(length(c.normal) > 0.5f)) c.normal = hm.face_normal[size_t(faces[0])];
  return c;
}

// The chart's face corners as local vertex indices, in OpenMesh's order (counter-clockwise).
void corners(const HalfEdgeMesh& hm, const LocalChart& c, int f, int out[3]) {
  int k = 0;
  for (auto v : hm.mesh.fv_range(HalfEdgeTriMesh::FaceHandle(f))) out[k++] = c.local.at(v.idx());
}

void plane_axes(Vec3 n, Vec3& t, Vec3& b) { orthonormal_basis(n, t, b); }

void project(LocalChart& c) {
  Vec3 t, b;
  plane_axes(c.normal, t, b);
  c.uv.resize(c.position.size());
  for (size_t i = 0; i < c.position.size(); ++i) c.uv[i] = {dot(c.position[i], t), dot(c.position[i], b)};
}

// Least-squares conformal map with two vertices pinned at their projections: the two farthest
// apart along the chart's main axis, which fixes scale and turn without bending the map.
bool conformal_map(const HalfEdgeMesh& hm, LocalChart& c) {
  project(c);  // pins and the fallback frame come from the projection
  const int n = int(c.vertex.size());
  Vec2 mean{};
  for (Vec2 p : c.uv) mean = mean + p;
  mean = mean * (1.0f / float(n));
  double sxx = 0, sxy = 0, syy = 0;
  for (Vec2 p : c.uv) {
    Vec2 d = p - mean;
    sxx += d.x * d.x, sxy += d.x * d.y, syy += d.y * d.y;
  }
  double angle = 0.5 * std::atan2(2 * sxy, sxx - syy);
  Vec2 axis{float(std::cos(angle)), float(std::sin(angle))};
  int pin[2] = {0, 0};
  float lo = INFINITY, hi = -INFINITY;
  for (int i = 0; i < n; ++i) {
    float s = c.uv[size_t(i)].x * axis.x + c.uv[size_t(i)].y * axis.y;
    if (s < lo) lo = s, pin[0] = i;
    if (s > hi) hi = s, pin[1] = i;
  }
  if (pin[0] == pin[1]) return false;

  std::vector<int> column(size_t(n), -1);
  int free = 0;
  for (int i = 0; i < n; ++i)
    if (i != pin[0] && i != pin[1]) column[size_t(i)] = free++;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * Eigen::Index(c.faces.size()));
  int row = 0;
  for (int f : c.faces) {
    int v[3];
    corners(hm, c, f, v);
    // The triangle in its own plane: q0 at the origin, q1 on the x axis.
    Vec3 p0 = c.position[size_t(v[0])], p1 = c.position[size_t(v[1])], p2 = c.position[size_t(v[2])];
    Vec3 ex = normalize(p1 - p0), ey = cross(hm.face_normal[size_t(f)], ex);
    double q[3][2] = {{0, 0}, {dot(p1 - p0, ex), 0}, {dot(p2 - p0, ex), dot(p2 - p0, ey)}};
    double area = 0.5 * q[1][0] * q[2][1];
    if (!(area > 0)) continue;
    double w = 1.0 / (2.0 * std::sqrt(area));
    // Cauchy-Riemann on the linear map: u_x = v_y and u_y = -v_x, with grad f = sum f_j perp(e_j) / 2A.
    for (int j = 0; j < 3; ++j) {
      double ex_j = q[(j + 2) % 3][0] - q[(j + 1) % 3][0], ey_j = q[(j + 2) % 3][1] - q[(j + 1) % 3][1];
      double cu[2] = {-ey_j * w, ex_j * w}, cv[2] = {-ex_j * w, -ey_j * w};
      int col = column[size_t(v[j])];
      for (int e = 0; e < 2; ++e) {
        if (col >= 0) {
          entries.emplace_back(row + e, 2 * col, cu[e]);
          entries.emplace_back(row + e, 2 * col + 1, cv[e]);
        } else {
          Vec2 fixed = c.uv[size_t(v[j])];
          rhs[row + e] -= cu[e] * fixed.x + cv[e] * fixed.y;
        }
      }
    }
    row += 2;
  }
  Eigen::SparseMatrix<double> a(row, 2 * free);
  a.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseMatrix<double> normal = a.transpose() * a;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
  if (solver.info() != Eigen::Success) return false;
  Eigen::VectorXd x = solver.solve(a.transpose() * rhs.head(row));
  if (solver.info() != Eigen::Success || !x.allFinite()) return false;
  for (int i = 0; i < n; ++i)
    if (column[size_t(i)] >= 0) c.uv[size_t(i)] = {float(x[2 * column[size_t(i)]]), float(x[2 * column[size_t(i)] + 1])};
  return true;
}

double uv_area(const HalfEdgeMesh& hm, const LocalChart& c, int f) {
  int v[3];
  corners(hm, c, f, v);
  return 0.5 * double(cross2(c.uv[size_t(v[1])] - c.uv[size_t(v[0])], c.uv[size_t(v[2])] - c.uv[size_t(v[0])]));
}

// True when every face keeps its orientation and no two overlap: rasterised on a fine grid, the
// pieces in any cell add up to at most the cell.
bool maps_cleanly(const HalfEdgeMesh& hm, const LocalChart& c) {
  Vec2 lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
  double total = 0;
  for (Vec2 p : c.uv) lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)}, hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  for (int f : c.faces) {
    double a = uv_area(hm, c, f);
    if (!(a > 0)) return false;
    total += a;
  }
  if (c.faces.size() == 1) return true;
  // About 16 cells per face on average, at most 512 a side.
  float extent = std::max(hi.x - lo.x, hi.y - lo.y);
  float cell = float(std::sqrt(total / (16.0 * double(c.faces.size()))));
  cell = std::max(cell, extent / 512.0f);
  int w = std::max(1, int(std::ceil((hi.x - lo.x) / cell)) + 1), h = std::max(1, int(std::ceil((hi.y - lo.y) / cell)) + 1);
  std::vector<float> covered(size_t(w) * size_t(h), 0.0f);
  bool clean = true;
  for (int f : c.faces) {
    int v[3];
    corners(hm, c, f, v);
    Vec2 g[3];
    for (int k = 0; k < 3; ++k) g[k] = (c.uv[size_t(v[k])] - lo) * (1.0f / cell);
    for_each_covered_texel(g[0], g[1], g[2], w, h, [&](const TexelPiece& piece) {
      float& sum = covered[size_t(piece.y) * size_t(w) + size_t(piece.x)];
      sum += piece.area;
      clean &= sum <= 1.02f;
    });
    if (!clean) return false;
  }
  return true;
}

std::vector<FaceList> connected_parts(const HalfEdgeMesh& hm, const FaceList& faces) {
  std::unordered_map<int, int> part;
  for (int f : faces) part[f] = -1;
  std::vector<FaceList> parts;
  for (int seed : faces) {
    if (part[seed] >= 0) continue;
    FaceList stack{seed}, mine;
    part[seed] = int(parts.size());
    while (!stack.empty()) {
      int f = stack.back();
      stack.pop_back();
      mine.push_back(f);
      for (auto h : hm.mesh.fh_range(HalfEdgeTriMesh::FaceHandle(f))) {
        auto opposite = h.opp();
        if (opposite.is_boundary()) continue;
        auto it = part.find(opposite.face().idx());
        if (it == part.end() || it->second >= 0) continue;
        it->second = int(parts.size());
        stack.push_back(opposite.face().idx());
      }
    }
    parts.push_back(std::move(mine));
  }
  return parts;
}

// How many closed loops the chart's border makes.
int boundary_loops(const HalfEdgeMesh& hm, const FaceList& faces) {
  std::unordered_map<int, bool> in_chart;
  for (int f : faces) in_chart[f] = true;
  auto outside = [&](HalfEdgeTriMesh::HalfedgeHandle h) {
    auto o = hm.mesh.opposite_halfedge_handle(h);
    return hm.mesh.is_boundary(o) || !in_chart.count(hm.mesh.face_handle(o).idx());
  };
  // Border half-edges of the chart, linked head to tail (at a vertex where the border touches
  // itself several continue; any will do for counting loops).
  std::unordered_map<int, std::vector<int>> leaving;  // from vertex -> border half-edges
  std::vector<int> border;
  for (int f : faces)
    for (auto h : hm.mesh.fh_range(HalfEdgeTriMesh::FaceHandle(f)))
      if (outside(h)) {
        border.push_back(h.idx());
        leaving[h.from().idx()].push_back(h.idx());
      }
  std::unordered_map<int, bool> seen;
  int loops = 0;
  for (int start : border) {
    if (seen[start]) continue;
    ++loops;
    for (int h = start; !seen[h];) {
      seen[h] = true;
      int to = hm.mesh.to_vertex_handle(HalfEdgeTriMesh::HalfedgeHandle(h)).idx();
      int next = -1;
      for (int candidate : leaving[to])
        if (!seen[candidate]) next = candidate;
      if (next < 0) break;
      h = next;
    }
  }
  return loops;
}

// Halves a chart across its longest extent (by face centroid) when it cannot be mapped whole.
std::pair<FaceList, FaceList> halve(const HalfEdgeMesh& hm, const FaceList& faces) {
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  std::vector<Vec3> centre(faces.size());
  for (size_t i = 0; i < faces.size(); ++i) {
    Vec3 s{};
    for (auto v : hm.mesh.fv_range(HalfEdgeTriMesh::FaceHandle(faces[i]))) s += to_vec3(hm.mesh.point(v));
    centre[i] = s / 3.0f;
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], centre[i][a]), hi[a] = std::max(hi[a], centre[i][a]);
  }
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (hi[a] - lo[a] > hi[axis] - lo[axis]) axis = a;
  std::vector<size_t> order(faces.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return centre[a][axis] < centre[b][axis]; });
  std::pair<FaceList, FaceList> out;
  for (size_t k = 0; k < order.size(); ++k) (k < order.size() / 2 ? out.first : out.second).push_back(faces[order[k]]);
  return out;
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

// The direction of the smallest rectangle round the points (a side of it lies along a hull edge),
// and that rectangle's sides along and across it.
Vec2 smallest_rectangle(const std::vector<Vec2>& points, Vec2* sides) {
  std::vector<Vec2> hull = convex_hull(points);
  Vec2 best_axis{1, 0};
  float best_area = INFINITY;
  *sides = {0, 0};
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
    if (area < best_area * 0.9999f) best_area = area, best_axis = u, *sides = {hi_u - lo_u, hi_v - lo_v};
  }
  return best_axis;
}

// Turns the chart so its bounding rectangle is smallest when charts may turn, and moves its
// minimum corner to the origin.
void fit_bounding_rectangle(Chart& chart, bool may_rotate) {
  Vec2 sides;
  const Vec2 best_axis = may_rotate ? smallest_rectangle(chart.corner_uv, &sides) : Vec2{1, 0};
  Vec2 lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
  for (Vec2& p : chart.corner_uv) {
    p = {p.x * best_axis.x + p.y * best_axis.y, -p.x * best_axis.y + p.y * best_axis.x};
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  for (Vec2& p : chart.corner_uv) p = p - lo;
  chart.extent = hi - lo;
}

Chart make_chart(const HalfEdgeMesh& hm, const LocalChart& c, uint32_t mesh_index, bool may_rotate) {
  // Conformal maps keep angles, not area: scale the chart to its surface area so that a texel
  // covers the same area everywhere.
  double area_3d = 0, area_uv = 0;
  for (int f : c.faces) area_3d += hm.face_area[size_t(f)], area_uv += uv_area(hm, c, f);
  float scale = area_uv > 0 ? float(std::sqrt(area_3d / area_uv)) : 1.0f;
  Chart chart;
  chart.mesh = mesh_index;
  std::vector<int> faces = c.faces;
  std::sort(faces.begin(), faces.end(), [&](int a, int b) { return hm.input_triangle[size_t(a)] < hm.input_triangle[size_t(b)]; });
  for (int f : faces) {
    uint32_t t = hm.input_triangle[size_t(f)];
    chart.triangles.push_back(t);
    for (int k = 0; k < 3; ++k) chart.corner_uv.push_back(c.uv[size_t(c.local.at(hm.corner_vertex[3 * t + k]))] * scale);
  }
  fit_bounding_rectangle(chart, may_rotate);
  return chart;
}

// Sander et al.'s L2 stretch of a mapped chart, scaled to its area as make_chart scales it: the
// whole chart's (area-weighted) and its worst face's.
Vec2 chart_stretch(const HalfEdgeMesh& hm, const LocalChart& c) {
  double area_3d = 0, area_uv = 0, sum = 0, worst = 0;
  for (int f : c.faces) {
    int v[3];
    corners(hm, c, f, v);
    const Vec2 t[3] = {c.uv[size_t(v[0])], c.uv[size_t(v[1])], c.uv[size_t(v[2])]};
    const Vec3 q[3] = {c.position[size_t(v[0])], c.position[size_t(v[1])], c.position[size_t(v[2])]};
    const double a = 0.5 * double(cross2(t[1] - t[0], t[2] - t[0])), a3 = hm.face_area[size_t(f)];
    if (!(a > 0) || !(a3 > 0)) continue;
    Vec3 ss = (q[0] * (t[1].y - t[2].y) + q[1] * (t[2].y - t[0].y) + q[2] * (t[0].y - t[1].y)) / float(2 * a);
    Vec3 st = (q[0] * (t[2].x - t[1].x) + q[1] * (t[0].x - t[2].x) + q[2] * (t[1].x - t[0].x)) / float(2 * a);
    const double l2 = std::sqrt((double(dot(ss, ss)) + double(dot(st, st))) / 2);
    sum += l2 * l2 * a3, area_3d += a3, area_uv += a, worst = std::max(worst, l2);
  }
  if (!(area_3d > 0)) return {1, 1};
  const double normaliser = std::sqrt(area_uv / area_3d);
  return {float(std::sqrt(sum / area_3d) * normaliser), float(worst * normaliser)};
}

// A conformal map may squash a face it cannot lay flat well (a sliver at a sharp corner of a
// curved chart) to a line; a chart whose worst face stretches more than this is split instead.
constexpr float kMostFaceStretch = 4;

// Flattens `faces` (one connected piece): a plane by projection; a curved disc by a conformal map.
// False when the piece is a curved ring, or its map folds, overlaps itself or squashes a face.
bool map_chart(const HalfEdgeMesh& hm, const FaceList& faces, LocalChart& c) {
  static const float cos_planar = std::cos(0.5f * 3.14159265f / 180.0f);
  c = gather(hm, faces);
  bool planar = std::all_of(faces.begin(), faces.end(), [&](int f) { return dot(hm.face_normal[size_t(f)], c.normal) >= cos_planar; });
  // A curved chart must be a disc: a ring (the top of a torus, a band round a cylinder) flattens
  // into an annulus, and rings are what fold.
  if (planar) return project(c), maps_cleanly(hm, c);
  return boundary_loops(hm, faces) <= 1 && conformal_map(hm, c) && maps_cleanly(hm, c) &&
         chart_stretch(hm, c).y <= kMostFaceStretch;
}

// Where piece `s` touches chart `n`: the two ends of the longest stretch of edge they share, as
// each one's UVs put them, and whether the surface folds there.
struct Contact {
  float length = 0;  // metres of edge shared in all, over every stretch
  float longest = 0;
  Vec2 n_from, n_to, s_from, s_to;
  bool folds = true;  // across the longest stretch
};

// Piece `s` laid beside chart `n`, unfolded about where they touch: its own flattening moved,
// turned and scaled so that its ends of the contact land on n's. Faces keep their orientation, so
// the piece falls on the far side of the edge. False when a vertex both share lands elsewhere in n
// (the piece wraps round) or the union does not map cleanly.
bool hinge(const HalfEdgeMesh& hm, const LocalChart& n, const LocalChart& s, const Contact& at, LocalChart& out) {
  const Vec2 from = at.s_to - at.s_from, to = at.n_to - at.n_from;
  const float length2 = from.x * from.x + from.y * from.y;
  if (!(length2 > 0)) return false;
  // z -> n_from + (z - s_from) * to / from, in complex numbers.
  const Vec2 k{(to.x * from.x + to.y * from.y) / length2, (to.y * from.x - to.x * from.y) / length2};
  auto place = [&](Vec2 z) {
    const Vec2 d = z - at.s_from;
    return Vec2{at.n_from.x + d.x * k.x - d.y * k.y, at.n_from.y + d.x * k.y + d.y * k.x};
  };
  out = n;
  const float tolerance = 1e-4f * std::sqrt(to.x * to.x + to.y * to.y);
  for (size_t i = 0; i < s.vertex.size(); ++i) {
    const Vec2 uv = place(s.uv[i]);
    auto [it, inserted] = out.local.emplace(s.vertex[i], int(out.vertex.size()));
    if (inserted) {
      out.vertex.push_back(s.vertex[i]);
      out.position.push_back(s.position[i]);
      out.uv.push_back(uv);
    } else if (const Vec2 off = out.uv[size_t(it->second)] - uv; std::hypot(off.x, off.y) > tolerance) {
      return false;
    }
  }
  out.faces.insert(out.faces.end(), s.faces.begin(), s.faces.end());
  return maps_cleanly(hm, out);
}

// The mesh's open edges (an edge with a face on one side only), found by where they pass, so a
// piece can find the charts it touches without sharing vertices with them: a floor split by a
// T-junction, the faces of a level's brushes, a wall meeting a slab.
class OpenEdges {
 public:
  struct Edge {
    int face, from_vertex, to_vertex;
    Vec3 from, to;
  };
  explicit OpenEdges(const HalfEdgeMesh& hm) {
    double total = 0;
    for (auto h : hm.mesh.halfedges())
      if (!h.is_boundary() && h.opp().is_boundary()) {
        edges_.push_back({h.face().idx(), h.from().idx(), h.to().idx(), to_vec3(hm.mesh.point(h.from())), to_vec3(hm.mesh.point(h.to()))});
        total += double(length(edges_.back().to - edges_.back().from));
      }
    if (edges_.empty()) return;
    cell_ = float(2 * total / double(edges_.size()));
    for (size_t e = 0; e < edges_.size(); ++e) {
      const Vec3 d = edges_[e].to - edges_[e].from;
      // Every cell the edge passes is marked: steps of half a cell, and a long edge's at most 4096.
      const int steps = std::min(4096, 1 + int(2 * length(d) / cell_));
      int64_t last = INT64_MIN;
      for (int i = 0; i <= steps; ++i) {
        const int64_t key = cell_key(edges_[e].from + d * (float(i) / float(steps)));
        if (key != last) by_cell_[key].push_back(uint32_t(e)), last = key;
      }
    }
  }
  // Open edges passing the cell where `p` lies: candidates to test, each perhaps more than once.
  template <class Visit>
  void near(Vec3 p, Visit visit) const {
    if (edges_.empty()) return;
    auto it = by_cell_.find(cell_key(p));
    if (it != by_cell_.end())
      for (uint32_t e : it->second) visit(edges_[e]);
  }

 private:
  int64_t cell_key(Vec3 p) const {
    auto c = [&](float v) { return int64_t(std::floor(v / cell_)) & 0x1fffff; };
    return c(p.x) << 42 | c(p.y) << 21 | c(p.z);
  }
  std::vector<Edge> edges_;
  float cell_ = 1;
  std::unordered_map<int64_t, std::vector<uint32_t>> by_cell_;
};

// Where edge a (of one face) and edge b (of another) lie along one line, run opposite ways (as two
// faces side by side do) and overlap: the overlap's ends as parameters along each.
bool touch(Vec3 a0, Vec3 a1, Vec3 b0, Vec3 b1, float ta[2], float tb[2]) {
  const Vec3 da = a1 - a0, db = b1 - b0;
  const float la2 = dot(da, da), lb2 = dot(db, db);
  if (!(la2 > 0) || !(lb2 > 0)) return false;
  const float la = std::sqrt(la2), lb = std::sqrt(lb2);
  if (dot(da, db) > -0.9999f * la * lb) return false;
  const float tolerance = 1e-4f * std::max(la, lb);
  if (length(cross(a0 - b0, db)) > tolerance * lb || length(cross(a1 - b0, db)) > tolerance * lb) return false;
  const float t0 = dot(a0 - b0, db) / lb2, t1 = dot(a1 - b0, db) / lb2;  // a's ends along b; t0 > t1
  tb[0] = std::max(0.0f, t1), tb[1] = std::min(1.0f, t0);
  if ((tb[1] - tb[0]) * lb <= tolerance) return false;
  for (int i = 0; i < 2; ++i) ta[i] = dot(b0 + db * tb[i] - a0, da) / la2;
  return true;
}

Vec2 along(const LocalChart& c, int from, int to, float t) {
  const Vec2 a = c.uv[size_t(c.local.at(from))], b = c.uv[size_t(c.local.at(to))];
  return a + (b - a) * t;
}

enum class Sliver { None, Resolved, BelowATexel };

// Slivers and specks (thinner than options.sliver_width, or smaller than small_chart_area) cost
// more in padding than they hold. Each joins the chart it shares the most edge with: first one
// where the surface does not fold (less than the hard-edge angle), if the two flatten together
// cleanly and stretch no more than they do apart (L2 within 0.1%, the worst face within 1%): a
// chamfer onto its face, a strip of a thin rod onto the next strip; else, unfolded as it is onto
// a neighbour across any edge (the side of a thin box onto its top, a window frame's profile onto
// its face), if the union maps cleanly. A piece can also join a chart it touches without sharing
// vertices (a T-junction, the brushes of a game level): it is hinged there alike. On its own,
// every such piece took its texels and a ring of padding (the FZK-Haus: 2,750 charts under a
// texel of area, 70% of its charts).
void merge_slivers(const HalfEdgeMesh& hm, const ChartOptions& options, std::vector<LocalChart>& charts,
                   UnwrapProgress& progress) {
  const float cos_fold = std::cos(options.hard_edge_degrees * 3.14159265f / 180.0f);
  std::unordered_map<int, size_t> chart_of;  // face -> index into charts
  for (size_t i = 0; i < charts.size(); ++i)
    for (int f : charts[i].faces) chart_of[f] = i;
  const OpenEdges open_edges(hm);
  // Sizes in metres: a conformal map keeps angles, not scale, so its UVs are scaled by the ratio
  // of areas, as make_chart scales them.
  auto sliver_kind = [&](const LocalChart& c) {
    double area_3d = 0, area_uv = 0;
    for (int f : c.faces) area_3d += hm.face_area[size_t(f)], area_uv += uv_area(hm, c, f);
    Vec2 sides;
    smallest_rectangle(c.uv, &sides);
    const double across = std::min(sides.x, sides.y) * std::sqrt(area_3d / std::max(area_uv, 1e-30));
    if (across < options.texel_size || area_3d < double(options.texel_size) * options.texel_size) return Sliver::BelowATexel;
    return across < options.sliver_width || area_3d < options.small_chart_area ? Sliver::Resolved : Sliver::None;
  };
  std::vector<size_t> order(charts.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::vector<double> area(charts.size(), 0);
  for (size_t i = 0; i < charts.size(); ++i)
    for (int f : charts[i].faces) area[i] += hm.face_area[size_t(f)];
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return area[a] < area[b]; });
  std::vector<bool> gone(charts.size(), false);
  for (size_t k = 0; k < order.size(); ++k) {
    progress.poll();
    const size_t s = order[k];
    const Sliver kind = gone[s] ? Sliver::None : sliver_kind(charts[s]);
    if (kind == Sliver::None) continue;
    std::map<size_t, Contact> contacts;
    auto add_contact = [&](int f, int g, float length, Vec2 n_from, Vec2 n_to, Vec2 s_from, Vec2 s_to) {
      auto it = chart_of.find(g);
      if (it == chart_of.end() || it->second == s) return;
      Contact& c = contacts[it->second];
      c.length += length;
      if (length > c.longest)
        c = {c.length, length, n_from, n_to, s_from, s_to, dot(hm.face_normal[size_t(f)], hm.face_normal[size_t(g)]) < cos_fold};
    };
    for (int f : charts[s].faces)
      for (auto h : hm.mesh.fh_range(HalfEdgeTriMesh::FaceHandle(f))) {
        const int a = h.from().idx(), b = h.to().idx();
        if (!h.opp().is_boundary()) {
          auto n = chart_of.find(h.opp().face().idx());
          if (n == chart_of.end() || n->second == s) continue;
          add_contact(f, h.opp().face().idx(), hm.mesh.calc_edge_length(h), along(charts[n->second], a, b, 0),
                      along(charts[n->second], a, b, 1), along(charts[s], a, b, 0), along(charts[s], a, b, 1));
          continue;
        }
        const Vec3 a0 = to_vec3(hm.mesh.point(h.from())), a1 = to_vec3(hm.mesh.point(h.to()));
        std::set<std::pair<int, int>> seen;
        open_edges.near((a0 + a1) * 0.5f, [&](const OpenEdges::Edge& e) {
          float ta[2], tb[2];
          auto n = chart_of.find(e.face);
          if (n == chart_of.end() || n->second == s || !touch(a0, a1, e.from, e.to, ta, tb)) return;
          if (!seen.insert({e.from_vertex, e.to_vertex}).second) return;
          const LocalChart& c = charts[n->second];
          add_contact(f, e.face, (tb[1] - tb[0]) * length(e.to - e.from), along(c, e.from_vertex, e.to_vertex, tb[0]),
                      along(c, e.from_vertex, e.to_vertex, tb[1]), along(charts[s], a, b, ta[0]), along(charts[s], a, b, ta[1]));
        });
      }
    std::vector<std::pair<float, size_t>> neighbours;
    for (const auto& [n, contact] : contacts) neighbours.push_back({-contact.length, n});
    std::sort(neighbours.begin(), neighbours.end());
    const Vec2 own = chart_stretch(hm, charts[s]);
    // Unfolded onto a neighbour as it is, when it is finer than a texel (a texel cannot show its
    // light apart from its neighbour's anyway) or no flat neighbour takes it.
    for (bool as_it_is : {kind == Sliver::BelowATexel, true}) {
      for (auto [unused, n] : neighbours) {
        LocalChart merged;
        if (as_it_is) {
          if ((kind == Sliver::Resolved && contacts[n].folds) || !hinge(hm, charts[n], charts[s], contacts[n], merged)) continue;
        } else {
          if (contacts[n].folds) continue;
          FaceList faces = charts[n].faces;
          faces.insert(faces.end(), charts[s].faces.begin(), charts[s].faces.end());
          if (!map_chart(hm, faces, merged)) continue;
        }
        const Vec2 theirs = chart_stretch(hm, charts[n]), both = chart_stretch(hm, merged);
        if (both.x > std::max(own.x, theirs.x) * 1.001f || both.y > std::max(own.y, theirs.y) * 1.01f) continue;
        for (int f : charts[s].faces) chart_of[f] = n;
        charts[n] = std::move(merged);
        gone[s] = true;
        break;
      }
      if (gone[s]) break;
    }
  }
  std::vector<LocalChart> left;
  for (size_t i = 0; i < charts.size(); ++i)
    if (!gone[i]) left.push_back(std::move(charts[i]));
  charts = std::move(left);
}

}  // namespace

std::vector<Chart> flatten_charts(const HalfEdgeMesh& hm, const std::vector<int>& chart_of_face, int chart_count,
                                  uint32_t mesh_index, const ChartOptions& options, bool may_rotate,
                                  UnwrapProgress& progress) {
  std::vector<FaceList> pending{size_t(chart_count)};
  for (size_t f = 0; f < chart_of_face.size(); ++f)
    if (chart_of_face[f] >= 0) pending[size_t(chart_of_face[f])].push_back(int(f));
  std::vector<LocalChart> mapped;
  size_t flattened = 0;  // faces, for progress: a chart split in two is counted again
  while (!pending.empty()) {
    FaceList faces = std::move(pending.back());
    pending.pop_back();
    if (faces.empty()) continue;
    for (FaceList& part : connected_parts(hm, faces)) {
      progress.at(double(flattened) / double(chart_of_face.size()));
      flattened += part.size();
      LocalChart c;
      const bool mapped_whole = map_chart(hm, part, c);
      if (mapped_whole || part.size() == 1) {
        if (!mapped_whole) project(c);
        mapped.push_back(std::move(c));
        continue;
      }
      auto [a, b] = halve(hm, part);
      pending.push_back(std::move(a));
      pending.push_back(std::move(b));
    }
  }
  if (options.sliver_width > 0 || options.small_chart_area > 0) merge_slivers(hm, options, mapped, progress);
  std::vector<Chart> out;
  for (const LocalChart& c : mapped) out.push_back(make_chart(hm, c, mesh_index, may_rotate));
  // The order charts are produced in depends only on the mesh: sort for stable output anyway.
  std::sort(out.begin(), out.end(), [](const Chart& a, const Chart& b) { return a.triangles[0] < b.triangles[0]; });
  return out;
}

}  // namespace radbake
