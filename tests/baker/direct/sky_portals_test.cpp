// Rays aimed into the glazing (baker/direct/sky_portals.h): the directions they take and the
// density they state, against solid angles known in closed form.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "baker/direct/sky_portals.h"
#include "baker/surface/material_sampler.h"
#include "baker/surface/sampling.h"
#include "baker/surface/surface.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

// A scene of glazing quads, as the bake sees it.
struct Glazed {
  Scene scene;
  Surface surface;
  SkyPortals portals;
};

Glazed glazing(const std::vector<std::array<Vec3, 3>>& quads) {
  Glazed g;
  const int glass = test::add_material(g.scene, {0.8f, 0.8f, 0.8f});
  g.scene.materials[size_t(glass)].transmission = 1;
  for (const auto& q : quads) test::add_quad(g.scene, q[0], q[1], q[2], glass, "pane");
  g.surface = build_surface(g.scene, test::unwrap(g.scene, test::coarse_atlas()));
  const MaterialSampler materials(g.scene, g.surface);
  g.portals = SkyPortals(g.surface, materials);
  return g;
}

TEST(SkyPortals, TheSolidAngleOfAnOctantsTriangleIsAnEighthOfTheSphere) {
  const Vec3 corners[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  // 4 pi / 8, exactly; 1e-12 bounds double rounding.
  EXPECT_NEAR(solid_angle({0, 0, 0}, corners), M_PI / 2, 1e-12);
  // A 1 m square 2 m ahead, its half: 4 atan(1 / (4 sqrt(4.5))) / 2 (a rectangle's solid angle,
  // a b / (d sqrt(a^2 + b^2 + d^2)) inside the atan for half-sides a = b = 0.5 at distance d = 2).
  const Vec3 half[3] = {{-0.5f, -0.5f, 2}, {0.5f, -0.5f, 2}, {0.5f, 0.5f, 2}};
  EXPECT_NEAR(solid_angle({0, 0, 0}, half), 2 * std::atan(0.25 / (2 * std::sqrt(4.5))), 1e-7);
}

TEST(SkyPortals, AimedRaysFillATrianglesSolidAngleEvenly) {
  // A pane 1.5 m up a wall, seen obliquely from a floor point 0.5 m out and 1 m aside: rays spread
  // by area would crowd its far end.
  Glazed g;
  const int glass = test::add_material(g.scene, {0.8f, 0.8f, 0.8f});
  g.scene.materials[size_t(glass)].transmission = 1;
  const Vec3 a{0, 1.5f, 0}, b{2, 1.5f, 0}, c{0, 2.5f, 0};
  test::add_mesh(g.scene, {a, b, c}, {0, 1, 2}, glass, "pane");
  g.surface = build_surface(g.scene, test::unwrap(g.scene, test::coarse_atlas()));
  g.portals = SkyPortals(g.surface, MaterialSampler(g.scene, g.surface));
  ASSERT_EQ(g.portals.size(), 1u);
  const Vec3 at{-1, 0, 0.5f};
  const PortalView view(g.portals, at, {0, 1, 0});
  ASSERT_FALSE(view.empty());
  const double whole = solid_angle(at, g.portals.corners(0));
  // Its four halved copies (corners and edge midpoints): each should take its solid angle's share.
  const Vec3 ab = (a + b) * 0.5f, bc = (b + c) * 0.5f, ca = (c + a) * 0.5f;
  const Vec3 parts[4][3] = {{a, ab, ca}, {ab, b, bc}, {ca, bc, c}, {ab, bc, ca}};
  double hits[4] = {};
  const uint32_t n = 40000;
  for (uint32_t k = 0; k < n; ++k) {
    const Vec3 d = view.aim(at, cmj_sample(k, n, 7));
    ASSERT_NEAR(length(d), 1.0f, 1e-5f);
    ASSERT_LT(d.z, 0);
    const Vec3 p = at + d * (-at.z / d.z);  // where it crosses the pane's plane, z = 0
    const float s = p.x / 2, t = (p.y - 1.5f) / 1;  // p = a + s (b - a) + t (c - a)
    ASSERT_GT(std::min(s, t), -1e-4f);
    ASSERT_LT(s + t, 1 + 1e-4f);
    hits[s + t < 0.5f ? 0 : s > 0.5f ? 1 : t > 0.5f ? 2 : 3] += 1.0 / n;
    // Uniform in its solid angle: the density is one over it wherever the ray passes.
    ASSERT_NEAR(view.density(at, d) * whole, 1.0, 1e-4);
  }
  // Stratified, the shares come out far closer than a binomial's 0.25%; 0.5% bounds them.
  for (int q = 0; q < 4; ++q) EXPECT_NEAR(hits[q], solid_angle(at, parts[q]) / whole, 0.005) << "part " << q;
}

// The projected solid angle of a polygon from `at` on a surface facing n, by Lambert's contour
// formula: half the sum over its edges of the angle each spans times the cosine between n and the
// normal of the plane through the edge and `at`.
double projected_solid_angle(Vec3 at, Vec3 n, const std::vector<Vec3>& polygon) {
  double sum = 0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Vec3 r0 = normalize(polygon[i] - at), r1 = normalize(polygon[(i + 1) % polygon.size()] - at);
    const double gamma = std::acos(std::clamp(double(dot(r0, r1)), -1.0, 1.0));
    sum += gamma * double(dot(n, normalize(cross(r0, r1))));
  }
  return std::fabs(sum) / 2;
}

TEST(SkyPortals, AimedRaysWeightedByTheirDensityGiveAWindowsProjectedSolidAngle) {
  // The same window as two triangles, which the point weighs unequally (solid angle times the
  // cosine toward each): whatever the shares, cos / density averages to the window's projected
  // solid angle, E / L for a window of uniform luminance L. Also from points of a texel's footprint
  // beside its centre, whose rays go through the points the centre's would reach.
  const Glazed g = glazing({{Vec3{0, 1.5f, 0}, Vec3{2, 0, 0}, Vec3{0, 1, 0}}});
  ASSERT_EQ(g.portals.size(), 2u);
  const Vec3 at{-1, 0, 0.5f}, up{0, 1, 0};
  const PortalView view(g.portals, at, up);
  for (const Vec3 from : {at, at + Vec3{0.1f, 0, 0}, at + Vec3{-0.05f, 0, 0.1f}}) {
    const uint32_t n = 4096;
    double estimate = 0;
    for (uint32_t k = 0; k < n; ++k) {
      const Vec3 d = view.aim(from, cmj_sample(k, n, 11));
      estimate += double(dot(d, up)) / view.density(from, d) / n;
    }
    const double exact = projected_solid_angle(from, up, {{0, 1.5f, 0}, {2, 1.5f, 0}, {2, 2.5f, 0}, {0, 2.5f, 0}});
    // 0.2% bounds 4,096 stratified rays' error over a smooth integrand.
    EXPECT_NEAR(estimate / exact, 1.0, 0.002) << estimate << " against " << exact << " from x " << from.x << " z " << from.z;
  }
}

TEST(SkyPortals, AWindowBehindTheSurfaceOrEdgeOnIsNotAimedAt) {
  const Glazed g = glazing({{Vec3{0, 1, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}}});
  // Below the floor the pane stands on, in the pane's own plane, and facing away from it.
  EXPECT_TRUE(PortalView(g.portals, {0.5f, 2.5f, 1}, {0, 1, 0}).empty());
  EXPECT_TRUE(PortalView(g.portals, {3, 1.5f, 0}, {-1, 0, 0}).empty());
  EXPECT_TRUE(PortalView(g.portals, {0.5f, 1.5f, 1}, {0, 0, 1}).empty());
  EXPECT_FALSE(PortalView(g.portals, {0.5f, 0, 1}, {0, 1, 0}).empty());
}

TEST(SkyPortals, TwoWindowsAreAimedAtByWhatTheyCouldBring) {
  // A near and a far pane of one size, both straight ahead of a wall point facing them: the near
  // one fills 9x the far one's solid angle (1 m against 3 m, nearly), and takes that much more of
  // the aimed rays.
  const Glazed g = glazing({{Vec3{-0.05f, -0.05f, 1}, Vec3{0.1f, 0, 0}, Vec3{0, 0.1f, 0}},
                            {Vec3{0.95f, -0.05f, 3}, Vec3{0.1f, 0, 0}, Vec3{0, 0.1f, 0}}});
  const Vec3 at{0, 0, 0}, facing{0, 0, 1};
  const PortalView view(g.portals, at, facing);
  uint32_t near = 0;
  const uint32_t n = 4096;
  // The far pane lies a third of the way across (x / z = 1 / 3), the near one within 0.05.
  for (uint32_t k = 0; k < n; ++k) near += view.aim(at, cmj_sample(k, n, 3)).x < 0.2f;
  const double near_angle = solid_angle(at, g.portals.corners(0)) + solid_angle(at, g.portals.corners(1));
  const double far_angle = solid_angle(at, g.portals.corners(2)) + solid_angle(at, g.portals.corners(3));
  const Vec3 far_centre{1, 0, 3};
  const double expected = near_angle / (near_angle + far_angle * double(dot(normalize(far_centre), facing)));
  // Stratified over the triangles' shares, the count is exact to a ray or two.
  EXPECT_NEAR(double(near) / n, expected, 2.0 / n);
  EXPECT_GT(expected, 0.85);
}

}  // namespace
}  // namespace radbake
