// The write stage as a library call: everything a bake's folder receives, from the result and
// plain options, and a stop between files that leaves the engine glTF unwritten.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "baker/pipeline/bake.h"
#include "baker/surface/back_faces.h"
#include "base/errors.h"
#include "io/gltf/gltf_loader.h"
#include "io/run/bake_outputs.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

struct CornellBake {
  LoadedScene loaded;
  Atlas atlas;
  BakeResult result;
};

CornellBake cornell_bake() {
  CornellBake b{load_gltf(test::source_path("samples/cornell_box/cornell_box.gltf")), {}, {}};
  add_back_faces(b.loaded.scene);
  b.atlas = test::unwrap(b.loaded.scene, test::coarse_atlas());
  b.result = bake(b.loaded.scene, b.atlas, BakeOptions{});
  return b;
}

TEST(BakeOutputs, WritesThePagesTheDisplayFileAndTheEngineGltfThatNamesThem) {
  CornellBake b = cornell_bake();
  const std::string folder = test::fresh_folder("bake_outputs");
  OutputOptions options;
  options.name = "box";
  const WrittenOutputs written = write_bake_outputs(b.loaded, b.atlas, b.result, options, folder);
  EXPECT_EQ(b.result.elements.size(), 0u) << "the per-element data is freed before writing";
  EXPECT_TRUE(b.result.irradiance.empty());
  EXPECT_EQ(written.gltf.gltf_file, "box.gltf");
  EXPECT_EQ(written.display.file, "box_display.glb");
  EXPECT_TRUE(std::filesystem::is_regular_file(folder + "/box_display.glb"));
  ASSERT_EQ(written.lightmaps.files.size(), b.atlas.pages.size());
  nlohmann::json gltf;
  std::ifstream(folder + "/box.gltf") >> gltf;
  const nlohmann::json& pages = gltf["extras"]["radbake"]["pages"];
  ASSERT_EQ(pages.size(), b.atlas.pages.size());
  for (size_t p = 0; p < pages.size(); ++p)
    for (const PageEncoding& encoding : page_encodings()) {
      const std::string file = pages[p][encoding.key].get<std::string>();
      EXPECT_EQ(file, written.lightmaps.files[p][size_t(&encoding - page_encodings().data())]);
      EXPECT_TRUE(std::filesystem::is_regular_file(folder + "/" + file)) << file;
    }
}

TEST(BakeOutputs, AStopBetweenFilesThrowsCancelledBeforeTheEngineGltf) {
  CornellBake b = cornell_bake();
  const std::string folder = test::fresh_folder("bake_outputs_stopped");
  OutputOptions options;
  options.name = "box";
  int asked = 0;
  options.go_on = [&] { return ++asked <= 2; };  // the pages, the directional pages and probes; not the display
  EXPECT_THROW(write_bake_outputs(b.loaded, b.atlas, b.result, options, folder), Cancelled);
  EXPECT_EQ(asked, 3);
  EXPECT_TRUE(std::filesystem::is_regular_file(folder + "/box_lightmap_0.exr"));
  EXPECT_FALSE(std::filesystem::exists(folder + "/box.gltf"));
  EXPECT_FALSE(std::filesystem::exists(folder + "/box_display.glb"));
}

}  // namespace
}  // namespace radbake
