// Back faces of double-sided surfaces as surfaces of their own. glTF's doubleSided shows one
// material on both faces, but the two faces of a wall or a ceiling made of a single face see
// different light (the sunlit roof above, the lamp below). This stage gives such triangles a
// back-face twin: the same vertices with reversed winding and flipped normals, a single-sided
// triangle with its own lightmap texels. Everything after it (atlas, elements, transport, solve)
// sees only single-sided triangles, and the writer shows each face its own texels.
//
// Which triangles get a twin: a double-sided triangle whose back can receive light. Triangles are
// grouped into shells per node (the glTF node, Blender's object), joined where they share an edge
// (positions welded exactly). An open shell (an edge used by one face, or by more than two, or by
// two that wind the same way) has reachable backs: every double-sided triangle in it gets a twin.
// A closed, consistently wound shell divides space in two; light reaches the side its backs face
// (the inside when it winds outward) only from a source there, so its triangles get twins only
// when a punctual light or an emitting triangle of another shell lies on that side (a lamp inside
// a room modelled as a box). A closed shell with nothing behind its backs (a box, a chair, any
// watertight solid: nearly everything Blender exports, where backface culling off, its default,
// makes every material double-sided) keeps one texel per point, shown on both faces.
#pragma once

#include <cstddef>

#include "base/scene.h"

namespace radbake {

struct BackFaceCount {
  size_t double_sided_triangles = 0;  // in the scene as read
  size_t twins = 0;                   // of them given a back-face twin
};

// Appends one back-face instance (MeshInstance::back_of) per instance with twinned triangles.
// Its TEXCOORD_1 is dropped: the back's lightmap UVs are always generated. Once per scene, after
// loading and before the atlas (the command, the tests' bake helpers and the accuracy study do).
BackFaceCount add_back_faces(Scene& scene);

}  // namespace radbake
