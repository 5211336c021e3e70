// Closed forms the tests measure the baker against, computed independently of baker/ in double.
#pragma once

#include <vector>

#include "baker/math.h"

namespace radbake::test {

// Howell's catalogue B-3: the form factor from a point to a parallel a x b rectangle at height c,
// the point straight under one of its corners.
double corner_point_to_rectangle(double a, double b, double c);

// Howell B-3 again, from a point at (px, pz) to a parallel rectangle [x0, x1] x [z0, z1] at height
// h, under it or beside it.
double point_to_rectangle(double px, double pz, double x0, double x1, double z0, double z1, double h);

// Lambert's contour integral (Hottel's form, Howell's catalogue introduction): the form factor from
// a point x with unit normal n to a planar polygon, sum over its edges of the angle each subtends
// times the cosine between n and the edge's plane, over 2 pi. The whole polygon must lie on the
// side of x's tangent plane that n points to (clip it first otherwise). Any polygon, any tilt:
// what Howell B-3 gives for a parallel rectangle, it gives for a perpendicular one too.
double point_to_polygon(Vec3 x, Vec3 n, const std::vector<Vec3>& corners);

// The solid angle (sr) of a 2a x 2b rectangle seen from a point at distance d on the normal
// through its centre: 4 asin(ab / sqrt((a^2 + d^2)(b^2 + d^2))).
double centred_rectangle_solid_angle(double a, double b, double d);

// Irradiance in lux from a point light of `candela` at `light` on a surface at x with unit normal
// n, unoccluded: I cos(theta) / d^2, zero behind the surface.
double point_light_lux(double candela, Vec3 light, Vec3 x, Vec3 n);

}  // namespace radbake::test
