#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <queue>

#include "uv/charts.h"

namespace radbake {
namespace {

constexpr float kDegrees = 3.14159265358979323846f / 180.0f;

Vec3 face_centroid(const HalfEdgeTriMesh& mesh, HalfEdgeTriMesh::FaceHandle f) {
  Vec3 c{};
  for (auto v : mesh.fv_range(f)) c += to_vec3(mesh.point(v));
  return c / 3.0f;
}

// Neighbour across each edge of face f, with the edge's length.
template <typename Visit>
void for_each_neighbour(const HalfEdgeTriMesh& mesh, int f, Visit&& visit) {
  for (auto h : mesh.fh_range(HalfEdgeTriMesh::FaceHandle(f))) {
    auto opposite = h.opp();
    if (opposite.is_boundary()) continue;
    Vec3 a = to_vec3(mesh.point(h.from())), b = to_vec3(mesh.point(h.to()));
    visit(opposite.face().idx(), length(b - a));
  }
}

}  // namespace

std::vector<int> grow_charts(const HalfEdgeMesh& hm, const ChartOptions& options, int* chart_count) {
  const HalfEdgeTriMesh& mesh = hm.mesh;
  const int faces = int(mesh.n_faces());
  const float cos_cone = std::cos(options.max_normal_deviation_degrees * kDegrees);
  const float cos_hard = std::cos(options.hard_edge_degrees * kDegrees);
  std::vector<int> chart(static_cast<size_t>(faces), -1);
  std::vector<Vec3> centroid(static_cast<size_t>(faces));
  for (int f = 0; f < faces; ++f) centroid[size_t(f)] = face_centroid(mesh, HalfEdgeTriMesh::FaceHandle(f));

  // Seeds: largest faces first, so big flat regions start charts and small ones join them.
  std::vector<int> seeds(static_cast<size_t>(faces));
  std::iota(seeds.begin(), seeds.end(), 0);
  std::stable_sort(seeds.begin(), seeds.end(), [&](int a, int b) { return hm.face_area[size_t(a)] > hm.face_area[size_t(b)]; });

  int count = 0;
  std::vector<Vec3> chart_normal;  // area-weighted sum of face normals
  std::vector<float> chart_area;
  using Candidate = std::pair<float, int>;  // cost, face
  for (int seed : seeds) {
    if (chart[size_t(seed)] >= 0) continue;
    const int c = count++;
    const Vec3 seed_normal = hm.face_normal[size_t(seed)], seed_centre = centroid[size_t(seed)];
    Vec3 normal_sum = seed_normal * hm.face_area[size_t(seed)];
    float area = hm.face_area[size_t(seed)];
    chart[size_t(seed)] = c;
    std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> frontier;
    auto offer = [&](int from) {
      for_each_neighbour(mesh, from, [&](int g, float) {
        if (chart[size_t(g)] >= 0 || dot(hm.face_normal[size_t(g)], hm.face_normal[size_t(from)]) < cos_hard) return;
        // Round charts: nearer the seed first, faces turning away from the chart's normal later.
        float turn = 1 - dot(hm.face_normal[size_t(g)], normalize(normal_sum));
        frontier.push({length(centroid[size_t(g)] - seed_centre) * (1 + 8 * turn), g});
      });
    };
    offer(seed);
    while (!frontier.empty()) {
      int f = frontier.top().second;
      frontier.pop();
      if (chart[size_t(f)] >= 0) continue;
      Vec3 n = hm.face_normal[size_t(f)];
      // Within the cone of both the seed and the chart's current mean normal: the mean alone could
      // drift round a cylinder and close it into a ring.
      if (dot(n, seed_normal) < cos_cone || dot(n, normalize(normal_sum)) < cos_cone) continue;
      chart[size_t(f)] = c;
      normal_sum += n * hm.face_area[size_t(f)];
      area += hm.face_area[size_t(f)];
      offer(f);
    }
    chart_normal.push_back(normal_sum);
    chart_area.push_back(area);
  }

  // Tiny charts (a chamfer, a sliver between two walls) cost more in padding than they hold in
  // texels: each joins the neighbour it shares the longest edge with, if the neighbour's normal
  // is within a wider cone. The flattening checks the result; a merge that folds gets split.
  if (options.small_chart_area > 0) {
    std::vector<int> order(static_cast<size_t>(count));
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return chart_area[size_t(a)] < chart_area[size_t(b)]; });
    std::vector<std::vector<int>> faces_of(static_cast<size_t>(count));
    for (int f = 0; f < faces; ++f) faces_of[size_t(chart[size_t(f)])].push_back(f);
    const float cos_merge = std::cos(std::min(89.0f, options.max_normal_deviation_degrees * 1.5f) * kDegrees);
    std::vector<int> merged_into(static_cast<size_t>(count));
    std::iota(merged_into.begin(), merged_into.end(), 0);
    auto root = [&](int c) {
      while (merged_into[size_t(c)] != c) c = merged_into[size_t(c)];
      return c;
    };
    for (int c : order) {
      if (chart_area[size_t(c)] >= options.small_chart_area || root(c) != c) continue;
      std::map<int, float> shared;
      for (int f : faces_of[size_t(c)])
        for_each_neighbour(mesh, f, [&](int g, float len) {
          int other = root(chart[size_t(g)]);
          if (other != c) shared[other] += len;
        });
      int best = -1;
      float best_len = 0;
      for (auto [other, len] : shared)
        if (len > best_len && dot(normalize(chart_normal[size_t(c)]), normalize(chart_normal[size_t(other)])) >= cos_merge)
          best = other, best_len = len;
      if (best < 0) continue;
      merged_into[size_t(c)] = best;
      chart_normal[size_t(best)] += chart_normal[size_t(c)];
      chart_area[size_t(best)] += chart_area[size_t(c)];
    }
    // Renumber densely.
    std::vector<int> renumber(static_cast<size_t>(count), -1);
    int dense = 0;
    for (int f = 0; f < faces; ++f) {
      int r = root(chart[size_t(f)]);
      if (renumber[size_t(r)] < 0) renumber[size_t(r)] = dense++;
      chart[size_t(f)] = renumber[size_t(r)];
    }
    count = dense;
  }
  *chart_count = count;
  return chart;
}

}  // namespace radbake
