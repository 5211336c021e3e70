#include "baker/direct/sky_portals.h"

#include <algorithm>
#include <cmath>

namespace radbake {
namespace {

// Directions in double: a far window's solid angle is the small difference of angles near pi.
struct Dir {
  double x, y, z;
};
Dir operator-(Dir a, Dir b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Dir operator+(Dir a, Dir b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Dir operator*(Dir a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(Dir a, Dir b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Dir cross(Dir a, Dir b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
Dir unit(Dir a) {
  const double l = std::sqrt(dot(a, a));
  return l > 0 ? a * (1 / l) : a;
}
Dir toward(Vec3 from, Vec3 to) { return unit(Dir{double(to.x) - from.x, double(to.y) - from.y, double(to.z) - from.z}); }
double angle_between(Dir a, Dir b) { return std::acos(std::clamp(dot(a, b), -1.0, 1.0)); }

// Ignored below this: seen edge-on or from its own plane, a triangle brings nothing.
constexpr double kLeastSolidAngle = 1e-12;

// Arvo's "Stratified sampling of spherical triangles" (SIGGRAPH 1995): u.x sets the area of the
// sub-triangle a, b, c' swept first, u.y the point along the arc from b to c'.
Dir sample_spherical_triangle(const PortalView::Cone& cone, Vec2 u) {
  const Dir a{cone.a[0], cone.a[1], cone.a[2]}, b{cone.b[0], cone.b[1], cone.b[2]}, c{cone.c[0], cone.c[1], cone.c[2]};
  const double area = double(u.x) * cone.solid_angle;
  const double s = std::sin(area - cone.alpha), t = std::cos(area - cone.alpha);
  const double cos_alpha = cone.cos_alpha, sin_alpha = cone.sin_alpha;
  const double uu = t - cos_alpha, v = s + sin_alpha * cone.cos_ab;
  const double denominator = (v * s + uu * t) * sin_alpha;
  const double q = denominator != 0 ? std::clamp(((v * t - uu * s) * cos_alpha - v) / denominator, -1.0, 1.0) : 1.0;
  const Dir c_prime = a * q + unit(c - a * dot(c, a)) * std::sqrt(std::max(0.0, 1 - q * q));
  const double z = 1 - double(u.y) * (1 - dot(c_prime, b));
  return unit(b * z + unit(c_prime - b * dot(c_prime, b)) * std::sqrt(std::max(0.0, 1 - z * z)));
}

void put(double (&to)[3], Dir d) { to[0] = d.x, to[1] = d.y, to[2] = d.z; }
Dir as_dir(Vec3 v) { return {v.x, v.y, v.z}; }

// Where the ray from `from` along unit d meets the triangle, at a positive distance (Moller and
// Trumbore, in double).
bool meets(Dir from, Dir d, const Vec3* corner, double& distance) {
  const Dir a = as_dir(corner[0]), e1 = as_dir(corner[1]) - a, e2 = as_dir(corner[2]) - a;
  const Dir p = cross(d, e2);
  const double det = dot(e1, p);
  if (std::fabs(det) < 1e-20) return false;
  const Dir s = from - a;
  const double u = dot(s, p) / det;
  if (u < 0 || u > 1) return false;
  const Dir q = cross(s, e1);
  const double v = dot(d, q) / det;
  if (v < 0 || u + v > 1) return false;
  distance = dot(e2, q) / det;
  return distance > 0;
}

}  // namespace

double solid_angle(Vec3 from, const Vec3* c) {
  const Dir a = toward(from, c[0]), b = toward(from, c[1]), d = toward(from, c[2]);
  return 2 * std::fabs(std::atan2(dot(a, cross(b, d)), 1 + dot(a, b) + dot(b, d) + dot(d, a)));
}

SkyPortals::SkyPortals(const Surface& surface, const MaterialSampler& materials) {
  for (uint32_t t = 0; t < surface.triangle_count(); ++t) {
    // A double-sided pane's back-face twin lies in its plane: its front stands for both.
    if (surface.back_face[t] || !(surface.area[t] > 0) || !materials.glazing(t)) continue;
    if (size() == kMostTriangles) {
      corner_.clear();
      return;
    }
    for (int k = 0; k < 3; ++k) corner_.push_back(surface.corners[3 * t + k]);
  }
}

namespace {

// The cone of triangle t (corners c) seen from `from`, without its share.
PortalView::Cone cone_from(Vec3 from, const Vec3* c, uint32_t t, double seen) {
  const Dir a = toward(from, c[0]), b = toward(from, c[1]), d = toward(from, c[2]);
  PortalView::Cone cone{};
  cone.triangle = t;
  put(cone.a, a), put(cone.b, b), put(cone.c, d);
  cone.alpha = angle_between(unit(cross(a, b)), unit(cross(d, a)) * -1.0);
  cone.cos_alpha = std::cos(cone.alpha), cone.sin_alpha = std::sin(cone.alpha);
  cone.solid_angle = seen;
  cone.cos_ab = dot(a, b);
  put(cone.normal, unit(cross(as_dir(c[1]) - as_dir(c[0]), as_dir(c[2]) - as_dir(c[0]))));
  return cone;
}

// A triangle nearer a texel's centre than this many times the texel's reach is aimed at from
// each ray's own origin: carried over from the centre, the density of rays to it would vary too
// much across the footprint (a glass box's floor texels beside its walls: 3.2% at worst, against
// 0.69% so).
constexpr float kNearInReaches = 16;

}  // namespace

PortalView::PortalView(const SkyPortals& portals, Vec3 at, Vec3 normal, float reach) : portals_(&portals), at_(at) {
  double total = 0;
  for (uint32_t t = 0; t < portals.size(); ++t) {
    const Vec3* corner = portals.corners(t);
    const float in_front = std::max({dot(corner[0] - at, normal), dot(corner[1] - at, normal), dot(corner[2] - at, normal)});
    if (!(in_front > 0)) continue;
    const double seen = solid_angle(at, corner);
    if (!(seen > kLeastSolidAngle)) continue;
    Cone cone = cone_from(at, corner, t, seen);
    const Dir plane{cone.normal[0], cone.normal[1], cone.normal[2]};
    cone.near = std::fabs(dot(as_dir(at) - as_dir(corner[0]), plane)) < kNearInReaches * reach;
    // The light a window could bring goes with its solid angle and the cosine toward it; the
    // cosine's floor keeps a window that rises from the surface's plane in reach.
    const Vec3 centre = (corner[0] + corner[1] + corner[2]) / 3.0f;
    cone.share = seen * std::max(0.05, double(dot(normalize(centre - at), normal)));
    total += cone.share;
    cone.cumulative = total;
    cones_.push_back(cone);
  }
  for (Cone& cone : cones_) cone.share /= total, cone.cumulative /= total;
}

Vec3 PortalView::aim(Vec3 from, Vec2 u) const {
  const auto chosen = std::lower_bound(cones_.begin(), cones_.end(), double(u.x),
                                       [](const Cone& cone, double x) { return cone.cumulative < x; });
  const Cone& cone = chosen == cones_.end() ? cones_.back() : *chosen;
  const double low = cone.cumulative - cone.share;
  const float within = cone.share > 0 ? float(std::clamp((double(u.x) - low) / cone.share, 0.0, 1.0)) : 0.5f;
  const Vec3* corner = portals_->corners(cone.triangle);
  if (cone.near) {
    const double seen = solid_angle(from, corner);
    const Dir d = seen > kLeastSolidAngle ? sample_spherical_triangle(cone_from(from, corner, cone.triangle, seen), {within, u.y})
                                          : toward(from, (corner[0] + corner[1] + corner[2]) / 3.0f);
    return normalize(Vec3{float(d.x), float(d.y), float(d.z)});
  }
  const Dir d = sample_spherical_triangle(cone, {within, u.y});
  // The point of the triangle's plane the centre's ray reaches, seen from `from`.
  const Dir n{cone.normal[0], cone.normal[1], cone.normal[2]};
  const double along = dot(n, d);
  if (along == 0) return normalize(Vec3{float(d.x), float(d.y), float(d.z)});
  const Dir point = as_dir(at_) + d * (dot(n, as_dir(corner[0]) - as_dir(at_)) / along);
  const Dir to = unit(point - as_dir(from));
  return normalize(Vec3{float(to.x), float(to.y), float(to.z)});
}

double PortalView::density(Vec3 from, Vec3 d) const {
  const Dir origin = as_dir(from), dir = unit(as_dir(d));
  double total = 0;
  for (const Cone& cone : cones_) {
    const Vec3* corner = portals_->corners(cone.triangle);
    double distance;
    if (!meets(origin, dir, corner, distance)) continue;
    if (cone.near) {
      const double seen = solid_angle(from, corner);
      if (seen > kLeastSolidAngle) total += cone.share / seen;
      continue;
    }
    // Per steradian from `at`, to per square metre of the glazing, to per steradian from `from`.
    const Dir point = origin + dir * distance, from_centre = point - as_dir(at_);
    const Dir n{cone.normal[0], cone.normal[1], cone.normal[2]};
    const double centre_distance2 = dot(from_centre, from_centre);
    const double facing_centre = std::fabs(dot(n, from_centre)) / std::sqrt(centre_distance2);
    const double facing = std::fabs(dot(n, dir));
    if (!(facing > 1e-12) || !(centre_distance2 > 0)) continue;
    total += cone.share / cone.solid_angle * facing_centre / centre_distance2 * distance * distance / facing;
  }
  return total;
}

}  // namespace radbake
