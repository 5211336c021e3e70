#include "baker/finish/directional_lightmaps.h"

#include <algorithm>
#include <cmath>

namespace radbake {

Rgb IrradianceSh::at(Vec3 n) const {
  const Rgb e = c0 + c1x * n.x + c1y * n.y + c1z * n.z;
  return {std::max(0.0f, e.x), std::max(0.0f, e.y), std::max(0.0f, e.z)};
}

IrradianceSh fit_irradiance_sh(Rgb irradiance, const LightDirection& from, Vec3 normal) {
  IrradianceSh sh;
  for (int c = 0; c < 3; ++c) {
    const float e = irradiance[c];
    if (!(e > 0)) continue;
    const Vec3 mean = from.channel(c) / e;
    const float spread = std::min(1.0f, length(mean));
    // 1: one direction; 0: as even as a uniformly lit hemisphere (mean length 2/3) or more so.
    const float directional = std::clamp((spread - 2.0f / 3.0f) * 3.0f, 0.0f, 1.0f);
    Vec3 c1 = normal * (e * 0.5f * (1 - directional));
    if (directional > 0) {
      const Vec3 d = mean / spread;
      // E_perp of the direction, held where it grazes the surface (a hair of light at the horizon
      // must not give a normal map a thousand times the texel's light).
      c1 += d * (e * directional / std::max(dot(normal, d), 0.05f));
    }
    sh.c1x[c] = c1.x;
    sh.c1y[c] = c1.y;
    sh.c1z[c] = c1.z;
    sh.c0[c] = e - dot(c1, normal);  // exactly the irradiance at the surface's normal
  }
  return sh;
}

Vec3 dominant_direction(Rgb irradiance, const LightDirection& from) {
  const Rgb weight{0.2126f, 0.7152f, 0.0722f};  // Rec. 709 luminance
  const float total = dot(irradiance, weight);
  if (!(total > 0)) return {};
  const Vec3 d{dot(from.x, weight), dot(from.y, weight), dot(from.z, weight)};
  const Vec3 mean = d / total;
  return length(mean) > 1 ? normalize(mean) : mean;
}

std::vector<LightDirection> total_light_directions(const std::vector<LightDirection>& direct,
                                                   const std::vector<LightDirection>& gathered_mean,
                                                   const std::vector<Rgb>& indirect) {
  std::vector<LightDirection> total = direct;
  for (size_t i = 0; i < total.size() && i < gathered_mean.size(); ++i) total[i] += gathered_mean[i] * indirect[i];
  return total;
}

std::vector<std::vector<LightmapPage>> directional_pages(Directional mode, const Elements& elements,
                                                         const std::vector<Rgb>& irradiance,
                                                         const std::vector<LightDirection>& from,
                                                         const std::vector<AtlasPage>& pages) {
  const size_t n = elements.size();
  if (mode == Directional::Dominant) {
    std::vector<Rgb> direction(n);
    for (size_t i = 0; i < n; ++i) direction[i] = dominant_direction(irradiance[i], from[i]);
    return {compose_pages(elements, direction, pages)};
  }
  std::vector<Rgb> c0(n), c1x(n), c1y(n), c1z(n);
  for (size_t i = 0; i < n; ++i) {
    const IrradianceSh sh = fit_irradiance_sh(irradiance[i], from[i], elements.normal[i]);
    c0[i] = sh.c0;
    c1x[i] = sh.c1x;
    c1y[i] = sh.c1y;
    c1z[i] = sh.c1z;
  }
  return {compose_pages(elements, c0, pages), compose_pages(elements, c1x, pages), compose_pages(elements, c1y, pages),
          compose_pages(elements, c1z, pages)};
}

}  // namespace radbake
