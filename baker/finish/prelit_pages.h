// Pre-lit pages: what a surface looks like under its baked light, as luminance in cd/m2
// (reflectance x irradiance / pi, plus what it emits), on the lightmap's charts. A viewer that
// knows nothing of lightmaps shows them as an unlit material's base colour.
//
// Glazing shows the light it lets through as well: its diffuse transmittance times the irradiance
// on its other face, over pi, as a pane of frosted glass does (and as three.js's rough transmission
// shows the engine file's). A clear pane reflects almost nothing and would otherwise show black,
// since the sky behind it is no surface. An alpha-blended surface (glTF's BLEND) shows the light
// of the part of it that is there: the display file blends it over what is behind by its alpha.
//
// They may be finer than the lightmap: light varies slowly and is sampled from the lightmap
// bilinearly, while the reflectance is read from the material at every pre-lit texel, so a base
// colour texture keeps its detail up to `detail` times the lightmap's density.
#pragma once

#include <vector>

#include "baker/finish/finish.h"
#include "baker/surface/glazing.h"
#include "baker/surface/surface.h"
#include "base/scene.h"

namespace radbake {

struct PrelitOptions {
  int detail = 0;              // pre-lit texels per lightmap texel along a side: 1, 2 or 4; 0: automatic
  int max_page_size = 4096;    // a pre-lit page side never passes this (automatic detail only)
  float emission_scale = 1;    // as BakeOptions::emission_scale
  Glazing glazing;  // as BakeOptions::glazing
  bool lightmap_is_irradiance = true;  // false: the pages hold radiosity (lm/m2 leaving)
  // --directional sh's pages (c0, c1x, c1y, c1z; directional_lightmaps.h): the irradiance is read
  // for each pre-lit texel's normal, its normal map applied, so the bumps show. Null: the lightmap's.
  const std::vector<std::vector<LightmapPage>>* sh = nullptr;
};

struct PrelitPages {
  std::vector<LightmapPage> pages;  // cd/m2, dilated over the whole page; `valid` marks covered texels
  int detail = 1;
};

// The detail at which base colour textures (and with `normal_maps` normal maps) keep their texels:
// the area-weighted median, over textured triangles, of texture texels per lightmap texel along a
// side, rounded up to 1, 2 or 4, and no larger than keeps pages within `max_page_size`. 1 when
// nothing is textured.
int automatic_prelit_detail(const Scene& scene, const Surface& surface, int max_page_size, bool normal_maps = false);

PrelitPages prelit_pages(const Scene& scene, const Surface& surface, const std::vector<LightmapPage>& lightmap,
                         const PrelitOptions& options);

// The same, per atlas output vertex: what the vertex light (baker/finish/finish.h vertex_values) looks
// like on a surface of reflectance 1, in cd/m2: irradiance / pi, or radiosity / pi.
Rgb prelit_vertex(Rgb vertex_value);

}  // namespace radbake
