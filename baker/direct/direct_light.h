// Direct irradiance at every element, in lux: from KHR_lights_punctual lights with shadow rays,
// and from emitting surfaces as area lights (the exact unoccluded form factor to each emitting
// triangle, averaged over points spread over the texel, times the seen fraction of it measured
// with stratified shadow rays weighted by the form factor kernel).
#pragma once

#include <cstdint>
#include <vector>

#include "baker/surface/elements.h"
#include "baker/surface/light_direction.h"
#include "baker/surface/material_sampler.h"
#include "baker/surface/ray_tracer.h"
#include "base/progress.h"
#include "base/scene.h"

namespace radbake {

struct DirectLightOptions {
  int punctual_rays = 4;    // shadow rays per element per light, spread over the texel footprint
  int area_light_rays = 16; // shadow rays per element per emitting triangle, at most
  // Both set from the effect plan. false: a convex enclosure, every light is seen unoccluded.
  bool shadow_rays = true;
  // Cast no shadow ray where a light's unoccluded contribution is zero (outside its range or cone).
  bool cull_unlit = true;
  std::vector<uint8_t> light_traced;  // per light: 0 skips it (the plan culled it); empty: every light
};

// Both return the irradiance of the elements in `range`, the first at index 0; with
// `directions`, also where it comes from (light_direction.h), the same way.
std::vector<Rgb> punctual_irradiance(const Elements& elements, const Surface& surface,
                                     const std::vector<Light>& lights, const RayTracer& tracer,
                                     const DirectLightOptions& options, uint64_t seed, Progress& progress,
                                     ElementRange range = {}, std::vector<LightDirection>* directions = nullptr);

std::vector<Rgb> emitter_irradiance(const Elements& elements, const Surface& surface, const MaterialSampler& materials,
                                    const RayTracer& tracer, const DirectLightOptions& options, uint64_t seed,
                                    Progress& progress, ElementRange range = {},
                                    std::vector<LightDirection>* directions = nullptr);

// Irradiance at point x (unit normal n) from a Lambertian polygon of unit exitance, unoccluded:
// the point-to-polygon form factor by Lambert's contour integral. The polygon must lie on the
// side of x's tangent plane that n points to.
double polygon_form_factor(Vec3 x, Vec3 n, const Vec3* polygon, int count);

// The same contour integral without the normal: the unit direction the polygon's light arrives
// from on average (its vector form factor, normalised), for directional lightmaps.
Vec3 polygon_light_direction(Vec3 x, const Vec3* polygon, int count);

// Unoccluded irradiance in lux from a punctual light of the given kind, ignoring shadows: the
// closed forms the tests compare against (inverse square, cosine, spot cone, range window).
Rgb punctual_light_irradiance(const Light& light, Vec3 x, Vec3 n, Vec3* to_light, float* distance);

}  // namespace radbake
