// Embree behind one RAII wrapper: it owns the device and scene, registers the error callback once,
// and answers occlusion and nearest-hit queries over the Surface's triangles from any thread.
#pragma once

#include <cstdint>
#include <memory>

#include "baker/math.h"
#include "baker/surface.h"

namespace radbake {

struct Hit {
  uint32_t triangle = UINT32_MAX;  // UINT32_MAX: the ray left the scene
  Vec2 bary;                       // (b1, b2) on that triangle
  float distance = 0;              // metres along the unit direction
  bool front = false;              // the ray struck the side the geometric normal points to

  bool missed() const { return triangle == UINT32_MAX; }
};

class RayTracer {
 public:
  explicit RayTracer(const Surface& surface);
  ~RayTracer();
  RayTracer(const RayTracer&) = delete;
  RayTracer& operator=(const RayTracer&) = delete;

  // Directions must be unit length; distances are metres along them.
  bool occluded(Vec3 origin, Vec3 direction, float t_near, float t_far) const;
  Hit intersect(Vec3 origin, Vec3 direction, float t_near, float t_far) const;

  uint64_t rays_cast() const;  // since construction, all threads

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace radbake
