// Which neighbouring texels may share a patch (sample_placement.cpp's joins): a patch spreads one
// exitance over its members, so members facing different ways must not share one. On the
// FZK-Haus, ceiling texels over a wall's top had their samples moved onto a face of the lit room
// beside it, joined the dark room's ceiling texels next to them, and shone the lit room's light
// into the dark room (1.1 lx there by the path tracer, 6.8 lx baked at the defaults, 3.0 since).
#include <gtest/gtest.h>

#include "baker/surface/sampling.h"
#include "baker/transport/patches.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

TEST(PatchJoins, TexelsFacingNinetyDegreesApartNeverShareAPatch) {
  // A floor and the wall standing on its far edge, one mesh whose own lightmap UVs unfold both
  // into one chart, so that texels across the fold are neighbours on the page and see each other.
  Scene scene;
  MeshInstance fold;
  fold.name = "floor and wall, one chart";
  fold.positions = {{0, 0, 0}, {1, 0, 0}, {1, 0, -1}, {0, 0, -1}, {1, 1, -1}, {0, 1, -1}};
  fold.triangles = {0, 1, 2, 0, 2, 3, 3, 2, 4, 3, 4, 5};  // the floor faces +y, the wall +z
  fold.texcoords = {{}, {{0.1f, 0.1f}, {0.9f, 0.1f}, {0.9f, 0.5f}, {0.1f, 0.5f}, {0.9f, 0.9f}, {0.1f, 0.9f}}};
  fold.material = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  scene.instances.push_back(fold);
  AtlasOptions atlas;
  atlas.texel_density = 20;
  const auto placed = test::placed_elements(scene, atlas);
  const Elements& e = placed->elements;
  PatchOptions whole_chart;
  whole_chart.block_size = 64;  // one block holds the chart: only the joins can part it
  const Patches patches = build_patches(e, placed->surface, whole_chart);
  size_t floor_texels = 0, wall_texels = 0;
  for (size_t p = 0; p < patches.size(); ++p) {
    int facing_up = 0, facing_out = 0;
    for (uint32_t k = patches.first_member[p]; k < patches.first_member[p + 1]; ++k) {
      const Vec3 n = placed->surface.normal[e.triangle[patches.members[k]]];
      facing_up += n.y > 0.9f;
      facing_out += n.z > 0.9f;
    }
    EXPECT_TRUE(facing_up == 0 || facing_out == 0)
        << "patch " << p << " holds " << facing_up << " floor and " << facing_out << " wall texels";
    floor_texels += size_t(facing_up);
    wall_texels += size_t(facing_out);
  }
  EXPECT_GT(floor_texels, 300u);  // 20 x 20 texels each, less the fold's
  EXPECT_GT(wall_texels, 300u);
}

}  // namespace
}  // namespace radbake
