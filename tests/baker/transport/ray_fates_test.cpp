// Where the form factors' and the final gather's rays end (ray_fates.h, report.json's
// counts.gather_rays and counts.form_factor_rays), against scenes whose answer is known: a closed
// room keeps every ray, two squares sharing an edge keep the share Howell's catalogue gives, and a
// single-sided panel shows its back.
#include <gtest/gtest.h>

#include "baker/surface/elements.h"
#include "baker/surface/material_sampler.h"
#include "baker/surface/ray_tracer.h"
#include "baker/surface/surface.h"
#include "baker/transport/patch_transport.h"
#include "baker/transport/patches.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

constexpr double kPerpendicular = 0.20004;  // Howell C-14, unit squares sharing an edge

size_t valid_elements(const Elements& e) {
  size_t n = 0;
  for (size_t i = 0; i < e.size(); ++i) n += e.valid(i);
  return n;
}

TEST(RayFates, AClosedRoomKeepsEveryRayOfTheGatherAndTheFormFactors) {
  BakeOptions options;
  options.gather.rays = 64;
  const test::Baked b = test::bake_scene(test::lit_room(0.5f, {1, 1, 1}, false), test::coarse_atlas(), options);
  const BakeReport& r = b.result.report;
  // Every valid element casts its gather rays, and all of them are counted.
  EXPECT_EQ(r.gather_rays.total(), uint64_t(valid_elements(b.result.elements)) * options.gather.rays);
  EXPECT_EQ(r.gather_rays[RayFate::TookLight], r.gather_rays.total());
  EXPECT_GE(r.form_factor_rays.total(), uint64_t(r.patches) * options.form_factors.rays_per_patch);
  EXPECT_EQ(r.form_factor_rays[RayFate::TookLight], r.form_factor_rays.total());
}

Scene perpendicular_squares_under_a_lamp() {
  Scene scene;
  int m = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  test::add_quad(scene, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, m, "floor");  // faces +z
  test::add_quad(scene, {0, 0, 0}, {0, 0, 1}, {1, 0, 0}, m, "wall");   // faces +y, shares the x axis edge
  Light lamp;
  lamp.intensity = 10;
  lamp.position = {0.5f, 0.7f, 0.7f};
  scene.lights.push_back(lamp);
  return scene;
}

// Two equal squares see each other with the same form factor, so a ray from either, cast
// cosine-distributed from a uniformly chosen point, lands on the other with probability F and
// leaves the scene otherwise: nothing is lost at their common edge. The form factors' fates are
// also their rows' own account of what landed and what left.
TEST(RayFates, TwoSquaresSharingAnEdgeKeepTheShareOfHowellsFormFactor) {
  const Scene scene = perpendicular_squares_under_a_lamp();
  const AtlasOptions atlas_options{32.0f, 256, 2};
  const auto placed = test::placed_elements(scene, atlas_options);
  const Surface& surface = placed->surface;
  const RayTracer& tracer = *placed->tracer;
  const Elements& e = placed->elements;
  Progress progress;
  PatchOptions blocks;
  blocks.block_size = 4;
  const Patches patches = build_patches(e, surface, blocks);
  const PatchTransport t =
      trace_patch_transport(e, patches, surface, tracer, 4096, std::vector<double>(patches.size(), 1.0), 7, progress);
  const RayFates& f = t.fates;
  // The fates are the rows' own account: what each row measured landing and leaving.
  double landed = 0, escaped = 0, rays = 0;
  for (size_t p = 0; p < patches.size(); ++p) {
    for (uint64_t k = t.row_start[p]; k < t.row_start[p + 1]; ++k) landed += double(t.rays[p]) * t.form_factor[k];
    escaped += double(t.rays[p]) * t.escaped[p];
    rays += t.rays[p];
  }
  EXPECT_EQ(double(f.total()), rays);
  EXPECT_NEAR(f.share(RayFate::TookLight), landed / rays, 1e-5);  // float rows
  EXPECT_NEAR(f.share(RayFate::Escaped), escaped / rays, 1e-5);
  RecordProperty("form_factor_took_light", std::to_string(f.share(RayFate::TookLight)));
  // Over a million rays the share's noise is under 0.05%; 2% of F bounds it with what the origins
  // of the texels along the common edge, kept a little off it, take away (measured: -1.5%).
  EXPECT_NEAR(f.share(RayFate::TookLight), kPerpendicular, 0.02 * kPerpendicular);
  EXPECT_EQ(f[RayFate::BackFace], 0u);
  // The texels along the common edge stand for every point a ray strikes there.
  EXPECT_LT(double(f.front_face_took_none()) / double(f.total()), 1e-3);

  BakeOptions options;
  options.gather.rays = 1024;
  const test::Baked b = test::bake_scene(scene, atlas_options, options);
  const RayFates& g = b.result.report.gather_rays;
  RecordProperty("gather_took_light", std::to_string(g.share(RayFate::TookLight)));
  EXPECT_EQ(g.total(), uint64_t(valid_elements(b.result.elements)) * options.gather.rays);
  EXPECT_NEAR(g.share(RayFate::TookLight), kPerpendicular, 0.02 * kPerpendicular);
  EXPECT_LT(double(g.front_face_took_none()) / double(g.total()), 1e-3);
}

// A single-sided panel hung in a closed room: rays from the ceiling strike its front and take its
// light, rays from the floor strike its back, which takes none.
TEST(RayFates, ASingleSidedPanelsBackIsCountedAsBackFace) {
  Scene scene = test::lit_room(0.5f, {1, 1, 1}, false);
  test::add_quad(scene, {0.5f, 1.0f, 0.5f}, {0, 0, 1}, {1, 0, 0}, scene.instances[0].material, "panel");  // faces +y
  BakeOptions options;
  options.gather.rays = 64;
  const test::Baked b = test::bake_scene(scene, test::coarse_atlas(), options);
  for (const RayFates* f : {&b.result.report.gather_rays, &b.result.report.form_factor_rays}) {
    EXPECT_GT(f->share(RayFate::BackFace), 0.01);
    EXPECT_GT(f->share(RayFate::TookLight), 0.9);
    EXPECT_EQ((*f)[RayFate::Escaped], 0u);
  }
}

}  // namespace
}  // namespace radbake
