// Ray-cast form factors (trace_patch_transport) and the point-to-polygon form factor against
// closed forms from Howell's catalogue.
#include <gtest/gtest.h>

#include <cmath>

#include "baker/direct_light.h"
#include "baker/material_sampler.h"
#include "baker/patch_transport.h"
#include "baker/ray_tracer.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

// F(A -> B) for two unit squares, by the patch transport with every square one patch.
double ray_cast_form_factor(const Scene& scene, uint32_t rays) {
  Atlas atlas = test::unwrap(scene, {32.0f, 256, 2});
  Surface surface = build_surface(scene, atlas);
  RayTracer tracer(surface);
  MaterialSampler materials(scene, surface);
  Progress progress;
  Elements e = build_elements(surface, materials, {}, progress);
  place_samples(e, surface, tracer, 1, progress);
  PatchOptions one_patch_per_square;
  one_patch_per_square.block_size = 1024;
  Patches patches = build_patches(e, surface, one_patch_per_square);
  EXPECT_EQ(patches.size(), 2u);
  PatchTransport t = trace_patch_transport(e, patches, surface, tracer, rays, {1.0, 1.0}, 7, progress);
  // Patch 0 is the first square (elements are ordered by page position, charts by size).
  uint32_t a = patches.patch_of_element[patches.members[0]];
  for (uint64_t k = t.row_start[a]; k < t.row_start[a + 1]; ++k)
    if (t.target[k] != a) return t.form_factor[k];
  return 0;
}

TEST(FormFactor, ParallelUnitSquaresAtUnitDistance) {
  Scene scene;
  int m = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  test::add_quad(scene, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, m);  // faces +z
  test::add_quad(scene, {0, 0, 1}, {0, 1, 0}, {1, 0, 0}, m);  // faces -z, one metre above
  // Howell C-11: 0.19982. 1% bounds the ray-casting estimate with 2 x 200k stratified rays.
  double f = ray_cast_form_factor(scene, 200000);
  RecordProperty("form_factor", std::to_string(f));
  EXPECT_NEAR(f, 0.19982, 0.01 * 0.19982);
}

TEST(FormFactor, PerpendicularUnitSquaresSharingAnEdge) {
  Scene scene;
  int m = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  test::add_quad(scene, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, m);  // faces +z
  test::add_quad(scene, {0, 0, 0}, {0, 0, 1}, {1, 0, 0}, m);  // faces +y, shares the x axis edge
  // Howell C-14: 0.20004, within 1%.
  double f = ray_cast_form_factor(scene, 200000);
  RecordProperty("form_factor", std::to_string(f));
  EXPECT_NEAR(f, 0.20004, 0.01 * 0.20004);
}

// Point on the normal through a corner of an a x b rectangle at distance c (Howell B-3).
double corner_point_to_rectangle(double a, double b, double c) {
  double A = a / c, B = b / c;
  return (A / std::sqrt(1 + A * A) * std::atan(B / std::sqrt(1 + A * A)) +
          B / std::sqrt(1 + B * B) * std::atan(A / std::sqrt(1 + B * B))) /
         (2 * M_PI);
}

TEST(FormFactor, PointToPolygonMatchesTheClosedForm) {
  const double cases[][3] = {{1, 1, 1}, {0.3, 2, 0.5}, {5, 5, 0.1}, {0.01, 0.02, 3}};
  for (const auto& c : cases) {
    Vec3 rect[4] = {{0, 0, float(c[2])}, {float(c[0]), 0, float(c[2])}, {float(c[0]), float(c[1]), float(c[2])},
                    {0, float(c[1]), float(c[2])}};
    double expected = corner_point_to_rectangle(c[0], c[1], c[2]);
    // Lambert's contour integral is exact; 1e-5 relative bounds float round-off.
    EXPECT_NEAR(polygon_form_factor({0, 0, 0}, {0, 0, 1}, rect, 4), expected, 1e-5 * expected)
        << c[0] << " x " << c[1] << " at " << c[2];
  }
}

}  // namespace
}  // namespace radbake
