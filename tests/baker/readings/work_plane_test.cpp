// The work plane (baker/readings/work_plane.h): a grid at a height over the floors, indoors only
// unless asked, a grid per storey, and rooms where walls divide a storey.
#include <gtest/gtest.h>

#include <cmath>

#include "support/closed_forms.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

BakeOptions lamp_and_work_plane(Scene& scene, Vec3 lamp_at) {
  Light lamp;
  lamp.intensity = 100;
  lamp.position = lamp_at;
  scene.lights.push_back(lamp);
  BakeOptions options;
  options.gather.rays = 4;  // the readings' values are not what these tests look at
  options.work_plane.enabled = true;
  options.work_plane.spacing = 0.5;
  return options;
}

TEST(WorkPlane, AGridAtAHeightOverTheNamedFloorsOnly) {
  Scene scene;
  const int grey = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  test::add_quad(scene, {0, 0, 2}, {3, 0, 0}, {0, 0, -2}, grey, "classroom floor");  // 3 x 2 m at y = 0
  test::add_quad(scene, {0, 0.75f, 1}, {1, 0, 0}, {0, 0, -1}, grey, "desk");          // a desk top over it
  test::add_quad(scene, {5, 0.2f, 2}, {2, 0, 0}, {0, 0, -2}, grey, "terrace");        // elsewhere, higher
  Light lamp;
  lamp.intensity = 100;
  lamp.position = {1.5f, 2.5f, 1};
  scene.lights.push_back(lamp);
  BakeOptions options;
  options.work_plane.enabled = true;
  options.work_plane.over = {"floor"};
  options.work_plane.spacing = 0.5;
  options.work_plane.outdoors = true;  // quads in the open
  const BakeResult r = test::bake_scene(scene, test::coarse_atlas(), options).result;
  const WorkPlane& plane = r.work_plane;
  EXPECT_EQ(plane.columns, 6);
  EXPECT_EQ(plane.rows, 4);
  ASSERT_EQ(r.sensors.size(), 24u);
  for (const Sensor& s : r.sensors) {
    EXPECT_FLOAT_EQ(s.position.y, 0.8f);  // over the floor, not the desk: the lowest floor
    EXPECT_LT(s.position.x, 3.0f);        // not over the terrace
  }
  // Without names: every surface facing up, the lowest under each point in the one storey (the
  // desk, the floor and the terrace are within a storey's height), the terrace's points too.
  options.work_plane.over.clear();
  const BakeResult all = test::bake_scene(scene, test::coarse_atlas(), options).result;
  size_t terrace = 0;
  for (const Sensor& s : all.sensors) terrace += s.position.x > 4.9f && std::fabs(s.position.y - 1.0f) < 1e-5f;
  EXPECT_EQ(terrace, 16u);  // 2 x 2 m at 0.5 m
  // Facing up with nothing above but the lamp, each point reads I cos / d^2 (1e-4: float
  // rounding; the floor and the desk top below the plane are behind the meter).
  for (size_t k = 0; k < r.sensors.size(); ++k) {
    const double lamp_lux = test::point_light_lux(100, lamp.position, r.sensors[k].position, {0, 1, 0});
    EXPECT_NEAR(r.sensor_lux[k], lamp_lux, 1e-4 * lamp_lux);
  }
}

TEST(WorkPlane, AtHeightZeroItIsNotShadedByTheFloorItLiesOn) {
  Scene scene;
  const int grey = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  test::add_quad(scene, {0, 0, 2}, {2, 0, 0}, {0, 0, -2}, grey, "floor");
  BakeOptions options = test::under_a_uniform_sky(1000);
  options.sky.rays = 64;
  options.work_plane.enabled = true;
  options.work_plane.height = 0;
  options.work_plane.outdoors = true;
  const BakeResult r = test::bake_scene(scene, test::coarse_atlas(), options).result;
  ASSERT_EQ(r.sensors.size(), 16u);
  // pi L at every point: 1e-4 bounds float rounding; a ray stopped by the floor would take 1/64.
  for (double lux : r.sensor_lux) EXPECT_NEAR(lux, M_PI * 1000, 1e-4 * M_PI * 1000);
}

// A 4 x 3 x 4 m room (walls facing in) in the middle of a 12 x 12 m terrain, a flat roof-top on
// it, and an open canopy over part of the terrain: only the room's floor is indoors.
TEST(WorkPlane, CoversEnclosedFloorsOnlyUnlessAskedForOutdoors) {
  Scene scene;
  const int grey = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  test::add_box(scene, {0, 0, 0}, {4, 3, 4}, true, grey, "room");
  test::add_box(scene, {-0.2f, 3, -0.2f}, {4.2f, 3.2f, 4.2f}, false, grey, "roof slab");
  test::add_quad(scene, {-4, -0.01f, 8}, {12, 0, 0}, {0, 0, -12}, grey, "terrain");
  test::add_quad(scene, {5, 2.5f, 7}, {2, 0, 0}, {0, 0, -2}, grey, "canopy");  // facing up, open on every side
  BakeOptions options = lamp_and_work_plane(scene, {2, 2.5f, 2});
  const BakeResult inside = test::bake_scene(scene, test::coarse_atlas(), options).result;
  const WorkPlane& plane = inside.work_plane;
  ASSERT_EQ(plane.storeys.size(), 1u);
  EXPECT_EQ(plane.sensors.size(), 64u);  // the room's 4 x 4 m at 0.5 m
  for (const Sensor& s : plane.sensors) {
    EXPECT_TRUE(s.position.x > 0 && s.position.x < 4 && s.position.z > 0 && s.position.z < 4) << s.position.x << "," << s.position.z;
    EXPECT_NEAR(s.position.y, 0.8f, 1e-5);  // float rounding of the floor found 4.2 m down
  }
  // Left out: the terrain's other points, the roof's top, the canopy's top.
  EXPECT_EQ(plane.outdoor_points, 24u * 24u - 64u + 64u + 16u);
  ASSERT_EQ(plane.rooms.size(), 1u);
  EXPECT_EQ(plane.rooms[0].sensors.size(), 64u);
  // Asked for outdoors: every floor point, in two storeys (the terrain and the room's floor at 0,
  // the roof at 3.2; the canopy at 2.5 is within a storey's height of the roof, so it falls in
  // the storey at 0, under whose points the terrain is lower).
  options.work_plane.outdoors = true;
  const BakeResult all = test::bake_scene(scene, test::coarse_atlas(), options).result;
  EXPECT_EQ(all.work_plane.outdoor_points, 0u);
  size_t points = 0;
  for (const WorkPlaneStorey& storey : all.work_plane.storeys)
    for (int32_t k : storey.sensor_at) points += k >= 0;
  EXPECT_EQ(points, all.work_plane.sensors.size());
  EXPECT_GT(points, 24u * 24u);
}

// Two storeys of a 6 x 3 x 4 m house, the lower one split by a wall at x = 3 with a door-less
// opening nowhere: three rooms, two maps' worth of grids.
TEST(WorkPlane, AGridPerStoreyAndARoomPerEnclosedRegion) {
  Scene scene;
  const int grey = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  test::add_box(scene, {0, 0, 0}, {6, 3, 4}, true, grey, "ground floor");
  test::add_box(scene, {2.95f, 0, 0}, {3.05f, 3, 4}, false, grey, "partition");
  test::add_box(scene, {0, 3.2f, 0}, {6, 6, 4}, true, grey, "first floor");
  test::add_box(scene, {1, 3.9f, 1}, {2, 3.95f, 2}, false, grey, "desk top");  // not a storey (its legs left out)
  BakeOptions options = lamp_and_work_plane(scene, {1.5f, 2.5f, 2});
  const BakeResult r = test::bake_scene(scene, test::coarse_atlas(), options).result;
  const WorkPlane& plane = r.work_plane;
  ASSERT_EQ(plane.columns, 12);
  ASSERT_EQ(plane.rows, 8);
  ASSERT_EQ(plane.storeys.size(), 2u);
  EXPECT_NEAR(plane.storeys[0].floor_height, 0, 0.05);   // within the levels' 5 cm bins
  EXPECT_NEAR(plane.storeys[1].floor_height, 3.2, 0.05);
  for (size_t s = 0; s < 2; ++s) {
    size_t points = 0;
    for (int32_t k : plane.storeys[s].sensor_at) {
      if (k < 0) continue;
      ++points;
      // Over the storey's floor, not the desk (whose top is under the plane's 3.2 + 0.8 m).
      EXPECT_NEAR(r.sensors[size_t(k)].position.y, plane.storeys[s].floor_height + 0.8, 1e-4) << s;
    }
    EXPECT_EQ(points, 96u) << s;  // every cell of 6 x 4 m at 0.5 m
  }
  ASSERT_EQ(plane.rooms.size(), 3u);
  // The ground floor's two rooms, numbered in reading order (the west one first), 48 points each.
  EXPECT_EQ(plane.rooms[0].storey, 0);
  EXPECT_EQ(plane.rooms[1].storey, 0);
  EXPECT_EQ(plane.rooms[2].storey, 1);
  EXPECT_EQ(plane.rooms[0].number, 1);
  EXPECT_EQ(plane.rooms[1].number, 2);
  EXPECT_EQ(plane.rooms[2].number, 1);
  EXPECT_EQ(plane.rooms[0].sensors.size(), 48u);
  EXPECT_EQ(plane.rooms[1].sensors.size(), 48u);
  EXPECT_EQ(plane.rooms[2].sensors.size(), 96u);
  for (int32_t k : plane.rooms[0].sensors) EXPECT_LT(r.sensors[size_t(k)].position.x, 3.0f);
  for (int32_t k : plane.rooms[1].sensors) EXPECT_GT(r.sensors[size_t(k)].position.x, 3.0f);
  // The lamp is in the west room: its points read the lamp, the east room's only what comes
  // round... nothing (the partition is closed): the rooms' readings differ as the picture shows.
  double west = 0, east = 0;
  for (int32_t k : plane.rooms[0].sensors) west += r.sensor_lux[size_t(k)];
  for (int32_t k : plane.rooms[1].sensors) east += r.sensor_lux[size_t(k)];
  EXPECT_GT(west, 100 * std::max(east, 1e-9));
}

}  // namespace
}  // namespace radbake
