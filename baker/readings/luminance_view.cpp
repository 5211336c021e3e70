#include "baker/readings/luminance_view.h"

#include <tbb/parallel_for.h>

#include <cmath>

#include "baker/direct/sky_light.h"
#include "baker/surface/sampling.h"
#include "baker/transport/patch_transport.h"

namespace radbake {

namespace {

// What an eye's rays see of a finished bake.
struct Seeing {
  const Elements& elements;
  const std::vector<Rgb>& exitance;
  const Surface& surface;
  const RayTracer& tracer;
  const SkyLight& sky;
  SkyView view;
  Vec3 origin;

  // cd/m2 along d: a surface's exitance / pi, or the sky's or the ground's.
  double luminance(Vec3 d) const {
    const Hit hit = tracer.intersect_light_path(origin, d, 0.0f, INFINITY);
    if (hit.missed()) return sky.enabled ? view.luminance(d) : 0.0;
    if (!hit.front) return 0;
    const int64_t e = element_for_hit(elements, surface, tracer, hit, kFromTheOpen);
    return e >= 0 && elements.valid(size_t(e)) ? photopic(exitance[size_t(e)]) / M_PI : 0.0;
  }

  // The share of the sun's disc seen from the eye (0 when the sun is down or there is none).
  double sun_seen(uint64_t seed) const {
    Rng rng(seed, Stream::View, uint64_t(-1));
    return sun_disc_seen(view, tracer, origin, sky.sun_rays, rng.next_u32());
  }
};

}  // namespace

PerspectiveImage render_perspective(const EyeView& eye, const ViewOptions& options, const Elements& elements,
                                    const std::vector<Rgb>& exitance, const Surface& surface, const RayTracer& tracer,
                                    const SkyLight& sky, uint64_t seed) {
  PerspectiveImage image;
  image.width = options.perspective_width, image.height = std::max(1, options.perspective_width * 3 / 4);
  image.luminance.assign(size_t(image.width) * size_t(image.height), 0.0f);
  const Vec3 forward = normalize(eye.direction), up = normalize(eye.up - forward * dot(eye.up, forward));
  const Vec3 right = normalize(cross(forward, up));
  const Seeing seeing{elements, exitance, surface, tracer, sky, SkyView(sky), sensor_origin(eye.position, forward, surface.scene_extent)};
  const double half = std::tan(options.perspective_fov * M_PI / 360), pixel = 2 * half / image.width;  // image plane at 1
  const uint32_t rays = std::max<uint32_t>(1, options.rays_per_pixel);
  tbb::parallel_for(tbb::blocked_range<int>(0, image.height, 4), [&](const tbb::blocked_range<int>& r) {
    for (int y = r.begin(); y < r.end(); ++y)
      for (int x = 0; x < image.width; ++x) {
        Rng rng(seed, Stream::View, (uint64_t(1) << 40) ^ (uint64_t(y) * uint64_t(image.width) + uint64_t(x)));
        const uint32_t pattern = rng.next_u32();
        double sum = 0;
        for (uint32_t k = 0; k < rays; ++k) {
          const Vec2 u = cmj_sample(k, rays, pattern);
          const double px = -half + (x + u.x) * pixel, py = pixel * (0.5 * image.height - y - u.y);
          sum += seeing.luminance(normalize(forward + right * float(px) + up * float(py)));
        }
        image.luminance[size_t(y) * size_t(image.width) + size_t(x)] = float(sum / rays);
      }
  });
  // The sun into the pixel it falls in, as the luminance that pixel's solid angle needs.
  const Vec3 sun = sun_direction(sky);
  const double seen = dot(sun, forward) > 0 ? seeing.sun_seen(seed) : 0;
  if (seen > 0) {
    const double px = dot(sun, right) / dot(sun, forward), py = dot(sun, up) / dot(sun, forward);
    const int x = int(std::floor((px + half) / pixel)), y = int(std::floor(0.5 * image.height - py / pixel));
    if (x >= 0 && y >= 0 && x < image.width && y < image.height) {
      const double c = double(dot(sun, forward)), omega = pixel * pixel * c * c * c;
      image.luminance[size_t(y) * size_t(image.width) + size_t(x)] += float(sky.sun_illuminance * seen / omega);
    }
  }
  return image;
}

FisheyeImage render_fisheye(const EyeView& eye, const ViewOptions& options, const Elements& elements,
                            const std::vector<Rgb>& exitance, const Surface& surface, const RayTracer& tracer,
                            const SkyLight& sky, uint64_t seed) {
  FisheyeImage image;
  image.size = options.size;
  image.view = normalize(eye.direction);
  image.up = normalize(eye.up - image.view * dot(eye.up, image.view));
  image.luminance.assign(size_t(image.size) * size_t(image.size), 0.0f);
  const Seeing seeing{elements, exitance, surface, tracer, sky, SkyView(sky), sensor_origin(eye.position, image.view, surface.scene_extent)};
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
          sum += seeing.luminance(normalize(image.view * float(std::cos(theta)) + across * float(std::sin(theta))));
        }
        image.luminance[size_t(y) * size_t(image.size) + size_t(x)] = float(sum / rays);
      }
  });
  // The sun: what of its disc the eye sees, into the pixel its centre falls in.
  const Vec3 sun = sun_direction(sky);
  const double seen = dot(sun, image.view) > 0 ? seeing.sun_seen(seed) : 0;
  if (seen > 0) {
    const double theta = std::acos(std::min(1.0f, dot(sun, image.view))), rr = theta / (M_PI / 2);
    const double phi = std::atan2(double(dot(sun, image.up)), double(dot(sun, right)));
    const int x = std::min(image.size - 1, int(std::floor(radius + rr * std::cos(phi) * radius)));
    const int y = std::min(image.size - 1, int(std::floor(radius - rr * std::sin(phi) * radius)));
    Vec3 centre;
    double omega;
    if (fisheye_pixel(image, x, y, &centre, &omega))
      image.luminance[size_t(y) * size_t(image.size) + size_t(x)] += float(sky.sun_illuminance * seen / omega);
  }
  return image;
}

}  // namespace radbake
