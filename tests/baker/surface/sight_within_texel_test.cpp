// sees_within_texel: between two points of one chart, the chart's own steps and corners do not
// block the line (a window frame's stepped profile, finer than a texel, hid every sample from the
// faces round it), but the two faces of something thin always do, even in one chart (a
// door leaf whose edges the atlas hinged: its dark face would take the lit face's light).
#include <gtest/gtest.h>

#include "baker/surface/elements.h"
#include "baker/surface/ray_tracer.h"
#include "baker/surface/surface.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

constexpr float kLift = 1e-3f;  // metres off the surface, as samples and hits are lifted

struct Built {
  Surface surface;
  // The triangle of the instance whose normal is `n`.
  uint32_t facing(Vec3 n) const {
    for (uint32_t t = 0; t < surface.triangle_count(); ++t)
      if (dot(surface.normal[t], n) > 0.999f) return t;
    ADD_FAILURE() << "no triangle faces " << n.x << ", " << n.y << ", " << n.z;
    return 0;
  }
};

// A block's faces, each of one chart as the atlas makes them, or all in one chart as it makes a
// thin part's when it hinges the edges onto a face.
Built block(Vec3 lo, Vec3 hi, bool one_chart) {
  Scene scene;
  test::add_box(scene, lo, hi, false, test::add_material(scene, {0.5f, 0.5f, 0.5f}), "block");
  Atlas atlas = test::unwrap(scene, {64.0f, 256, 2});
  if (one_chart)
    for (AtlasMesh& mesh : atlas.meshes)
      for (uint32_t& chart : mesh.triangle_chart) chart = atlas.meshes[0].triangle_chart[0];
  return {build_surface(scene, atlas)};
}

TEST(SightWithinTexel, ACornerOfTheTexelsOwnChartDoesNotBlock) {
  // A 10 cm frame profile's outer corner: a point on each face beside it, the line between them
  // cutting through the corner.
  for (bool one_chart : {true, false}) {
    const Built b = block({0, 0, 0}, {0.1f, 0.1f, 1}, one_chart);
    RayTracer tracer(b.surface);
    const Vec3 on_side{0.1f + kLift, 0.09f, 0.5f}, on_top{0.09f, 0.1f + kLift, 0.5f};
    const bool seen = sees_within_texel(b.surface, tracer, on_side, b.facing({1, 0, 0}), on_top, b.facing({0, 1, 0}));
    EXPECT_EQ(seen, one_chart) << (one_chart ? "one chart: its corner is detail" : "two charts: the corner blocks");
  }
}

TEST(SightWithinTexel, TheTwoFacesOfSomethingThinNeverSeeEachOther) {
  // A 1 cm door leaf, its faces in one chart: a point on each face, 2 cm apart along it.
  const Built b = block({0, 0, 0}, {0.01f, 1, 1}, true);
  RayTracer tracer(b.surface);
  const Vec3 lit{0.01f + kLift, 0.5f, 0.5f}, dark{-kLift, 0.5f, 0.52f};
  EXPECT_FALSE(sees_within_texel(b.surface, tracer, lit, b.facing({1, 0, 0}), dark, b.facing({-1, 0, 0})));
  EXPECT_FALSE(sees_within_texel(b.surface, tracer, dark, b.facing({-1, 0, 0}), lit, b.facing({1, 0, 0})));
  // Two points of one face always see each other.
  const Vec3 beside{0.01f + kLift, 0.55f, 0.45f};
  EXPECT_TRUE(sees_within_texel(b.surface, tracer, lit, b.facing({1, 0, 0}), beside, b.facing({1, 0, 0})));
}

}  // namespace
}  // namespace radbake
