#include "baker/surface/surface.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace radbake {

Surface build_surface(const Scene& scene, const Atlas& atlas) {
  assert(atlas.meshes.size() == scene.instances.size());
  Surface s;
  s.pages = atlas.pages;
  size_t triangle_count = 0;
  std::vector<uint32_t> first_triangle;  // per instance
  for (const MeshInstance& inst : scene.instances) {
    first_triangle.push_back(uint32_t(triangle_count));
    triangle_count += inst.triangle_count();
  }
  s.twin.assign(triangle_count, UINT32_MAX);
  s.back_face.assign(triangle_count, 0);
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    const MeshInstance& inst = scene.instances[i];
    if (inst.back_of < 0) continue;
    for (size_t t = 0; t < inst.triangle_count(); ++t) {
      const uint32_t back = first_triangle[i] + uint32_t(t);
      const uint32_t front = first_triangle[size_t(inst.back_of)] + inst.front_triangle[t];
      s.twin[back] = front;
      s.twin[front] = back;
      s.back_face[back] = 1;
    }
  }
  s.corners.reserve(3 * triangle_count);
  s.corner_normals.reserve(3 * triangle_count);
  s.corner_lightmap.reserve(3 * triangle_count);
  s.corner_vertex.reserve(3 * triangle_count);
  s.normal.reserve(triangle_count);
  s.area.reserve(triangle_count);

  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    const MeshInstance& inst = scene.instances[i];
    const AtlasMesh& lm = atlas.meshes[i];
    const AtlasPage& page = atlas.pages[size_t(lm.page)];
    for (size_t t = 0; t < inst.triangle_count(); ++t) {
      Vec3 p[3];
      for (int k = 0; k < 3; ++k) {
        uint32_t out_vertex = lm.triangles[3 * t + k];
        uint32_t v = lm.source_vertex[out_vertex];
        assert(v == inst.triangles[3 * t + k]);
        p[k] = inst.positions[v];
        for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[k][a]), hi[a] = std::max(hi[a], p[k][a]);
        s.corners.push_back(p[k]);
        s.corner_vertex.push_back(v);
        Vec2 uv = lm.uvs[out_vertex];
        s.corner_lightmap.push_back({uv.x * page.width, uv.y * page.height});
      }
      // Counter-clockwise is the front unless the node mirrors (glTF 2.0 section 3.7.4).
      Vec3 n = cross(p[1] - p[0], p[2] - p[0]);
      if (inst.mirrored) n = -n;
      float len = length(n);
      Vec3 face = len > 0 ? n / len : Vec3{0, 0, 0};
      s.normal.push_back(face);
      s.area.push_back(0.5f * len);
      for (int k = 0; k < 3; ++k) {
        Vec3 shading = inst.normals.empty() ? face : inst.normals[inst.triangles[3 * t + k]];
        s.corner_normals.push_back(shading);
      }
      s.instance.push_back(uint32_t(i));
      s.material.push_back(inst.material);
      s.page.push_back(uint32_t(lm.page));
      s.chart.push_back(lm.triangle_chart[t]);
    }
  }
  s.scene_extent = s.corners.empty() ? 0.0f : length(hi - lo);
  return s;
}

std::vector<MeshView> mesh_views(const Scene& scene) {
  std::vector<MeshView> views;
  for (const MeshInstance& inst : scene.instances) {
    MeshView v;
    v.positions = inst.positions.data();
    v.vertex_count = inst.vertex_count();
    v.triangles = inst.triangles.data();
    v.triangle_count = inst.triangle_count();
    v.lightmap_uvs = inst.lightmap_uvs() ? inst.lightmap_uvs()->data() : nullptr;
    v.name = inst.name;
    if (inst.lightmap_image >= 0 && size_t(inst.lightmap_image) < scene.images.size()) {
      v.uv_page = inst.lightmap_image;
      v.uv_page_width = scene.images[size_t(inst.lightmap_image)].width;
      v.uv_page_height = scene.images[size_t(inst.lightmap_image)].height;
    }
    views.push_back(v);
  }
  return views;
}

}  // namespace radbake
