// The stand-in chart packer and the TEXCOORD_1 check: every triangle gets its own area of a
// page, no texel is shared between charts, padding is kept, usable input UVs are kept.
#include <gtest/gtest.h>

#include <map>

#include "base/errors.h"
#include "io/gltf/gltf_loader.h"
#include "support/scene_builders.h"
#include "uv/texel_coverage.h"

namespace radbake {
namespace {

struct Layout {
  // Per page, per texel: the chart covering it, -1 for none, -2 for more than one.
  std::vector<std::vector<int64_t>> owner;
  size_t shared = 0;
};

Layout rasterise(const Atlas& atlas) {
  Layout l;
  for (const AtlasPage& p : atlas.pages) l.owner.emplace_back(size_t(p.width) * p.height, -1);
  for (const AtlasMesh& m : atlas.meshes) {
    const AtlasPage& page = atlas.pages[size_t(m.page)];
    for (size_t t = 0; t < m.triangle_chart.size(); ++t) {
      if (m.triangle_chart[t] == UINT32_MAX) continue;
      Vec2 c[3];
      for (int k = 0; k < 3; ++k) {
        Vec2 uv = m.uvs[m.triangles[3 * t + k]];
        c[k] = {uv.x * page.width, uv.y * page.height};
      }
      for_each_covered_texel(c[0], c[1], c[2], page.width, page.height, [&](const TexelPiece& piece) {
        int64_t& o = l.owner[size_t(m.page)][size_t(piece.y) * page.width + piece.x];
        if (o == -1) {
          o = m.triangle_chart[t];
        } else if (o != int64_t(m.triangle_chart[t]) && o != -2) {
          o = -2;
          ++l.shared;
        }
      });
    }
  }
  return l;
}

// Texels of one chart with another chart's texel within `padding` texels (Chebyshev distance).
size_t padding_violations(const Atlas& atlas, const Layout& l, int padding) {
  size_t bad = 0;
  for (size_t p = 0; p < atlas.pages.size(); ++p) {
    const int w = atlas.pages[p].width, h = atlas.pages[p].height;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        int64_t o = l.owner[p][size_t(y) * w + x];
        if (o < 0) continue;
        for (int dy = -padding; dy <= padding; ++dy)
          for (int dx = -padding; dx <= padding; ++dx) {
            int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
            int64_t n = l.owner[p][size_t(ny) * w + nx];
            bad += n >= 0 && n != o;
          }
      }
  }
  return bad;
}

void expect_sound_layout(const Scene& scene, const Atlas& atlas, int padding) {
  ASSERT_EQ(atlas.meshes.size(), scene.instances.size());
  for (size_t i = 0; i < atlas.meshes.size(); ++i) {
    const AtlasMesh& m = atlas.meshes[i];
    const MeshInstance& inst = scene.instances[i];
    ASSERT_EQ(m.triangles.size(), inst.triangles.size());
    for (size_t t = 0; t < inst.triangle_count(); ++t) {
      for (int k = 0; k < 3; ++k)  // the split keeps each corner's source vertex
        EXPECT_EQ(m.source_vertex[m.triangles[3 * t + k]], inst.triangles[3 * t + k]);
      Vec3 p0 = inst.positions[inst.triangles[3 * t]];
      float world = length(cross(inst.positions[inst.triangles[3 * t + 1]] - p0, inst.positions[inst.triangles[3 * t + 2]] - p0));
      Vec2 u0 = m.uvs[m.triangles[3 * t]];
      float uv = std::fabs(cross2(m.uvs[m.triangles[3 * t + 1]] - u0, m.uvs[m.triangles[3 * t + 2]] - u0));
      if (world > 0) {
        EXPECT_GT(uv, 0.0f) << "triangle " << t << " of mesh " << i << " got no lightmap area";
      }
    }
    for (Vec2 uv : m.uvs) {
      EXPECT_GE(uv.x, 0.0f);
      EXPECT_LE(uv.x, 1.0f);
      EXPECT_GE(uv.y, 0.0f);
      EXPECT_LE(uv.y, 1.0f);
    }
  }
  Layout l = rasterise(atlas);
  EXPECT_EQ(l.shared, 0u) << "texels covered by two charts";
  EXPECT_EQ(padding_violations(atlas, l, padding), 0u);
}

TEST(Atlas, CornellBoxChartsNeverShareTexelsAndKeepPadding) {
  LoadedScene s = load_gltf(test::source_path("samples/cornell_box/cornell_box.gltf"));
  Atlas atlas = test::unwrap(s.scene, {0.0f, 256, 2});
  EXPECT_EQ(atlas.pages.size(), 1u);  // auto density fills one page
  expect_sound_layout(s.scene, atlas, 2);
}

TEST(Atlas, AwkwardTrianglesEachGetTheirOwnArea) {
  Scene scene;
  int m = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  MeshInstance odd;
  odd.name = "odd";
  odd.material = m;
  odd.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0},             // ordinary
                   {2, 0, 0}, {3, 0, 0}, {2.5f, 0.001f, 0},      // a 1 mm sliver
                   {4, 0, 0}, {4, 0, 0}, {4, 0, 0},              // zero area
                   {5, 0, 0}, {6, 0, 0}, {5, 1, 0}, {6, 1, 0.5f}};  // two triangles at an angle
  odd.triangles = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 10, 12, 11};
  scene.instances.push_back(odd);
  for (int padding : {0, 2, 4}) {
    Atlas atlas = test::unwrap(scene, {64.0f, 512, padding});
    expect_sound_layout(scene, atlas, padding);
    EXPECT_EQ(atlas.meshes[0].triangle_chart[2], UINT32_MAX);  // the zero-area triangle has no chart
  }
}

// A caller's out-of-range options are bad input (exit status 2 in the CLI), not a bug of ours.
TEST(Atlas, OptionsOutOfTheirRangeAreAnInputError) {
  Scene scene;
  test::add_quad(scene, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, test::add_material(scene, {0.5f, 0.5f, 0.5f}));
  for (const AtlasOptions& bad : {AtlasOptions{64.0f, 8, 2}, AtlasOptions{64.0f, 32768, 2}, AtlasOptions{64.0f, 512, 65},
                                  AtlasOptions{64.0f, 512, -1}, AtlasOptions{-1.0f, 512, 2}})
    EXPECT_THROW(test::unwrap(scene, bad), InputError) << bad.max_page_size << " " << bad.padding << " " << bad.texel_density;
  EXPECT_NO_THROW(test::unwrap(scene, AtlasOptions{64.0f, 512, 2}));
}

TEST(Atlas, TooMuchForOnePageMakesMorePagesNotSmallerTexels) {
  Scene scene;
  int m = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  for (int i = 0; i < 6; ++i) test::add_quad(scene, {float(i) * 3, 0, 0}, {2, 0, 0}, {0, 2, 0}, m);
  Atlas atlas = test::unwrap(scene, {50.0f, 256, 2});  // each 2 m quad is 100 x 100 texels
  EXPECT_GT(atlas.pages.size(), 1u);
  EXPECT_FLOAT_EQ(atlas.texel_density, 50.0f);
  expect_sound_layout(scene, atlas, 2);
  for (const AtlasMesh& mesh : atlas.meshes) {  // texel size stays what was asked for
    const AtlasPage& page = atlas.pages[size_t(mesh.page)];
    float span = 0;
    for (Vec2 uv : mesh.uvs) span = std::max(span, uv.x * page.width);
    float lo = INFINITY;
    for (Vec2 uv : mesh.uvs) lo = std::min(lo, uv.x * page.width);
    EXPECT_NEAR(span - lo, 100.0f, 0.01f);
  }
}

TEST(Atlas, AMeshLargerThanAPageIsScaledDownAndReported) {
  Scene scene;
  test::add_quad(scene, {0, 0, 0}, {10, 0, 0}, {0, 10, 0}, test::add_material(scene, {0.5f, 0.5f, 0.5f}), "huge");
  Atlas atlas = test::unwrap(scene, {100.0f, 256, 2});
  ASSERT_EQ(atlas.warnings.size(), 1u);
  EXPECT_NE(atlas.warnings[0].find("'huge' is too large"), std::string::npos);
  expect_sound_layout(scene, atlas, 2);
}

MeshInstance quad_with_lightmap_uvs(std::vector<Vec2> uvs) {
  MeshInstance inst;
  inst.name = "quad";
  inst.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  inst.triangles = {0, 1, 2, 0, 2, 3};
  inst.texcoords = {{}, uvs};
  return inst;
}

TEST(Atlas, UsableInputLightmapUvsAreKeptAsTheyAre) {
  Scene scene;
  std::vector<Vec2> uvs = {{0.1f, 0.1f}, {0.9f, 0.1f}, {0.9f, 0.9f}, {0.1f, 0.9f}};
  scene.instances.push_back(quad_with_lightmap_uvs(uvs));
  Atlas atlas = test::unwrap(scene, {32.0f, 256, 2});
  ASSERT_TRUE(atlas.meshes[0].kept_input_uvs);
  EXPECT_TRUE(atlas.warnings.empty());
  for (size_t v = 0; v < uvs.size(); ++v) {
    EXPECT_EQ(atlas.meshes[0].uvs[v].x, uvs[v].x);
    EXPECT_EQ(atlas.meshes[0].uvs[v].y, uvs[v].y);
  }
}

TEST(Atlas, OverlappingOrOutOfRangeInputUvsAreRegeneratedWithAWarning) {
  const std::vector<std::vector<Vec2>> bad = {
      {{0.1f, 0.1f}, {0.9f, 0.1f}, {0.9f, 0.9f}, {0.1f, 0.1f}},    // second triangle has no area
      {{0.1f, 0.1f}, {0.9f, 0.1f}, {0.9f, 0.9f}, {0.95f, 0.2f}},  // the triangles fold over each other
      {{0.1f, 0.1f}, {1.9f, 0.1f}, {1.9f, 0.9f}, {0.1f, 0.9f}},    // leaves [0, 1]
  };
  for (const auto& uvs : bad) {
    Scene scene;
    scene.instances.push_back(quad_with_lightmap_uvs(uvs));
    Atlas atlas = test::unwrap(scene, {32.0f, 256, 2});
    EXPECT_FALSE(atlas.meshes[0].kept_input_uvs);
    ASSERT_EQ(atlas.warnings.size(), 1u);
    EXPECT_NE(atlas.warnings[0].find("generating lightmap UVs"), std::string::npos) << atlas.warnings[0];
    expect_sound_layout(scene, atlas, 2);
  }
}

}  // namespace
}  // namespace radbake
