// Where the sky comes in: the scene's glazing (triangles whose material has
// KHR_materials_transmission), as light portals (the idea of Cycles' and Mitsuba's portals). A
// point in a room sees the sky through its windows, a small part of its hemisphere, which
// cosine-distributed rays mostly miss; rays aimed at points spread over the glazing find it. Both
// kinds are combined by the balance heuristic (Veach 1997): each ray counts f / (N_c p_c + N_p p_p),
// so whatever the sky brings in elsewhere (an opening without glass, the sky outdoors) is still
// counted by the cosine-distributed rays, and nothing is counted twice.
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
  // (each ray's density sums over them all; such scenes keep cosine-distributed rays alone).
  static constexpr size_t kMostTriangles = 1024;
  SkyPortals() = default;
  SkyPortals(const Surface& surface, const MaterialSampler& materials);

  bool empty() const { return area_.empty(); }
  size_t size() const { return area_.size(); }
  // Whether any glazing lies in front of the plane through `point` facing `normal`: else rays
  // aimed at it would all go behind the surface (a roof, a wall the windows sit in), and the point
  // keeps cosine-distributed rays alone.
  bool any_in_front(Vec3 point, Vec3 normal) const;
  // A direction from `from` toward a point of the glazing chosen by u (triangles by area, a
  // uniform point on one): not normalised to the triangle it was aimed at, any glazing it passes
  // counts alike in density().
  Vec3 aim(Vec3 from, Vec2 u) const;
  // The density (per steradian) with which aim() gives the unit direction d from `from`: over
  // every glazing triangle the ray from `from` along d passes, area share / area x distance^2 / |cos|.
  double density(Vec3 from, Vec3 d) const;

 private:
  std::vector<Vec3> corner_;   // three per triangle
  std::vector<Vec3> normal_;   // unit, per triangle
  std::vector<double> area_;   // m^2, per triangle
  std::vector<double> cumulative_;  // running share of the area, ending at 1
  std::vector<Vec3> centre_;        // per triangle, its corners' mean
  std::vector<float> reach_;        // per triangle, its farthest corner from the centre
};

}  // namespace radbake
