// Page sizes: generated pages are powers of two on each side by default, within the largest power
// of two not above --max-page-size, filled by the automatic density rather than padded after it;
// any_page_size gives the tight pages; a kept TEXCOORD_1 keeps its own page size, and meshes the
// file lays out on one page share it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "io/gltf/gltf_loader.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

bool power_of_two(int v) { return v > 0 && (v & (v - 1)) == 0; }

int smallest_power_of_two_at_least(int v) {
  int p = 1;
  while (p < v) p *= 2;
  return p;
}

Scene sample(const std::string& name) {
  return load_gltf(test::source_path("samples/" + name + "/" + name + ".gltf")).scene;
}

AtlasOptions options(float density, int max_page_size, bool any_page_size = false) {
  AtlasOptions o;
  o.texel_density = density;
  o.max_page_size = max_page_size;
  o.any_page_size = any_page_size;
  o.automatic_texels = SIZE_MAX;  // an automatic density fills the page: what these tests are about
  return o;
}

// Every corner of every generated chart, in texels of its page.
std::vector<Vec2> texel_corners(const Atlas& atlas) {
  std::vector<Vec2> out;
  for (const AtlasMesh& m : atlas.meshes) {
    const AtlasPage& page = atlas.pages[size_t(m.page)];
    for (Vec2 uv : m.uvs) out.push_back({uv.x * float(page.width), uv.y * float(page.height)});
  }
  return out;
}

TEST(PageSize, SamplesGetPowerOfTwoPagesWithThePaddingKept) {
  for (const char* name : {"cornell_box", "ferren", "study_room"}) {
    const Scene scene = sample(name);
    // 300 is not a power of two: pages stay within 256.
    for (int max_page_size : {512, 300}) {
      const Atlas atlas = test::unwrap(scene, options(0, max_page_size));
      const int limit = max_page_size == 512 ? 512 : 256;
      ASSERT_EQ(atlas.pages.size(), 1u) << name;
      const AtlasPage& page = atlas.pages[0];
      EXPECT_TRUE(power_of_two(page.width) && power_of_two(page.height)) << name << " " << page.width << "x" << page.height;
      EXPECT_LE(page.width, limit) << name;
      EXPECT_LE(page.height, limit) << name;
      EXPECT_EQ(atlas.stats.padding_violations, 0u) << name;
      EXPECT_EQ(atlas.stats.overlapping_texels, 0u) << name;
      // The density was chosen for the power-of-two page, not for a smaller one then padded
      // (which could leave up to three quarters of it empty). Measured 70% (Cornell box), 87%
      // (ferren), 84% (study room); 60% leaves room for packing changes.
      EXPECT_GT(atlas.stats.utilisation, 0.6) << name;
    }
  }
}

TEST(PageSize, TheDefaultBudgetGetsTheSmallestPowerOfTwoPageThatHoldsItFilled) {
  // The defaults (50,000 texels, pages up to 1024) once gave the Cornell box and the classroom one
  // 1024 x 128 page, 39% and 40% used. Now: the smallest square or 2:1 page that holds the budget
  // to a factor of sqrt(2), filled up to twice it. So (a) the page is square or 2:1, (b) the next
  // smaller such page does not hold the budget (what the same unwrap, capped at it, gets is under
  // 1/sqrt(2) of it), (c) the scene gets between 1/sqrt(2) and 2 times the budget, and (d) the page
  // is well used.
  for (const char* name : {"cornell_box", "classroom", "study_room"}) {
    const Scene scene = sample(name);
    AtlasOptions defaults;
    const Atlas atlas = test::unwrap(scene, defaults);
    ASSERT_EQ(atlas.pages.size(), 1u) << name;
    const AtlasPage page = atlas.pages[0];
    EXPECT_TRUE(page.width == page.height || page.width == 2 * page.height) << name << " " << page.width << "x" << page.height;
    // The budget counts texels as the surface area over the texel's area.
    auto budget_share = [&](const Atlas& a) {
      return a.surface_area * double(a.texel_density) * a.texel_density / double(defaults.automatic_texels);
    };
    const double step = 1 + 1e-3;  // the density search's
    EXPECT_GE(budget_share(atlas), 1 / (std::sqrt(2.0) * step)) << name;
    EXPECT_LE(budget_share(atlas), 2 * step) << name;
    // Measured 69.3% (Cornell box), 81.9% (classroom), 87.4% (study room), each on 256 x 256. 65%
    // leaves room for packing changes; 70% of every corpus scene is the aim, not yet reached.
    EXPECT_GE(atlas.stats.utilisation, 0.65) << name;
    // A smaller page: for a 2:1 page the square of its height, the next smaller shape; for a
    // square one the square of half its side (the 2:1 page between cannot be asked for alone).
    AtlasOptions smaller = defaults;
    smaller.max_page_size = page.width == page.height ? page.width / 2 : page.height;
    const Atlas capped = test::unwrap(scene, smaller);
    EXPECT_LT(budget_share(capped), 1 / std::sqrt(2.0)) << name;
  }
}

TEST(PageSize, PowerOfTwoPagesOnlyAddEmptyTexelsToTheTightOnes) {
  // Same packing page (512), so the same charts land on the same texels; only the page grows and
  // the UVs are divided by its new size. 1e-3 texel bounds float rounding of uv * side. At 60
  // texels/m the Cornell box's charts take a strip of the page (356 x 36 texels when written).
  const Scene scene = sample("cornell_box");
  const Atlas tight = test::unwrap(scene, options(60, 512, true));
  const Atlas pow2 = test::unwrap(scene, options(60, 512));
  ASSERT_EQ(tight.pages.size(), 1u);
  ASSERT_EQ(pow2.pages.size(), 1u);
  EXPECT_FALSE(power_of_two(tight.pages[0].width) && power_of_two(tight.pages[0].height))
      << "the tight page happens to be a power of two; the test needs a sample where it is not";
  EXPECT_EQ(tight.pages[0].width % 4, 0);
  EXPECT_EQ(tight.pages[0].height % 4, 0);
  EXPECT_EQ(pow2.pages[0].width, smallest_power_of_two_at_least(tight.pages[0].width));
  EXPECT_EQ(pow2.pages[0].height, smallest_power_of_two_at_least(tight.pages[0].height));
  EXPECT_FLOAT_EQ(tight.texel_density, pow2.texel_density);
  const std::vector<Vec2> a = texel_corners(tight), b = texel_corners(pow2);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR(a[i].x, b[i].x, 1e-3f) << "corner " << i;
    EXPECT_NEAR(a[i].y, b[i].y, 1e-3f) << "corner " << i;
  }
  EXPECT_EQ(pow2.stats.covered_texels, tight.stats.covered_texels);
  EXPECT_EQ(pow2.stats.padding_violations, 0u);
}

TEST(PageSize, EveryPageOfAManyPageAtlasIsAPowerOfTwo) {
  // Nine 100 x 100-texel quads on pages of 256, four to a page: the third page holds one quad and
  // gets a power-of-two page only as large as that quad needs.
  Scene scene;
  int m = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  for (int i = 0; i < 9; ++i) test::add_quad(scene, {float(i) * 3, 0, 0}, {2, 0, 0}, {0, 2, 0}, m);
  const Atlas atlas = test::unwrap(scene, options(50, 256));
  ASSERT_GT(atlas.pages.size(), 1u);
  EXPECT_FLOAT_EQ(atlas.texel_density, 50.0f);
  bool smaller = false;
  for (const AtlasPage& p : atlas.pages) {
    EXPECT_TRUE(power_of_two(p.width) && power_of_two(p.height)) << p.width << "x" << p.height;
    EXPECT_LE(p.width, 256);
    EXPECT_LE(p.height, 256);
    smaller |= p.width * p.height < 256 * 256;
  }
  EXPECT_TRUE(smaller) << "the last page should be only as large as its charts need";
  EXPECT_EQ(atlas.stats.padding_violations, 0u);
  EXPECT_EQ(atlas.stats.overlapping_texels, 0u);
}

TEST(PageSize, KeptInputUvsKeepTheirOwnPageSize) {
  // A 1 m quad whose UVs span 0.8 x 0.8 at 30 texels/m: a 37.5-texel side rounded up to a multiple
  // of 4 (page_side_for_own_uvs), not to a power of two.
  Scene scene;
  MeshInstance inst;
  inst.name = "quad";
  inst.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  inst.triangles = {0, 1, 2, 0, 2, 3};
  inst.texcoords = {{}, {{0.1f, 0.1f}, {0.9f, 0.1f}, {0.9f, 0.9f}, {0.1f, 0.9f}}};
  scene.instances.push_back(inst);
  const Atlas atlas = test::unwrap(scene, options(30, 256));
  ASSERT_TRUE(atlas.meshes[0].kept_input_uvs);
  EXPECT_EQ(atlas.pages[0].width, 40);
  EXPECT_EQ(atlas.pages[0].height, 40);
}

// Two 1 m quads laid out side by side on one 64 x 32 input page (a re-bake of radbake's output, or
// another baker's): `gap` texels between their charts.
Scene two_quads_on_one_page(float gap) {
  Scene scene;
  for (int q = 0; q < 2; ++q) {
    MeshInstance inst;
    inst.name = "quad " + std::to_string(q);
    const float x = float(q) * 2;
    inst.positions = {{x, 0, 0}, {x + 1, 0, 0}, {x + 1, 1, 0}, {x, 1, 0}};
    inst.triangles = {0, 1, 2, 0, 2, 3};
    const float u0 = (2 + float(q) * (24 + gap)) / 64, u1 = u0 + 24.0f / 64;
    inst.texcoords = {{}, {{u0, 4.0f / 32}, {u1, 4.0f / 32}, {u1, 28.0f / 32}, {u0, 28.0f / 32}}};
    inst.lightmap_image = 0;
    scene.instances.push_back(inst);
  }
  Image page;
  page.width = 64, page.height = 32;
  scene.images.push_back(page);
  return scene;
}

TEST(PageSize, MeshesLaidOutOnOneInputPageKeepSharingItAtItsSize) {
  const Scene scene = two_quads_on_one_page(4);
  const Atlas atlas = test::unwrap(scene, AtlasOptions{});
  ASSERT_EQ(atlas.pages.size(), 1u) << "a page per mesh";
  EXPECT_EQ(atlas.pages[0].width, 64);
  EXPECT_EQ(atlas.pages[0].height, 32);
  for (const AtlasMesh& m : atlas.meshes) {
    EXPECT_TRUE(m.kept_input_uvs);
    EXPECT_EQ(m.page, 0);
  }
  EXPECT_TRUE(atlas.warnings.empty());
}

TEST(PageSize, MeshesThatCannotShareTheirInputPageGetGeneratedUvs) {
  // Charts that overlap on the page, and a page larger than allowed: generated, one page (not a
  // page per mesh, each mostly empty), with a warning.
  const struct {
    float gap;
    int max_page_size;
    const char* says;
  } cases[] = {{-4, 1024, "overlap"}, {4, 32, "larger than 32"}};
  for (const auto& c : cases) {
    const Atlas atlas = test::unwrap(two_quads_on_one_page(c.gap), options(0, c.max_page_size));
    EXPECT_EQ(atlas.pages.size(), 1u) << c.says;
    for (const AtlasMesh& m : atlas.meshes) EXPECT_FALSE(m.kept_input_uvs) << c.says;
    ASSERT_EQ(atlas.warnings.size(), 1u) << c.says;
    EXPECT_NE(atlas.warnings[0].find(c.says), std::string::npos) << atlas.warnings[0];
    EXPECT_NE(atlas.warnings[0].find("generating lightmap UVs"), std::string::npos) << atlas.warnings[0];
  }
}

}  // namespace
}  // namespace radbake
