// Reading a file radbake wrote: what its extras.radbake record says COLOR_0 holds decides whether
// COLOR_0 is read as a base colour; _BAKED_LIGHT is never read; TEXCOORD_1 on a MOZ_lightmap page
// names that page and its size; back-face primitives are left out and their fronts made double-sided.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "baker/surface/surface.h"
#include "base/scene.h"
#include "io/gltf/gltf_loader.h"
#include "io/lightmaps/lightmap_images.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

using json = nlohmann::json;

// The colours each attribute holds, all different, so a read colour says which was read.
constexpr float kColor0 = 0.1f, kSourceColor0 = 0.5f, kBakedLight = 0.9f;

struct Variant {
  json record;                 // extras.radbake, or null for none
  bool back_primitive = true;  // mesh 0 has a back-face primitive for its primitive 0
  json lightmap = {{"index", 0}, {"texCoord", 1}, {"intensity", 100}};  // material 0's MOZ_lightmap
};

template <typename T>
void append(std::vector<uint8_t>& bin, const std::vector<T>& values) {
  const size_t at = bin.size();
  bin.resize(at + values.size() * sizeof(T));
  std::memcpy(bin.data() + at, values.data(), values.size() * sizeof(T));
}

// Two quads: mesh 0 baked before (MOZ_lightmap material, TEXCOORD_1 on a 32 x 16 page, COLOR_0,
// _SOURCE_COLOR_0, _BAKED_LIGHT, and its back-face primitive), mesh 1 with a COLOR_0 of its own
// and a plain material.
std::string write_file(const std::string& name, const Variant& v) {
  const std::string folder = test::fresh_folder("radbake_output_" + name);
  std::vector<uint8_t> bin;
  append(bin, std::vector<float>{0, 0, 0, 1, 0, 0, 1, 0, -1, 0, 0, -1});  // 0: positions, facing +y
  append(bin, std::vector<uint16_t>{0, 1, 2, 0, 2, 3});                  // 48: front
  append(bin, std::vector<uint16_t>{0, 2, 1, 0, 3, 2});                  // 60: back
  auto rgb = [](float c) { return std::vector<float>(12, c); };
  append(bin, rgb(kColor0));                                             // 72
  append(bin, rgb(kSourceColor0));                                       // 120
  append(bin, rgb(kBakedLight));                                         // 168
  append(bin, std::vector<float>{0.1f, 0.1f, 0.4f, 0.1f, 0.4f, 0.4f, 0.1f, 0.4f});  // 216: TEXCOORD_1
  std::ofstream(folder + "/scene.bin", std::ios::binary).write(reinterpret_cast<const char*>(bin.data()), long(bin.size()));
  write_png(folder + "/page.png", 32, 16, std::vector<uint8_t>(32 * 16 * 3, 128));

  json views = json::array(), accessors = json::array();
  auto add = [&](size_t offset, size_t length, size_t count, const char* type, int component, bool bounds = false) {
    views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}});
    json a = {{"bufferView", views.size() - 1}, {"componentType", component}, {"count", count}, {"type", type}};
    if (bounds) a["min"] = {0, 0, -1}, a["max"] = {1, 0, 0};
    accessors.push_back(a);
    return int(accessors.size() - 1);
  };
  const int position = add(0, 48, 4, "VEC3", 5126, true), front = add(48, 12, 6, "SCALAR", 5123),
            back = add(60, 12, 6, "SCALAR", 5123), color0 = add(72, 48, 4, "VEC3", 5126),
            source = add(120, 48, 4, "VEC3", 5126), baked = add(168, 48, 4, "VEC3", 5126),
            uv1 = add(216, 32, 4, "VEC2", 5126);
  const json attributes = {{"POSITION", position}, {"TEXCOORD_0", uv1},        {"TEXCOORD_1", uv1},
                           {"COLOR_0", color0},    {"_SOURCE_COLOR_0", source}, {"_BAKED_LIGHT", baked}};
  json baked_mesh = {{"name", "baked"}};
  baked_mesh["primitives"] = json::array({{{"attributes", attributes}, {"indices", front}, {"material", 0}}});
  if (v.back_primitive)
    baked_mesh["primitives"].push_back({{"attributes", attributes},
                                        {"indices", back},
                                        {"material", 0},
                                        {"extras", {{"radbake", {{"back_faces_of_primitive", 0}}}}}});
  json plain_mesh = {{"name", "plain"}};
  plain_mesh["primitives"] = json::array(
      {{{"attributes", {{"POSITION", position}, {"COLOR_0", color0}}}, {"indices", front}, {"material", 1}}});
  json baked_material = {{"name", "baked (one face)"}};
  baked_material["extensions"]["MOZ_lightmap"] = v.lightmap;
  json doc;
  doc["asset"] = {{"version", "2.0"}};
  doc["scene"] = 0;
  doc["scenes"] = json::array({{{"nodes", {0, 1}}}});
  doc["nodes"] = json::array({{{"name", "baked"}, {"mesh", 0}}, {{"name", "plain"}, {"mesh", 1}, {"translation", {0, 1, 0}}}});
  doc["meshes"] = json::array({baked_mesh, plain_mesh});
  doc["materials"] = json::array({baked_material, {{"name", "plain"}}});
  doc["textures"] = json::array({{{"source", 0}}});
  doc["images"] = json::array({{{"uri", "page.png"}}});
  doc["buffers"] = json::array({{{"uri", "scene.bin"}, {"byteLength", bin.size()}}});
  doc["bufferViews"] = views;
  doc["accessors"] = accessors;
  doc["extensionsUsed"] = json::array({"MOZ_lightmap"});
  if (!v.record.is_null()) doc["extras"]["radbake"] = v.record;
  std::ofstream(folder + "/scene.gltf") << doc.dump(1);
  return folder + "/scene.gltf";
}

const MeshInstance& named(const Scene& s, const std::string& node) {
  for (const MeshInstance& inst : s.instances)
    if (inst.name.rfind(node + " /", 0) == 0) return inst;
  throw std::runtime_error("no instance of node " + node);
}

float first_colour(const MeshInstance& inst) { return inst.colors.empty() ? -1.0f : inst.colors[0].x; }

TEST(RadbakeOutput, ColourAttributesAreReadAsTheRecordSays) {
  const json legacy = {{"generator", "radbake"}, {"color_0_intensity", 2.0}};
  const struct {
    const char* name;
    json record;
    float baked, plain;  // the colour read for each mesh; -1 none
  } cases[] = {
      // Before color_0_holds, radbake always put light in COLOR_0 (and said color_0_intensity).
      {"legacy", legacy, kSourceColor0, kColor0},
      {"light", {{"generator", "radbake"}, {"color_0_holds", "light"}}, kSourceColor0, kColor0},
      {"prelit", {{"generator", "radbake"}, {"color_0_holds", "prelit"}}, kSourceColor0, kColor0},
      {"source", {{"generator", "radbake"}, {"color_0_holds", "source"}, {"color_0_intensity", 2.0}}, kColor0, kColor0},
      // Not radbake's: COLOR_0 is colours, whatever else is there.
      {"other_tool", {{"generator", "elsewhere"}, {"color_0_intensity", 2.0}}, kColor0, kColor0},
      {"no_record", nullptr, kColor0, kColor0},
  };
  for (const auto& c : cases) {
    LoadedScene s = load_gltf(write_file(c.name, {c.record}));
    EXPECT_EQ(first_colour(named(s.scene, "baked")), c.baked) << c.name;
    EXPECT_EQ(first_colour(named(s.scene, "plain")), c.plain) << c.name;
    for (const MeshInstance& inst : s.scene.instances)  // _BAKED_LIGHT is never a colour
      for (Rgb colour : inst.colors) EXPECT_NE(colour.x, kBakedLight) << c.name;
  }
}

TEST(RadbakeOutput, ItsBackFacePrimitivesAreLeftOutAndTheirFrontsAreDoubleSided) {
  LoadedScene s = load_gltf(write_file("backs", {{{"generator", "radbake"}, {"color_0_holds", "source"}}}));
  ASSERT_EQ(s.scene.instances.size(), 2u);  // the back primitive is not geometry
  const MeshInstance& front = named(s.scene, "baked");
  EXPECT_EQ(front.primitive, 0);
  EXPECT_TRUE(material_of(s.scene, front.material).double_sided);
  EXPECT_FALSE(material_of(s.scene, named(s.scene, "plain").material).double_sided);
  // Its layout held the backs too: generated afresh, not kept for the fronts alone.
  EXPECT_EQ(front.lightmap_uvs(), nullptr);
  EXPECT_EQ(front.lightmap_image, -1);

  // In a file radbake did not write, the same primitive is geometry like any other.
  LoadedScene other = load_gltf(write_file("backs_elsewhere", {nullptr}));
  EXPECT_EQ(other.scene.instances.size(), 3u);
}

TEST(RadbakeOutput, TexcoordOneOnALightmapPageNamesThePageAndItsSize) {
  LoadedScene s = load_gltf(write_file("page", {{{"generator", "radbake"}, {"color_0_holds", "source"}}, false}));
  const MeshInstance& baked = named(s.scene, "baked");
  ASSERT_NE(baked.lightmap_uvs(), nullptr);
  EXPECT_EQ(baked.lightmap_image, 0);
  EXPECT_EQ(named(s.scene, "plain").lightmap_image, -1);
  const std::vector<MeshView> views = mesh_views(s.scene);
  EXPECT_EQ(views[0].uv_page, 0);
  EXPECT_EQ(views[0].uv_page_width, 32);
  EXPECT_EQ(views[0].uv_page_height, 16);
  // Kept on a page of that size, not a square one sized by density.
  const Atlas atlas = test::unwrap(s.scene, AtlasOptions{});
  EXPECT_TRUE(atlas.meshes[0].kept_input_uvs);
  EXPECT_EQ(atlas.pages[size_t(atlas.meshes[0].page)].width, 32);
  EXPECT_EQ(atlas.pages[size_t(atlas.meshes[0].page)].height, 16);

  // A MOZ_lightmap the loader cannot follow names no page, and refuses nothing.
  const json unusable[] = {{{"index", 7}, {"texCoord", 1}}, {{"index", -1}, {"texCoord", 1}},
                           {{"index", 0.5}, {"texCoord", 1}}, {{"index", 0}, {"texCoord", 0}}, {{"texCoord", 1}}};
  int k = 0;
  for (const json& lightmap : unusable) {
    Variant v{{{"generator", "radbake"}}, false, lightmap};
    LoadedScene u = load_gltf(write_file("unusable_" + std::to_string(k++), v));
    EXPECT_EQ(named(u.scene, "baked").lightmap_image, -1) << lightmap.dump();
  }
}

}  // namespace
}  // namespace radbake
