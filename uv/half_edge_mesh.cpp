// OpenMesh grows its vertex properties with default-constructed VectorT (left uninitialised on
// purpose, then assigned); GCC 12 sees the copy inlined here and warns. Not our uninitialised read,
// and the warning is reported against the standard headers, so it is silenced for this file.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include "uv/half_edge_mesh.h"

#include <OpenMesh/Core/System/omstream.hh>

#include <cmath>
#include <cstring>
#include <unordered_map>

namespace radbake {
namespace {

struct PositionKey {
  uint32_t bits[3];
  bool operator==(const PositionKey& o) const { return std::memcmp(bits, o.bits, sizeof bits) == 0; }
};
struct PositionHash {
  size_t operator()(const PositionKey& k) const {
    return (size_t(k.bits[0]) * 73856093u) ^ (size_t(k.bits[1]) * 19349663u) ^ (size_t(k.bits[2]) * 83492791u);
  }
};

}  // namespace

HalfEdgeMesh build_half_edge_mesh(const MeshView& in) {
  // OpenMesh reports every rejected face on its error stream; rejections are expected here.
  omerr().disable();
  HalfEdgeMesh out;
  HalfEdgeTriMesh& mesh = out.mesh;
  out.corner_vertex.assign(3 * in.triangle_count, -1);

  // Coincident positions become one vertex, so meshes exported with split vertices (flat
  // shading, texture seams) still connect.
  std::unordered_map<PositionKey, int, PositionHash> welded;
  std::vector<int> vertex_of_input(in.vertex_count, -1);
  auto welded_vertex = [&](uint32_t v) {
    if (vertex_of_input[v] >= 0) return vertex_of_input[v];
    Vec3 p = in.positions[v];
    for (int i = 0; i < 3; ++i)
      if (p[i] == 0.0f) p[i] = 0.0f;  // -0 and +0 are the same place
    PositionKey key;
    std::memcpy(key.bits, &p, sizeof key.bits);
    auto [it, inserted] = welded.emplace(key, 0);
    if (inserted) it->second = mesh.add_vertex({p.x, p.y, p.z}).idx();
    return vertex_of_input[v] = it->second;
  };

  for (uint32_t t = 0; t < in.triangle_count; ++t) {
    const uint32_t* tri = in.triangles + 3 * t;
    Vec3 p[3] = {in.positions[tri[0]], in.positions[tri[1]], in.positions[tri[2]]};
    Vec3 n = cross(p[1] - p[0], p[2] - p[0]);
    float len = length(n);
    if (!(len > 0) || !std::isfinite(len)) continue;
    int v[3] = {welded_vertex(tri[0]), welded_vertex(tri[1]), welded_vertex(tri[2])};
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) continue;
    auto face = mesh.add_face(HalfEdgeTriMesh::VertexHandle(v[0]), HalfEdgeTriMesh::VertexHandle(v[1]),
                              HalfEdgeTriMesh::VertexHandle(v[2]));
    if (!face.is_valid()) {
      for (int k = 0; k < 3; ++k) v[k] = mesh.add_vertex({p[k].x, p[k].y, p[k].z}).idx();
      face = mesh.add_face(HalfEdgeTriMesh::VertexHandle(v[0]), HalfEdgeTriMesh::VertexHandle(v[1]),
                           HalfEdgeTriMesh::VertexHandle(v[2]));
      ++out.isolated_faces;
    }
    out.input_triangle.push_back(t);
    out.face_normal.push_back(n / len);
    out.face_area.push_back(0.5f * len);
    for (int k = 0; k < 3; ++k) out.corner_vertex[3 * t + k] = v[k];
  }
  omerr().enable();
  return out;
}

}  // namespace radbake
