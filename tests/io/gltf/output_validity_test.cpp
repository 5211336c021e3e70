// Output valid whatever comes in: what radbake accepts but the Khronos glTF-Validator
// would reject in what radbake writes (bad vertex data, extension values out of range, morph
// targets, images that are no PNG or JPEG, skins on unskinned meshes, EXT_texture_webp naming other
// images) is repaired or dropped with one warning naming its JSON pointer, and both files radbake
// writes (NAME.gltf and NAME_display.glb) validate with no error and no warning
// (docs/hostile_input.md). Each case edits the lit room with a textured floor and bakes it with the
// radbake binary.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>

#include "io/gltf/base64.h"
#include "io/gltf/gltf_loader.h"
#include "support/commands.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN(), kInf = std::numeric_limits<float>::infinity();
// A float written and read back is within this of unit length once normalised (float rounding).
constexpr double kUnitLength = 1e-6;
const char* const kBakeOptions = " --max-page-size 64 --quality draft --gather-rays 16 --patch-rays 64 --threads 1";

// A PNG's signature over eight zeros, which no decoder reads.
const char* const kGarbagePng = "data:image/png;base64,iVBORw0KGgoAAAAAAAAAAA==";
// A 1 x 1 lossless WebP (the one browsers' WebP feature tests decode).
const std::vector<uint8_t> kWebp = {0x52, 0x49, 0x46, 0x46, 0x1a, 0x00, 0x00, 0x00, 0x57, 0x45, 0x42, 0x50,
                                    0x56, 0x50, 0x38, 0x4c, 0x0d, 0x00, 0x00, 0x00, 0x2f, 0x00, 0x00, 0x00,
                                    0x10, 0x07, 0x10, 0x11, 0x11, 0x88, 0x88, 0xfe, 0x07, 0x00};

// tests/fixtures/red_textured_floor.gltf (wall+x is mesh 0, four vertices whose normal is -X; the
// floor, wall-y, is mesh 3 with the textured material 0) with data added in extra.bin beside it.
struct Room {
  json doc = json::parse(test::slurp(test::source_path("tests/fixtures/red_textured_floor.gltf")));
  std::vector<uint8_t> extra;
  std::map<std::string, std::vector<uint8_t>> files;  // more files beside it, by name

  template <typename T>
  int add(const std::vector<T>& values, const char* type, int component_type) {
    if (extra.empty()) doc["buffers"].push_back({{"uri", "extra.bin"}, {"byteLength", 0}});
    const size_t at = extra.size();
    extra.resize(at + (values.size() * sizeof(T) + 3) / 4 * 4, 0);
    std::memcpy(extra.data() + at, values.data(), values.size() * sizeof(T));
    doc["bufferViews"].push_back({{"buffer", doc["buffers"].size() - 1}, {"byteOffset", at}, {"byteLength", values.size() * sizeof(T)}});
    const size_t components = std::string(type) == "VEC2" ? 2 : std::string(type) == "VEC3" ? 3 : 4;
    doc["accessors"].push_back({{"bufferView", doc["bufferViews"].size() - 1}, {"componentType", component_type},
                                {"count", values.size() / components}, {"type", type}});
    return int(doc["accessors"].size() - 1);
  }
  int add(const std::vector<float>& values, const char* type) { return add(values, type, 5126); }

  json& attributes(int mesh) { return doc["meshes"][mesh]["primitives"][0]["attributes"]; }

  // Writes the room as FOLDER/NAME.gltf (and extra.bin, and `files`); returns its path.
  std::string save(const std::string& name) {
    const std::string folder = test::fresh_folder("validity_" + name);
    if (!extra.empty()) {
      doc["buffers"].back()["byteLength"] = extra.size();
      files["extra.bin"] = extra;
    }
    for (const auto& [file, bytes] : files)
      std::ofstream(folder + "/" + file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), long(bytes.size()));
    std::ofstream(folder + "/" + name + ".gltf") << doc.dump();
    return folder + "/" + name + ".gltf";
  }
};

struct Baked {
  test::Outcome run;
  std::string folder, name;
  json doc;  // NAME.gltf

  std::string path(const std::string& file) const { return folder + "/" + file; }

  // How many warnings name `pointer` (followed by a space, colon or parenthesis, so /images/0 is
  // not /images/0/mimeType).
  size_t warnings_naming(const std::string& pointer) const {
    size_t n = 0, at = 0;
    for (size_t end; (end = run.err.find('\n', at)) != std::string::npos; at = end + 1) {
      const std::string line = run.err.substr(at, end - at);
      if (line.rfind("radbake: warning: ", 0) != 0) continue;
      for (size_t p = line.find(pointer); p != std::string::npos; p = line.find(pointer, p + 1))
        if (p + pointer.size() < line.size() && std::strchr(" :)", line[p + pointer.size()])) {
          ++n;
          break;
        }
    }
    return n;
  }

  // The floats of output accessor `index`, packed.
  std::vector<float> floats(int index) const {
    const json& a = doc["accessors"][index];
    EXPECT_EQ(a["componentType"], 5126);
    const json& view = doc["bufferViews"][a["bufferView"].get<size_t>()];
    const std::string bytes = test::slurp(path(doc["buffers"][view["buffer"].get<size_t>()]["uri"]));
    const std::string type = a["type"];
    const size_t components = type == "SCALAR" ? 1 : type == "VEC2" ? 2 : type == "VEC3" ? 3 : 4;
    const size_t stride = view.value("byteStride", 4 * components);
    const size_t offset = view.value("byteOffset", size_t(0)) + a.value("byteOffset", size_t(0));
    std::vector<float> out(a["count"].get<size_t>() * components);
    for (size_t i = 0; i < out.size(); ++i)
      std::memcpy(&out[i], bytes.data() + offset + i / components * stride + i % components * 4, 4);
    return out;
  }

  const json& primitive_of_node(size_t node) const {
    return doc["meshes"][doc["nodes"][node]["mesh"].get<size_t>()]["primitives"][0];
  }
};

Baked bake(const std::string& input, const std::string& extra_options = "") {
  Baked b;
  b.folder = (fs::path(input).parent_path() / "out").string();
  b.name = fs::path(input).stem().string();
  b.run = test::radbake("bake " + input + " -o " + b.folder + kBakeOptions + extra_options);
  EXPECT_EQ(b.run.status, 0) << b.run.err;
  if (fs::exists(b.path(b.name + ".gltf"))) b.doc = json::parse(test::slurp(b.path(b.name + ".gltf")));
  return b;
}

// The validator's report (tests/tools/validate_gltf.mjs) on `file`.
json validate(const std::string& file) {
  EXPECT_TRUE(fs::exists(test::source_path("tests/tools/node_modules/gltf-validator")))
      << "the validator is not installed: run ./dev test (npm ci in tests/tools)";
  const test::Outcome v = test::run("node " + test::source_path("tests/tools/validate_gltf.mjs") + " " + file);
  return json::parse(v.out.empty() ? "{}" : v.out);
}

// Both files validate with no error and no warning.
void expect_valid(const Baked& b) {
  for (const std::string& file : {b.name + ".gltf", b.name + "_display.glb"}) {
    const json report = validate(b.path(file));
    EXPECT_EQ(report.value("errors", -1), 0) << file << ": " << report.dump();
    EXPECT_EQ(report.value("warnings", -1), 0) << file << ": " << report.dump();
  }
}

void expect_unit(const std::vector<float>& v, size_t stride, const std::string& what) {
  for (size_t i = 0; i + 2 < v.size(); i += stride)
    EXPECT_NEAR(std::sqrt(double(v[i]) * v[i] + double(v[i + 1]) * v[i + 1] + double(v[i + 2]) * v[i + 2]), 1.0, kUnitLength)
        << what << " element " << i / stride;
}

TEST(OutputValidity, AssimpsBoxBadNormalsBakesToValidOutput) {
  const std::string box = "/usr/share/assimp/models/glTF2/BoxBadNormals-glTF-Binary/BoxBadNormals.glb";
  ASSERT_TRUE(fs::exists(box)) << "Debian's assimp-testmodels is not installed: ./dev installs it";
  const std::string input = test::fresh_folder("validity_box") + "/BoxBadNormals.glb";
  fs::copy_file(box, input);
  const Baked b = bake(input, " --sky uniform");
  // Four normals of zero length and four of length 0.1, on faces of four vertices each.
  EXPECT_EQ(b.warnings_naming("/meshes/0/primitives/0/attributes/NORMAL"), 1u) << b.run.err;
  EXPECT_NE(b.run.err.find("4 renormalised, 4 of no direction recomputed from their faces"), std::string::npos) << b.run.err;
  expect_valid(b);
  // Every written normal is a unit vector along an axis (the box's faces), none zero.
  const std::vector<float> n = b.floats(b.primitive_of_node(1)["attributes"]["NORMAL"]);
  expect_unit(n, 3, "NORMAL");
  for (size_t v = 0; v < n.size() / 3; ++v)
    EXPECT_NEAR(std::max({std::fabs(n[3 * v]), std::fabs(n[3 * v + 1]), std::fabs(n[3 * v + 2])}), 1.0f, kUnitLength) << v;
}

// wall+x: NaN, infinite and zero normals recomputed from the face, a huge one renormalised, a NaN
// texcoord written as 0; wall-x: tangents of short xyz and w 0.5 or NaN repaired; wall+y: a zero
// tangent, which cannot be repaired, dropped. One warning per attribute, naming it.
TEST(OutputValidity, BadNormalsTangentsAndTexcoordsAreRepairedOrDropped) {
  Room room;
  room.attributes(0)["NORMAL"] = room.add({kNaN, 0, 0, kInf, 0, 0, 0, 0, 0, -1e30f, 0, 0}, "VEC3");
  room.attributes(0)["TEXCOORD_0"] = room.add({kNaN, 0.5f, 1, 0, -kInf, 1, 0, 0}, "VEC2");
  room.attributes(1)["TANGENT"] = room.add({0, 1, 0, 0.5f, 0, 1, 0, kNaN, 0, 0.5f, 0, -1, 0, 1, 0, 1}, "VEC4");
  room.attributes(2)["TANGENT"] = room.add({0, 0, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1}, "VEC4");
  const Baked b = bake(room.save("vertex_values"));
  for (const char* pointer : {"/meshes/0/primitives/0/attributes/NORMAL", "/meshes/0/primitives/0/attributes/TEXCOORD_0",
                              "/meshes/1/primitives/0/attributes/TANGENT", "/meshes/2/primitives/0/attributes/TANGENT"})
    EXPECT_EQ(b.warnings_naming(pointer), 1u) << pointer << "\n" << b.run.err;
  EXPECT_NE(b.run.err.find("dropped /meshes/2/primitives/0/attributes/TANGENT from the output"), std::string::npos) << b.run.err;
  expect_valid(b);

  const std::vector<float> normals = b.floats(b.primitive_of_node(0)["attributes"]["NORMAL"]);
  for (size_t v = 0; v < normals.size() / 3; ++v) {
    EXPECT_NEAR(normals[3 * v], -1.0f, kUnitLength) << v;  // the wall's face normal, -X
    EXPECT_NEAR(std::hypot(normals[3 * v + 1], normals[3 * v + 2]), 0.0f, kUnitLength) << v;
  }
  for (float c : b.floats(b.primitive_of_node(0)["attributes"]["TEXCOORD_0"])) EXPECT_TRUE(std::isfinite(c));
  const std::vector<float> tangents = b.floats(b.primitive_of_node(1)["attributes"]["TANGENT"]);
  expect_unit(tangents, 4, "TANGENT");
  for (size_t v = 0; v < tangents.size() / 4; ++v) EXPECT_EQ(std::fabs(tangents[4 * v + 3]), 1.0f) << v;
  EXPECT_FALSE(b.primitive_of_node(2)["attributes"].contains("TANGENT"));
}

// Attributes that keep the input's accessors (own lightmap UVs, kept) are repaired too.
TEST(OutputValidity, KeptInputAccessorsAreRepairedToo) {
  json doc = json::parse(test::slurp(test::source_path("tests/fixtures/own_lightmap_uvs.gltf")));
  Room room;
  room.doc = doc;
  const int count = room.doc["accessors"][room.attributes(0)["POSITION"].get<int>()]["count"];
  std::vector<float> zero(3 * size_t(count), 0.0f);
  room.attributes(0)["NORMAL"] = room.add(zero, "VEC3");
  const Baked b = bake(room.save("kept_uvs"));
  EXPECT_EQ(b.warnings_naming("/meshes/0/primitives/0/attributes/NORMAL"), 1u) << b.run.err;
  expect_valid(b);
  expect_unit(b.floats(b.primitive_of_node(0)["attributes"]["NORMAL"]), 3, "NORMAL");
}

TEST(OutputValidity, MaterialExtensionValuesOutOfRangeAreClampedAndOfAnotherTypeDropped) {
  Room room;
  json& m = room.doc["materials"];
  m[0]["extensions"]["KHR_materials_ior"] = {{"ior", -1}};
  m[1]["extensions"]["KHR_materials_ior"] = {{"ior", 0.5}};
  m[1]["extensions"]["KHR_materials_transmission"] = {{"transmissionFactor", 2}};
  m[2]["extensions"]["KHR_materials_ior"] = {{"ior", "1.5"}};
  m[2]["extensions"]["KHR_materials_specular"] = {{"specularFactor", nullptr}, {"specularColorFactor", {2, 3, 4}}};
  for (const char* e : {"KHR_materials_ior", "KHR_materials_transmission", "KHR_materials_specular"}) room.doc["extensionsUsed"].push_back(e);
  const std::string input = room.save("material_range");
  LoadedScene loaded = load_gltf(input);
  EXPECT_EQ(loaded.scene.materials[0].ior, 1.0f);
  EXPECT_EQ(loaded.scene.materials[1].transmission, 1.0f);
  const Baked b = bake(input);
  EXPECT_NE(b.run.err.find("clamped /materials/0/extensions/KHR_materials_ior/ior from -1 to 1.0"), std::string::npos) << b.run.err;
  EXPECT_NE(b.run.err.find("clamped /materials/1/extensions/KHR_materials_transmission/transmissionFactor from 2 to 1.0"),
            std::string::npos) << b.run.err;
  for (const char* pointer : {"/materials/1/extensions/KHR_materials_ior/ior", "/materials/2/extensions/KHR_materials_ior/ior",
                              "/materials/2/extensions/KHR_materials_specular/specularFactor"})
    EXPECT_EQ(b.warnings_naming(pointer), 1u) << pointer << "\n" << b.run.err;
  // specularColorFactor's range is [0, inf): kept as it is.
  EXPECT_EQ(b.warnings_naming("/materials/2/extensions/KHR_materials_specular/specularColorFactor"), 0u) << b.run.err;
  expect_valid(b);
  for (const json& material : b.doc["materials"]) {
    if (material["name"] == "floor") {
      EXPECT_EQ(material["extensions"]["KHR_materials_ior"]["ior"], 1.0);
    } else if (material["name"] == "lamp") {
      EXPECT_FALSE(material["extensions"]["KHR_materials_ior"].contains("ior"));
    }
  }
}

// A NaN displacement is written as 0, so the target's bounds (which glTF requires of POSITION) are
// finite; 5,000 empty targets go with their weights; a mesh's empty target goes, its other stays.
TEST(OutputValidity, MorphTargetsAreFiniteAndNeverEmpty) {
  Room room;
  room.doc["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", room.add({kNaN, 0, 0, 0, 0.1f, 0, 0, 0, 0, 0, 0, 0}, "VEC3")}}};
  room.doc["meshes"][0]["weights"] = {0.5};
  room.doc["meshes"][1]["primitives"][0]["targets"] = json::array();
  for (int t = 0; t < 5000; ++t) room.doc["meshes"][1]["primitives"][0]["targets"].push_back(json::object());
  room.doc["meshes"][1]["weights"] = std::vector<double>(5000, 0.0);
  room.doc["nodes"][1]["weights"] = std::vector<double>(5000, 0.25);
  const int lift = room.add({0, 0.1f, 0, 0, 0.1f, 0, 0, 0.1f, 0, 0, 0.1f, 0}, "VEC3");
  room.doc["meshes"][2]["primitives"][0]["targets"] = {json::object(), {{"POSITION", lift}}};
  room.doc["meshes"][2]["weights"] = {0.1, 0.7};
  const Baked b = bake(room.save("morph_targets"));
  EXPECT_EQ(b.warnings_naming("/meshes/0/primitives/0/targets/0/POSITION"), 1u) << b.run.err;
  EXPECT_NE(b.run.err.find("dropped 5000 empty morph targets of /meshes/1 from the output"), std::string::npos) << b.run.err;
  EXPECT_NE(b.run.err.find("dropped 1 empty morph targets of /meshes/2 from the output"), std::string::npos) << b.run.err;
  expect_valid(b);

  const json& target = b.doc["accessors"][b.primitive_of_node(0)["targets"][0]["POSITION"].get<size_t>()];
  for (const char* bound : {"min", "max"})
    for (const json& c : target[bound]) EXPECT_TRUE(c.is_number()) << target;
  EXPECT_FALSE(b.primitive_of_node(1).contains("targets"));
  EXPECT_FALSE(b.doc["nodes"][1].contains("weights"));
  const json& mesh2 = b.doc["meshes"][b.doc["nodes"][2]["mesh"].get<size_t>()];
  EXPECT_EQ(mesh2["primitives"][0]["targets"].size(), 1u);
  EXPECT_EQ(mesh2["weights"], json({0.7}));
}

// An image no decoder reads is not written, and the texture reference to it goes; a PNG declared
// JPEG is written declared PNG.
TEST(OutputValidity, ImagesThatDoNotDecodeAreNotWrittenAndMimeTypesFollowTheBytes) {
  Room room;
  std::string png_uri = room.doc["images"][0]["uri"];
  room.doc["images"][0]["uri"] = kGarbagePng;
  room.doc["images"].push_back({{"uri", "data:image/jpeg" + png_uri.substr(png_uri.find(';'))}, {"mimeType", "image/jpeg"}});
  room.doc["textures"].push_back({{"source", 1}});
  room.doc["materials"][0]["emissiveTexture"] = {{"index", 1}};
  const Baked b = bake(room.save("images"));
  EXPECT_EQ(b.warnings_naming("/images/0"), 1u) << b.run.err;
  EXPECT_NE(b.run.err.find("dropped /images/0 ('floor') from the output (a PNG that does not decode)"), std::string::npos)
      << b.run.err;
  EXPECT_EQ(b.warnings_naming("/images/1/mimeType"), 1u) << b.run.err;
  EXPECT_EQ(b.warnings_naming("/images/1/uri"), 1u) << b.run.err;
  expect_valid(b);
  for (const json& material : b.doc["materials"])
    if (material["name"].get<std::string>().rfind("floor", 0) == 0) {
      EXPECT_FALSE(material["pbrMetallicRoughness"].contains("baseColorTexture")) << material;
      EXPECT_EQ(material["pbrMetallicRoughness"]["baseColorFactor"], json({1, 1, 1, 1.0}));
    }
  for (const json& image : b.doc["images"]) {
    EXPECT_NE(image.value("uri", ""), kGarbagePng);
    if (image.value("uri", "").rfind("data:", 0) == 0) {
      EXPECT_EQ(image["mimeType"], "image/png");
      EXPECT_EQ(image["uri"].get<std::string>().rfind("data:image/png;", 0), 0u);
    }
  }
}

// Debian's assimp-testmodels duck, converted by assimp, names a TGA texture: not written, its
// reference gone, the base colour factor kept.
TEST(OutputValidity, AssimpsDuckWithATgaTextureBakesWithoutIt) {
  const std::string dae = "/usr/share/assimp/models/Collada/duck.dae";
  ASSERT_TRUE(fs::exists(dae)) << "Debian's assimp-testmodels is not installed: ./dev installs it";
  const std::string folder = test::fresh_folder("validity_duck");
  for (const char* file : {"duck.dae", "duckCM.tga"}) fs::copy_file("/usr/share/assimp/models/Collada/" + std::string(file), folder + "/" + file);
  const test::Outcome converted = test::run("cd " + folder + " && assimp export duck.dae duck.gltf -f gltf2");
  ASSERT_EQ(converted.status, 0) << converted.out << converted.err << " (assimp-utils: ./dev installs it)";
  const json input = json::parse(test::slurp(folder + "/duck.gltf"));
  ASSERT_NE(input["images"][0]["uri"].get<std::string>().find(".tga"), std::string::npos);
  const Baked b = bake(folder + "/duck.gltf", " --sky uniform");
  EXPECT_NE(b.run.err.find("dropped /images/0 ('./duckCM.tga') from the output (neither PNG nor JPEG"), std::string::npos) << b.run.err;
  for (const std::string& file : {b.name + ".gltf", b.name + "_display.glb"}) {
    const json report = validate(b.path(file));
    EXPECT_EQ(report.value("errors", -1), 0) << report.dump();
    for (const json& message : report["messages"]) EXPECT_NE(message.get<std::string>().rfind("IMAGE_", 0), 0u) << message;
  }
  for (const json& image : b.doc["images"]) EXPECT_EQ(image["uri"].get<std::string>().find(".tga"), std::string::npos);
  const json& pbr = input["materials"][0]["pbrMetallicRoughness"];
  for (const json& material : b.doc["materials"]) {
    EXPECT_FALSE(material["pbrMetallicRoughness"].contains("baseColorTexture"));
    EXPECT_EQ(material["pbrMetallicRoughness"].value("baseColorFactor", json()), pbr.value("baseColorFactor", json()));
  }
}

// A skin on a node whose mesh has no joints goes; so do joints on a mesh shown without a skin.
TEST(OutputValidity, SkinsGoWhereMeshesAreNotSkinned) {
  Room room;
  room.doc["nodes"].push_back({{"name", "joint"}});
  room.doc["scenes"][0]["nodes"].push_back(room.doc["nodes"].size() - 1);
  room.doc["skins"] = {{{"joints", {room.doc["nodes"].size() - 1}}}};
  room.doc["nodes"][0]["skin"] = 0;
  room.attributes(1)["JOINTS_0"] = room.add(std::vector<uint8_t>(16, 0), "VEC4", 5121);
  room.attributes(1)["WEIGHTS_0"] = room.add({1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, "VEC4");
  const Baked b = bake(room.save("skins"));
  EXPECT_EQ(b.warnings_naming("/nodes/0/skin"), 1u) << b.run.err;
  EXPECT_EQ(b.warnings_naming("/meshes/1/primitives/0/attributes/JOINTS_0"), 1u) << b.run.err;
  EXPECT_EQ(b.warnings_naming("/meshes/1/primitives/0/attributes/WEIGHTS_0"), 1u) << b.run.err;
  expect_valid(b);
  EXPECT_FALSE(b.doc["nodes"][0].contains("skin"));
  EXPECT_FALSE(b.primitive_of_node(1)["attributes"].contains("JOINTS_0"));
}

// EXT_texture_webp naming a PNG goes (the PNG becomes the texture's source where it has none);
// naming real WebP, it stays, beside its PNG fallback.
TEST(OutputValidity, ExtTextureWebpMustNameWebp) {
  Room room;
  room.doc["textures"][0]["extensions"]["EXT_texture_webp"] = {{"source", 0}};
  room.doc["textures"].push_back({{"extensions", {{"EXT_texture_webp", {{"source", 0}}}}}});
  room.doc["materials"][0]["emissiveTexture"] = {{"index", 1}};
  room.doc["extensionsUsed"].push_back("EXT_texture_webp");
  const Baked png = bake(room.save("webp_naming_png"));
  EXPECT_EQ(png.warnings_naming("/textures/0/extensions/EXT_texture_webp"), 1u) << png.run.err;
  EXPECT_NE(png.run.err.find("dropped /textures/1/extensions/EXT_texture_webp from the output (/images/0 is PNG, not WebP; "
                             "/images/0 is the texture's source instead)"),
            std::string::npos) << png.run.err;
  expect_valid(png);
  for (const json& texture : png.doc["textures"]) EXPECT_FALSE(texture.contains("extensions")) << texture;
  const json& used = png.doc["extensionsUsed"];
  EXPECT_EQ(std::count(used.begin(), used.end(), "EXT_texture_webp"), 0);

  Room webp;
  webp.doc["images"].push_back({{"uri", "texture.webp"}});
  webp.files["texture.webp"] = kWebp;
  webp.doc["textures"][0]["extensions"]["EXT_texture_webp"] = {{"source", 1}};
  webp.doc["extensionsUsed"].push_back("EXT_texture_webp");
  const Baked kept = bake(webp.save("webp_naming_webp"));
  EXPECT_EQ(kept.warnings_naming("/textures/0/extensions/EXT_texture_webp"), 0u) << kept.run.err;
  expect_valid(kept);
  bool named = false;
  for (const json& texture : kept.doc["textures"])
    if (texture.contains("extensions")) {
      const json& image = kept.doc["images"][texture["extensions"]["EXT_texture_webp"]["source"].get<size_t>()];
      named = test::slurp(kept.path(image["uri"])).rfind("RIFF", 0) == 0;
    }
  EXPECT_TRUE(named) << kept.doc["textures"] << kept.doc["images"];
}

// KHR_materials_pbrSpecularGlossiness (archived; beside MOZ_lightmap the validator warns
// MULTIPLE_EXTENSIONS) is dropped, and leaves extensionsUsed and extensionsRequired. The floor
// keeps the metallic-roughness material it gives beside it (what current viewers show: assimp
// writes a glass's alpha only there); a wall that gives none gets its diffuse part as one, which
// the bake reads too.
TEST(OutputValidity, SpecularGlossinessIsDroppedForMetallicRoughness) {
  Room room;
  const json red = {1, 0, 0, 0.5}, diffuse = {0.25, 0.5, 0.75, 1.0};
  json& floor = room.doc["materials"][0];
  floor["pbrMetallicRoughness"]["baseColorFactor"] = red;
  floor["extensions"]["KHR_materials_pbrSpecularGlossiness"] = {{"diffuseFactor", diffuse}};
  room.doc["materials"].push_back({{"name", "spec-gloss wall"},
                                   {"extensions", {{"KHR_materials_pbrSpecularGlossiness",
                                                    {{"diffuseFactor", diffuse}, {"specularFactor", {0.5, 0.5, 0.5}},
                                                     {"glossinessFactor", 0.25}}}}}});
  room.doc["meshes"][0]["primitives"][0]["material"] = room.doc["materials"].size() - 1;
  for (const char* list : {"extensionsUsed", "extensionsRequired"}) room.doc[list].push_back("KHR_materials_pbrSpecularGlossiness");
  const std::string input = room.save("specular_glossiness");
  const Baked b = bake(input);
  EXPECT_EQ(b.warnings_naming("/materials/0/extensions/KHR_materials_pbrSpecularGlossiness"), 1u) << b.run.err;
  EXPECT_EQ(b.warnings_naming("/materials/" + std::to_string(room.doc["materials"].size() - 1) +
                              "/extensions/KHR_materials_pbrSpecularGlossiness"), 1u) << b.run.err;
  expect_valid(b);
  for (const char* list : {"extensionsUsed", "extensionsRequired"})
    for (const json& name : b.doc.value(list, json::array())) EXPECT_NE(name, "KHR_materials_pbrSpecularGlossiness") << list;
  size_t floors = 0, walls = 0;
  for (const json& material : b.doc["materials"]) {
    EXPECT_FALSE(material.contains("extensions") && material["extensions"].contains("KHR_materials_pbrSpecularGlossiness"));
    const std::string name = material["name"];
    if (name.rfind("floor", 0) == 0) {
      ++floors;
      EXPECT_EQ(material["pbrMetallicRoughness"]["baseColorFactor"], red);
    } else if (name.rfind("spec-gloss wall", 0) == 0) {
      ++walls;
      EXPECT_EQ(material["pbrMetallicRoughness"]["baseColorFactor"], diffuse);
      EXPECT_EQ(material["pbrMetallicRoughness"]["metallicFactor"], 0.0);
      EXPECT_EQ(material["pbrMetallicRoughness"]["roughnessFactor"], 0.75);  // 1 - glossiness
    }
  }
  EXPECT_GT(floors, 0u);
  EXPECT_GT(walls, 0u);
  // The bake reads what the output says: the floor's red, the wall's diffuse.
  const Scene scene = load_gltf(input).scene;
  EXPECT_FLOAT_EQ(scene.materials[0].base_color.x, 1.0f);
  EXPECT_FLOAT_EQ(scene.materials[0].base_alpha, 0.5f);
  EXPECT_FLOAT_EQ(scene.materials.back().base_color.y, 0.5f);
  EXPECT_FLOAT_EQ(scene.materials.back().base_color.z, 0.75f);
}

// PNG chunks the validator flags (IMAGE_FEATURES_UNSUPPORTED: cHRM other than sRGB's, gAMA other
// than 1/2.2, iCCP, non-square pHYs) are taken out of images radbake writes, wherever the image
// lives: a file beside the scene, a data URI, a buffer view. The pixels are the same bytes.
struct Chunk {
  std::string type, data;
};

uint32_t crc32_of(const std::string& bytes) {
  uint32_t crc = 0xffffffffu;
  for (unsigned char c : bytes) {
    crc ^= c;
    for (int k = 0; k < 8; ++k) crc = crc & 1 ? 0xedb88320u ^ (crc >> 1) : crc >> 1;
  }
  return ~crc;
}

std::string big_endian(uint32_t v) { return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)}; }

std::vector<Chunk> png_chunks(const std::string& png) {
  std::vector<Chunk> chunks;
  for (size_t at = 8; at + 12 <= png.size();) {
    const uint32_t length = uint32_t(uint8_t(png[at])) << 24 | uint32_t(uint8_t(png[at + 1])) << 16 |
                            uint32_t(uint8_t(png[at + 2])) << 8 | uint32_t(uint8_t(png[at + 3]));
    chunks.push_back({png.substr(at + 4, 4), png.substr(at + 8, length)});
    at += 12 + length;
  }
  return chunks;
}

std::string png_of(const std::vector<Chunk>& chunks) {
  std::string png = "\x89PNG\r\n\x1a\n";
  for (const Chunk& c : chunks) png += big_endian(uint32_t(c.data.size())) + c.type + c.data + big_endian(crc32_of(c.type + c.data));
  return png;
}

TEST(OutputValidity, PngColourSpaceAspectAndAnimationChunksAreTakenOut) {
  Room plain;
  const std::string uri = plain.doc["images"][0]["uri"], header = "data:image/png;base64,";
  ASSERT_EQ(uri.rfind(header, 0), 0u);
  const std::string original = from_base64(uri.substr(header.size()));
  std::vector<Chunk> chunks = png_chunks(original);
  ASSERT_EQ(chunks.front().type, "IHDR");
  // Adobe RGB's primaries, a gamma of 1/1.8, an (empty-named) ICC profile, pixels twice as tall as wide.
  std::string chrm;
  for (uint32_t v : {31270u, 32900u, 64000u, 33000u, 21000u, 71000u, 15000u, 6000u}) chrm += big_endian(v);
  const std::vector<Chunk> flagged = {{"cHRM", chrm}, {"gAMA", big_endian(55556)}, {"iCCP", std::string("x\0\0", 3)},
                                      {"pHYs", big_endian(2835) + big_endian(5670) + std::string(1, '\1')}};
  chunks.insert(chunks.begin() + 1, flagged.begin(), flagged.end());
  const std::string marked = png_of(chunks);
  std::string idat;
  for (const Chunk& c : png_chunks(original))
    if (c.type == "IDAT") idat += c.data;

  for (const std::string place : {"file", "data URI", "buffer view"}) {
    SCOPED_TRACE(place);
    Room room;
    json& image = room.doc["images"][0];
    if (place == "file") {
      image["uri"] = "floor.png";
      room.files["floor.png"] = std::vector<uint8_t>(marked.begin(), marked.end());
    } else if (place == "data URI") {
      image["uri"] = header + to_base64(marked);
    } else {
      image.erase("uri");
      const int accessor = room.add(std::vector<uint8_t>(marked.begin(), marked.end()), "SCALAR", 5121);
      image["bufferView"] = room.doc["accessors"][accessor]["bufferView"];
      image["mimeType"] = "image/png";
      room.doc["accessors"].erase(room.doc["accessors"].size() - 1);
    }
    const Baked b = bake(room.save("png_" + std::to_string(place.size())));
    EXPECT_EQ(b.warnings_naming("/images/0"), 1u) << b.run.err;
    EXPECT_NE(b.run.err.find("cHRM, gAMA, iCCP, pHYs chunks out"), std::string::npos) << b.run.err;
    expect_valid(b);
    // The written image: its chunks are the original's, IDAT for IDAT.
    ASSERT_EQ(b.doc["images"].size(), 2u);  // the floor's and the lightmap page's
    const json& written = b.doc["images"][0];
    std::string bytes;
    if (written.contains("bufferView")) {
      const json& view = b.doc["bufferViews"][written["bufferView"].get<size_t>()];
      bytes = test::slurp(b.path(b.doc["buffers"][view["buffer"].get<size_t>()]["uri"]))
                  .substr(view.value("byteOffset", size_t(0)), view["byteLength"].get<size_t>());
    } else if (written["uri"].get<std::string>().rfind(header, 0) == 0) {
      bytes = from_base64(written["uri"].get<std::string>().substr(header.size()));
    } else {
      bytes = test::slurp(b.path(written["uri"]));
    }
    EXPECT_EQ(bytes, original);
  }
}

}  // namespace
}  // namespace radbake
