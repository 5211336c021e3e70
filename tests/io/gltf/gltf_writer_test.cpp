// Writing the baked glTF: the input kept whole, lightmap UVs, COLOR_0 and MOZ_lightmap added,
// instanced meshes split per node, the input's own TEXCOORD_1 kept, a double-sided face's back
// as a primitive of its own; the output loads back.
#include <cstring>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/gltf/gltf_loader.h"
#include "io/gltf/gltf_source.h"
#include "io/lightmaps/lightmap_images.h"
#include "support/commands.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

json read_json(const std::string& path) {
  std::ifstream in(path);
  return json::parse(in);
}

// The output read as any glTF rather than as radbake's own: without its extras.radbake record the
// loader reads COLOR_0 (the baked light) as colours and a back-face primitive as geometry, where
// baking the output again leaves both out (tests/io/gltf/radbake_output_test.cpp).
LoadedScene load_without_record(const std::string& out) {
  json doc = read_json(out);
  doc.erase("extras");
  const std::string plain = (fs::path(out).parent_path() / "without_record.gltf").string();
  std::ofstream(plain) << doc.dump();
  return load_gltf(plain);
}

TEST(GltfWriter, CornellBoxOutputKeepsTheSceneAndAddsTheBake) {
  std::string folder = test::fresh_folder("writer_cornell");
  std::string input = test::source_path("samples/cornell_box/cornell_box.gltf");
  std::string out = test::bake_file_to_folder(input, folder, {0.0f, 128, 2});
  json in = read_json(input), doc = read_json(out);

  EXPECT_EQ(doc["nodes"].size(), in["nodes"].size());
  EXPECT_EQ(doc["cameras"], in["cameras"]);
  EXPECT_EQ(doc["asset"], in["asset"]);
  for (size_t n = 0; n < in["nodes"].size(); ++n) {  // names, transforms, cameras untouched
    EXPECT_EQ(doc["nodes"][n].value("name", ""), in["nodes"][n].value("name", ""));
    EXPECT_EQ(doc["nodes"][n].value("rotation", json()), in["nodes"][n].value("rotation", json()));
  }
  const json& used = doc["extensionsUsed"];
  EXPECT_NE(std::find(used.begin(), used.end(), "MOZ_lightmap"), used.end());
  EXPECT_NE(std::find(used.begin(), used.end(), "KHR_materials_emissive_strength"), used.end());
  EXPECT_FALSE(doc.contains("extensionsRequired"));  // MOZ_lightmap only in extensionsUsed

  for (const json& mesh : doc["meshes"])
    for (const json& prim : mesh["primitives"]) {
      ASSERT_TRUE(prim["attributes"].contains("TEXCOORD_1")) << mesh["name"];
      // The baked light is application data; COLOR_0, a base colour multiplier, is the input's (none here).
      ASSERT_TRUE(prim["attributes"].contains("_BAKED_LIGHT")) << mesh["name"];
      EXPECT_FALSE(prim["attributes"].contains("COLOR_0")) << mesh["name"];
      const json& material = doc["materials"][prim["material"].get<size_t>()];
      const json& lightmap = material["extensions"]["MOZ_lightmap"];
      EXPECT_EQ(lightmap["texCoord"], 1);
      EXPECT_GT(lightmap["intensity"].get<double>(), 0);
      const json& image = doc["images"][doc["textures"][lightmap["index"].get<size_t>()]["source"].get<size_t>()];
      EXPECT_TRUE(fs::exists(fs::path(folder) / image["uri"].get<std::string>()));
    }
  EXPECT_EQ(doc["extras"]["radbake"]["quantity"], "irradiance");
  EXPECT_EQ(doc["extras"]["radbake"]["unit"], "lx");
  for (const json& page : doc["extras"]["radbake"]["pages"]) {
    EXPECT_TRUE(fs::exists(fs::path(folder) / page["exr"].get<std::string>()));
    LightmapPage exr = read_lightmap_exr((fs::path(folder) / page["exr"].get<std::string>()).string());
    EXPECT_GT(exr.width, 0);
  }

  // It loads back: same instances, each with lightmap UVs, and no baked light read as base colour
  // even without radbake's record.
  LoadedScene back = load_without_record(out);
  LoadedScene original = load_gltf(input);
  ASSERT_EQ(back.scene.instances.size(), original.scene.instances.size());
  for (const MeshInstance& inst : back.scene.instances) {
    ASSERT_NE(inst.lightmap_uvs(), nullptr) << inst.name;
    EXPECT_TRUE(inst.colors.empty()) << inst.name;
  }
  EXPECT_EQ(back.scene.lights.size(), original.scene.lights.size());
}

// Mean of a float VEC3 attribute of the first primitive of `mesh`, read through tinygltf.
double mean_attribute(const LoadedScene& loaded, int mesh, const std::string& attribute) {
  const tinygltf::Model& model = loaded.source->model;
  size_t element_size;
  std::vector<uint8_t> bytes =
      accessor_bytes(model, model.meshes[size_t(mesh)].primitives[0].attributes.at(attribute), &element_size);
  std::vector<float> values(bytes.size() / 4);
  std::memcpy(values.data(), bytes.data(), values.size() * 4);
  double sum = 0;
  for (float v : values) sum += v;
  return sum / double(values.size());
}

TEST(GltfWriter, AnInstancedMeshGetsACopyAndALightingPerNode) {
  std::string folder = test::fresh_folder("writer_instanced");
  std::string out = test::bake_file_to_folder(test::source_path("tests/fixtures/instanced_mesh.gltf"), folder,
                                              {0.0f, 256, 2});
  json doc = read_json(out);
  int near_mesh = -1, corner_mesh = -1;
  for (const json& node : doc["nodes"]) {
    if (node.value("name", "") == "block_near_lamp") near_mesh = node["mesh"];
    if (node.value("name", "") == "block_in_corner") corner_mesh = node["mesh"];
  }
  ASSERT_GE(near_mesh, 0);
  ASSERT_GE(corner_mesh, 0);
  EXPECT_NE(near_mesh, corner_mesh);
  const json& a = doc["meshes"][size_t(near_mesh)]["primitives"][0]["attributes"];
  const json& b = doc["meshes"][size_t(corner_mesh)]["primitives"][0]["attributes"];
  EXPECT_NE(a["TEXCOORD_1"], b["TEXCOORD_1"]);  // their own places in the atlas
  EXPECT_NE(a["_BAKED_LIGHT"], b["_BAKED_LIGHT"]);

  LoadedScene back = load_gltf(out);
  // the one by the lamp is brighter
  EXPECT_GT(mean_attribute(back, near_mesh, "_BAKED_LIGHT"), 2 * mean_attribute(back, corner_mesh, "_BAKED_LIGHT"));
}

TEST(GltfWriter, TheInputsOwnLightmapUvsAreKept) {
  std::string input = test::source_path("tests/fixtures/own_lightmap_uvs.gltf");
  std::string out = test::bake_file_to_folder(input, test::fresh_folder("writer_own_uvs"), {32.0f, 256, 2});
  LoadedScene original = load_gltf(input), back = load_gltf(out);
  ASSERT_EQ(back.scene.instances.size(), original.scene.instances.size());
  for (size_t i = 0; i < original.scene.instances.size(); ++i) {
    const std::vector<Vec2>& a = *original.scene.instances[i].lightmap_uvs();
    const std::vector<Vec2>& b = *back.scene.instances[i].lightmap_uvs();
    ASSERT_EQ(a.size(), b.size());
    for (size_t v = 0; v < a.size(); ++v) {
      EXPECT_EQ(a[v].x, b[v].x);
      EXPECT_EQ(a[v].y, b[v].y);
    }
  }
}

// A one-face double-sided ceiling (normal up) under the sun with a lamp below: its back is baked
// apart, and written as a second primitive of the ceiling's mesh with lightmap UVs into its own
// charts, flipped normals, reversed winding and a single-sided copy of the material, as is the
// front's, so a viewer shows each face its own light. The Khronos validator finds no fault.
TEST(GltfWriter, DoubleSidedFaceGetsABackPrimitiveWithItsOwnLightmapUvs) {
  std::string folder = test::fresh_folder("writer_one_face_ceiling");
  std::string input = test::source_path("tests/fixtures/one_face_ceiling.gltf");
  std::string out = test::bake_file_to_folder(input, folder, {16, 128, 2});
  json in = read_json(input), doc = read_json(out);
  size_t ceiling_node = 0;
  while (in["nodes"][ceiling_node].value("name", "") != "ceiling") ++ceiling_node;
  const json& mesh = doc["meshes"][doc["nodes"][ceiling_node]["mesh"].get<size_t>()];
  ASSERT_EQ(mesh["primitives"].size(), 2u);
  const json &front = mesh["primitives"][0], &back = mesh["primitives"][1];
  EXPECT_EQ(back["extras"]["radbake"]["back_faces_of_primitive"], 0);
  for (const json* prim : {&front, &back}) {
    const json& material = doc["materials"][(*prim)["material"].get<size_t>()];
    EXPECT_FALSE(material.value("doubleSided", false)) << material["name"];
    EXPECT_TRUE(material["extensions"].contains("MOZ_lightmap"));
  }
  // The back's UVs are its own: another accessor, over a rectangle apart from the front's.
  const json &uv_front = doc["accessors"][front["attributes"]["TEXCOORD_1"].get<size_t>()],
             &uv_back = doc["accessors"][back["attributes"]["TEXCOORD_1"].get<size_t>()];
  EXPECT_NE(front["attributes"]["TEXCOORD_1"], back["attributes"]["TEXCOORD_1"]);
  bool apart = false;
  for (int a = 0; a < 2; ++a)
    apart |= uv_back["min"][a].get<double>() >= uv_front["max"][a].get<double>() ||
             uv_front["min"][a].get<double>() >= uv_back["max"][a].get<double>();
  EXPECT_TRUE(apart) << uv_front << uv_back;
  // Every other mesh, single-sided, keeps one primitive.
  for (size_t n = 0; n < doc["nodes"].size(); ++n) {
    if (n == ceiling_node || !doc["nodes"][n].contains("mesh")) continue;
    EXPECT_EQ(doc["meshes"][doc["nodes"][n]["mesh"].get<size_t>()]["primitives"].size(), 1u);
  }

  // Loaded back: the back primitive faces down (its winding and its normals), the front up.
  LoadedScene baked = load_without_record(out);
  std::vector<const MeshInstance*> ceiling;
  for (const MeshInstance& inst : baked.scene.instances)
    if (inst.node == int(ceiling_node)) ceiling.push_back(&inst);
  ASSERT_EQ(ceiling.size(), 2u);
  for (const MeshInstance* inst : ceiling) {
    const float up = inst->primitive == 0 ? 1.0f : -1.0f;
    const Vec3* p = inst->positions.data();
    const uint32_t* t = inst->triangles.data();
    EXPECT_GT(up * cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]).y, 0) << inst->primitive;
    for (Vec3 n : inst->normals) EXPECT_EQ(n.y, up) << inst->primitive;
  }

  ASSERT_TRUE(fs::exists(test::source_path("tests/tools/node_modules/gltf-validator")))
      << "the validator is not installed: run ./dev test (npm ci in tests/tools)";
  test::Outcome v = test::run("node " + test::source_path("tests/tools/validate_gltf.mjs") + " " + out);
  EXPECT_EQ(v.status, 0) << v.out << v.err;
  json summary = json::parse(v.out);
  EXPECT_EQ(summary["errors"], 0) << v.out;
  EXPECT_EQ(summary["warnings"], 0) << v.out;
}

TEST(GltfWriter, ExtrasAndUnknownExtensionsSurvive) {
  // The external-buffer room, decorated with what radbake does not model.
  std::string folder = test::fresh_folder("writer_extras_in");
  json doc = read_json(test::source_path("tests/fixtures/external_buffer.gltf"));
  fs::copy_file(test::source_path("tests/fixtures/external_buffer.bin"), fs::path(folder) / "external_buffer.bin");
  doc["extras"] = {{"project", "classroom"}, {"revision", 7}};
  doc["nodes"][0]["extras"] = {{"tag", "north wall"}};
  doc["materials"][0]["extensions"]["EXT_example_custom"] = {{"roughnessBoost", 0.5}};
  doc["extensionsUsed"].push_back("EXT_example_custom");
  std::string input = (fs::path(folder) / "decorated.gltf").string();
  std::ofstream(input) << doc.dump();

  json out = read_json(test::bake_file_to_folder(input, test::fresh_folder("writer_extras_out"), {0.0f, 128, 2}));
  EXPECT_EQ(out["extras"]["project"], "classroom");
  EXPECT_EQ(out["extras"]["revision"], 7);
  EXPECT_TRUE(out["extras"].contains("radbake"));
  EXPECT_EQ(out["nodes"][0]["extras"]["tag"], "north wall");
  EXPECT_EQ(out["materials"][0]["extensions"]["EXT_example_custom"]["roughnessBoost"], 0.5);
  const json& used = out["extensionsUsed"];
  EXPECT_NE(std::find(used.begin(), used.end(), "EXT_example_custom"), used.end());
  // The lightmap materials are copies, so the custom extension is on those too.
  size_t with_custom = 0;
  for (const json& m : out["materials"]) with_custom += m.contains("extensions") && m["extensions"].contains("EXT_example_custom");
  EXPECT_GE(with_custom, 2u);
}

}  // namespace
}  // namespace radbake
