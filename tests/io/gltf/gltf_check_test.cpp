// The document checked on input (io/gltf/gltf_check.cpp): what radbake reads is refused when invalid,
// naming its JSON pointer; what it only copies is dropped with a warning, so the baked glTF never
// carries the input's slips; extension declarations follow use; extras are kept as they are.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

#include "base/errors.h"
#include "io/gltf/gltf_extensions.h"
#include "io/gltf/gltf_loader.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

using json = nlohmann::json;

// A lit room with a textured floor and its buffers inline, so an edited copy stands alone.
json room() {
  std::ifstream in(test::source_path("tests/fixtures/red_textured_floor.gltf"));
  return json::parse(in);
}

std::string save(const std::string& name, const json& doc) { return test::write_text_file(name + ".gltf", doc.dump()); }

bool warned(const Scene& scene, const std::string& text) {
  for (const std::string& w : scene.warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}

json bake(const std::string& input, const std::string& name) {
  std::ifstream out(test::bake_file_to_folder(input, test::fresh_folder(name), {0.0f, 64, 2}));
  return json::parse(out);
}

std::string refusal(const json& doc, const std::string& name) {
  try {
    load_gltf(save(name, doc));
  } catch (const InputError& e) {
    return e.what();
  }
  return "(loaded)";
}

TEST(GltfCheck, ASlipInWhatRadbakeReadsRefusesTheFileNamingItsPointer) {
  json doc = room();
  doc["materials"][0]["pbrMetallicRoughness"]["metallicFactor"] = "high";
  EXPECT_NE(refusal(doc, "schema_string_for_number").find("schema_string_for_number.gltf: /materials/0/pbrMetallicRoughness/metallicFactor: must be a number"),
            std::string::npos);
  doc = room();
  doc["materials"][0]["emissiveTexture"] = {{"texCoord", 0}};
  EXPECT_NE(refusal(doc, "schema_no_index").find(": /materials/0/emissiveTexture: index is missing"), std::string::npos);
  doc = room();
  doc["nodes"][0]["mesh"] = {{"index", 0}};
  EXPECT_NE(refusal(doc, "schema_object_for_index").find(": /nodes/0/mesh: must be a whole number"), std::string::npos);
  doc = room();
  doc["accessors"][0]["type"] = "VEC5";
  EXPECT_NE(refusal(doc, "schema_enum").find(": /accessors/0/type: must be one of SCALAR"), std::string::npos);
}

TEST(GltfCheck, WhatRadbakeOnlyCopiesIsDroppedWithAWarningAndNeverWritten) {
  json doc = room();
  doc["materials"][0]["normalTexture"] = {{"scale", 1}};              // no index
  doc["materials"][1]["occlusionTexture"] = {{"index", 0}, {"strength", 2}};  // out of range
  doc["nodes"][0]["name"] = 12;
  doc["cameras"] = {{{"type", "fisheye"}}, {{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}}};
  doc["nodes"][0]["camera"] = 1;  // the valid one, renumbered to 0
  doc["nodes"][1]["camera"] = 0;  // the dropped one
  const std::string input = save("schema_drops", doc);
  const Scene scene = load_gltf(input).scene;
  for (const char* pointer : {"dropped /materials/0/normalTexture", "dropped /materials/1/occlusionTexture",
                              "dropped /nodes/0/name", "dropped /cameras/0", "dropped /nodes/1/camera"})
    EXPECT_TRUE(warned(scene, pointer)) << pointer;

  const json out = bake(input, "schema_drops_out");
  for (const json& m : out["materials"]) {
    EXPECT_FALSE(m.contains("normalTexture"));
    EXPECT_FALSE(m.contains("occlusionTexture"));
  }
  EXPECT_FALSE(out["nodes"][0].contains("name"));
  ASSERT_EQ(out["cameras"].size(), 1u);
  EXPECT_EQ(out["cameras"][0]["type"], "perspective");
  EXPECT_EQ(out["nodes"][0]["camera"], 0);
  EXPECT_FALSE(out["nodes"][1].contains("camera"));
}

TEST(GltfCheck, ExtensionsAreDeclaredAsUsedAndExtrasKeptWhateverTheyHold) {
  json doc = room();
  doc["materials"][0]["extensions"]["EXT_vendor_thing"] = {{"level", 3}};  // used, not declared
  doc["materials"][1]["extensions"]["EXT_vendor_broken"] = 5;             // not an object
  doc["materials"][1]["extensions"]["KHR_lights_punctual"] = {{"light", 0}};  // not a material's
  doc["extensionsUsed"].push_back("EXT_vendor_broken");
  doc["extensionsUsed"].push_back(doc["extensionsUsed"][0]);  // listed twice
  doc["extensionsRequired"] = {"KHR_texture_transform"};       // used nowhere
  doc["nodes"][0]["extras"] = {1, "two", nullptr};
  const std::string input = save("schema_extensions", doc);
  const Scene scene = load_gltf(input).scene;
  EXPECT_TRUE(warned(scene, "declared EXT_vendor_thing in /extensionsUsed"));
  EXPECT_TRUE(warned(scene, "dropped /materials/1/extensions/EXT_vendor_broken"));
  EXPECT_TRUE(warned(scene, "dropped /materials/1/extensions/KHR_lights_punctual"));
  EXPECT_TRUE(warned(scene, "dropped KHR_texture_transform from /extensionsRequired"));

  const json out = bake(input, "schema_extensions_out");
  EXPECT_EQ(out["materials"][0]["extensions"]["EXT_vendor_thing"]["level"], 3);
  EXPECT_FALSE(out["materials"][1]["extensions"].contains("EXT_vendor_broken"));
  EXPECT_FALSE(out["materials"][1]["extensions"].contains("KHR_lights_punctual"));
  const json& used = out["extensionsUsed"];
  EXPECT_EQ(std::count(used.begin(), used.end(), "EXT_vendor_thing"), 1);
  EXPECT_EQ(std::count(used.begin(), used.end(), doc["extensionsUsed"][0]), 1);
  EXPECT_FALSE(out.contains("extensionsRequired"));
  EXPECT_EQ(out["nodes"][0]["extras"], json({1, "two", nullptr}));
}

TEST(GltfCheck, AGlbIsReassembledAroundItsCleanedJson) {
  // lit_room.glb with a normalTexture that has no index: the BIN chunk must still be found.
  std::ifstream in(test::source_path("tests/fixtures/lit_room.glb"), std::ios::binary);
  std::vector<char> glb((std::istreambuf_iterator<char>(in)), {});
  uint32_t json_length;
  std::memcpy(&json_length, glb.data() + 12, 4);
  json doc = json::parse(glb.begin() + 20, glb.begin() + 20 + json_length);
  doc["materials"][0]["normalTexture"] = {{"texCoord", 0}};
  std::string text = doc.dump();
  text.append((4 - text.size() % 4) % 4, ' ');
  std::vector<char> edited(glb.begin(), glb.begin() + 12);
  const uint32_t length = uint32_t(text.size()), type = 0x4E4F534Au;
  edited.insert(edited.end(), reinterpret_cast<const char*>(&length), reinterpret_cast<const char*>(&length) + 4);
  edited.insert(edited.end(), reinterpret_cast<const char*>(&type), reinterpret_cast<const char*>(&type) + 4);
  edited.insert(edited.end(), text.begin(), text.end());
  edited.insert(edited.end(), glb.begin() + 20 + ((json_length + 3) & ~3u), glb.end());
  const uint32_t total = uint32_t(edited.size());
  std::memcpy(edited.data() + 8, &total, 4);
  const std::string path = test::fresh_folder("schema_glb") + "/edited.glb";
  std::ofstream(path, std::ios::binary).write(edited.data(), std::streamsize(edited.size()));

  const Scene original = load_gltf(test::source_path("tests/fixtures/lit_room.glb")).scene;
  const Scene cleaned = load_gltf(path).scene;
  EXPECT_TRUE(warned(cleaned, "dropped /materials/0/normalTexture"));
  ASSERT_EQ(cleaned.instances.size(), original.instances.size());
  for (size_t i = 0; i < original.instances.size(); ++i)
    EXPECT_EQ(cleaned.instances[i].positions.size(), original.instances[i].positions.size());
  const json out = bake(path, "schema_glb_out");
  EXPECT_FALSE(out["materials"][0].contains("normalTexture"));
}

// KHR_lights_punctual's one rule for a spot's cone: 0 <= innerConeAngle < outerConeAngle <= pi/2.
TEST(GltfCheck, ASpotsInnerConeIsAtLeastZeroAndBelowItsOuterCone) {
  auto with_spot = [](double inner, double outer) {
    json doc = room();
    doc["extensionsUsed"].push_back("KHR_lights_punctual");
    doc["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"type", "spot"}, {"intensity", 10}, {"spot", {{"innerConeAngle", inner}, {"outerConeAngle", outer}}}}};
    doc["nodes"][6]["extensions"]["KHR_lights_punctual"] = {{"light", 0}};
    return doc;
  };
  const std::string pointer = ": /extensions/KHR_lights_punctual/lights/0/spot/innerConeAngle: ";
  EXPECT_NE(refusal(with_spot(0.4, 0.4), "spot_equal").find(pointer + "must be below outerConeAngle"), std::string::npos);
  EXPECT_NE(refusal(with_spot(0.5, 0.4), "spot_wider").find(pointer + "must be below outerConeAngle"), std::string::npos);
  EXPECT_NE(refusal(with_spot(-0.1, 0.4), "spot_negative").find(pointer + "is -0.1; must be from 0 to"), std::string::npos);
  EXPECT_EQ(refusal(with_spot(0, 0.4), "spot_zero"), "(loaded)");
  EXPECT_EQ(refusal(with_spot(0.39, 0.4), "spot_just_below"), "(loaded)");
}

// The table of extensions (io/gltf/gltf_extensions.h) against what io/gltf really does with them.

// Every extension name io/gltf spells out has its row: a reader or writer that learns an extension
// without the table would be caught here.
TEST(GltfExtensions, EveryExtensionTheGltfCodeNamesHasARow) {
  const std::regex quoted("\"((KHR|EXT|MOZ)_[A-Za-z_]+)\"");
  std::set<std::string> named;
  for (const auto& entry : std::filesystem::directory_iterator(test::source_path("io/gltf"))) {
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    const std::string code = text.str();
    for (auto it = std::sregex_iterator(code.begin(), code.end(), quoted); it != std::sregex_iterator(); ++it)
      named.insert((*it)[1]);
  }
  named.erase("KHR_materials_");  // the prefix the shared row answers for
  EXPECT_GE(named.size(), 10u);
  for (const std::string& name : named) {
    const GltfExtension* row = gltf_extension(name);
    EXPECT_TRUE(row && name == row->name) << name << " is named in io/gltf but has no row of its own";
  }
}

// A file that lists an extension in extensionsRequired bakes exactly when its row says so; one
// that requires an extension without a row, or a Khronos material extension without one, is refused.
TEST(GltfExtensions, ARequiredExtensionBakesExactlyWhenItsRowSaysSo) {
  std::vector<std::pair<std::string, bool>> cases = {{"EXT_made_up_here", false}, {"KHR_materials_made_up_here", false}};
  for (const GltfExtension& row : gltf_extensions()) cases.emplace_back(row.name, row.bakes_when_required);
  for (const auto& [name, bakes] : cases) {
    json doc = room();
    doc["extensionsUsed"].push_back(name);
    doc["extensionsRequired"] = {name};
    const std::string outcome = refusal(doc, "required_" + name);
    if (bakes) EXPECT_EQ(outcome, "(loaded)") << name;
    else EXPECT_NE(outcome.find("/extensionsRequired: the file requires extension " + name), std::string::npos) << outcome;
  }
}

// Where each row says an extension may sit: elsewhere it is dropped with a warning (a material's
// extension on a node, a node's on a material). Where it may sit, an extension radbake reads
// refuses the file when its object is not an object; any other is dropped.
TEST(GltfExtensions, EachSitsWhereItsRowSaysAndAnInvalidOneIsRefusedOnlyIfRadbakeReadsIt) {
  size_t placed = 0;
  for (const GltfExtension& row : gltf_extensions()) {
    if (row.sits_on == 0) continue;
    ++placed;
    const std::string name = row.name;
    const bool on_material = row.sits_on & kOnMaterial;
    json doc = room();
    doc["extensionsUsed"].push_back(name);
    if (on_material) doc["nodes"][0]["extensions"][name] = json::object();
    else doc["materials"][0]["extensions"][name] = json::object();
    const Scene scene = load_gltf(save("misplaced_" + name, doc)).scene;
    EXPECT_TRUE(warned(scene, on_material ? "dropped /nodes/0/extensions/" + name : "dropped /materials/0/extensions/" + name))
        << name;

    doc = room();
    doc["extensionsUsed"].push_back(name);
    json* where = &doc;
    std::string at = "";
    if (row.sits_on & kOnMaterial) where = &doc["materials"][0], at = "/materials/0";
    else if (row.sits_on & kOnTextureInfo)
      where = &doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"],
      at = "/materials/0/pbrMetallicRoughness/baseColorTexture";
    (*where)["extensions"][name] = 5;
    const std::string outcome = refusal(doc, "not_an_object_" + name);
    if (row.refused_when_invalid) {
      EXPECT_NE(outcome.find(at + "/extensions/" + name + ": must be an object"), std::string::npos) << outcome;
    } else {
      EXPECT_EQ(outcome, "(loaded)") << name;
      EXPECT_TRUE(warned(load_gltf(save("not_an_object_" + name, doc)).scene, "dropped " + at + "/extensions/" + name))
          << name;
    }
  }
  EXPECT_GE(placed, 12u);
}

}  // namespace
}  // namespace radbake
