#include "baker/surface/back_faces.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstring>
#include <map>
#include <numeric>

namespace radbake {
namespace {

// A triangle of one node, by instance and triangle number.
struct NodeTriangle {
  uint32_t instance, triangle;
};

struct Shells {
  std::vector<uint32_t> of;     // shell of each node triangle; UINT32_MAX for degenerate ones
  std::vector<uint8_t> closed;  // per shell
  size_t count = 0;
};

struct DoubleTriangle {
  double p[3][3];
};

DoubleTriangle corners(const MeshInstance& inst, uint32_t t) {
  DoubleTriangle d;
  // Front winding: counter-clockwise unless the node mirrors.
  const uint32_t order[3] = {0, inst.mirrored ? 2u : 1u, inst.mirrored ? 1u : 2u};
  for (int k = 0; k < 3; ++k) {
    const Vec3 v = inst.positions[inst.triangles[3 * t + order[k]]];
    d.p[k][0] = v.x, d.p[k][1] = v.y, d.p[k][2] = v.z;
  }
  return d;
}

// Shells of a node's triangles: joined across shared edges of exactly equal positions.
Shells find_shells(const Scene& scene, const std::vector<NodeTriangle>& tris) {
  std::map<std::array<uint32_t, 3>, uint32_t> weld;
  auto id = [&](Vec3 p) {
    std::array<uint32_t, 3> key;
    std::memcpy(key.data(), &p, sizeof key);
    return weld.emplace(key, uint32_t(weld.size())).first->second;
  };
  struct EdgeUse {
    uint32_t uses = 0;
    int winding = 0;  // +1 per use from the lower vertex id to the higher, -1 the other way
    uint32_t first;
  };
  std::map<std::pair<uint32_t, uint32_t>, EdgeUse> edges;
  Shells s;
  s.of.assign(tris.size(), UINT32_MAX);
  std::vector<uint32_t> parent(tris.size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::vector<uint8_t> degenerate(tris.size(), 0);
  for (uint32_t k = 0; k < tris.size(); ++k) {
    const MeshInstance& inst = scene.instances[tris[k].instance];
    uint32_t v[3];
    for (int c = 0; c < 3; ++c) v[c] = id(inst.positions[inst.triangles[3 * tris[k].triangle + c]]);
    if (inst.mirrored) std::swap(v[1], v[2]);
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) {
      degenerate[k] = 1;
      continue;
    }
    for (int c = 0; c < 3; ++c) {
      const uint32_t a = v[c], b = v[(c + 1) % 3];
      EdgeUse& e = edges[{std::min(a, b), std::max(a, b)}];
      if (e.uses++ == 0) e.first = k;
      else parent[find(k)] = find(e.first);
      e.winding += a < b ? 1 : -1;
    }
  }
  std::vector<uint32_t> number(tris.size(), UINT32_MAX);
  for (uint32_t k = 0; k < tris.size(); ++k) {
    if (degenerate[k]) continue;
    uint32_t root = find(k);
    if (number[root] == UINT32_MAX) number[root] = uint32_t(s.count++);
    s.of[k] = number[root];
  }
  s.closed.assign(s.count, 1);
  for (const auto& [key, e] : edges)
    if (e.uses != 2 || e.winding != 0) s.closed[s.of[e.first]] = 0;
  return s;
}

// Whether `q` is inside the closed shell made of `shell`'s triangles: the parity of the crossings
// of a ray in a direction no axis-aligned model lines up with.
bool inside(const std::vector<DoubleTriangle>& shell, const double lo[3], const double hi[3], const double q[3]) {
  for (int a = 0; a < 3; ++a)
    if (q[a] < lo[a] || q[a] > hi[a]) return false;
  const double d[3] = {0.5773, 0.6180, 0.5330};
  auto sub = [](const double* a, const double* b, double* o) { o[0] = a[0] - b[0], o[1] = a[1] - b[1], o[2] = a[2] - b[2]; };
  auto crs = [](const double* a, const double* b, double* o) {
    o[0] = a[1] * b[2] - a[2] * b[1], o[1] = a[2] * b[0] - a[0] * b[2], o[2] = a[0] * b[1] - a[1] * b[0];
  };
  auto dt = [](const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  int crossings = 0;
  for (const DoubleTriangle& t : shell) {  // Moller-Trumbore
    double e1[3], e2[3], pv[3], tv[3], qv[3];
    sub(t.p[1], t.p[0], e1);
    sub(t.p[2], t.p[0], e2);
    crs(d, e2, pv);
    const double det = dt(e1, pv);
    if (det == 0) continue;
    sub(q, t.p[0], tv);
    const double u = dt(tv, pv) / det;
    if (u < 0 || u > 1) continue;
    crs(tv, e1, qv);
    const double v = dt(d, qv) / det;
    if (v < 0 || u + v > 1) continue;
    crossings += dt(e2, qv) / det > 0;
  }
  return crossings % 2 == 1;
}

struct Source {
  double point[3];
  bool at_infinity;      // a directional light: on the outside of every shell
  uint32_t node_triangle = UINT32_MAX;  // an emitting triangle of the node being looked at
};

// Per node triangle: 1 when it is double-sided and its back can receive light.
std::vector<uint8_t> backs_to_twin(const Scene& scene, const std::vector<NodeTriangle>& tris,
                                   const std::vector<Source>& sources) {
  const Shells shells = find_shells(scene, tris);
  std::vector<uint8_t> lit_behind(shells.count, 0);
  for (size_t s = 0; s < shells.count; ++s) lit_behind[s] = !shells.closed[s];
  std::vector<std::vector<DoubleTriangle>> closed(shells.count);
  for (uint32_t k = 0; k < tris.size(); ++k)
    if (shells.of[k] != UINT32_MAX && shells.closed[shells.of[k]])
      closed[shells.of[k]].push_back(corners(scene.instances[tris[k].instance], tris[k].triangle));
  for (size_t s = 0; s < shells.count; ++s) {
    if (closed[s].empty()) continue;
    double volume = 0, lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (const DoubleTriangle& t : closed[s]) {
      const double* a = t.p[0];
      const double* b = t.p[1];
      const double* c = t.p[2];
      volume += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
      for (const double* p : {a, b, c})
        for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], p[i]), hi[i] = std::max(hi[i], p[i]);
    }
    const bool backs_face_inside = volume > 0;
    for (const Source& src : sources) {
      if (src.node_triangle != UINT32_MAX && shells.of[src.node_triangle] == s) continue;  // its own glow
      const bool in = !src.at_infinity && inside(closed[s], lo, hi, src.point);
      if (in == backs_face_inside) {
        lit_behind[s] = 1;
        break;
      }
    }
  }
  std::vector<uint8_t> twin(tris.size(), 0);
  for (uint32_t k = 0; k < tris.size(); ++k) {
    const MeshInstance& inst = scene.instances[tris[k].instance];
    twin[k] = shells.of[k] != UINT32_MAX && lit_behind[shells.of[k]] && material_of(scene, inst.material).double_sided;
  }
  return twin;
}

MeshInstance back_instance(const MeshInstance& front, int front_index, const std::vector<uint32_t>& which) {
  MeshInstance back;
  back.name = front.name + " (back faces)";
  back.node = front.node, back.mesh = front.mesh, back.primitive = front.primitive;
  back.material = front.material;
  back.mirrored = front.mirrored;
  back.positions = front.positions;
  back.normals = front.normals;
  for (Vec3& n : back.normals) n = -n;
  back.texcoords = front.texcoords;
  if (back.texcoords.size() > 1) back.texcoords[1].clear();
  back.colors = front.colors;
  back.color_0_was_light = front.color_0_was_light;  // the same COLOR_0 in the file
  back.back_of = front_index;
  back.front_triangle = which;
  for (uint32_t t : which)
    back.triangles.insert(back.triangles.end(),
                          {front.triangles[3 * t], front.triangles[3 * t + 2], front.triangles[3 * t + 1]});
  return back;
}

}  // namespace

BackFaceCount add_back_faces(Scene& scene) {
  assert(std::none_of(scene.instances.begin(), scene.instances.end(),
                      [](const MeshInstance& inst) { return inst.back_of >= 0; }));  // once per scene
  BackFaceCount count;
  const size_t instances = scene.instances.size();
  std::map<int, std::vector<uint32_t>> by_node;  // instances without a node stand alone
  for (uint32_t i = 0; i < instances; ++i) {
    const MeshInstance& inst = scene.instances[i];
    by_node[inst.node >= 0 ? inst.node : -1 - int(i)].push_back(i);
    if (material_of(scene, inst.material).double_sided) count.double_sided_triangles += inst.triangle_count();
  }
  if (count.double_sided_triangles == 0) return count;

  std::vector<Source> sources;
  for (const Light& l : scene.lights)
    sources.push_back({{l.position.x, l.position.y, l.position.z}, l.type == LightType::Directional});
  struct Emitting {
    uint32_t instance, triangle;
  };
  std::vector<Emitting> emitting;
  for (uint32_t i = 0; i < instances; ++i) {
    const MeshInstance& inst = scene.instances[i];
    if (!material_of(scene, inst.material).emits()) continue;
    for (uint32_t t = 0; t < inst.triangle_count(); ++t) emitting.push_back({i, t});
  }

  std::vector<std::vector<uint32_t>> twinned(instances);
  for (const auto& [node, members] : by_node) {
    std::vector<NodeTriangle> tris;
    std::map<uint32_t, uint32_t> first_of_instance;
    bool any_double_sided = false;
    for (uint32_t i : members) {
      any_double_sided |= material_of(scene, scene.instances[i].material).double_sided;
      first_of_instance[i] = uint32_t(tris.size());
      for (uint32_t t = 0; t < scene.instances[i].triangle_count(); ++t) tris.push_back({i, t});
    }
    if (!any_double_sided) continue;
    std::vector<Source> node_sources = sources;
    for (const Emitting& e : emitting) {
      const DoubleTriangle c = corners(scene.instances[e.instance], e.triangle);
      Source s{{}, false};
      for (int a = 0; a < 3; ++a) s.point[a] = (c.p[0][a] + c.p[1][a] + c.p[2][a]) / 3;
      auto mine = first_of_instance.find(e.instance);
      if (mine != first_of_instance.end()) s.node_triangle = mine->second + e.triangle;
      node_sources.push_back(s);
    }
    const std::vector<uint8_t> twin = backs_to_twin(scene, tris, node_sources);
    for (size_t k = 0; k < tris.size(); ++k)
      if (twin[k]) twinned[tris[k].instance].push_back(tris[k].triangle);
  }
  for (uint32_t i = 0; i < instances; ++i) {
    if (twinned[i].empty()) continue;
    count.twins += twinned[i].size();
    scene.instances.push_back(back_instance(scene.instances[i], int(i), twinned[i]));
  }
  return count;
}

}  // namespace radbake
