#include "baker/finish/prelit_pages.h"

#include <algorithm>
#include <cmath>

#include "baker/finish/directional_lightmaps.h"
#include "baker/finish/vertex_refinement.h"
#include "baker/surface/material_sampler.h"

namespace radbake {
namespace {

constexpr float kPi = 3.14159265358979323846f;

// Texture texels per lightmap texel along a side, for one of the triangle's textures.
float texels_per_lightmap_texel(const Scene& scene, const Surface& surface, uint32_t t, const TextureRef& ref) {
  if (!ref.present()) return 0;
  const MeshInstance& inst = scene.instances[surface.instance[t]];
  const size_t set = size_t(ref.tex_coord);
  if (set >= inst.texcoords.size() || inst.texcoords[set].empty()) return 0;
  const Image& image = scene.images[size_t(ref.image)];
  Vec2 uv[3];
  for (int k = 0; k < 3; ++k) {
    const Vec2 p = inst.texcoords[set][surface.corner_vertex[3 * t + k]];
    uv[k] = {p.x * ref.transform.scale.x * float(image.width), p.y * ref.transform.scale.y * float(image.height)};
  }
  const Vec2* lm = &surface.corner_lightmap[3 * t];
  const float lm_area = std::fabs(cross2(lm[1] - lm[0], lm[2] - lm[0]));
  const float uv_area = std::fabs(cross2(uv[1] - uv[0], uv[2] - uv[0]));
  return lm_area > 0 ? std::sqrt(uv_area / lm_area) : 0;
}

// For the triangle's base colour texture, or its normal map where directional light shows it.
float texture_texels_per_lightmap_texel(const Scene& scene, const Surface& surface, uint32_t t, bool normals) {
  const Material& m = material_of(scene, surface.material[t]);
  return std::max(texels_per_lightmap_texel(scene, surface, t, m.base_color_texture),
                  normals ? texels_per_lightmap_texel(scene, surface, t, m.normal_texture) : 0.0f);
}

// Barycentric coordinates (of corners 1 and 2) of point p, in triangle t's plane.
Vec2 barycentric(const Surface& surface, uint32_t t, Vec3 p) {
  const Vec3 a = surface.corners[3 * t], e1 = surface.corners[3 * t + 1] - a, e2 = surface.corners[3 * t + 2] - a;
  const Vec3 d = p - a;
  const float d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2), d1 = dot(d, e1), d2 = dot(d, e2);
  const float det = d11 * d22 - d12 * d12;
  if (!(std::fabs(det) > 0)) return {1.0f / 3, 1.0f / 3};
  return {(d22 * d1 - d12 * d2) / det, (d11 * d2 - d12 * d1) / det};
}

// The irradiance on the other face of a twinned triangle at the point `bary` of this one.
Rgb irradiance_behind(const Surface& surface, const std::vector<LightmapPage>& lightmap, uint32_t t, Vec2 bary) {
  const uint32_t other = surface.twin[t];
  const Vec2 there = barycentric(surface, other, surface.point(t, bary));
  return sample_bilinear(lightmap[surface.page[other]], surface.lightmap_texel(other, there));
}

}  // namespace

int automatic_prelit_detail(const Scene& scene, const Surface& surface, int max_page_size, bool normal_maps) {
  std::vector<std::pair<float, float>> ratio_and_area;
  double total = 0;
  for (uint32_t t = 0; t < surface.triangle_count(); ++t) {
    const float ratio = texture_texels_per_lightmap_texel(scene, surface, t, normal_maps);
    if (ratio <= 0 || !std::isfinite(ratio) || surface.area[t] <= 0) continue;
    ratio_and_area.push_back({ratio, surface.area[t]});
    total += surface.area[t];
  }
  if (ratio_and_area.empty()) return 1;
  std::sort(ratio_and_area.begin(), ratio_and_area.end());
  double seen = 0;
  float median = ratio_and_area.back().first;
  for (const auto& [ratio, area] : ratio_and_area)
    if ((seen += area) >= total / 2) {
      median = ratio;
      break;
    }
  int largest_side = 1;
  for (const AtlasPage& p : surface.pages) largest_side = std::max({largest_side, p.width, p.height});
  int detail = 1;
  while (detail < 4 && float(detail) < median && largest_side * detail * 2 <= max_page_size) detail *= 2;
  return detail;
}

PrelitPages prelit_pages(const Scene& scene, const Surface& surface, const std::vector<LightmapPage>& lightmap,
                         const PrelitOptions& options) {
  PrelitPages out;
  out.detail = options.detail > 0 ? options.detail
                                  : automatic_prelit_detail(scene, surface, options.max_page_size, options.sh != nullptr);
  const int n = out.detail;
  const MaterialSampler materials(scene, surface, options.emission_scale, options.glazing);
  out.pages.resize(lightmap.size());
  for (size_t p = 0; p < lightmap.size(); ++p) {
    out.pages[p].width = lightmap[p].width * n;
    out.pages[p].height = lightmap[p].height * n;
    out.pages[p].texels.assign(size_t(out.pages[p].width) * size_t(out.pages[p].height), Rgb{});
    out.pages[p].valid.assign(out.pages[p].texels.size(), 0);
  }
  const float spacing = 1.0f / float(n);  // lightmap texels between pre-lit texels
  for (uint32_t t = 0; t < surface.triangle_count(); ++t) {
    if (surface.chart[t] == UINT32_MAX) continue;
    LightmapPage& page = out.pages[surface.page[t]];
    const LightmapPage& light = lightmap[surface.page[t]];
    Vec2 c[3];
    for (int k = 0; k < 3; ++k) c[k] = surface.corner_lightmap[3 * t + k] * float(n);
    const float area = cross2(c[1] - c[0], c[2] - c[0]);
    if (area == 0) continue;
    const bool blended = material_of(scene, surface.material[t]).alpha_mode == AlphaMode::Blend;
    const bool glazed = options.lightmap_is_irradiance && surface.twin[t] != UINT32_MAX && surface.material[t] >= 0 &&
                        scene.materials[size_t(surface.material[t])].transmission > 0;
    const int x0 = std::max(0, int(std::floor(std::min({c[0].x, c[1].x, c[2].x}))));
    const int x1 = std::min(page.width - 1, int(std::floor(std::max({c[0].x, c[1].x, c[2].x}))));
    const int y0 = std::max(0, int(std::floor(std::min({c[0].y, c[1].y, c[2].y}))));
    const int y1 = std::min(page.height - 1, int(std::floor(std::max({c[0].y, c[1].y, c[2].y}))));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const Vec2 q{float(x) + 0.5f, float(y) + 0.5f};
        const float b1 = cross2(q - c[0], c[2] - c[0]) / area;
        const float b2 = cross2(c[1] - c[0], q - c[0]) / area;
        const float b0 = 1 - b1 - b2;
        if (b0 < 0 || b1 < 0 || b2 < 0) continue;  // centre outside: dilation fills it from its chart
        const Vec2 bary{b1, b2};
        // Pages are dilated, so every texel read holds light of the nearest chart.
        const Vec2 at = q * (1.0f / float(n));
        Rgb value = sample_bilinear(light, at);
        if (options.sh) {
          const auto& sh = *options.sh;
          const size_t pg = surface.page[t];
          value = IrradianceSh{sample_bilinear(sh[0][pg], at), sample_bilinear(sh[1][pg], at),
                               sample_bilinear(sh[2][pg], at), sample_bilinear(sh[3][pg], at)}
                      .at(materials.mapped_normal(t, bary, spacing));
        }
        const Rgb emitted = materials.emission(t, bary, spacing);
        Rgb reflected = materials.reflectance(t, bary, spacing) * value;
        // An alpha-blended surface's reflectance counts only the share of it that is there; the
        // display file blends it by that share (its alpha), so it shows the light of what is there.
        if (blended) reflected = reflected / std::max(materials.coverage(t, bary, spacing), 1e-3f);
        Rgb seen = options.lightmap_is_irradiance ? reflected + emitted : value;
        if (glazed) seen += irradiance_behind(surface, lightmap, t, bary) * materials.diffuse_transmittance(t, bary);
        const size_t i = size_t(y) * size_t(page.width) + size_t(x);
        page.texels[i] = seen / kPi;
        page.valid[i] = 1;
      }
  }
  for (LightmapPage& page : out.pages) dilate_page(page);
  return out;
}

Rgb prelit_vertex(Rgb vertex_value) { return vertex_value / kPi; }

}  // namespace radbake
