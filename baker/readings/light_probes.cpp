#include "baker/readings/light_probes.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "baker/direct/direct_light.h"
#include "baker/direct/sky_light.h"
#include "baker/surface/sampling.h"
#include "baker/transport/patch_transport.h"

namespace radbake {
namespace {

Vec3 sphere_direction(Vec2 u) {
  const float z = 1 - 2 * u.x, r = std::sqrt(std::max(0.0f, 1 - z * z)), phi = 2 * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

void add(ShL2& sh, const Rgb& value, Vec3 d) {
  const std::array<float, 9> y = sh_basis(d);
  for (size_t k = 0; k < 9; ++k) sh[k] += value * y[k];
}

// The emitting triangles, picked in proportion to area times their brightest emission. The path
// tracer keeps a table like it of its own: it is the reference probes are tested against, and
// shares nothing with the baker but the scene, the ray tracer and the lights.
struct EmitterTable {
  std::vector<uint32_t> triangle;
  std::vector<double> cumulative;  // of the weights
  std::vector<float> brightest;    // lm/m2
  double total = 0;

  EmitterTable(const Surface& surface, const MaterialSampler& materials) {
    for (uint32_t t = 0; t < surface.triangle_count(); ++t) {
      if (!materials.emits(t) || !(surface.area[t] > 0)) continue;
      const float b = max_component(materials.emission_bound(t));
      if (!(b > 0)) continue;
      triangle.push_back(t);
      brightest.push_back(b);
      cumulative.push_back(total += double(surface.area[t]) * b);
    }
  }
  size_t pick(double u) const {
    return std::min(size_t(std::lower_bound(cumulative.begin(), cumulative.end(), u * total) - cumulative.begin()),
                    triangle.size() - 1);
  }
};

}  // namespace

std::array<float, 9> sh_basis(Vec3 d) {
  return {0.282095f,
          0.488603f * d.y,
          0.488603f * d.z,
          0.488603f * d.x,
          1.092548f * d.x * d.y,
          1.092548f * d.y * d.z,
          0.315392f * (3 * d.z * d.z - 1),
          1.092548f * d.x * d.z,
          0.546274f * (d.x * d.x - d.y * d.y)};
}

Rgb probe_irradiance(const ShL2& radiance, Vec3 n) {
  const std::array<float, 9> y = sh_basis(n);
  const float band[9] = {kPi, 2 * kPi / 3, 2 * kPi / 3, 2 * kPi / 3, kPi / 4, kPi / 4, kPi / 4, kPi / 4, kPi / 4};
  Rgb e{};
  for (size_t k = 0; k < 9; ++k) e += radiance[k] * (band[k] * y[k]);
  return e;
}

LightProbes place_probes(const Surface& surface, const RayTracer& tracer, const ProbeOptions& options) {
  LightProbes out;
  if (surface.corners.empty()) return out;
  out.lo = out.hi = surface.corners[0];
  for (const Vec3& c : surface.corners)
    for (int a = 0; a < 3; ++a) {
      out.lo[a] = std::min(out.lo[a], c[a]);
      out.hi[a] = std::max(out.hi[a], c[a]);
    }
  const Vec3 extent = out.hi - out.lo;
  float spacing = options.spacing > 0 ? options.spacing : max_component(extent) / 8;
  if (!(spacing > 0)) return out;
  int count[3];
  auto fill = [&] {
    size_t total = 1;
    for (int a = 0; a < 3; ++a)
      total *= size_t(count[a] = int(std::clamp(std::floor(double(extent[a]) / spacing), 1.0, 1e6)));
    return total;
  };
  while (fill() > std::max<size_t>(1, options.max_probes)) spacing *= 1.1f;
  out.spacing = spacing;
  std::vector<Vec3> points;
  for (int i = 0; i < count[0]; ++i)
    for (int j = 0; j < count[1]; ++j)
      for (int k = 0; k < count[2]; ++k) {
        const int at[3] = {i, j, k};
        Vec3 p;
        for (int a = 0; a < 3; ++a) p[a] = out.lo[a] + (extent[a] - float(count[a] - 1) * spacing) / 2 + float(at[a]) * spacing;
        points.push_back(p);
      }
  out.grid_points = points.size();
  // Inside a solid (a block, behind the walls) most directions first meet the back of a surface.
  std::vector<uint8_t> inside(points.size(), 0);
  tbb::parallel_for(size_t(0), points.size(), [&](size_t i) {
    int backs = 0, directions = 0;
    for (int x = -1; x <= 1; ++x)
      for (int y = -1; y <= 1; ++y)
        for (int z = -1; z <= 1; ++z) {
          if (x == 0 && y == 0 && z == 0) continue;
          ++directions;
          const Hit hit = tracer.intersect(points[i], normalize(Vec3{float(x), float(y), float(z)}), 0.0f, INFINITY);
          backs += !hit.missed() && !hit.front;
        }
    inside[i] = 4 * backs > directions;
  });
  for (size_t i = 0; i < points.size(); ++i) {
    if (inside[i]) ++out.inside;
    else out.probes.push_back({points[i], {}});
  }
  return out;
}

void light_probes(LightProbes& probes, const BakeGeometry& geometry, const std::vector<Rgb>& exitance,
                  const std::vector<Light>& lights, const SkyLight& sky, const ProbeOptions& options, uint64_t seed,
                  Progress& progress) {
  const Elements& elements = geometry.elements;
  const Surface& surface = *geometry.surface;
  const MaterialSampler& materials = *geometry.materials;
  const RayTracer& tracer = *geometry.tracer;
  const EmitterTable emitters(surface, materials);
  const SkyView view(sky);
  const uint32_t rays = std::max<uint32_t>(1, options.rays), samples = std::max<uint32_t>(1, options.emitter_samples);
  const float lift = 1e-5f * surface.scene_extent;
  progress.begin("light probes", probes.probes.size());
  tbb::parallel_for(size_t(0), probes.probes.size(), [&](size_t i) {
    LightProbe& probe = probes.probes[i];
    const Vec3 p = probe.position;
    Rng rng(seed, Stream::LightProbe, i);
    ShL2 sh{};
    // What surfaces reflect, and the sky: uniform over the sphere, each ray 4 pi / rays.
    const uint32_t pattern = rng.next_u32();
    ShL2 seen{};
    for (uint32_t k = 0; k < rays; ++k) {
      const Vec3 d = sphere_direction(cmj_sample(k, rays, pattern));
      const Hit hit = tracer.intersect_light_path(p, d, 0.0f, INFINITY);
      Rgb radiance{};
      if (hit.missed()) {
        if (sky.enabled) radiance = Rgb{1, 1, 1} * float(view.luminance(d));
      } else if (hit.front) {
        const int64_t e = element_for_hit(elements, surface, tracer, hit, kFromTheOpen);
        if (e >= 0 && elements.valid(size_t(e))) radiance = (exitance[size_t(e)] - elements.emission[size_t(e)]) / kPi;
      }
      add(seen, radiance, d);
    }
    for (size_t k = 0; k < 9; ++k) sh[k] = seen[k] * (4 * kPi / float(rays));
    // Emitting surfaces by shadow rays to points on them, in proportion to area times brightness.
    if (!emitters.triangle.empty()) {
      const uint32_t pick_pattern = rng.next_u32(), point_pattern = rng.next_u32();
      ShL2 lit{};
      for (uint32_t k = 0; k < samples; ++k) {
        const size_t j = emitters.pick(cmj_sample(k, samples, pick_pattern).x);
        const uint32_t t = emitters.triangle[j];
        const Vec2 bary = uniform_triangle(cmj_sample(k, samples, point_pattern));
        const Vec3 y = surface.point(t, bary);
        Vec3 to = y + surface.normal[t] * lift - p;
        const float r = length(to);
        if (!(r > 0)) continue;
        to = to / r;
        const float facing = -dot(surface.normal[t], to);
        if (facing <= 0 || tracer.transmittance(p, to, 0.0f, r * (1 - 1e-5f)) <= 0) continue;
        // Radiance M / pi over the solid angle the point stands for: cos / r^2 over the density
        // of y by area (brightest / total).
        const float weight = facing / (r * r) * float(emitters.total / emitters.brightest[j]);
        add(lit, materials.emission(t, bary, 0.0f) * (weight / kPi), to);
      }
      for (size_t k = 0; k < 9; ++k) sh[k] += lit[k] / float(samples);
    }
    // Punctual lights and the sun: light from one direction, E_perp there.
    for (const Light& light : lights) {
      Vec3 to{};
      float distance = 0;
      // Facing the light, its irradiance is the perpendicular one.
      Vec3 probe_to_light = light.type == LightType::Directional ? -light.direction : normalize(light.position - p);
      const Rgb e = punctual_light_irradiance(light, p, probe_to_light, &to, &distance);
      if (!(max_component(e) > 0)) continue;
      const float passes = tracer.transmittance(p, to, 0.0f, std::isfinite(distance) ? distance * (1 - 1e-5f) : INFINITY);
      if (passes > 0) add(sh, e * passes, to);
    }
    if (sky.enabled && view.sun_up() && sky.sun_illuminance > 0) {
      const double share = sun_disc_seen(view, tracer, p, sky.sun_rays, rng.next_u32());
      if (share > 0) add(sh, Rgb{1, 1, 1} * float(sky.sun_illuminance * share), sun_direction(sky));
    }
    probe.radiance = sh;
    progress.advance(1);
  });
  progress.end();
}

}  // namespace radbake
