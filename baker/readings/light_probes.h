// Light probes (--probes): the light at points in the empty space of a scene, as L2 spherical
// harmonics, for what moves through it (engines light a moving object from the probes around it).
// From the finished bake, not a second one: rays over the whole sphere take the light the texel
// they strike reflects (its exitance less its emission, over pi) or the sky's; emitting surfaces,
// punctual lights and the sun come by shadow rays to points on them, so a small lamp is not left
// to the rays' chance.
//
// Convention: per probe and colour channel, nine coefficients L_lm of the incident radiance
// (cd/m2) on the real orthonormal basis, in the order (l, m) = (0,0), (1,-1), (1,0), (1,1), (2,-2),
// (2,-1), (2,0), (2,1), (2,2), with Y_1-1 = 0.488603 y, Y_10 = 0.488603 z, Y_11 = 0.488603 x (glTF
// world axes, +Y up). The irradiance on a surface of unit normal n is Ramamoorthi and Hanrahan's
// E(n) = sum over l, m of A_l L_lm Y_lm(n), A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4 (lux).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "baker/surface/bake_geometry.h"
#include "baker/surface/elements.h"
#include "baker/surface/material_sampler.h"
#include "baker/surface/ray_tracer.h"
#include "baker/surface/surface.h"
#include "base/progress.h"
#include "base/scene.h"
#include "daylight/sky.h"

namespace radbake {

struct ProbeOptions {
  bool enabled = false;
  float spacing = 0;              // metres between probes on the grid; 0: the longest side of the bounds / 8
  uint32_t rays = 4096;           // sphere rays per probe, for the light surfaces reflect
  uint32_t emitter_samples = 512; // shadow rays per probe to points of emitting surfaces
  size_t max_probes = 65536;      // the spacing grows until the grid holds at most this many
};

using ShL2 = std::array<Rgb, 9>;

struct LightProbe {
  Vec3 position;  // metres
  ShL2 radiance;  // L_lm, cd/m2
};

struct LightProbes {
  float spacing = 0;                // metres
  Vec3 lo, hi;                      // the grid's bounds (the scene's)
  std::vector<LightProbe> probes;
  size_t grid_points = 0;           // before pruning
  size_t inside = 0;                // pruned: inside a solid (most directions meet back faces)
};

// Ramamoorthi and Hanrahan's irradiance from the coefficients, lux, for unit normal n.
Rgb probe_irradiance(const ShL2& radiance, Vec3 n);

// The real orthonormal SH basis up to l = 2 at unit direction d, in the convention's order.
std::array<float, 9> sh_basis(Vec3 d);

// Where probes go: the cell centres of a grid over the scene's bounds, less those inside solids.
LightProbes place_probes(const Surface& surface, const RayTracer& tracer, const ProbeOptions& options);

// Fills every probe's coefficients from the bake: `exitance` per element (emission plus reflected
// light, lm/m2), the scene's punctual lights, the sky (may be disabled).
void light_probes(LightProbes& probes, const BakeGeometry& geometry, const std::vector<Rgb>& exitance,
                  const std::vector<Light>& lights, const SkyLight& sky, const ProbeOptions& options, uint64_t seed,
                  Progress& progress);

}  // namespace radbake
