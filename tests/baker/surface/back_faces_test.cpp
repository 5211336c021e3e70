// Which double-sided triangles get a back-face twin (baker/surface/back_faces.h): those whose back can
// receive light. Open surfaces always; closed shells only with a light on the side their backs
// face; single-sided materials never.
#include <gtest/gtest.h>

#include "baker/surface/back_faces.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

// A cube of side `size` as one mesh (one node), twelve triangles, wound outward unless `inward`.
void add_cube(Scene& scene, Vec3 lo, bool inward, int material, float size = 1) {
  std::vector<Vec3> p;
  for (int k = 0; k < 8; ++k) p.push_back(lo + Vec3{float(k & 1), float((k >> 1) & 1), float((k >> 2) & 1)} * size);
  // Each face counter-clockwise seen from outside.
  const uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::vector<uint32_t> triangles;
  for (const auto& q : quads) {
    uint32_t t[6] = {q[0], q[1], q[2], q[0], q[2], q[3]};
    if (inward) std::swap(t[1], t[2]), std::swap(t[4], t[5]);
    triangles.insert(triangles.end(), t, t + 6);
  }
  test::add_mesh(scene, p, triangles, material, "cube");
}

Light point_light(Vec3 at) {
  Light l;
  l.position = at;
  return l;
}

TEST(BackFaces, OpenQuadGetsAReversedTwinWithItsOwnLightmapUvs) {
  Scene scene;
  const int card = test::add_material(scene, {0.5f, 0.5f, 0.5f}, {0, 0, 0}, 1, true);
  test::add_quad(scene, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, card, "card");
  scene.instances[0].texcoords = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  scene.lights.push_back(point_light({0, 0, -5}));
  const BackFaceCount count = add_back_faces(scene);
  EXPECT_EQ(count.double_sided_triangles, 2u);
  EXPECT_EQ(count.twins, 2u);
  ASSERT_EQ(scene.instances.size(), 2u);
  const MeshInstance &front = scene.instances[0], &back = scene.instances[1];
  EXPECT_EQ(back.back_of, 0);
  EXPECT_EQ(back.front_triangle, (std::vector<uint32_t>{0, 1}));
  EXPECT_EQ(back.triangles, (std::vector<uint32_t>{0, 2, 1, 0, 3, 2}));  // same corners, reversed
  EXPECT_EQ(back.node, front.node);
  EXPECT_EQ(back.primitive, front.primitive);
  EXPECT_EQ(back.material, card);
  for (size_t v = 0; v < back.normals.size(); ++v) EXPECT_EQ(back.normals[v].z, -front.normals[v].z);
  EXPECT_EQ(back.lightmap_uvs(), nullptr);  // the back's charts are generated
  ASSERT_EQ(back.texcoords[0].size(), 4u);  // textures read the same
  for (size_t v = 0; v < 4; ++v) EXPECT_EQ(back.texcoords[0][v].x, front.texcoords[0][v].x);
}

TEST(BackFaces, SingleSidedMaterialsGetNone) {
  Scene scene;
  const int grey = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  test::add_quad(scene, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, grey);
  scene.lights.push_back(point_light({0, 0, 5}));
  EXPECT_EQ(add_back_faces(scene).twins, 0u);
  EXPECT_EQ(scene.instances.size(), 1u);
}

// A closed shell divides space: its backs get light only from a source on their side.
TEST(BackFaces, ClosedShellGetsTwinsOnlyWithALightBehindItsBacks) {
  struct Case {
    const char* what;
    bool inward;
    Light light;
    size_t twins;
  };
  Light sun;
  sun.type = LightType::Directional;
  const Case cases[] = {
      {"block, lamp outside: the inside is dark", false, point_light({3, 3, 3}), 0},
      {"block, sun outside", false, sun, 0},
      {"box room wound outward, lamp inside", false, point_light({0.5f, 0.5f, 0.5f}), 12},
      {"room wound inward, lamp inside: its backs face out", true, point_light({0.5f, 0.5f, 0.5f}), 0},
      {"room wound inward, sun outside lights its backs", true, sun, 12},
  };
  for (const Case& c : cases) {
    Scene scene;
    const int white = test::add_material(scene, {0.8f, 0.8f, 0.8f}, {0, 0, 0}, 1, true);
    add_cube(scene, {0, 0, 0}, c.inward, white);
    scene.lights.push_back(c.light);
    EXPECT_EQ(add_back_faces(scene).twins, c.twins) << c.what;
  }
}

TEST(BackFaces, AnEmitterInsideAClosedShellLightsItsBacksButItsOwnGlowDoesNot) {
  Scene scene;
  const int white = test::add_material(scene, {0.8f, 0.8f, 0.8f}, {0, 0, 0}, 1, true);
  const int glow = test::add_material(scene, {0, 0, 0}, {1, 1, 1}, 100, true);
  add_cube(scene, {0, 0, 0}, false, glow);  // a glowing closed lamp: nobody sees its inside
  scene.lights.push_back(point_light({5, 5, 5}));
  EXPECT_EQ(add_back_faces(scene).twins, 0u);
  test::add_quad(scene, {-1, -1, -1}, {3, 0, 0}, {0, 3, 0}, white, "an open card");
  add_cube(scene, {-2, -2, -2}, false, white, 5);  // a box room wound outward, the lamp inside
  const BackFaceCount count = add_back_faces(scene);
  // The glowing cube (12, its own glow does not count), the card (2, open) and the box around
  // the glowing cube (12, whose backs face the glow).
  EXPECT_EQ(count.double_sided_triangles, 26u);
  EXPECT_EQ(count.twins, 14u);
}

TEST(BackFaces, ClosedShellAcrossPrimitivesOfOneNodeIsClosed) {
  // Blender splits an object by material into primitives of one mesh: the shell is the node's.
  Scene scene;
  const int a = test::add_material(scene, {0.8f, 0.8f, 0.8f}, {0, 0, 0}, 1, true);
  const int b = test::add_material(scene, {0.4f, 0.4f, 0.4f}, {0, 0, 0}, 1, true);
  add_cube(scene, {0, 0, 0}, false, a);
  MeshInstance& whole = scene.instances[0];
  MeshInstance top = whole;
  top.primitive = 1;
  top.material = b;
  top.triangles.assign(whole.triangles.end() - 6, whole.triangles.end());
  whole.triangles.resize(whole.triangles.size() - 6);
  scene.instances.push_back(top);
  scene.lights.push_back(point_light({3, 3, 3}));
  EXPECT_EQ(add_back_faces(scene).twins, 0u);
}

}  // namespace
}  // namespace radbake
