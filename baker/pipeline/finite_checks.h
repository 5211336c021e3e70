// A NaN or an infinity never reaches a page: each stage's output is checked where it is made, and
// the first non-finite value is reported with where it sits (stage, element and its texel, patch,
// triangle and mesh), so the stage and the geometry that made it can be found.
#pragma once

#include <cstdint>
#include <vector>

#include "baker/surface/elements.h"
#include "baker/surface/surface.h"
#include "baker/transport/patch_transport.h"
#include "baker/transport/patches.h"
#include "base/math.h"
#include "base/scene.h"

namespace radbake {

// Where to look up names for the message.
struct FiniteCheckContext {
  const Scene& scene;
  const Surface& surface;
  const Elements& elements;
};

// The elements themselves: sample point, area, reflectance and emission.
void check_elements(const FiniteCheckContext& where);

// Per-element values (irradiance, direct light). `patch_of_element` may be empty.
void check_element_values(const char* stage, const std::vector<Rgb>& values, const FiniteCheckContext& where,
                          const std::vector<uint32_t>& patch_of_element = {});

// The patches themselves (area, reflectance, emission), their form factors and per-patch values.
void check_patches(const char* stage, const Patches& patches, const PatchTransport& transport,
                   const std::vector<Rgb>& values, const FiniteCheckContext& where);

// Finished vertex values, per instance.
void check_vertex_values(const std::vector<std::vector<Rgb>>& values, const Scene& scene);

}  // namespace radbake
