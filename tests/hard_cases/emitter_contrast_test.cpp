// Emitters a million times apart in one scene: two closed rooms, one lit a million times more
// brightly than the other. A stopping rule relative to all the light in the scene would call the
// solve done before the dim room has shot anything, and one ambient term for the whole scene
// would pour the bright room's leftover light into the dim one. Each room must come out as if it
// were baked alone.
#include <gtest/gtest.h>

#include <cmath>

#include "baker/surface/material_sampler.h"
#include "hard_cases/hard_case_checks.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

constexpr float kRho = 0.8f;
constexpr float kBright = 1e6f, kDim = 1;  // cd/m2 of each room's ceiling

// A closed 1 m room at x0 whose ceiling emits `luminance`; every face has reflectance kRho.
void add_room(Scene& scene, float x0, float luminance, const char* name) {
  int walls = test::add_material(scene, {kRho, kRho, kRho});
  int ceiling = test::add_material(scene, {kRho, kRho, kRho}, {1, 1, 1}, luminance);
  test::add_box(scene, {x0, 0, 0}, {x0 + 1, 1, 1}, true, {walls, walls, walls, ceiling, walls, walls}, name);
}

// The rooms are 1 m apart: a margin keeps each room's end walls in it against float round-off.
bool in_room(Vec3 p, float x0) { return p.x > x0 - 0.01f && p.x < x0 + 1.01f; }

// All the ceiling's light is absorbed at last: (1 - rho) sum(E A) = M A_ceiling, so the mean
// irradiance over the room's 6 m2 is M / (6 (1 - rho)).
double closed_form_mean(float luminance) { return luminance * kExitancePerEmissiveUnit / (6.0 * (1.0 - kRho)); }

const AtlasOptions kAtlas{16.0f, 256, 2};

TEST(EmitterContrast, EachRoomMatchesItsClosedFormAndItsLoneBake) {
  // The same patches in both bakes (the automatic size depends on the whole scene's texel count),
  // so they differ only where the solve treats the dim room differently.
  BakeOptions options;
  options.patches.block_size = 4;
  Scene both;
  add_room(both, 0, kBright, "bright room");
  add_room(both, 2, kDim, "dim room");
  test::Baked b = test::bake_scene(both, kAtlas, options);
  test::expect_finite_and_non_negative(b.result);
  EXPECT_TRUE(b.result.report.converged);

  Scene alone;
  add_room(alone, 2, kDim, "dim room");
  test::Baked lone = test::bake_scene(alone, kAtlas, options);

  const double bright = test::mean_irradiance(b.result, [](Vec3 p, Vec3) { return in_room(p, 0); }).x;
  const double dim = test::mean_irradiance(b.result, [](Vec3 p, Vec3) { return in_room(p, 2); }).x;
  RecordProperty("bright_room_relative_error", std::to_string(bright / closed_form_mean(kBright) - 1));
  RecordProperty("dim_room_relative_error", std::to_string(dim / closed_form_mean(kDim) - 1));
  // 1%: the 0.1% unshot tolerance, covered by the ambient term, and the texel quadrature of the
  // ceiling's direct light; a dim room left unshot or lit by the bright one's ambient is off by
  // tens of percent or by orders of magnitude.
  EXPECT_NEAR(bright, closed_form_mean(kBright), 0.01 * closed_form_mean(kBright));
  EXPECT_NEAR(dim, closed_form_mean(kDim), 0.01 * closed_form_mean(kDim));

  // Face by face against the dim room baked alone: the light's distribution too, not just its total.
  double worst = 0;
  for (int axis = 0; axis < 3; ++axis)
    for (float side : {-1.0f, 1.0f}) {
      auto on_face = [&](Vec3 p, Vec3 n) { return in_room(p, 2) && n[axis] * side > 0.9f; };
      const double together = test::mean_irradiance(b.result, on_face).x;
      const double apart = test::mean_irradiance(lone.result, on_face).x;
      worst = std::max(worst, std::fabs(together / apart - 1));
      // 1%: the two bakes differ only in their random numbers (texels are numbered differently),
      // which moves a face's mean by a few tenths of a percent.
      EXPECT_NEAR(together, apart, 0.01 * apart) << "face with normal " << side << " along axis " << axis;
    }
  RecordProperty("dim_room_worst_face_vs_lone_bake", std::to_string(worst));
}

}  // namespace
}  // namespace radbake
