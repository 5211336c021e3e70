// Where the sky comes in: the scene's glazing (triangles whose material has
// KHR_materials_transmission), as light portals (the idea of Cycles' and Mitsuba's portals). A
// point in a room sees the sky through its windows, a small part of its hemisphere, which
// cosine-distributed rays mostly miss; rays aimed into the windows find it. Both kinds are combined
// by the balance heuristic (Veach 1997): each ray counts f / (N_c p_c + N_p p_p), so whatever the
// sky brings in elsewhere (an opening without glass, the sky outdoors) is still counted by the
// cosine-distributed rays, and nothing is counted twice.
//
// Aimed rays are uniform in the solid angle of one glazing triangle (Arvo 1995), the triangle
// chosen by the light it could bring the point: its solid angle there times the cosine toward its
// centre. Rays chosen by area alone spent as many on a far window as on the near one, and within a
// window fell densest where it is seen edge-on. The cones are worked out once a texel, from its
// centre; a ray from elsewhere on its footprint goes to the point of the glazing the centre's ray
// would reach, and its density is carried over to its own origin (the change of variables through
// that point), so the weights stay exact. Glazing within a few texels' reach is aimed at from each
// ray's own origin, where that change would vary too much.
#pragma once

#include <cstdint>
#include <vector>

#include "baker/surface/material_sampler.h"
#include "baker/surface/surface.h"
#include "base/math.h"

namespace radbake {

class SkyPortals {
 public:
  // No portals: a scene without glazing, or with more than kMostTriangles glazing triangles
  // (each point weighs them all, and each ray's density sums over them; such scenes keep
  // cosine-distributed rays alone).
  static constexpr size_t kMostTriangles = 1024;
  SkyPortals() = default;
  SkyPortals(const Surface& surface, const MaterialSampler& materials);

  bool empty() const { return corner_.empty(); }
  size_t size() const { return corner_.size() / 3; }
  const Vec3* corners(size_t triangle) const { return &corner_[3 * triangle]; }

 private:
  std::vector<Vec3> corner_;  // three per triangle
};

// The glazing as one point sees it: which triangles its aimed rays go into, and how often.
class PortalView {
 public:
  // Weighs each triangle as seen from `at` by a surface facing `normal`, for rays from within
  // `reach` (metres) of it: none that lies wholly behind the surface's plane (a roof, the wall a
  // window sits in) or that it sees edge-on.
  PortalView(const SkyPortals& portals, Vec3 at, Vec3 normal, float reach = 0);
  // Whether any triangle may be aimed at: else the point keeps cosine-distributed rays alone.
  bool empty() const { return cones_.empty(); }
  // A unit direction from `from` (near `at`) to a point of the glazing, by u in the unit square:
  // u.x picks the triangle and, rescaled within its share, with u.y the direction from `at` within
  // its solid angle, so stratified u stay stratified.
  Vec3 aim(Vec3 from, Vec2 u) const;
  // The density (per steradian) with which aim() gives the unit direction d from `from`: over the
  // triangles the ray meets, share / solid angle from `at`, carried to `from` through the point met.
  double density(Vec3 from, Vec3 d) const;

  // A glazing triangle's corners seen from `at`, as unit directions, and what Arvo's sampling
  // takes from them.
  struct Cone {
    uint32_t triangle;
    double a[3], b[3], c[3];
    double normal[3];  // the triangle's plane, unit
    double solid_angle, alpha, cos_alpha, sin_alpha, cos_ab, share, cumulative;
    bool near;  // aimed at from each ray's own origin
  };

 private:
  const SkyPortals* portals_ = nullptr;
  Vec3 at_{};
  std::vector<Cone> cones_;
};

// The solid angle (sr) of the triangle a, b, c seen from `from` (Van Oosterom and Strackee 1983).
double solid_angle(Vec3 from, const Vec3* corners);

}  // namespace radbake
