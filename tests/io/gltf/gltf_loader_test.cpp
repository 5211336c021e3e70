// Reading glTF into the plain Scene: every way of drawing triangles, transforms, binary and
// external buffers, materials, textures, lights, and one clear error for each kind of bad file.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <tuple>

#include "baker/pipeline/bake.h"
#include "baker/surface/material_sampler.h"
#include "base/errors.h"
#include "io/gltf/base64.h"
#include "io/gltf/gltf_loader.h"
#include "support/commands.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

std::string fixture(const std::string& name) { return test::source_path("tests/fixtures/" + name); }

double instance_area(const MeshInstance& inst, Vec3* normal_sum) {
  double area = 0;
  *normal_sum = {};
  for (size_t t = 0; t < inst.triangle_count(); ++t) {
    Vec3 p0 = inst.positions[inst.triangles[3 * t]];
    Vec3 n = cross(inst.positions[inst.triangles[3 * t + 1]] - p0, inst.positions[inst.triangles[3 * t + 2]] - p0);
    if (inst.mirrored) n = -n;
    area += 0.5 * length(n);
    *normal_sum += normalize(n);
  }
  return area;
}

TEST(GltfLoader, EveryTriangleTopologyAndIndexWidthGivesTheSameQuad) {
  Scene s = load_gltf(fixture("primitive_kinds.gltf")).scene;
  ASSERT_EQ(s.instances.size(), 7u);  // u8, u16, u32, plain, strip, fan, nested child
  for (const MeshInstance& inst : s.instances) {
    EXPECT_EQ(inst.triangle_count(), 2u) << inst.name;
    Vec3 n;
    double area = instance_area(inst, &n);
    bool nested = inst.name.find("nested_child") != std::string::npos;
    EXPECT_NEAR(area, nested ? 4.0 : 1.0, 1e-6) << inst.name;  // the child is scaled by 2
    // Winding kept: both triangles face +y (strips alternate, fans pivot on vertex 0).
    EXPECT_NEAR(n.y, 2.0, 1e-5) << inst.name;
  }
  EXPECT_EQ(s.summary.skipped_primitives, 1u);
  bool warned = false;
  for (const std::string& w : s.warnings) warned |= w.find("points or lines") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(GltfLoader, NestedTransformsComposeParentMatrixAndChildTrs) {
  Scene s = load_gltf(fixture("primitive_kinds.gltf")).scene;
  const MeshInstance* child = nullptr;
  for (const MeshInstance& inst : s.instances)
    if (inst.name.find("nested_child") != std::string::npos) child = &inst;
  ASSERT_NE(child, nullptr);
  // Child: scale 2 then move +1 in x; parent matrix: move +20 in z. The quad spans x 0..1, z -1..0.
  float lo_x = INFINITY, hi_x = -INFINITY, lo_z = INFINITY, hi_z = -INFINITY;
  for (Vec3 p : child->positions) {
    lo_x = std::min(lo_x, p.x), hi_x = std::max(hi_x, p.x);
    lo_z = std::min(lo_z, p.z), hi_z = std::max(hi_z, p.z);
  }
  EXPECT_FLOAT_EQ(lo_x, 1);
  EXPECT_FLOAT_EQ(hi_x, 3);
  EXPECT_FLOAT_EQ(lo_z, 18);
  EXPECT_FLOAT_EQ(hi_z, 20);
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].type, LightType::Directional);
  EXPECT_FLOAT_EQ(s.lights[0].intensity, 1000);
  EXPECT_NEAR(s.lights[0].direction.y, -1.0f, 1e-6f);  // the node turns -Z to point down
}

// A slanted triangle whose NORMAL is its face normal, under nodes that turn, stretch and mirror
// it: in world space each vertex normal must still be the face normal (normals go by the
// matrix's inverse transpose). The turn is what found the fault: normals went by the inverse, so
// the corpus's teapots, turned from Z-up to Y-up by their root node, had their shading normals
// pointing into the pot, and the path tracer lit their hits from behind (teapots RMSE 11% -> 1.3%).
TEST(GltfLoader, VertexNormalsTurnStretchAndMirrorWithTheirFaces) {
  // Corners (0,0,0) (1,0,-1) (0,1,0): face normal (1,0,1)/sqrt(2), counter-clockwise seen from it.
  const float r = 0.70710678f;
  const float data[] = {0, 0, 0, 1, 0, -1, 0, 1, 0, r, 0, r, r, 0, r, r, 0, r};
  const std::string buffer = to_base64(std::string(reinterpret_cast<const char*>(data), sizeof data));
  const std::string gltf = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1, 2, 3]}],
  "nodes": [{"name": "turned", "mesh": 0, "rotation": [0.5, 0.1, -0.3, 0.8062258]},
            {"name": "z_up_to_y_up", "mesh": 0, "matrix": [0.0254, 0, 0, 0, 0, 0, -0.0254, 0, 0, 0.0254, 0, 0, 0, 0, 0, 1]},
            {"name": "stretched", "mesh": 0, "rotation": [0, 0.3826834, 0, 0.9238795], "scale": [3, 0.5, 1]},
            {"name": "mirrored", "mesh": 0, "scale": [-1, 2, 1], "rotation": [0.2, 0, 0, 0.9797959]}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, -1], "max": [1, 1, 0]},
                {"bufferView": 0, "byteOffset": 36, "componentType": 5126, "count": 3, "type": "VEC3"}],
  "bufferViews": [{"buffer": 0, "byteLength": 72}],
  "buffers": [{"byteLength": 72, "uri": "data:application/octet-stream;base64,)" + buffer + R"("}]})";
  const Scene s = load_gltf(test::write_text_file("turned_normals.gltf", gltf)).scene;
  ASSERT_EQ(s.instances.size(), 4u);
  for (const MeshInstance& inst : s.instances) {
    Vec3 face;
    instance_area(inst, &face);  // the world face normal, on the front side (mirroring flips the winding)
    ASSERT_EQ(inst.normals.size(), 3u) << inst.name;
    // 1e-5: float rounding of a unit vector through one 3x3 product.
    for (Vec3 n : inst.normals) EXPECT_NEAR(dot(normalize(n), face), 1.0f, 1e-5f) << inst.name;
  }
}

TEST(GltfLoader, BinaryAndExternalBufferFilesLoadTheSameScene) {
  Scene glb = load_gltf(fixture("lit_room.glb")).scene;
  Scene ext = load_gltf(fixture("external_buffer.gltf")).scene;
  ASSERT_EQ(glb.instances.size(), ext.instances.size());
  for (size_t i = 0; i < glb.instances.size(); ++i) {
    ASSERT_EQ(glb.instances[i].positions.size(), ext.instances[i].positions.size());
    EXPECT_EQ(std::memcmp(glb.instances[i].positions.data(), ext.instances[i].positions.data(),
                          glb.instances[i].positions.size() * sizeof(Vec3)),
              0);
  }
  EXPECT_EQ(glb.materials.size(), 2u);
  EXPECT_TRUE(glb.materials[1].emits());
  EXPECT_FLOAT_EQ(glb.materials[1].emissive_strength, 2000);
}

// A one-triangle file whose material, texture and light options are all set by hand.
std::string one_triangle_gltf(const std::string& material, const std::string& extra_top_level) {
  // Positions (0,0,0) (1,0,0) (0,0,-1) and UVs (0,0) (1,0) (0,1), little-endian floats.
  const float data[] = {0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 1};
  static const char* b64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const unsigned char* bytes = reinterpret_cast<const unsigned char*>(data);
  std::string enc;
  for (size_t i = 0; i < sizeof data; i += 3) {
    unsigned v = bytes[i] << 16 | (i + 1 < sizeof data ? bytes[i + 1] << 8 : 0) | (i + 2 < sizeof data ? bytes[i + 2] : 0);
    enc += b64[v >> 18 & 63];
    enc += b64[v >> 12 & 63];
    enc += i + 1 < sizeof data ? b64[v >> 6 & 63] : '=';
    enc += i + 2 < sizeof data ? b64[v & 63] : '=';
  }
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1]}],
  "nodes": [{"mesh": 0}, {"translation": [0, 2, 0], "rotation": [-0.7071068, 0, 0, 0.7071068],
             "extensions": {"KHR_lights_punctual": {"light": 0}}}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1, "TEXCOORD_1": 1}, "material": 0}]}],
  "materials": [)" + material + R"(],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, -1], "max": [1, 0, 0]},
                {"bufferView": 0, "byteOffset": 36, "componentType": 5126, "count": 3, "type": "VEC2"}],
  "bufferViews": [{"buffer": 0, "byteLength": 60}],
  "buffers": [{"byteLength": 60, "uri": "data:application/octet-stream;base64,)" + enc + R"("}],
  "extensionsUsed": ["KHR_lights_punctual", "KHR_texture_transform", "KHR_materials_emissive_strength"],
  "extensions": {"KHR_lights_punctual": {"lights": [{"type": "spot", "intensity": 42, "color": [1, 0.5, 0.25],
      "range": 10, "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.4}}]}})" + extra_top_level + "}";
}

TEST(GltfLoader, MaterialTextureTransformEmissionAndSpotLightAreRead) {
  const std::string material = R"({"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.25, 1, 1], "metallicFactor": 0.2,
      "baseColorTexture": {"index": 0, "texCoord": 0, "extensions": {"KHR_texture_transform":
          {"offset": [0.5, 0.25], "rotation": 0.3, "scale": [2, 3], "texCoord": 1}}}},
      "emissiveFactor": [1, 0.5, 0], "doubleSided": true,
      "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 7}}})";
  const std::string textures = R"(, "textures": [{"source": 0, "sampler": 0}],
      "samplers": [{"wrapS": 33071, "wrapT": 33648}],
      "images": [{"uri": "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAIAAACQd1PeAAAADElEQVR4nGP4z8AAAAMBAQDJ/pLvAAAAAElFTkSuQmCC"}])";
  Scene s = load_gltf(test::write_text_file("material.gltf", one_triangle_gltf(material, textures))).scene;
  ASSERT_EQ(s.materials.size(), 1u);
  const Material& m = s.materials[0];
  EXPECT_FLOAT_EQ(m.base_color.y, 0.25f);
  EXPECT_FLOAT_EQ(m.metallic, 0.2f);
  EXPECT_FLOAT_EQ(m.emissive_strength, 7);
  EXPECT_TRUE(m.double_sided);
  ASSERT_TRUE(m.base_color_texture.present());
  EXPECT_EQ(m.base_color_texture.tex_coord, 1);  // the transform's override wins
  EXPECT_FLOAT_EQ(m.base_color_texture.transform.offset.x, 0.5f);
  EXPECT_FLOAT_EQ(m.base_color_texture.transform.rotation, 0.3f);
  EXPECT_FLOAT_EQ(m.base_color_texture.transform.scale.y, 3);
  EXPECT_EQ(m.base_color_texture.wrap_s, Wrap::ClampToEdge);
  EXPECT_EQ(m.base_color_texture.wrap_t, Wrap::MirroredRepeat);
  ASSERT_EQ(s.images.size(), 1u);
  EXPECT_EQ(s.images[0].width, 1);
  ASSERT_EQ(s.lights.size(), 1u);
  const Light& spot = s.lights[0];
  EXPECT_EQ(spot.type, LightType::Spot);
  EXPECT_FLOAT_EQ(spot.intensity, 42);
  EXPECT_FLOAT_EQ(spot.color.z, 0.25f);
  EXPECT_FLOAT_EQ(spot.range, 10);
  EXPECT_FLOAT_EQ(spot.outer_cone_angle, 0.4f);
  EXPECT_FLOAT_EQ(spot.position.y, 2);
  EXPECT_NEAR(spot.direction.y, -1, 1e-6);
}

TEST(GltfLoader, MaterialFeaturesDiffuseRadiosityLeavesOutAreNamed) {
  const std::string material = R"({"alphaMode": "BLEND", "extensions": {
      "KHR_materials_transmission": {"transmissionFactor": 0.9, "transmissionTexture": {"index": 0}},
      "KHR_materials_volume": {"thicknessFactor": 0.1},
      "KHR_materials_specular": {"specularFactor": 0.5}, "KHR_materials_clearcoat": {"clearcoatFactor": 0}}})";
  const std::string one_texture = R"(, "textures": [{"source": 0}],
      "images": [{"uri": "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAIAAACQd1PeAAAADElEQVR4nGP4z8AAAAMBAQDJ/pLvAAAAAElFTkSuQmCC"}])";
  Scene s = load_gltf(test::write_text_file("glass.gltf", one_triangle_gltf(material, one_texture))).scene;
  ASSERT_EQ(s.materials.size(), 1u);
  // A clearcoat factor of zero switches the clearcoat off: nothing to warn about. Transmission's
  // factor and BLEND are simulated (baker/surface/material_sampler.h); its texture is not read.
  EXPECT_EQ(s.materials[0].unsimulated,
            (std::vector<std::string>{"the transmission texture (KHR_materials_transmission; its factor is read)",
                                      "volume (KHR_materials_volume)", "specular (KHR_materials_specular)"}));
}

TEST(GltfLoader, GlazingAndCutOutsAreRead) {
  Scene glass = load_gltf(test::write_text_file("glazing.gltf", one_triangle_gltf(R"({"extensions": {
      "KHR_materials_transmission": {"transmissionFactor": 0.9}, "KHR_materials_ior": {"ior": 1.6}},
      "extras": {"visible_transmittance": 0.72}})", ""))).scene;
  EXPECT_FLOAT_EQ(glass.materials[0].transmission, 0.9f);
  EXPECT_FLOAT_EQ(glass.materials[0].ior, 1.6f);
  EXPECT_FLOAT_EQ(glass.materials[0].visible_transmittance, 0.72f);
  EXPECT_EQ(glass.materials[0].alpha_mode, AlphaMode::Opaque);
  Scene leaves = load_gltf(test::write_text_file("leaves.gltf", one_triangle_gltf(R"({"alphaMode": "MASK", "alphaCutoff": 0.3})", ""))).scene;
  EXPECT_EQ(leaves.materials[0].alpha_mode, AlphaMode::Mask);
  EXPECT_FLOAT_EQ(leaves.materials[0].alpha_cutoff, 0.3f);
  EXPECT_FLOAT_EQ(leaves.materials[0].transmission, 0);
  EXPECT_LT(leaves.materials[0].visible_transmittance, 0);
  try {
    load_gltf(test::write_text_file("bad_glazing.gltf", one_triangle_gltf(R"({"name": "Pane", "extras": {"visible_transmittance": 1.5}})", "")));
    FAIL() << "a visible transmittance of 1.5 was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("material 'Pane': extras.visible_transmittance must be a number 0..1"), std::string::npos)
        << e.what();
  }
}

TEST(GltfLoader, TexturedAlbedoChangesTheBake) {
  // A red-textured floor tints the ceiling it lights; a white one does not.
  auto ceiling_red_over_green = [](const char* file) {
    LoadedScene s = load_gltf(fixture(file));
    test::Baked b = test::bake_scene(s.scene, {0.0f, 128, 2}, {});
    Rgb e = test::mean_irradiance(b.result, [](Vec3 p, Vec3 n) { return n.y < -0.9f && p.y > 1.99f; });
    return e.x / e.y;
  };
  double red = ceiling_red_over_green("red_textured_floor.gltf");
  double white = ceiling_red_over_green("white_textured_floor.gltf");
  RecordProperty("red_floor_ceiling_r_over_g", std::to_string(red));
  RecordProperty("white_floor_ceiling_r_over_g", std::to_string(white));
  EXPECT_NEAR(white, 1.0, 0.02);  // a grey texture keeps light white (2%: gather noise)
  EXPECT_GT(red, 1.2 * white);
}

struct BadFile {
  const char* file;
  const char* says;
};

class BadInput : public ::testing::TestWithParam<BadFile> {};

TEST_P(BadInput, IsOneClearInputError) {
  try {
    LoadedScene s = load_gltf(fixture(std::string("bad/") + GetParam().file));
    Atlas atlas = test::unwrap(s.scene, {0.0f, 64, 2});
    bake(s.scene, atlas, {});
    FAIL() << "no error";
  } catch (const InputError& e) {
    std::string message = e.what();
    EXPECT_NE(message.find(GetParam().says), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

// These were once refused in tinygltf's words ("Spot light description not found.",
// "Failed to decode 'uri' : data:... in Buffer") with no JSON pointer. Each is now refused by
// radbake's own check, at its pointer, before tinygltf reads the file.
TEST(GltfLoader, RefusalsNameTheirJsonPointerInRadbakesWords) {
  const std::string folder = test::fresh_folder("loader_pointer_refusals");
  nlohmann::json cornell = nlohmann::json::parse(test::slurp(test::source_path("samples/cornell_box/cornell_box.gltf")));
  const std::string bin = test::slurp(test::source_path("samples/cornell_box/cornell_box.bin"));
  const std::string base64 = to_base64(bin);
  const std::vector<std::tuple<std::string, std::function<void(nlohmann::json&)>, std::string>> cases = {
      {"spot_without_spot",
       [](nlohmann::json& g) {
         g["extensionsUsed"].push_back("KHR_lights_punctual");
         g["extensions"]["KHR_lights_punctual"] = {{"lights", {{{"type", "spot"}, {"intensity", 10}}}}};
       },
       "/extensions/KHR_lights_punctual/lights/0: spot is missing"},
      {"buffer_base64_broken",
       [&](nlohmann::json& g) {
         g["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.substr(0, 400) + "!!!!" + base64.substr(404);
       },
       "/buffers/0/uri: is a data URI whose base64 breaks at character 401 ('!')"},
      {"buffer_base64_cut_short",
       [&](nlohmann::json& g) {
         g["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.substr(0, base64.size() - 3);
       },
       "/buffers/0/uri: is a data URI whose base64 length is not a multiple of 4"},
      {"image_base64_broken",
       [&](nlohmann::json& g) { g["images"] = {{{"uri", "data:image/png;base64,iVBORw0KGgo=AAAA"}}}; },
       "/images/0/uri: is a data URI whose base64 breaks at character 13 ('A')"},
      {"data_uri_not_base64",
       [&](nlohmann::json& g) { g["buffers"][0]["uri"] = "data:application/octet-stream,rawbytes"; },
       "/buffers/0/uri: is a data URI that is not base64"},
  };
  std::filesystem::copy_file(test::source_path("samples/cornell_box/cornell_box.bin"), folder + "/cornell_box.bin");
  // A .glb whose JSON chunk claims one byte less than it holds (tinygltf: "BIN Chunk data length
  // exceeds the GLB size.").
  {
    nlohmann::json g = cornell;
    g["buffers"][0].erase("uri");
    std::string text = g.dump();
    text.append((4 - text.size() % 4) % 4, ' ');
    std::string bytes;
    auto u32 = [&](uint32_t v) { bytes.append(reinterpret_cast<const char*>(&v), 4); };
    const std::string padded_bin = bin + std::string((4 - bin.size() % 4) % 4, '\0');
    u32(0x46546C67), u32(2), u32(uint32_t(12 + 8 + text.size() + 8 + padded_bin.size()));
    u32(uint32_t(text.size() - 1)), u32(0x4E4F534A), bytes += text;
    u32(uint32_t(padded_bin.size())), u32(0x004E4942), bytes += padded_bin;
    std::ofstream(folder + "/chunk_length.glb", std::ios::binary) << bytes;
    try {
      load_gltf(folder + "/chunk_length.glb");
      ADD_FAILURE() << "chunk_length.glb: no error";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("chunk_length.glb: not a valid .glb: chunk at byte 12 is " +
                                           std::to_string(text.size() - 1) + " bytes long, not a multiple of 4"),
                std::string::npos) << e.what();
    }
  }
  for (const auto& [name, edit, says] : cases) {
    nlohmann::json g = cornell;
    edit(g);
    const std::string file = folder + "/" + name + ".gltf";
    std::ofstream(file) << g.dump();
    try {
      load_gltf(file);
      ADD_FAILURE() << name << ": no error";
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(name + ".gltf: " + says), std::string::npos) << message;
      EXPECT_EQ(message.find("tinygltf"), std::string::npos) << message;
    }
  }
}

const BadFile kBadFiles[] = {
    {"invalid_json.gltf", "not valid JSON (syntax error at byte"},
    {"missing_buffer.gltf", "missing_buffer.bin"},
    {"index_out_of_range.gltf", "index 7 at position 2 is out of range (3 vertices)"},
    {"nan_position.gltf", "/attributes/POSITION: has a non-finite value at vertex 1"},
    {"infinite_position.gltf", "/attributes/POSITION: has a non-finite value at vertex 1"},
    {"no_geometry.gltf", "no triangles"},
    {"no_light.gltf", "nothing in the scene emits light"},
    {"required_extension.gltf", "requires extension KHR_draco_mesh_compression"},
    {"does_not_exist.gltf", "no such file"},
};

INSTANTIATE_TEST_SUITE_P(Fixtures, BadInput, ::testing::ValuesIn(kBadFiles),
                         [](const ::testing::TestParamInfo<BadFile>& info) {
                           std::string name = info.param.file;
                           return name.substr(0, name.find('.'));
                         });

}  // namespace
}  // namespace radbake
