#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <queue>

#include "uv/charts.h"
#include "uv/half_edge_mesh.h"

namespace radbake {
namespace {

constexpr float kDegrees = 3.14159265358979323846f / 180.0f;
// How strongly a face turning away from a chart's normal counts against joining it, next to its
// distance from the chart's seed: round charts that follow the surface's folds.
constexpr float kTurnWeight = 8;
// Lloyd iterations: grow all charts at once, move each seed to its chart's middle, grow again.
constexpr int kRelaxations = 4;

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

struct Grower {
  const HalfEdgeMesh& hm;
  float cos_cone, cos_hard, curved_area_cap;
  std::vector<Vec3> centroid;
  UnwrapProgress& progress;

  struct State {
    int seed;
    Vec3 normal_sum;
    float area = 0;
    bool planar = true;
  };

  // Whether face f may join chart c now: inside the cone of its seed and of its mean normal (the
  // mean alone could drift round a cylinder and close it into a ring), and, once a chart is
  // curved, within the area cap that keeps curved charts from wrapping round a shape.
  bool accepts(const State& c, int f) const {
    Vec3 n = hm.face_normal[size_t(f)];
    if (dot(n, hm.face_normal[size_t(c.seed)]) < cos_cone || dot(n, normalize(c.normal_sum)) < cos_cone) return false;
    bool stays_planar = c.planar && dot(n, hm.face_normal[size_t(c.seed)]) > 0.99985f;
    return stays_planar || c.area + hm.face_area[size_t(f)] <= curved_area_cap;
  }

  float cost(const State& c, int f) const {
    float turn = 1 - dot(hm.face_normal[size_t(f)], normalize(c.normal_sum));
    return length(centroid[size_t(f)] - centroid[size_t(c.seed)]) * (1 + kTurnWeight * turn);
  }

  // Grows charts[first..] from their seeds at once, cheapest face first, over edges that are not
  // hard, into faces no chart holds yet.
  void grow(std::vector<State>& charts, std::vector<int>& chart, size_t first = 0) const {
    using Candidate = std::tuple<float, int, int>;  // cost, face, chart
    std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> frontier;
    auto offer = [&](int c, int from) {
      for_each_neighbour(hm.mesh, from, [&](int g, float) {
        if (chart[size_t(g)] < 0 && dot(hm.face_normal[size_t(g)], hm.face_normal[size_t(from)]) >= cos_hard)
          frontier.push({cost(charts[size_t(c)], g), g, c});
      });
    };
    for (size_t c = first; c < charts.size(); ++c) {
      State& s = charts[c];
      s.normal_sum = hm.face_normal[size_t(s.seed)] * hm.face_area[size_t(s.seed)];
      s.area = hm.face_area[size_t(s.seed)];
      s.planar = true;
      chart[size_t(s.seed)] = int(c);
      offer(int(c), s.seed);
    }
    for (size_t popped = 1; !frontier.empty(); ++popped) {
      if (popped % 4096 == 0) progress.poll();
      auto [unused, f, c] = frontier.top();
      frontier.pop();
      if (chart[size_t(f)] >= 0 || !accepts(charts[size_t(c)], f)) continue;
      State& s = charts[size_t(c)];
      chart[size_t(f)] = c;
      s.planar = s.planar && dot(hm.face_normal[size_t(f)], hm.face_normal[size_t(s.seed)]) > 0.99985f;
      s.normal_sum += hm.face_normal[size_t(f)] * hm.face_area[size_t(f)];
      s.area += hm.face_area[size_t(f)];
      offer(c, f);
    }
  }

  // Faces no chart took become seeds of new charts (largest first), each grown before the next.
  void seed_leftovers(std::vector<State>& charts, std::vector<int>& chart, const std::vector<int>& by_area) const {
    for (int f : by_area) {
      if (chart[size_t(f)] >= 0) continue;
      charts.push_back(State{f, {}, 0, true});
      grow(charts, chart, charts.size() - 1);
    }
  }

  // Each seed moves to the face nearest its chart's middle that faces the chart's way.
  void relocate(std::vector<State>& charts, const std::vector<int>& chart) const {
    std::vector<Vec3> middle(charts.size(), Vec3{});
    std::vector<float> area(charts.size(), 0);
    for (size_t f = 0; f < chart.size(); ++f) {
      if (chart[f] < 0) continue;
      middle[size_t(chart[f])] += centroid[f] * hm.face_area[f];
      area[size_t(chart[f])] += hm.face_area[f];
    }
    std::vector<float> best(charts.size(), INFINITY);
    for (size_t f = 0; f < chart.size(); ++f) {
      if (chart[f] < 0) continue;
      size_t c = size_t(chart[f]);
      Vec3 m = middle[c] / area[c];
      float turn = 1 - dot(hm.face_normal[f], normalize(charts[c].normal_sum));
      float score = length(centroid[f] - m) * (1 + kTurnWeight * turn);
      if (score < best[c]) best[c] = score, charts[c].seed = int(f);
    }
  }
};

}  // namespace

std::vector<int> grow_charts(const HalfEdgeMesh& hm, const ChartOptions& options, int* chart_count,
                             UnwrapProgress& progress) {
  const HalfEdgeTriMesh& mesh = hm.mesh;
  const int faces = int(mesh.n_faces());
  double total_area = 0;
  for (float a : hm.face_area) total_area += a;
  Grower grower{hm, std::cos(options.max_normal_deviation_degrees * kDegrees),
                std::cos(options.hard_edge_degrees * kDegrees),
                options.max_curved_chart_fraction > 0 ? float(total_area * options.max_curved_chart_fraction) : INFINITY,
                std::vector<Vec3>(static_cast<size_t>(faces)), progress};
  for (int f = 0; f < faces; ++f) {
    Vec3 c{};
    for (auto v : mesh.fv_range(HalfEdgeTriMesh::FaceHandle(f))) c += to_vec3(mesh.point(v));
    grower.centroid[size_t(f)] = c / 3.0f;
  }
  // Seeds: largest faces first, so big flat regions start charts and small ones join them.
  std::vector<int> by_area(static_cast<size_t>(faces));
  std::iota(by_area.begin(), by_area.end(), 0);
  std::stable_sort(by_area.begin(), by_area.end(), [&](int a, int b) { return hm.face_area[size_t(a)] > hm.face_area[size_t(b)]; });

  std::vector<Grower::State> charts;
  std::vector<int> chart(static_cast<size_t>(faces), -1);
  grower.seed_leftovers(charts, chart, by_area);
  for (int iteration = 0; iteration < kRelaxations; ++iteration) {
    progress.at(double(iteration + 1) / (kRelaxations + 1));
    grower.relocate(charts, chart);
    std::fill(chart.begin(), chart.end(), -1);
    grower.grow(charts, chart);
    grower.seed_leftovers(charts, chart, by_area);
  }
  int count = int(charts.size());
  std::vector<Vec3> chart_normal(size_t(count), Vec3{});
  std::vector<float> chart_area(size_t(count), 0);
  for (int f = 0; f < faces; ++f) {
    chart_normal[size_t(chart[size_t(f)])] += hm.face_normal[size_t(f)] * hm.face_area[size_t(f)];
    chart_area[size_t(chart[size_t(f)])] += hm.face_area[size_t(f)];
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
