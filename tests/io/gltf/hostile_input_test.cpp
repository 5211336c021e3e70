// Real and hostile input: every way a file crashed radbake, read files outside its
// folder, answered with a library's words or ran out of memory, each refused with one line that
// names the JSON pointer of the object at fault. Fixtures: tests/fixtures/make_hostile_fixtures.py.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "base/errors.h"
#include "io/gltf/gltf_loader.h"
#include "support/commands.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

namespace fs = std::filesystem;

std::string hostile(const std::string& name) { return test::source_path("tests/fixtures/hostile/" + name + ".gltf"); }

// The message load_gltf refuses `path` with; fails the test when it loads.
std::string refusal(const std::string& path, const LoadOptions& options = {}) {
  try {
    load_gltf(path, options);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << path << " loaded";
  return "";
}

// "FILE: POINTER: WHAT", one line.
void expect_refused(const std::string& message, const std::string& path, const std::string& pointer,
                    const std::string& says) {
  EXPECT_EQ(message.rfind(path + ": " + pointer + ": ", 0), 0u) << message;
  EXPECT_NE(message.find(says), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

// A copy of the hostile floor in a folder of its own, its JSON changed by `change`.
std::string floor_variant(const std::string& folder_name, const std::function<void(nlohmann::json&)>& change) {
  const std::string folder = test::fresh_folder(folder_name);
  nlohmann::json doc = nlohmann::json::parse(test::slurp(hostile("lit_textured_floor")));
  change(doc);
  fs::copy_file(test::source_path("tests/fixtures/hostile/texture.png"), folder + "/texture.png");
  std::ofstream(folder + "/scene.gltf") << doc.dump();
  return folder + "/scene.gltf";
}

TEST(HostileInput, TheBaseFloorLoadsWithItsTexture) {
  LoadedScene s = load_gltf(hostile("lit_textured_floor"));
  ASSERT_EQ(s.scene.images.size(), 1u);
  EXPECT_EQ(s.scene.images[0].width, 4);
  EXPECT_EQ(s.estimate.triangles, 2u);
}

TEST(HostileInput, ImageOutsideTheFolderIsRefused) {
  for (const char* name : {"image_absolute_path", "image_parent_path", "image_escaped_parent_path"})
    expect_refused(refusal(hostile(name)), hostile(name), "/images/0/uri", "names a file outside the scene's folder");
}

TEST(HostileInput, BufferOutsideTheFolderIsRefused) {
  for (const char* name : {"buffer_absolute_path", "buffer_parent_path"})
    expect_refused(refusal(hostile(name)), hostile(name), "/buffers/0/uri", "names a file outside the scene's folder");
}

TEST(HostileInput, SymlinkLeadingOutIsRefused) {
  const std::string path = floor_variant("hostile_symlink", [](nlohmann::json& doc) { doc["images"][0]["uri"] = "link.png"; });
  fs::create_symlink(test::source_path("tests/fixtures/outside_texture.png"), fs::path(path).parent_path() / "link.png");
  expect_refused(refusal(path), path, "/images/0/uri", "is a link to a file outside the scene's folder");
  // A link that stays inside is an ordinary file of the scene.
  fs::remove(fs::path(path).parent_path() / "link.png");
  fs::create_symlink("texture.png", fs::path(path).parent_path() / "link.png");
  EXPECT_EQ(load_gltf(path).scene.images[0].width, 4);
}

TEST(HostileInput, AllowExternalFilesReadsTheOutsideImage) {
  LoadOptions options;
  options.allow_external_files = true;
  LoadedScene s = load_gltf(hostile("image_parent_path"), options);
  ASSERT_EQ(s.scene.images.size(), 1u);
  EXPECT_EQ(s.scene.images[0].width, 4);
  EXPECT_NEAR(s.scene.images[0].channel(0, 0, 1), 200 / 255.0, 1e-6);  // the outside texture is green
}

TEST(HostileInput, AccessorClaiming2To31ElementsIsRefusedBeforeAllocating) {
  expect_refused(refusal(hostile("accessor_2g_elements")), hostile("accessor_2g_elements"), "/accessors/0",
                 "2147483648 elements need 25769803776 bytes of bufferView 0, which has 48");
  // Without a bufferView nothing in the file bounds the count: the triangle budget does.
  expect_refused(refusal(hostile("accessor_2g_zeros")), hostile("accessor_2g_zeros"), "/",
                 "715827882 triangles after instancing, more than --max-triangles 20000000");
}

TEST(HostileInput, DeeplyNestedExtrasAreRefusedBeforeParsing) {
  const std::string message = refusal(hostile("deep_extras"));
  EXPECT_NE(message.find("JSON nested deeper than 128 levels"), std::string::npos) << message;
}

TEST(HostileInput, ChainOf100000NodesLoads) {
  // Valid glTF, deeper than any recursion over nodes survives.
  const std::string path = floor_variant("hostile_chain", [](nlohmann::json& doc) {
    const size_t first = doc["nodes"].size(), length = 100000;
    for (size_t i = 0; i < length; ++i) {
      nlohmann::json node = {{"translation", {0, 0, 1e-6}}};
      if (i + 1 < length) node["children"] = {first + i + 1};
      else node["mesh"] = 0;
      doc["nodes"].push_back(node);
    }
    doc["scenes"][0]["nodes"].push_back(first);
  });
  LoadedScene s = load_gltf(path);
  ASSERT_EQ(s.scene.instances.size(), 2u);
  EXPECT_NEAR(s.scene.instances[1].positions[0].z, 0.1, 1e-4);  // 100,000 steps of a micrometre
}

TEST(HostileInput, InstancingBombIsRefusedAsANodeWithTwoParents) {
  expect_refused(refusal(hostile("instancing_bomb")), hostile("instancing_bomb"), "/nodes/3/children/0",
                 "node 4 is already a child of node 2; a glTF node has at most one parent");
}

TEST(HostileInput, CycleIsRefused) {
  const std::string path = floor_variant("hostile_cycle", [](nlohmann::json& doc) {
    doc["nodes"][0]["children"] = {1};
    doc["nodes"][1]["children"] = {0};
  });
  expect_refused(refusal(path), path, "/scenes/0/nodes/0", "node 0 is a child of node 1, not a root");
}

TEST(HostileInput, TangentShorterThanPositionIsRefused) {
  expect_refused(refusal(hostile("tangent_short")), hostile("tangent_short"), "/meshes/0/primitives/0/attributes/TANGENT",
                 "accessor 4 has 2 elements, POSITION has 4");
}

TEST(HostileInput, ColourOutsideZeroToOneIsRefused) {
  // COLOR_0 on the floor's positions: vertex 1 is at x = 2, a base-colour multiplier of 2.
  const std::string path = floor_variant("hostile_bright_colour", [](nlohmann::json& doc) {
    doc["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = 0;
  });
  expect_refused(refusal(path), path, "/meshes/0/primitives/0/attributes/COLOR_0", "has 2.000000 at vertex 1; colours lie in [0, 1]");
}

TEST(HostileInput, MaterialMinusOneIsRefused) {
  expect_refused(refusal(hostile("material_minus_one")), hostile("material_minus_one"), "/meshes/0/primitives/0/material",
                 "is -1; must be from 0 to 0");
}

TEST(HostileInput, TextureTransformScale1e19IsRefused) {
  expect_refused(refusal(hostile("texture_transform_1e19")), hostile("texture_transform_1e19"),
                 "/materials/0/pbrMetallicRoughness/baseColorTexture/extensions/KHR_texture_transform/scale/0",
                 "must be a number from -1000000 to 1000000");
}

TEST(HostileInput, Translation1e20IsRefused) {
  expect_refused(refusal(hostile("translation_1e20")), hostile("translation_1e20"), "/nodes/0",
                 "vertex 0 of its mesh lands at (1e+20, 0, 0) m, beyond the 1e7 m radbake bakes");
}

TEST(HostileInput, LightIntensity3e38IsRefused) {
  expect_refused(refusal(hostile("intensity_3e38")), hostile("intensity_3e38"),
                 "/extensions/KHR_lights_punctual/lights/0/intensity", "3.4e+38 cd is above the 1e+20 radbake bakes");
}

TEST(HostileInput, EmissiveStrength3e38IsRefused) {
  expect_refused(refusal(hostile("emissive_strength_3e38")), hostile("emissive_strength_3e38"),
                 "/materials/0/extensions/KHR_materials_emissive_strength/emissiveStrength",
                 "luminance of 3e+38 cd/m2, above the 1e+20");
}

TEST(HostileInput, BufferViewPastItsBufferIsRefusedEvenUnused) {
  expect_refused(refusal(hostile("buffer_view_past_buffer")), hostile("buffer_view_past_buffer"), "/bufferViews/4",
                 "runs past the end of buffer 0 (byteOffset + byteLength = 148, its byteLength is 140)");
}

TEST(HostileInput, InvalidByteStrideIsRefused) {
  expect_refused(refusal(hostile("byte_stride_not_multiple_of_4")), hostile("byte_stride_not_multiple_of_4"),
                 "/bufferViews/0/byteStride", "must be a multiple of 4");
  expect_refused(refusal(hostile("byte_stride_smaller_than_element")), hostile("byte_stride_smaller_than_element"),
                 "/accessors/0", "elements of 12 bytes do not fit bufferView 0's byteStride");
}

TEST(HostileInput, WrongJsonTypesAreOurWordsNotTheLibrarys) {
  // In what radbake reads, a slip refuses the file; in what it only copies (a name), the slip is
  // dropped with a warning naming it. tinygltf's own words (type_error.302) never show.
  const std::string refused = floor_variant("hostile_types", [](nlohmann::json& doc) { doc["nodes"][0]["mesh"] = "0"; });
  expect_refused(refusal(refused), refused, "/nodes/0/mesh", "");
  const std::string copied = floor_variant("hostile_types_copied", [](nlohmann::json& doc) { doc["meshes"][0]["name"] = 7; });
  const LoadedScene loaded = load_gltf(copied);
  EXPECT_TRUE(std::any_of(loaded.scene.warnings.begin(), loaded.scene.warnings.end(),
                          [](const std::string& w) { return w.find("/meshes/0/name") != std::string::npos; }));
}

TEST(HostileInput, BudgetsNameTheEstimateAndTheOption) {
  LoadOptions few;
  few.max_triangles = 1;
  expect_refused(refusal(hostile("lit_textured_floor"), few), hostile("lit_textured_floor"), "/",
                 "the scene has 2 triangles after instancing, more than --max-triangles 1 allows");
  LoadOptions small;
  small.max_memory_bytes = 1 << 20;
  expect_refused(refusal(hostile("lit_textured_floor"), small), hostile("lit_textured_floor"), "/",
                 "more than --max-memory 0.00 GB allows");
  // The lightmap's part: a 16384-texel page is 268 million texels.
  LoadedScene s = load_gltf(hostile("lit_textured_floor"));
  AtlasOptions huge;
  huge.max_page_size = 16384;
  LoadOptions eight_gb;
  eight_gb.max_memory_bytes = uint64_t(8) << 30;
  try {
    check_bake_budget(s, huge, eight_gb, "floor.gltf");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("268435456 lightmap texels"), std::string::npos) << e.what();
  }
  EXPECT_EQ(check_bake_budget(s, AtlasOptions{}, eight_gb, "floor.gltf").texels, 1024u * 1024u);
}

}  // namespace
}  // namespace radbake
