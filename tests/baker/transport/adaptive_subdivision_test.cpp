// Adaptive subdivision: patches split where neighbours' radiosity differs, and the refined solve
// comes close to a uniformly fine one with fewer patches. Progressive previews show the estimate
// as the solve refines it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "baker/direct/direct_light.h"
#include "baker/pipeline/bake.h"
#include "baker/surface/elements.h"
#include "baker/surface/material_sampler.h"
#include "baker/surface/ray_tracer.h"
#include "baker/surface/surface.h"
#include "baker/transport/interreflection.h"
#include "baker/transport/patches.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

// A 2 m room lit by a bulb near the ceiling, with a block on the floor casting a shadow.
Scene room_with_block() {
  Scene scene;
  int white = test::add_material(scene, {0.7f, 0.7f, 0.7f});
  int red = test::add_material(scene, {0.7f, 0.1f, 0.1f});
  test::add_box(scene, {0, 0, 0}, {2, 2, 2}, true, {red, white, white, white, white, white}, "room");
  test::add_box(scene, {0.7f, 0, 0.7f}, {1.2f, 0.6f, 1.2f}, false, white, "block");
  Light bulb;
  bulb.position = {1.4f, 1.8f, 1.4f};
  bulb.intensity = 100;  // cd
  scene.lights.push_back(bulb);
  return scene;
}

struct Prepared {
  Scene scene;
  Atlas atlas;
  Surface surface;
  std::unique_ptr<RayTracer> tracer;
  Elements elements;
  std::vector<Rgb> direct;
};

std::unique_ptr<Prepared> prepare(Scene scene, float density) {
  auto p = std::make_unique<Prepared>();
  p->scene = std::move(scene);
  p->atlas = test::unwrap(p->scene, {density, 1024, 2});
  p->surface = build_surface(p->scene, p->atlas);
  p->tracer = std::make_unique<RayTracer>(p->surface);
  MaterialSampler materials(p->scene, p->surface);
  Progress progress;
  p->elements = build_elements(p->surface, materials, {}, progress);
  place_samples(p->elements, p->surface, *p->tracer, 1, progress);
  p->direct = punctual_irradiance(p->elements, p->surface, p->scene.lights, *p->tracer, {}, 1, progress);
  return p;
}

Interreflection solve(const Prepared& p, int block, double subdivide) {
  PatchOptions patches;
  patches.block_size = block;
  SubdivisionOptions subdivision;
  subdivision.tolerance = subdivide;
  Progress progress;
  return solve_interreflection(p.elements, p.surface, *p.tracer, p.direct, {patches, {}, subdivision, {}, 3}, progress);
}

// Area-weighted RMS difference of the piecewise-constant radiosity (each element valued by its
// patch) from the reference's, over the reference's area-weighted mean.
double relative_rms(const Prepared& p, const Interreflection& a, const Interreflection& reference) {
  double squared = 0, mean = 0, area = 0;
  for (size_t i = 0; i < p.elements.size(); ++i) {
    uint32_t pa = a.patches.patch_of_element[i], pr = reference.patches.patch_of_element[i];
    if (pa == UINT32_MAX || pr == UINT32_MAX) continue;
    double va = sum(a.solution.exitance[pa]) / 3.0, vr = sum(reference.solution.exitance[pr]) / 3.0;
    squared += (va - vr) * (va - vr) * p.elements.area[i];
    mean += vr * p.elements.area[i];
    area += p.elements.area[i];
  }
  return std::sqrt(squared / area) / (mean / area);
}

TEST(AdaptiveSubdivision, SplitsOnlyWhereNeighboursDiffer) {
  Scene scene;
  int grey = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  test::add_quad(scene, {-1, 0, 1}, {2, 0, 0}, {0, 0, -2}, grey);  // 2 m floor, faces +y
  test::add_quad(scene, {-1, 2, -1}, {2, 0, 0}, {0, 0, 2}, grey);  // its ceiling, so rows are not empty
  Light bulb;
  bulb.position = {0, 1, 0};
  scene.lights.push_back(bulb);
  auto p = prepare(std::move(scene), 16);
  PatchOptions blocks;
  blocks.block_size = 4;
  Patches patches = build_patches(p->elements, p->surface, blocks);
  // Radiosity 1 lm/m2 where x < 0, 0.1 where x > 0: a sharp edge along x = 0 on the floor.
  std::vector<Rgb> exitance(patches.size());
  std::vector<float> centre_x(patches.size());
  for (size_t q = 0; q < patches.size(); ++q) {
    double x = 0, area = 0;
    for (uint32_t k = patches.first_member[q]; k < patches.first_member[q + 1]; ++k) {
      uint32_t i = patches.members[k];
      x += p->elements.position[i].x * p->elements.area[i];
      area += p->elements.area[i];
    }
    centre_x[q] = float(x / area);
    float v = centre_x[q] < 0 ? 1.0f : 0.1f;
    exitance[q] = {v, v, v};
  }
  std::vector<uint8_t> split = patches_to_split(p->elements, p->surface, patches, exitance, 0.2);
  size_t count = 0;
  for (size_t q = 0; q < patches.size(); ++q) {
    count += split[q];
    // Patches are 0.25 m wide and the edge falls between two patch centres, so only patches
    // centred within one patch width of x = 0 (1 cm for float round-off) may split.
    if (split[q]) {
      EXPECT_LE(std::fabs(centre_x[q]), 0.26f) << "patch " << q;
    }
  }
  EXPECT_GE(count, 16u);  // both sides of the edge, 8 rows of 0.25 m
  // Each split patch becomes up to four quarters (fewer where its block is cut by the chart's
  // edge), the others stay as they were.
  Patches finer = split_patches(p->elements, p->surface, patches, split);
  EXPECT_GT(finer.size(), patches.size() + count);
  EXPECT_LE(finer.size(), patches.size() + 3 * count);
}

TEST(AdaptiveSubdivision, ComesCloseToTheFineSolveWithFewerPatches) {
  auto p = prepare(room_with_block(), 16);
  Interreflection coarse = solve(*p, 16, 0);
  Interreflection fine = solve(*p, 2, 0);
  // Splitting where neighbours differ by half: measured 210 patches and 16% error, against 60
  // patches and 75% for the coarse solve (tolerances 0.1 to 0.3 split 2.5 to 12 times as many
  // patches for no better error here: the rest is smooth gradient that blocks of 16 texels flatten).
  Interreflection adaptive = solve(*p, 16, 0.5);
  double coarse_error = relative_rms(*p, coarse, fine), adaptive_error = relative_rms(*p, adaptive, fine);
  std::printf("patches: coarse %zu, adaptive %zu, fine %zu; error against fine: coarse %.2f%%, adaptive %.2f%%\n",
              coarse.patches.size(), adaptive.patches.size(), fine.patches.size(), 100 * coarse_error,
              100 * adaptive_error);
  ASSERT_GT(adaptive.rounds.size(), 1u);
  EXPECT_GT(adaptive.rounds.front().split, 0u);
  EXPECT_EQ(adaptive.rounds.back().patches, adaptive.patches.size());
  // A third of the coarse solve's error, with under a quarter of the fine solve's patches.
  EXPECT_LT(adaptive_error, coarse_error / 3);
  EXPECT_LT(adaptive.patches.size(), fine.patches.size() / 4);
}

TEST(ProgressivePreview, EarlyEstimatesArePlausibleWithTheAmbientTerm) {
  Scene scene = room_with_block();
  Atlas atlas = test::unwrap(scene, {16.0f, 512, 2});
  auto mean_of = [](const std::vector<LightmapPage>& pages) {
    double total = 0;
    size_t n = 0;
    for (const LightmapPage& page : pages)
      for (size_t t = 0; t < page.texels.size(); ++t)
        if (page.valid[t]) total += sum(page.texels[t]) / 3.0, ++n;
    return total / double(n);
  };
  for (bool ambient : {true, false}) {
    BakeOptions options;
    options.preview_every = 20;
    options.solve.ambient_term = ambient;
    std::vector<double> means;
    std::vector<size_t> steps;
    BakeResult result = bake(scene, atlas, options, {}, [&](const std::vector<LightmapPage>& pages, size_t step) {
      means.push_back(mean_of(pages));
      steps.push_back(step);
    });
    double final_mean = mean_of(result.pages);
    std::printf("ambient %d: %zu previews, first %.2f lx, last %.2f lx, final %.2f lx\n", ambient, means.size(),
                means.front(), means.back(), final_mean);
    ASSERT_GE(means.size(), 3u);
    for (size_t k = 0; k < steps.size(); ++k) EXPECT_EQ(steps[k], 20 * (k + 1));
    // The last estimate is the patch-level solution the final gather refines: within 5% of it.
    EXPECT_NEAR(means.back(), final_mean, 0.05 * final_mean);
    if (ambient) {
      // With the ambient term the very first estimate is already within 10% of the result...
      EXPECT_NEAR(means.front(), final_mean, 0.10 * final_mean);
    } else {
      // ...without it, shooting only adds light, so the estimates brighten toward it from below.
      for (size_t k = 1; k < means.size(); ++k) EXPECT_GE(means[k], means[k - 1] * (1 - 1e-6));
      EXPECT_LT(means.front(), 0.95 * final_mean);
    }
  }
}

}  // namespace
}  // namespace radbake
