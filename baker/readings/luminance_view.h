// A finished bake seen from an eye: a fisheye luminance image over the hemisphere in front of it,
// for glare (baker/readings/glare.h). A pixel takes the luminance of what its rays reach: a surface's
// exitance / pi (the texel the ray strikes; glazing passes a ray by its chances, as the gather's
// rays), the sky's or the ground's where a ray leaves the scene; the sun's disc, smaller than a
// pixel, adds its light (direct normal illuminance times what of the disc is seen) to the pixel it
// falls in, as the luminance that pixel's solid angle needs to carry it.
#pragma once

#include <cstdint>
#include <vector>

#include "baker/readings/glare.h"
#include "baker/surface/elements.h"
#include "baker/surface/ray_tracer.h"
#include "baker/surface/surface.h"
#include "daylight/sky.h"

namespace radbake {

struct EyeView {
  Vec3 position;            // metres
  Vec3 direction{0, 0, -1}; // where the eye looks (unit)
  Vec3 up{0, 1, 0};         // made perpendicular to `direction`
};

struct ViewOptions {
  int size = 512;              // fisheye pixels per side (180 degrees)
  uint32_t rays_per_pixel = 4; // spread over the pixel
  // The perspective image beside it: width (height 3/4 of it) and horizontal field of view.
  int perspective_width = 640;
  double perspective_fov = 70;  // degrees
};

// A perspective luminance image, rows top to bottom, cd/m2.
struct PerspectiveImage {
  int width = 0, height = 0;
  std::vector<float> luminance;
};

// `exitance` per element, lm/m2 (emission plus reflected light, photopic luminance taken: base/math.h);
// `sky` may be disabled.
PerspectiveImage render_perspective(const EyeView& eye, const ViewOptions& options, const Elements& elements,
                                    const std::vector<Rgb>& exitance, const Surface& surface, const RayTracer& tracer,
                                    const SkyLight& sky, uint64_t seed);

FisheyeImage render_fisheye(const EyeView& eye, const ViewOptions& options, const Elements& elements,
                            const std::vector<Rgb>& exitance, const Surface& surface, const RayTracer& tracer,
                            const SkyLight& sky, uint64_t seed);

}  // namespace radbake
