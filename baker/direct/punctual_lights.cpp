#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "baker/direct/direct_light.h"
#include "baker/surface/sampling.h"

namespace radbake {

Rgb punctual_light_irradiance(const Light& light, Vec3 x, Vec3 n, Vec3* to_light, float* distance) {
  if (light.type == LightType::Directional) {
    *to_light = -light.direction;
    *distance = INFINITY;
    float cosine = dot(n, *to_light);
    return cosine > 0 ? light.color * (light.intensity * cosine) : Rgb{};
  }
  Vec3 d = light.position - x;
  float dist2 = dot(d, d);
  float dist = std::sqrt(dist2);
  if (!(dist > 0)) return {};
  *to_light = d / dist;
  *distance = dist;
  float cosine = dot(n, *to_light);
  if (cosine <= 0) return {};
  float attenuation = 1.0f / dist2;
  if (light.range > 0) {  // KHR_lights_punctual's recommended window: zero at the range
    float r = dist / light.range;
    float window = std::clamp(1.0f - r * r * r * r, 0.0f, 1.0f);
    attenuation *= window * window;
  }
  if (light.type == LightType::Spot) {
    float cos_outer = std::cos(light.outer_cone_angle), cos_inner = std::cos(light.inner_cone_angle);
    float scale = 1.0f / std::max(0.001f, cos_inner - cos_outer);
    float cd = dot(light.direction, -*to_light);
    float a = std::clamp(cd * scale - cos_outer * scale, 0.0f, 1.0f);
    attenuation *= a * a;
  }
  return light.color * (light.intensity * cosine * attenuation);
}

std::vector<Rgb> punctual_irradiance(const Elements& e, const Surface& surface, const std::vector<Light>& lights,
                                     const RayTracer& tracer, const DirectLightOptions& options, uint64_t seed,
                                     Progress& progress, ElementRange range, std::vector<LightDirection>* directions) {
  range = range.within(e.size());
  std::vector<Rgb> irradiance(range.size());
  if (directions) directions->assign(range.size(), {});
  if (lights.empty()) return irradiance;
  const int rays = std::max(1, options.punctual_rays);
  progress.begin("punctual lights", range.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(range.begin, range.end, 256), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i) {
      if (!e.valid(i)) continue;
      const Vec3 ng = surface.normal[e.triangle[i]];
      Rng rng(seed, Stream::DirectLight, i);
      Rgb total{};
      LightDirection from{};
      for (size_t l = 0; l < lights.size(); ++l) {
        uint32_t pattern = rng.next_u32();  // drawn for culled lights too, so the others' samples stay the same
        if (l < options.light_traced.size() && !options.light_traced[l]) continue;
        Rgb sum{};
        for (int k = 0; k < rays; ++k) {
          // Each ray from its own point of the texel, so shadow edges are antialiased.
          Vec3 x = footprint_point(e, surface, i, cmj_sample(uint32_t(k), uint32_t(rays), pattern));
          Vec3 dir{};
          float dist = 0;
          Rgb value = punctual_light_irradiance(lights[l], x, e.normal[i], &dir, &dist);
          if (dot(ng, dir) <= 0 || (options.cull_unlit && max_component(value) <= 0)) continue;
          Vec3 origin = x + ng * e.offset[i];
          const Rgb arriving =
              options.shadow_rays
                  ? value * tracer.transmittance(origin, dir, 0.0f, std::isfinite(dist) ? dist * (1 - 1e-5f) : INFINITY)
                  : value;
          sum += arriving;
          from.add(arriving / float(rays), dir);
        }
        total += sum / float(rays);
      }
      irradiance[i - range.begin] = total;
      if (directions) (*directions)[i - range.begin] = from;
    }
    progress.advance(r.size());
  });
  progress.end();
  return irradiance;
}

}  // namespace radbake
