#include "baker/finish/display.h"

#include "baker/surface/surface.h"

namespace radbake {

DisplayLight display_light(const Scene& scene, const Atlas& atlas, const std::vector<LightmapPage>& pages,
                           const std::vector<std::vector<Rgb>>& vertex_values,
                           const std::vector<std::vector<LightmapPage>>* sh, float emission_scale,
                           bool lightmap_is_irradiance, float glazing_transmittance, const DisplayOptions& options) {
  const Surface surface = build_surface(scene, atlas);
  PrelitOptions prelit;
  prelit.detail = options.mode == DisplayMode::Page ? options.detail : 1;
  prelit.emission_scale = emission_scale;
  prelit.lightmap_is_irradiance = lightmap_is_irradiance;
  prelit.glazing_transmittance = glazing_transmittance;
  DisplayLight light;
  light.pages = prelit_pages(scene, surface, pages, prelit);
  // Metered on the flat pages: showing the normal maps' bumps (--directional sh) changes where the
  // light falls, not how much there is, and must not change the exposure.
  light.exposure = choose_exposure(light.pages.pages, options.exposure);
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
