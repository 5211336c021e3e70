// What every stage of a bake needs before the light: the surface, its materials, the ray tracer
// and the elements with their samples placed. Stages take it whole rather than its parts one by
// one. Held by pointer: the sampler and the tracer refer to the surface.
#pragma once

#include <memory>

#include "baker/surface/elements.h"
#include "baker/surface/material_sampler.h"
#include "baker/surface/ray_tracer.h"
#include "baker/surface/surface.h"

namespace radbake {

struct BakeGeometry {
  std::unique_ptr<Surface> surface;
  std::unique_ptr<MaterialSampler> materials;
  std::unique_ptr<RayTracer> tracer;
  Elements elements;
};

}  // namespace radbake
