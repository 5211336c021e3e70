#include "baker/finish/display.h"

#include "baker/surface/surface.h"

namespace radbake {
namespace {

// Per lightmap texel weights spread evenly over the pre-lit texels it holds.
std::vector<std::vector<float>> at_prelit_detail(const std::vector<std::vector<float>>& seen, const PrelitPages& prelit) {
  const int n = prelit.detail;
  std::vector<std::vector<float>> out(seen.size());
  for (size_t p = 0; p < seen.size() && p < prelit.pages.size(); ++p) {
    if (seen[p].empty()) continue;
    const LightmapPage& page = prelit.pages[p];
    const int lightmap_width = page.width / n;
    out[p].resize(size_t(page.width) * size_t(page.height));
    for (int y = 0; y < page.height; ++y)
      for (int x = 0; x < page.width; ++x)
        out[p][size_t(y) * size_t(page.width) + size_t(x)] =
            seen[p][size_t(y / n) * size_t(lightmap_width) + size_t(x / n)] / float(n * n);
  }
  return out;
}

}  // namespace

DisplayLight display_light(const Scene& scene, const Atlas& atlas, const std::vector<LightmapPage>& pages,
                           const std::vector<std::vector<Rgb>>& vertex_values,
                           const std::vector<std::vector<LightmapPage>>* sh, float emission_scale,
                           bool lightmap_is_irradiance, const Glazing& glazing,
                           const std::vector<std::vector<float>>* seen, const DisplayOptions& options) {
  const Surface surface = build_surface(scene, atlas);
  PrelitOptions prelit;
  prelit.detail = options.mode == DisplayMode::Page ? options.detail : 1;
  prelit.emission_scale = emission_scale;
  prelit.lightmap_is_irradiance = lightmap_is_irradiance;
  prelit.glazing = glazing;
  DisplayLight light;
  light.pages = prelit_pages(scene, surface, pages, prelit);
  // Metered on the flat pages: showing the normal maps' bumps (--directional sh) changes where the
  // light falls, not how much there is, and must not change the exposure.
  const std::vector<std::vector<float>> seen_prelit = seen ? at_prelit_detail(*seen, light.pages) : std::vector<std::vector<float>>{};
  light.exposure = choose_exposure(light.pages.pages, options.exposure, seen ? &seen_prelit : nullptr);
  if (options.mode == DisplayMode::None) return light;
  if (sh) {
    prelit.sh = sh;
    light.pages = prelit_pages(scene, surface, pages, prelit);
  }
  // Refined only for vertex light (the pages carry the shadows otherwise); unrefined, the atlas's meshes.
  RefinementOptions refinement;
  if (options.mode == DisplayMode::Vertex) refinement.max_triangles = options.vertex_refine_triangles;
  light.refined = refine_vertex_light(scene, atlas, pages, vertex_values, refinement);
  return light;
}

}  // namespace radbake
