// The camera a display file opens on when its input has none: a viewer's default view (the model
// from +Z, or from its own origin) shows a room from outside and a Cornell box from behind.
#pragma once

#include <string>
#include <vector>

#include "baker/surface/ray_tracer.h"
#include "baker/surface/surface.h"
#include "base/math.h"
#include "base/scene.h"

namespace radbake {

struct DisplayCamera {
  Vec3 eye;                // world space, metres
  Vec3 forward{0, 0, -1};  // unit, the way it looks; up is +Y (glTF's)
  float yfov = 0.8f;       // radians, vertical; the horizontal follows the viewer's aspect
  float znear = 0.01f;     // metres
  bool in_room = false;    // inside the largest enclosed region, or outside the model
  std::string why;         // one sentence for the report
};

// Inside the largest room of a work plane at eye height (the lower of 1.6 m and half the scene's
// height above the floor), along one of its horizontal axes: the one whose view ahead is most
// filled, whose back is most open (the missing wall of a set) and along which the room is longest;
// from the room's near end, backed up towards the wall behind or to the scene's bounds.
// Where no floor is enclosed: outside, from +Z and a little above, the bounding sphere filling
// the vertical field of view.
DisplayCamera display_camera(const Scene& scene, const Surface& surface, const RayTracer& tracer);

// What a viewer sees first on opening the display file: from the camera it opens on (the scene's
// first usable camera, else `added`), a grid of kDisplayViewRays rays down the vertical field of
// view (and across it at the camera's aspect ratio, square where it gives none), and per page,
// per lightmap texel, how many of them strike it (an alpha-blended surface takes its alpha of a ray
// and passes the rest, as the display file blends it). The exposure meters on it
// (baker/finish/exposure.h). Empty pages when no ray meets the scene.
constexpr int kDisplayViewRays = 128;
std::vector<std::vector<float>> display_view(const Scene& scene, const DisplayCamera& added, const Surface& surface,
                                             const RayTracer& tracer);

}  // namespace radbake
