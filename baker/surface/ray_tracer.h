// Embree behind one RAII wrapper: it owns the device and scene, registers the error callback once,
// and answers occlusion and nearest-hit queries over the Surface's triangles from any thread.
#pragma once

#include <cstdint>
#include <memory>

#include "baker/surface/surface.h"
#include "base/math.h"

namespace radbake {

struct Hit {
  uint32_t triangle = UINT32_MAX;  // UINT32_MAX: the ray left the scene
  Vec2 bary;                       // (b1, b2) on that triangle
  float distance = 0;              // metres along the unit direction
  bool front = false;              // the ray struck the side the geometric normal points to

  bool missed() const { return triangle == UINT32_MAX; }
};

class MaterialSampler;

// Rays are asked three ways. Solid: every surface stops them (geometry: what is buried, what
// faces what). For light, surfaces that let light through (cut-outs, partly transparent ones,
// glazing; MaterialSampler::transmittance) do not: transmittance() multiplies what each lets
// through, and intersect_light_path() lets a ray pass each with that probability.
class RayTracer {
 public:
  // Without `materials`, every surface is solid to every query.
  explicit RayTracer(const Surface& surface, const MaterialSampler* materials = nullptr);
  ~RayTracer();
  RayTracer(const RayTracer&) = delete;
  RayTracer& operator=(const RayTracer&) = delete;

  // Directions must be unit length; distances are metres along them.
  bool occluded(Vec3 origin, Vec3 direction, float t_near, float t_far) const;  // solid
  Hit intersect(Vec3 origin, Vec3 direction, float t_near, float t_far) const;  // solid
  // The share of light that gets from the origin to t_far, 0..1: 0 when a solid surface is in the
  // way, else the product of what each see-through surface passes.
  float transmittance(Vec3 origin, Vec3 direction, float t_near, float t_far) const;
  // The surface a ray of light stops at: a see-through one lets it pass with the probability of
  // its transmittance there, decided by a hash of the ray and the triangle (so the same ray
  // always makes the same choice, whatever the thread). Unbiased for light carried along the ray.
  Hit intersect_light_path(Vec3 origin, Vec3 direction, float t_near, float t_far) const;

  uint64_t rays_cast() const;  // since construction, all threads

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace radbake
