// Every triangle of the scene in one flat table, with its lightmap placement: what the ray tracer,
// the element builder and the light sources all index by a single triangle number.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "base/math.h"
#include "base/scene.h"
#include "uv/atlas.h"

namespace radbake {

struct Surface {
  // Three entries per triangle.
  std::vector<Vec3> corners;          // world space, metres
  std::vector<Vec3> corner_normals;   // unit shading normals (the face normal where the mesh has none)
  std::vector<Vec2> corner_lightmap;  // page texel units
  std::vector<uint32_t> corner_vertex;  // the instance's input vertex, for material attributes
  // One entry per triangle.
  std::vector<Vec3> normal;           // unit geometric normal on the front side (zero if degenerate)
  std::vector<float> area;            // m^2
  std::vector<uint32_t> instance;     // index into Scene::instances
  std::vector<int> material;          // index into Scene::materials, -1 for the default
  // The other face of a double-sided triangle given a back-face twin (baker/surface/back_faces.h), or
  // UINT32_MAX. Twins lie in the same plane: the ray tracer holds the fronts only and reports a
  // hit on a front's back as a hit on its twin's front.
  std::vector<uint32_t> twin;
  std::vector<uint8_t> back_face;     // 1: a back-face twin
  std::vector<uint32_t> page;
  std::vector<uint32_t> chart;        // UINT32_MAX for degenerate triangles
  std::vector<AtlasPage> pages;
  float scene_extent = 0;             // length of the scene's bounding box diagonal, metres

  size_t triangle_count() const { return area.size(); }
  Vec3 point(uint32_t t, Vec2 bary) const {  // bary = (b1, b2), weights of corners 1 and 2
    return corners[3 * t] * (1 - bary.x - bary.y) + corners[3 * t + 1] * bary.x + corners[3 * t + 2] * bary.y;
  }
  // The corners' normals interpolated, or the face's where they point behind it: a surface is lit
  // and seen from its winding's side, whatever a file's normals say, by every stage alike.
  Vec3 shading_normal(uint32_t t, Vec2 bary) const {
    const Vec3 n = normalize(corner_normals[3 * t] * (1 - bary.x - bary.y) + corner_normals[3 * t + 1] * bary.x +
                             corner_normals[3 * t + 2] * bary.y);
    return dot(n, normal[t]) > 0 ? n : normal[t];
  }
  // Metres per texel side on triangle t: its area over its area on the page, square-rooted.
  float texel_size(uint32_t t) const {
    const Vec2* c = &corner_lightmap[3 * t];
    return std::sqrt(area[t] / (0.5f * std::fabs(cross2(c[1] - c[0], c[2] - c[0]))));
  }
  Vec2 lightmap_texel(uint32_t t, Vec2 bary) const {
    return corner_lightmap[3 * t] * (1 - bary.x - bary.y) + corner_lightmap[3 * t + 1] * bary.x +
           corner_lightmap[3 * t + 2] * bary.y;
  }
};

Surface build_surface(const Scene& scene, const Atlas& atlas);

// The scene's instances as uv/ takes them, for ensure_lightmap_uvs (views into the scene).
std::vector<MeshView> mesh_views(const Scene& scene);

}  // namespace radbake
