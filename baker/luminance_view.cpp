#include "baker/luminance_view.h"

#include <tbb/parallel_for.h>

#include <cmath>

#include "baker/patch_transport.h"
#include "baker/sampling.h"

namespace radbake {

FisheyeImage render_fisheye(const EyeView& eye, const ViewOptions& options, const Elements& elements,
                            const std::vector<Rgb>& exitance, const Surface& surface, const RayTracer& tracer,
                            const SkyLight& sky, uint64_t seed) {
  FisheyeImage image;
  image.size = options.size;
  image.view = normalize(eye.direction);
  image.up = normalize(eye.up - image.view * dot(eye.up, image.view));
  image.luminance.assign(size_t(image.size) * size_t(image.size), 0.0f);
  const SkyView view(sky);
  const Vec3 origin = sensor_origin(eye.position, image.view, surface.scene_extent);
  const Vec3 right = normalize(cross(image.view, image.up));
  const double radius = 0.5 * image.size;
  const uint32_t rays = std::max<uint32_t>(1, options.rays_per_pixel);
  tbb::parallel_for(tbb::blocked_range<int>(0, image.size, 4), [&](const tbb::blocked_range<int>& r) {
    for (int y = r.begin(); y < r.end(); ++y)
      for (int x = 0; x < image.size; ++x) {
        Vec3 centre;
        double omega;
        if (!fisheye_pixel(image, x, y, &centre, &omega)) continue;
        Rng rng(seed, Stream::View, uint64_t(y) * uint64_t(image.size) + uint64_t(x));
        const uint32_t pattern = rng.next_u32();
        double sum = 0;
        for (uint32_t k = 0; k < rays; ++k) {
          const Vec2 u = cmj_sample(k, rays, pattern);
          const double px = (x + u.x - radius) / radius, py = (radius - y - u.y) / radius;
          const double rr = std::min(1.0, std::sqrt(px * px + py * py)), theta = rr * M_PI / 2;
          const Vec3 across = rr > 0 ? right * float(px / rr) + image.up * float(py / rr) : Vec3{};
          const Vec3 d = normalize(image.view * float(std::cos(theta)) + across * float(std::sin(theta)));
          const Hit hit = tracer.intersect_light_path(origin, d, 0.0f, INFINITY);
          if (hit.missed()) {
            if (sky.enabled) sum += view.luminance(d);
            continue;
          }
          if (!hit.front) continue;
          const int64_t e = element_for_hit(elements, surface, tracer, hit);
          if (e >= 0 && elements.valid(size_t(e))) sum += double(radbake::sum(exitance[size_t(e)])) / 3.0 / M_PI;
        }
        image.luminance[size_t(y) * size_t(image.size) + size_t(x)] = float(sum / rays);
      }
  });
  // The sun: what of its disc the eye sees, into the pixel its centre falls in.
  const Vec3 sun = sun_direction(sky);
  if (sky.enabled && view.sun_up() && dot(sun, image.view) > 0) {
    Rng rng(seed, Stream::View, uint64_t(-1));
    const uint32_t pattern = rng.next_u32(), sun_rays = std::max<uint32_t>(1, sky.sun_rays);
    double seen = 0;
    for (uint32_t k = 0; k < sun_rays; ++k) seen += tracer.transmittance(origin, view.toward_sun(cmj_sample(k, sun_rays, pattern)), 0.0f, INFINITY);
    seen /= sun_rays;
    const double theta = std::acos(std::min(1.0f, dot(sun, image.view))), rr = theta / (M_PI / 2);
    const double phi = std::atan2(double(dot(sun, image.up)), double(dot(sun, right)));
    const int x = std::min(image.size - 1, int(std::floor(radius + rr * std::cos(phi) * radius)));
    const int y = std::min(image.size - 1, int(std::floor(radius - rr * std::sin(phi) * radius)));
    Vec3 centre;
    double omega;
    if (seen > 0 && fisheye_pixel(image, x, y, &centre, &omega))
      image.luminance[size_t(y) * size_t(image.size) + size_t(x)] += float(sky.sun_illuminance * seen / omega);
  }
  return image;
}

}  // namespace radbake
