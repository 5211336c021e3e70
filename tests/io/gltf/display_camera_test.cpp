// The display file's camera: the input's kept where its node's world transform puts it, or, where
// the input has none, one the bake chose: inside the largest room, or outside an open object.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

#include "base/math.h"
#include "support/commands.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

json read_json(const std::string& path) { return json::parse(test::slurp(path)); }

json glb_json(const std::string& path) {
  const std::string bytes = test::slurp(path);
  uint32_t length = 0;
  std::memcpy(&length, bytes.data() + 12, 4);
  return json::parse(bytes.substr(20, length));
}

// A copy of a sample (its .gltf rewritten by `edit`, its .bin beside it), baked fast under an
// overcast sky; returns the output folder.
std::string bake_edited(const std::string& sample, const std::string& case_name, const std::function<void(json&)>& edit) {
  const std::string folder = test::fresh_folder("display_camera_" + case_name);
  const std::string dir = test::source_path("samples/" + sample);
  json doc = read_json(dir + "/" + sample + ".gltf");
  edit(doc);
  std::ofstream(folder + "/" + sample + ".gltf") << doc.dump();
  fs::copy_file(dir + "/" + sample + ".bin", folder + "/" + sample + ".bin");
  const test::Outcome r = test::radbake("bake " + folder + "/" + sample + ".gltf -o " + folder + "/out --quality draft " +
                                        "--texels 5000 --sky cie-overcast --quiet");
  EXPECT_EQ(r.status, 0) << r.err;
  return folder + "/out";
}

struct View {
  json camera;
  Vec3 position, forward;
};

// The display file's camera nodes, read as the file places them: root nodes (asserted) with a
// translation and a rotation; glTF cameras look down their local -Z.
std::vector<View> cameras_of(const std::string& display) {
  const json doc = glb_json(display);
  std::vector<View> views;
  for (size_t n : doc["scenes"][0]["nodes"]) {
    const json& node = doc["nodes"][n];
    if (!node.contains("camera")) continue;
    const json t = node.value("translation", json{0, 0, 0}), q = node.value("rotation", json{0, 0, 0, 1});
    const float x = q[0], y = q[1], z = q[2], w = q[3];
    views.push_back({doc["cameras"][size_t(node["camera"])],
                     {t[0], t[1], t[2]},
                     {-2 * (x * z + w * y), -2 * (y * z - w * x), -(1 - 2 * (x * x + y * y))}});
  }
  for (const json& node : doc["nodes"])
    for (size_t child : node.value("children", json::array()))
      EXPECT_FALSE(doc["nodes"][child].contains("camera")) << "a camera node that is not a root";
  return views;
}

void expect_valid(const std::string& file) {
  ASSERT_TRUE(fs::exists(test::source_path("tests/tools/node_modules/gltf-validator")))
      << "the validator is not installed: run ./dev test (npm ci in tests/tools)";
  const test::Outcome v = test::run("node " + test::source_path("tests/tools/validate_gltf.mjs") + " " + file);
  EXPECT_EQ(v.status, 0) << v.out << v.err;
  const json summary = json::parse(v.out);
  EXPECT_EQ(summary["errors"], 0) << v.out;
  EXPECT_EQ(summary["warnings"], 0) << v.out;
  EXPECT_EQ(summary["infos"], 0) << v.out;
}

// Float round trips through JSON text and a quaternion: far below a millimetre.
constexpr float kPlaced = 1e-4f;

TEST(DisplayCamera, KeepsTheInputsCamerasAtTheirWorldTransforms) {
  // The Cornell box's camera (at (0.278, 0.273, -0.8), turned to look along +Z) put under a parent
  // that lifts it 1 m and turns it 90 degrees about +Y, which maps (x, y, z) to (z, y, -x); and an
  // orthographic camera on a root node looking down -Z from (0, 0, 5).
  const std::string out = bake_edited("cornell_box", "kept", [](json& doc) {
    const size_t camera_node = doc["nodes"].size() - 1;
    ASSERT_TRUE(doc["nodes"][camera_node].contains("camera"));
    const double h = std::sqrt(0.5);
    doc["nodes"].push_back({{"name", "rig"}, {"translation", {0, 1, 0}}, {"rotation", {0, h, 0, h}},
                            {"children", {camera_node}}});
    doc["cameras"].push_back({{"type", "orthographic"}, {"orthographic", {{"xmag", 2}, {"ymag", 1.5}, {"zfar", 50}, {"znear", 0.1}}}});
    doc["nodes"].push_back({{"name", "plan"}, {"camera", 1}, {"translation", {0, 0, 5}}});
    json& roots = doc["scenes"][0]["nodes"];
    roots.erase(std::remove(roots.begin(), roots.end(), json(camera_node)), roots.end());
    roots.push_back(doc["nodes"].size() - 2);
    roots.push_back(doc["nodes"].size() - 1);
  });
  const std::vector<View> views = cameras_of(out + "/cornell_box_display.glb");
  ASSERT_EQ(views.size(), 2u);
  const Vec3 want[2][2] = {{{-0.8f, 1.273f, -0.278f}, {1, 0, 0}}, {{0, 0, 5}, {0, 0, -1}}};
  for (size_t k = 0; k < 2; ++k) {
    EXPECT_LT(length(views[k].position - want[k][0]), kPlaced) << k;
    EXPECT_LT(length(views[k].forward - want[k][1]), kPlaced) << k;
  }
  EXPECT_EQ(views[0].camera["type"], "perspective");
  EXPECT_NEAR(double(views[0].camera["perspective"]["yfov"]), 0.6860478808414068, 1e-12);
  EXPECT_EQ(views[1].camera["orthographic"], json({{"xmag", 2}, {"ymag", 1.5}, {"zfar", 50}, {"znear", 0.1}}));
  const std::string said = read_json(out + "/report.json")["display"]["camera"];
  EXPECT_NE(said.find("the input's 2 cameras, first 'camera'"), std::string::npos) << said;
  expect_valid(out + "/cornell_box_display.glb");
}

void drop_cameras(json& doc) {
  doc.erase("cameras");
  for (json& node : doc["nodes"]) node.erase("camera");
}

TEST(DisplayCamera, AddedInsideTheCornellBoxLookingAtTheBackWall) {
  // The box spans x 0..0.556, y 0..0.549, z 0..0.559, open at z = 0; the back wall is at z = 0.559.
  const std::string out = bake_edited("cornell_box", "cornell", drop_cameras);
  const std::vector<View> views = cameras_of(out + "/cornell_box_display.glb");
  ASSERT_EQ(views.size(), 1u);
  const Vec3 p = views[0].position;
  EXPECT_TRUE(p.x > 0 && p.x < 0.556f && p.y > 0 && p.y < 0.549f && p.z > 0 && p.z < 0.559f)
      << p.x << " " << p.y << " " << p.z;
  EXPECT_GT(views[0].forward.z, 0.99f) << "not looking at the back wall";
  const std::string said = read_json(out + "/report.json")["display"]["camera"];
  EXPECT_NE(said.find("added, the input has none: inside the largest enclosed region"), std::string::npos) << said;
  expect_valid(out + "/cornell_box_display.glb");

  // Seen from it in stock three.js (the render harness), an 8 x 8 grid of pixels all strike the box:
  // the eye is inside, the open front behind it.
  std::string points;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) points += (points.empty() ? "" : ";") + std::to_string(4 + 8 * i) + "," + std::to_string(4 + 8 * j);
  const test::Outcome shot = test::run("node " + test::source_path("web/render/render.mjs") + " " + out +
                                       "/cornell_box_display.glb --camera gltf --size 64x64 --points '" + points + "'");
  ASSERT_EQ(shot.status, 0) << shot.err;
  int struck = 0;
  const json rendered = json::parse(shot.out);
  for (const json& p : rendered["points"]) struck += !p["hit"].is_null();
  EXPECT_EQ(struck, 64);
}

TEST(DisplayCamera, AddedInsideTheClassroomAlongItsLength) {
  // The room spans x 0..9, y 0..3, z 0..7: longest along x.
  const std::string out = bake_edited("classroom", "classroom", drop_cameras);
  const std::vector<View> views = cameras_of(out + "/classroom_display.glb");
  ASSERT_EQ(views.size(), 1u);
  const Vec3 p = views[0].position;
  EXPECT_TRUE(p.x > 0 && p.x < 9 && p.y > 1 && p.y < 2 && p.z > 0 && p.z < 7) << p.x << " " << p.y << " " << p.z;
  EXPECT_GT(std::fabs(views[0].forward.x), 0.99f);
}

TEST(DisplayCamera, AddedOutsideAnOpenObject) {
  // One 4 m floor facing up, open to the sky: no room, so a camera outside its bounding sphere
  // (centre (2, 0, 2), radius 2 sqrt 2) looking at its centre.
  const std::string folder = test::fresh_folder("display_camera_open");
  const test::Outcome r = test::radbake("bake " + test::source_path("tests/fixtures/open_floor.gltf") + " -o " + folder +
                                        "/out --quality draft --texels 2000 --sky cie-overcast --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<View> views = cameras_of(folder + "/out/open_floor_display.glb");
  ASSERT_EQ(views.size(), 1u);
  const Vec3 centre{2, 0, 2};
  const Vec3 to_centre = centre - views[0].position;
  EXPECT_GT(length(to_centre), 2 * std::sqrt(2.0f));
  EXPECT_GT(dot(normalize(to_centre), views[0].forward), 0.9999f);
  EXPECT_GT(views[0].position.z, centre.z) << "not in front (+Z) of the model";
  const std::string said = read_json(folder + "/out/report.json")["display"]["camera"];
  EXPECT_NE(said.find("no floor is enclosed: outside"), std::string::npos) << said;
  expect_valid(folder + "/out/open_floor_display.glb");
}

}  // namespace
}  // namespace radbake
