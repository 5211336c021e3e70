// Closed forms the tests measure the baker against, computed independently of baker/ in double.
#pragma once

#include "baker/math.h"

namespace radbake::test {

// Howell's catalogue B-3: the form factor from a point to a parallel a x b rectangle at height c,
// the point straight under one of its corners.
double corner_point_to_rectangle(double a, double b, double c);

// Howell B-3 again, from a point at (px, pz) to a parallel rectangle [x0, x1] x [z0, z1] at height
// h, under it or beside it.
double point_to_rectangle(double px, double pz, double x0, double x1, double z0, double z1, double h);

// Irradiance in lux from a point light of `candela` at `light` on a surface at x with unit normal
// n, unoccluded: I cos(theta) / d^2, zero behind the surface.
double point_light_lux(double candela, Vec3 light, Vec3 x, Vec3 n);

}  // namespace radbake::test
