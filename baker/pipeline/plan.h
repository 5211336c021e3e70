// Effect planning: before a ray is cast, look at the scene and decide which effects it calls for,
// so that a bake spends no time on light its scene cannot have. Every choice carries its reason;
// the CLI prints them and report.json keeps them. Each skip gives the result the full simulation
// gives (tests/baker/pipeline/plan_test.cpp holds each one to that, bench/plan shows what it saves).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/math.h"
#include "base/scene.h"

namespace radbake {

struct PlanOptions {
  bool direct_only = false;          // the user asks for direct light only: no interreflection
  bool simulate_everything = false;  // plan nothing away: the reference every skip is checked against
  bool sky = false;                  // a (white) sky lights the scene too: BakeOptions::sky
};

struct PlanDecision {
  std::string effect;  // what the choice is about: "interreflection", "light 'Spot'", ...
  std::string choice;  // what the bake does
  std::string reason;  // why, in terms of the scene
};

struct EffectPlan {
  bool interreflection = true;  // false: irradiance is the direct light alone
  // Every reflectance grey and every emitter one colour: the solve runs on one channel and scales
  // it by `light_colour` (largest component 1) instead of solving three.
  bool one_channel = false;
  Rgb light_colour{1, 1, 1};
  bool texture_sampling = true;  // false: no texture or vertex colour anywhere, every material is constant
  std::vector<uint8_t> light_traced;  // per Scene::lights; 0: it cannot reach a surface, no shadow ray
  bool shadow_rays = true;  // false: a convex enclosure with the lights inside, nothing can shadow anything
  // The full simulation: every texel box-filters its footprint even where its material is constant,
  // and a shadow ray goes to every light a texel faces, inside its range and cone or not.
  bool exhaustive = false;
  std::vector<PlanDecision> decisions;
  std::vector<std::string> warnings;  // material features the bake does not simulate
};

// Throws InputError when nothing in the scene emits light, or no light can reach a surface.
EffectPlan plan_effects(const Scene& scene, const PlanOptions& options = {});

// Whether the light can reach the triangle's front: in front of its plane, within range of its
// nearest point, and, for a spot, not wholly behind the light nor (by bounding sphere) outside
// the cone. Conservative: never false for a triangle the light reaches.
bool light_can_reach(const Light& light, const Vec3 (&corners)[3]);

}  // namespace radbake
