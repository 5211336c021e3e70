// Internal to uv/: a mesh welded into OpenMesh's half-edge structure, so charts can walk across
// edges. Faces OpenMesh cannot take (a third face on an edge, a face wound against its
// neighbours) are added on vertices of their own: they become charts of their own, nothing breaks.
#pragma once

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <cstdint>
#include <vector>

#include "uv/mesh_view.h"

namespace radbake {

using HalfEdgeTriMesh = OpenMesh::TriMesh_ArrayKernelT<>;

struct HalfEdgeMesh {
  HalfEdgeTriMesh mesh;
  std::vector<uint32_t> input_triangle;  // per OpenMesh face
  std::vector<Vec3> face_normal;         // per OpenMesh face, unit
  std::vector<float> face_area;          // per OpenMesh face, m^2
  // Per input triangle corner (3 per triangle): its OpenMesh vertex, or -1 for triangles left out
  // (zero area, repeated corners, non-finite): those cover no texel and get no chart.
  std::vector<int> corner_vertex;
  size_t isolated_faces = 0;  // faces that had to be split off (non-manifold or misoriented)
};

HalfEdgeMesh build_half_edge_mesh(const MeshView& mesh);

inline Vec3 to_vec3(const HalfEdgeTriMesh::Point& p) { return {p[0], p[1], p[2]}; }

}  // namespace radbake
