// Pre-lit pages (the display file's light): each face shows the light it reflects, and a glazed
// face also the light its other face lets through, so windows are not black.
#include <gtest/gtest.h>

#include <cmath>

#include "baker/finish/prelit_pages.h"
#include "baker/surface/back_faces.h"
#include "baker/surface/material_sampler.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

constexpr float kPi = 3.14159265358979323846f;
constexpr float kInside = 100, kOutside = 10000;  // lux on the face toward the room, on the face toward the sky

// Two double-sided panes of 1 m, each given a back-face twin: glazing (transmission 1, visible
// transmittance 0.7) and a grey opaque sheet.
struct Panes {
  Scene scene;
  Atlas atlas;
  Surface surface;
  std::vector<LightmapPage> lightmap;
  int glazing = -1, sheet = -1;

  Panes() {
    glazing = test::add_material(scene, {0.9f, 0.9f, 0.9f}, {0, 0, 0}, 1, true);
    scene.materials[size_t(glazing)].transmission = 1;
    scene.materials[size_t(glazing)].visible_transmittance = 0.7f;
    sheet = test::add_material(scene, {0.5f, 0.5f, 0.5f}, {0, 0, 0}, 1, true);
    test::add_quad(scene, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, glazing, "window");  // front faces +Z: the room
    test::add_quad(scene, {2, 0, 0}, {1, 0, 0}, {0, 1, 0}, sheet, "sheet");
    add_back_faces(scene);
    atlas = test::unwrap(scene, {16.0f, 128, 2});
    surface = build_surface(scene, atlas);
    // Each face's own irradiance on every texel it covers, then dilated as the bake's pages are.
    for (const AtlasPage& p : atlas.pages) {
      LightmapPage page;
      page.width = p.width, page.height = p.height;
      page.texels.assign(size_t(p.width) * size_t(p.height), Rgb{});
      page.valid.assign(page.texels.size(), 0);
      lightmap.push_back(page);
    }
    for (uint32_t t = 0; t < surface.triangle_count(); ++t) {
      const float e = surface.back_face[t] ? kOutside : kInside;
      LightmapPage& page = lightmap[surface.page[t]];
      for (float b1 = 0.05f; b1 < 1; b1 += 0.05f)
        for (float b2 = 0.05f; b1 + b2 < 1; b2 += 0.05f) {
          const Vec2 at = surface.lightmap_texel(t, {b1, b2});
          const size_t i = size_t(at.y) * size_t(page.width) + size_t(at.x);
          page.texels[i] = {e, e, e};
          page.valid[i] = 1;
        }
    }
    for (LightmapPage& page : lightmap) dilate_page(page);
  }

  // The pre-lit luminance at the middle of triangle t, cd/m2.
  float shown(const PrelitPages& prelit, uint32_t t) const {
    const Vec2 at = surface.lightmap_texel(t, {1.0f / 3, 1.0f / 3});
    const LightmapPage& page = prelit.pages[surface.page[t]];
    return page.texels[size_t(at.y) * size_t(page.width) + size_t(at.x)].y;
  }
};

TEST(PrelitPages, GlazingShowsTheLightItLetsThroughFromItsOtherFace) {
  const Panes p;
  PrelitOptions options;
  options.detail = 1;
  const PrelitPages prelit = prelit_pages(p.scene, p.surface, p.lightmap, options);
  const MaterialSampler materials(p.scene, p.surface);
  size_t glazed = 0, sheets = 0;
  for (uint32_t t = 0; t < p.surface.triangle_count(); ++t) {
    ASSERT_NE(p.surface.twin[t], UINT32_MAX) << "every face has its twin";
    const float own = p.surface.back_face[t] ? kOutside : kInside, behind = p.surface.back_face[t] ? kInside : kOutside;
    if (p.surface.material[t] == p.glazing) {
      ++glazed;
      // A clear pane passes less of light from everywhere than along its normal (0.7 here).
      const float diffuse = materials.diffuse_transmittance(t, {1.0f / 3, 1.0f / 3});
      EXPECT_GT(diffuse, 0.6f);
      EXPECT_LT(diffuse, 0.7f);
      // Transmission 1: the pane reflects nothing diffusely; all it shows comes through. 0.1%:
      // float rounding of the bilinear read.
      EXPECT_NEAR(p.shown(prelit, t), diffuse * behind / kPi, 1e-3f * behind) << "triangle " << t;
    } else {
      ++sheets;
      EXPECT_NEAR(p.shown(prelit, t), 0.5f * own / kPi, 1e-3f * own) << "an opaque sheet shows only its own light";
    }
  }
  EXPECT_EQ(glazed, 4u);
  EXPECT_EQ(sheets, 4u);
}

}  // namespace
}  // namespace radbake
