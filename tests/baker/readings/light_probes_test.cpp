// Light probes (baker/readings/light_probes.h) against the path tracer, the independent method of
// the accuracy study, at points in the air of the Cornell box: the same nine coefficients of the
// light there, one from the bake, one from paths.
#include <gtest/gtest.h>

#include <cmath>

#include "baker/readings/light_probes.h"
#include "baker/surface/back_faces.h"
#include "baker/surface/material_sampler.h"
#include "baker/surface/sampling.h"
#include "baker/surface/surface.h"
#include "baker/transport/path_tracer.h"
#include "io/gltf/gltf_loader.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

// Whether p is inside the closed convex mesh `block` (behind every one of its faces).
bool inside(const MeshInstance& block, Vec3 p) {
  for (size_t t = 0; t < block.triangle_count(); ++t) {
    const Vec3 a = block.positions[block.triangles[3 * t]], b = block.positions[block.triangles[3 * t + 1]],
               c = block.positions[block.triangles[3 * t + 2]];
    if (dot(cross(b - a, c - a), p - a) >= 0) return false;
  }
  return true;
}

TEST(SphericalHarmonics, TheBasisIsOrthonormalAndTheIrradianceOfAnEvenSkyIsPiL) {
  // Uniform radiance L = 1 over the sphere: L00 = sqrt(4 pi), all else 0; every normal gets pi.
  ShL2 even{};
  even[0] = Rgb{1, 1, 1} * std::sqrt(4 * kPi);
  for (Vec3 n : {Vec3{0, 1, 0}, Vec3{1, 0, 0}, normalize(Vec3{1, -2, 3})})
    EXPECT_NEAR(probe_irradiance(even, n).x, kPi, 1e-5);
  // Projecting the basis by quadrature gives the identity (to the quadrature's 1e-3).
  const int steps = 400;
  double gram[9][9] = {};
  for (int i = 0; i < steps; ++i)
    for (int j = 0; j < 2 * steps; ++j) {
      const double theta = (i + 0.5) * M_PI / steps, phi = (j + 0.5) * M_PI / steps;
      const Vec3 d{float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)), float(std::cos(theta))};
      const auto y = sh_basis(d);
      const double w = std::sin(theta) * (M_PI / steps) * (M_PI / steps);
      for (int a = 0; a < 9; ++a)
        for (int b = 0; b < 9; ++b) gram[a][b] += w * y[size_t(a)] * y[size_t(b)];
    }
  for (int a = 0; a < 9; ++a)
    for (int b = 0; b < 9; ++b) EXPECT_NEAR(gram[a][b], a == b ? 1.0 : 0.0, 1e-3) << a << "," << b;
}

// The nine coefficients of the light at `p`, by the path tracer: 4,096 directions over the
// sphere, each taking the radiance of the surface it meets (its reflectance times the irradiance
// 32 paths find there, over pi), and the lamp's emission by quadrature over 4,096 points of each
// emitting triangle behind shadow rays. Independent of the bake's patches, solve and gather.
ShL2 path_traced_radiance_sh(Vec3 p, const Scene& scene, const Surface& surface, const MaterialSampler& materials,
                             const RayTracer& tracer) {
  constexpr uint32_t kDirections = 4096, kPaths = 32, kLampPoints = 4096;
  std::vector<Vec3> points, normals, directions;
  std::vector<Rgb> reflectance;
  for (uint32_t k = 0; k < kDirections; ++k) {
    const Vec2 u = cmj_sample(k, kDirections, 12345);
    const float z = 1 - 2 * u.x, r = std::sqrt(std::max(0.0f, 1 - z * z)), phi = 2 * kPi * u.y;
    const Vec3 d{r * std::cos(phi), r * std::sin(phi), z};
    const Hit hit = tracer.intersect_light_path(p, d, 0.0f, INFINITY);
    if (hit.missed() || !hit.front) continue;
    const Vec3 n = surface.shading_normal(hit.triangle, hit.bary);
    points.push_back(surface.point(hit.triangle, hit.bary) + surface.normal[hit.triangle] * 1e-5f);
    normals.push_back(n);
    directions.push_back(d);
    reflectance.push_back(materials.reflectance(hit.triangle, hit.bary, 0.0f));
  }
  Elements none;
  const std::vector<Rgb> irradiance =
      path_trace_points(points, normals, none, surface, materials, scene.lights, nullptr, tracer, kPaths, 11).irradiance;
  ShL2 sh{};
  for (size_t k = 0; k < points.size(); ++k) {
    const auto y = sh_basis(directions[k]);
    for (size_t m = 0; m < 9; ++m) sh[m] += reflectance[k] * irradiance[k] * (y[m] / kPi * 4 * kPi / kDirections);
  }
  for (uint32_t t = 0; t < surface.triangle_count(); ++t) {
    if (!materials.emits(t)) continue;
    for (uint32_t k = 0; k < kLampPoints; ++k) {
      const Vec2 bary = uniform_triangle(cmj_sample(k, kLampPoints, 777 + t));
      const Vec3 y = surface.point(t, bary);
      Vec3 to = y + surface.normal[t] * 1e-5f - p;
      const float r = length(to);
      to = to / r;
      const float facing = -dot(surface.normal[t], to);
      if (facing <= 0 || tracer.transmittance(p, to, 0.0f, r * (1 - 1e-5f)) <= 0) continue;
      const auto basis = sh_basis(to);
      for (size_t m = 0; m < 9; ++m)
        sh[m] += materials.emission(t, bary, 0.0f) * (basis[m] / kPi * facing / (r * r) * surface.area[t] / kLampPoints);
    }
  }
  return sh;
}

TEST(LightProbes, InTheCornellBoxTheyMatchThePathTracerForSixNormals) {
  LoadedScene loaded = load_gltf(test::source_path("samples/cornell_box/cornell_box.gltf"));
  BakeOptions options;
  options.probes.enabled = true;
  options.probes.spacing = 0.1f;
  AtlasOptions atlas;
  atlas.max_page_size = 256;
  const test::Baked b = test::bake_scene(loaded.scene, atlas, options);
  const LightProbes& probes = b.result.probes;
  ASSERT_GT(probes.probes.size(), 50u);
  EXPECT_GT(probes.inside, 0u) << "the blocks hold grid points: some must have been pruned";
  // No probe inside a block.
  size_t blocks = 0;
  for (const MeshInstance& instance : loaded.scene.instances) {
    if (instance.name.rfind("short_block /", 0) != 0 && instance.name.rfind("tall_block /", 0) != 0) continue;
    ++blocks;
    for (const LightProbe& p : probes.probes) EXPECT_FALSE(inside(instance, p.position)) << instance.name;
  }
  EXPECT_EQ(blocks, 2u);

  // Ten probes spread through the room, each for the six axis normals.
  Scene scene = loaded.scene;
  add_back_faces(scene);
  const Surface surface = build_surface(scene, b.atlas);
  const MaterialSampler materials(scene, surface, options.emission_scale, options.glazing);
  const RayTracer tracer(surface, &materials);
  const Vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  double worst = 0, worst_truncation = 0;
  for (size_t k = 0; k < 10; ++k) {
    const LightProbe& probe = probes.probes[(2 * k + 1) * probes.probes.size() / 20];
    const ShL2 reference = path_traced_radiance_sh(probe.position, scene, surface, materials, tracer);
    std::vector<Vec3> points(6, probe.position), normals(axes, axes + 6);
    const std::vector<Rgb> exact =
        path_trace_points(points, normals, b.result.elements, surface, materials, scene.lights, nullptr, tracer, 16384, 7)
            .irradiance;
    double scale = 0;  // the probe's mean reading over the six normals, lux
    for (Vec3 n : axes) scale += double(sum(probe_irradiance(reference, n))) / 18;
    for (Vec3 n : axes) {
      // L2 against L2: the bake's probe against the same nine coefficients of the path-traced
      // light. 3% bounds the bake's own error (radiosity against paths, 1-2% on the Cornell
      // box's surfaces) and both sides' noise: 3% of the reading, or of the probe's mean reading
      // where a reading is near nothing (facing the box's open side, where nine coefficients
      // ring below zero).
      const double expected = double(sum(probe_irradiance(reference, n))) / 3;
      const double got = double(sum(probe_irradiance(probe.radiance, n))) / 3;
      const double bound = 0.03 * std::max(std::fabs(expected), scale);
      worst = std::max(worst, std::fabs(got - expected) / std::max(std::fabs(expected), scale));
      EXPECT_NEAR(got, expected, bound) << "probe at " << probe.position.x << "," << probe.position.y << ","
                                        << probe.position.z << " facing " << n.x << "," << n.y << "," << n.z;
    }
    for (size_t a = 0; a < 6; ++a) {
      const double truth = double(sum(exact[a])) / 3;
      worst_truncation = std::max(worst_truncation,
                                  std::fabs(double(sum(probe_irradiance(reference, axes[a]))) / 3 - truth) / std::max(truth, scale));
    }
  }
  // What nine coefficients cannot hold: a small bright lamp's lobe rings into the normals facing
  // away from it. Printed for docs/directional.md, not asserted: it is L2's, not the bake's.
  std::printf("light probes: worst %.2f%% against the path-traced L2; L2 itself against the exact irradiance: "
              "worst %.1f%% (both of the reading or of the probe's mean reading, the larger)\n", 100 * worst,
              100 * worst_truncation);
}

}  // namespace
}  // namespace radbake
