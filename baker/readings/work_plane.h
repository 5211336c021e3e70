// A work plane: sensors on a grid at a height over the floors (CIE and EN 12464 measure
// illuminance on a horizontal plane, usually 0.8 m up for desks, 0 for circulation).
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
  // Which surfaces are floors: instances whose name holds one of these. Empty: under each grid
  // point, the lowest surface facing up.
  std::vector<std::string> over;
  size_t max_points = 1000000;  // refused beyond (a spacing too fine for the scene)
};

// The grid over the floors' extent in x and z (glTF's +Y up), cell centres at x0 + (c + 0.5) s.
struct WorkPlane {
  double x0 = 0, z0 = 0, spacing = 0;
  int columns = 0, rows = 0;
  std::vector<int32_t> sensor_at;  // rows x columns, row r at z0 + (r + 0.5) s; -1: no floor under it
  std::vector<Sensor> sensors;     // facing up
};

// Throws InputError when no floor is found or the grid would exceed max_points.
WorkPlane work_plane(const Scene& scene, const Surface& surface, const RayTracer& tracer,
                     const WorkPlaneOptions& options);

}  // namespace radbake
