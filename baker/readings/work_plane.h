// A work plane: sensors on a grid at a height over the floors (CIE and EN 12464 measure
// illuminance on a horizontal plane, usually 0.8 m up for desks, 0 for circulation), indoors only
// unless asked, one grid per storey, and the rooms the walls divide each storey into.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "baker/readings/sensor_points.h"
#include "baker/surface/ray_tracer.h"
#include "baker/surface/surface.h"
#include "base/scene.h"

namespace radbake {

struct WorkPlaneOptions {
  bool enabled = false;
  double height = 0.8;   // metres above the floor
  double spacing = 0.5;  // metres between grid points, along x and z
  // Which surfaces are floors: instances whose name holds one of these. Empty: every surface
  // facing up.
  std::vector<std::string> over;
  // false: only points under a roof and between walls (enclosed()); terrain, roofs and balconies
  // open to the sky are left out. true: every floor, as for a plaza or a sports field.
  bool outdoors = false;
  size_t max_points = 1000000;  // refused beyond (a spacing too fine for the scene)
};

// One level of floors: its grid of points.
struct WorkPlaneStorey {
  double floor_height = 0;         // metres: the most common floor height of the level
  std::vector<int32_t> sensor_at;  // rows x columns, row r at z0 + (r + 0.5) s; -1: no point there
};

// A region of one storey's grid that walls enclose: cells joined where a point sees its neighbour.
struct WorkPlaneRoom {
  int storey = 0;                 // index into WorkPlane::storeys
  int number = 0;                 // 1, 2, ... within its storey, in reading order of the map
  std::vector<int32_t> sensors;   // the points, indexed as sensor_at indexes them
  int label_column = 0, label_row = 0;  // the cell its number is drawn on: one of its own, central
};

// The grid over the floors' extent in x and z (glTF's +Y up), cell centres at x0 + (c + 0.5) s.
struct WorkPlane {
  double x0 = 0, z0 = 0, spacing = 0;
  int columns = 0, rows = 0;
  std::vector<WorkPlaneStorey> storeys;  // lowest first
  std::vector<WorkPlaneRoom> rooms;      // by storey, then number
  std::vector<Sensor> sensors;           // facing up
  size_t outdoor_points = 0;             // floor points left out as open to the sky or unwalled
  size_t sliver_points = 0;              // left out in regions under 1 m2 and 5% of their storey's largest
};

// Throws InputError when no floor is found or the grid would exceed max_points.
WorkPlane work_plane(const Scene& scene, const Surface& surface, const RayTracer& tracer,
                     const WorkPlaneOptions& options);

// A work plane whose sensors were appended after `offset` others: its indices shifted to match.
void shift_sensor_indices(WorkPlane& plane, int32_t offset);

// Whether a point is indoors: something above it, walls round it (at least 12 of 16 horizontal
// rays hit a surface within `reach` metres), and not inside a solid (a wall's core).
bool enclosed(const RayTracer& tracer, Vec3 point, float reach);

}  // namespace radbake
