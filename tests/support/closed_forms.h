// Closed forms the tests measure the baker against, computed independently of baker/ in double.
#pragma once

#include <functional>
#include <vector>

#include "base/math.h"

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

// Daylight through openings, for CIE 171's cases 5.9 to 5.12, in double precision throughout.
struct Vec3d {
  double x = 0, y = 0, z = 0;
};
inline Vec3d to_double(Vec3 v) { return {v.x, v.y, v.z}; }

// The skies of CIE 171's daylight tables, relative to the zenith luminance, for a view at `zenith`
// and `azimuth` with the sun at `sun_zenith`, `sun_azimuth` (radians; azimuths measured alike, from
// the same direction), zero below the horizon. Types 1 to 15 are the CIE standard general skies
// (ISO 15469:2004 / CIE S 011/E:2003, Table 1's gradation a, b and indicatrix c, d, e), written here
// from the standard and not from baker/; 16 is the traditional CIE overcast sky (1 + 2 cos Z) / 3,
// the sixteenth row of the report's tables.
double cie171_sky_luminance(int type, double zenith, double azimuth, double sun_zenith, double sun_azimuth);

// The illuminance an unobstructed horizontal plane gets from that sky over its zenith luminance,
// E_hz / L_z (sr): the midpoint rule in cos Z and azimuth on a 400 x 800 grid (not the baker's
// quadrature in Z). What CIE 171's sky components are percentages of.
double cie171_sky_horizontal_illuminance(int type, double sun_zenith, double sun_azimuth);

// The directional transmittance of CIE 171's 6 mm clear glass (cases 5.10, 5.12) at an angle of
// incidence of cosine c: the fifth-degree polynomial in c of Tregenza and Sharples' daylight
// algorithms (section 2.34), which the report gives (as quoted on radiance-online's "Glass
// transmittance" thread, 2017; with it the report's glazed tables come out to their rounding):
// 0.8788 at normal incidence, falling to 0 at grazing (held at 0 within half a degree of it, where
// the fit dips below).
double clear_glass_transmittance(double cos_incidence);

// A thin clear pane of refractive index n at an angle of incidence of cosine c, in double: both
// faces' Fresnel reflectances for each polarisation, the light bouncing between them, (1 - R) /
// (1 + R) each, unpolarised the mean (Born and Wolf 1.5.3; no absorption).
double thin_pane_transmittance(double cos_incidence, double ior);

// Luminance (cd/m2) seen through the opening point `through` in the unit direction `direction`.
using SeenLuminance = std::function<double(Vec3d through, Vec3d direction)>;

// The illuminance (lux) at x, unit normal n, from what it sees through a flat parallelogram opening
// corner + s u + t v (s, t in [0, 1]), all of which x sees: the integral over the opening of
// L(q, d) cos(theta_x) cos(theta_q) / r^2 dA, q a point of the opening and d the unit direction
// from x through it. Gauss-Legendre (4 x 4 points) on cells halved until each is smaller than a
// quarter of its distance from x, so points beside the opening's edge are integrated as well as
// points far from it (a uniform luminance gives Howell's and Lambert's view factors to 1e-10, 0.25 m
// from the edge too). The luminance must be smooth over the opening: split the opening where it
// jumps (at the horizon seen through a facade, at the edge of an overhang) and add the parts.
double illuminance_through_opening(Vec3d x, Vec3d n, Vec3d corner, Vec3d u, Vec3d v, const SeenLuminance& luminance);

}  // namespace radbake::test
