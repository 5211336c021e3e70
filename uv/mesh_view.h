// A mesh as the unwrapper takes it: pointers and counts into the caller's arrays, as xatlas's
// MeshDecl does, never a file format's types.
#pragma once

#include <cstdint>
#include <string>

#include "base/math.h"

namespace radbake {

struct MeshView {
  const Vec3* positions = nullptr;  // world space, metres
  size_t vertex_count = 0;
  const uint32_t* triangles = nullptr;  // three indices per triangle
  size_t triangle_count = 0;
  const Vec2* lightmap_uvs = nullptr;  // the input's TEXCOORD_1, or null
  // The input page those UVs were laid out on, when the file names one (a MOZ_lightmap texture, as
  // radbake and other bakers write): meshes naming the same page are checked together and, when
  // valid, keep sharing one page of its size. -1: none named; the mesh is checked, and gets a
  // page, on its own.
  int uv_page = -1;
  int uv_page_width = 0, uv_page_height = 0;  // texels
  std::string name;                    // for messages
};

}  // namespace radbake
