#include "baker/readings/work_plane.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "base/errors.h"

namespace radbake {
namespace {

// Free space a floor needs above it, metres: less is the ground under a slab, or a slab's top under
// the wall standing on it.
constexpr float kFloorClearance = 0.3f;
// Enclosure is judged this high over the floor at least, so a plane at height 0 does not test
// from the floor itself.
constexpr float kLeastProbeHeight = 0.1f;
// Floor heights are counted in bins this tall; storeys' levels are bins at least kLeastStoreyHeight
// apart (desks, landings and steps are parts of the storey they stand in).
constexpr double kLevelBin = 0.05, kLeastStoreyHeight = 2.0;
// Neighbouring points further apart in height than this are not one room (a step up to a stage,
// a ramp's sides).
constexpr float kLeastRoomStep = 0.5f;
// Regions smaller than this, m2, and than this share of their storey's largest, are window
// reveals and gaps between walls, not rooms (a model a metre across keeps its one room).
constexpr double kLeastRoomArea = 1.0, kSliverShare = 0.05;
constexpr int kEnclosureRays = 16, kEnclosingHits = 12, kInsideSolidBacks = 4;
// How far above its storey's level a floor may be: higher is a window sill, a shelf or a stair's
// upper steps, not a floor to work at.
constexpr float kMostFloorRise = 0.5f;

// A hit on the top side of a surface that faces up (within 45 degrees).
bool faces_up(const Surface& surface, const Hit& hit) { return hit.front && surface.normal[hit.triangle].y > 0.7f; }

bool is_floor(const Scene& scene, const Surface& surface, uint32_t triangle, const std::vector<std::string>& over) {
  if (over.empty()) return true;
  const std::string& name = scene.instances[surface.instance[triangle]].name;
  return std::any_of(over.begin(), over.end(), [&](const std::string& part) { return name.find(part) != std::string::npos; });
}

struct FloorPoint {
  size_t cell;
  float floor_y;
  Vec3 probe;  // where enclosure and rooms are judged: max(height, kLeastProbeHeight) over the floor
};

// The storeys' levels: the most common floor heights, each at least kLeastStoreyHeight from any
// more common one; lowest first.
std::vector<double> storey_levels(const std::vector<FloorPoint>& points) {
  std::map<long long, size_t> count;
  for (const FloorPoint& p : points) ++count[std::llround(p.floor_y / kLevelBin)];
  std::vector<std::pair<long long, size_t>> bins(count.begin(), count.end());
  std::stable_sort(bins.begin(), bins.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  std::vector<double> levels;
  for (const auto& [bin, n] : bins) {
    const double y = double(bin) * kLevelBin;
    if (std::all_of(levels.begin(), levels.end(), [&](double l) { return std::fabs(l - y) >= kLeastStoreyHeight; }))
      levels.push_back(y);
  }
  std::sort(levels.begin(), levels.end());
  return levels;
}

// Union-find over cells, for rooms.
struct Regions {
  std::vector<size_t> parent;
  explicit Regions(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), size_t(0)); }
  size_t root(size_t k) {
    while (parent[k] != k) k = parent[k] = parent[parent[k]];
    return k;
  }
  void join(size_t a, size_t b) { parent[root(a)] = root(b); }
};

}  // namespace

bool enclosed(const RayTracer& tracer, Vec3 point, float reach) {
  const Hit above = tracer.intersect(point, {0, 1, 0}, 0, INFINITY);
  if (above.missed()) return false;
  int walls = 0, backs = 0;
  for (int k = 0; k < kEnclosureRays; ++k) {
    const float a = float(2 * M_PI) * (float(k) + 0.5f) / float(kEnclosureRays);
    const Hit hit = tracer.intersect(point, {std::cos(a), 0, std::sin(a)}, 0, reach);
    walls += !hit.missed();
    backs += !hit.missed() && !hit.front;
  }
  // Inside a solid (a wall's core) surfaces round show their backs: on the FZK-Haus 6 to 16 of the
  // 16 from points in walls, 0 or 1 from points in rooms (a one-sided pane turned the wrong way).
  const bool inside_a_solid = backs >= kInsideSolidBacks;
  return walls >= kEnclosingHits && !inside_a_solid;
}

WorkPlane work_plane(const Scene& scene, const Surface& surface, const RayTracer& tracer,
                     const WorkPlaneOptions& options) {
  // The extent: the floors' own (named ones), or everything's.
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (uint32_t t = 0; t < surface.triangle_count(); ++t) {
    if (!(surface.area[t] > 0)) continue;
    const bool counts = options.over.empty() || is_floor(scene, surface, t, options.over);
    for (int k = 0; k < 3; ++k) {
      const Vec3 c = surface.corners[3 * t + k];
      if (!counts) continue;
      lo = {std::min(lo.x, c.x), std::min(lo.y, c.y), std::min(lo.z, c.z)};
      hi = {std::max(hi.x, c.x), std::max(hi.y, c.y), std::max(hi.z, c.z)};
    }
  }
  if (!(lo.x <= hi.x)) throw InputError("no surface is named like the work plane's floors (--work-plane-over)");
  float top = -INFINITY;
  for (const Vec3& c : surface.corners) top = std::max(top, c.y);
  WorkPlane plane;
  plane.spacing = options.spacing;
  const double columns = std::ceil((hi.x - lo.x) / options.spacing), rows = std::ceil((hi.z - lo.z) / options.spacing);
  if (!(columns * rows <= double(options.max_points)))
    throw InputError("the work plane would have " + std::to_string(uint64_t(std::max(columns, 1.0) * std::max(rows, 1.0))) +
                     " points, more than " + std::to_string(options.max_points) + ": raise --work-plane-spacing");
  plane.columns = std::max(1, int(columns));
  plane.rows = std::max(1, int(rows));
  // Centred over the extent.
  plane.x0 = 0.5 * (lo.x + hi.x) - 0.5 * plane.columns * options.spacing;
  plane.z0 = 0.5 * (lo.z + hi.z) - 0.5 * plane.rows * options.spacing;
  const size_t cells = size_t(plane.columns) * size_t(plane.rows);
  const float start = top + 1, reach = std::max(surface.scene_extent, 1e-3f) * 2;
  const float probe_height = std::max(float(options.height), kLeastProbeHeight);

  // Every floor under every grid point: down through each surface, keeping the tops of floors
  // with room above them, indoors unless outdoors were asked for.
  std::vector<FloorPoint> floors;
  for (size_t cell = 0; cell < cells; ++cell) {
    const int r = int(cell / size_t(plane.columns)), c = int(cell % size_t(plane.columns));
    const float x = float(plane.x0 + (c + 0.5) * options.spacing), z = float(plane.z0 + (r + 0.5) * options.spacing);
    float t_near = 0;
    for (int crossed = 0; crossed < 256; ++crossed) {
      const Hit hit = tracer.intersect({x, start, z}, {0, -1, 0}, t_near, INFINITY);
      if (hit.missed()) break;
      t_near = hit.distance * (1 + 1e-6f) + 1e-6f;
      if (!faces_up(surface, hit) || !is_floor(scene, surface, hit.triangle, options.over)) continue;
      const float floor_y = start - hit.distance;
      const float lift = 1e-3f + 1e-6f * std::fabs(floor_y);
      if (tracer.occluded({x, floor_y, z}, {0, 1, 0}, lift, kFloorClearance)) continue;
      const Vec3 probe{x, floor_y + probe_height, z};
      if (!options.outdoors && !enclosed(tracer, probe, reach)) {
        ++plane.outdoor_points;
        continue;
      }
      floors.push_back({cell, floor_y, probe});
    }
  }
  if (floors.empty())
    throw InputError(plane.outdoor_points > 0
                         ? "the work plane found no enclosed floor (" + std::to_string(plane.outdoor_points) +
                               " points are open to the sky or unwalled): --work-plane-outdoors measures them"
                         : std::string("the work plane found no floor facing up under its grid"));

  // Storeys, and in each the lowest floor under each point (a desk's top is not a floor).
  const std::vector<double> levels = storey_levels(floors);
  std::vector<std::vector<const FloorPoint*>> lowest(levels.size(), std::vector<const FloorPoint*>(cells, nullptr));
  for (const FloorPoint& p : floors) {
    size_t s = 0;
    while (s + 1 < levels.size() && levels[s + 1] <= p.floor_y + kLevelBin) ++s;
    if (p.floor_y > levels[s] + kMostFloorRise) continue;
    const FloorPoint*& kept = lowest[s][p.cell];
    if (!kept || p.floor_y < kept->floor_y) kept = &p;
  }
  const size_t width = size_t(plane.columns);
  for (size_t s = 0; s < levels.size(); ++s) {
    const std::vector<const FloorPoint*>& at = lowest[s];
    // Rooms: neighbouring points that see each other at the probe height.
    Regions regions(cells);
    auto joins = [&](size_t a, size_t b) {
      if (!at[a] || !at[b]) return false;
      const Vec3 pa = at[a]->probe, pb = at[b]->probe;
      if (std::fabs(pa.y - pb.y) > kLeastRoomStep) return false;
      const Vec3 d = pb - pa;
      const float distance = length(d);
      return !tracer.occluded(pa, d * (1 / distance), 0, distance);
    };
    for (size_t cell = 0; cell < cells; ++cell) {
      if (cell % width + 1 < width && joins(cell, cell + 1)) regions.join(cell, cell + 1);
      if (cell + width < cells && joins(cell, cell + width)) regions.join(cell, cell + width);
    }
    // Numbered in reading order of the map: by each room's first cell, rows from -Z.
    std::map<size_t, size_t> room_of_root;
    std::vector<std::vector<size_t>> room_cells;
    for (size_t cell = 0; cell < cells; ++cell) {
      if (!at[cell]) continue;
      auto [it, added] = room_of_root.emplace(regions.root(cell), room_cells.size());
      if (added) room_cells.emplace_back();
      room_cells[it->second].push_back(cell);
    }
    WorkPlaneStorey storey;
    storey.floor_height = levels[s];
    storey.sensor_at.assign(cells, -1);
    int numbered = 0;
    size_t largest = 0;
    for (const std::vector<size_t>& in_room : room_cells) largest = std::max(largest, in_room.size());
    for (const std::vector<size_t>& in_room : room_cells) {
      if (double(in_room.size()) * options.spacing * options.spacing < kLeastRoomArea &&
          double(in_room.size()) < kSliverShare * double(largest)) {
        plane.sliver_points += in_room.size();
        continue;
      }
      WorkPlaneRoom room;
      room.storey = int(plane.storeys.size());  // the storey about to be kept
      room.number = ++numbered;
      double cx = 0, cz = 0;
      for (size_t cell : in_room) {
        const FloorPoint& p = *at[cell];
        storey.sensor_at[cell] = int32_t(plane.sensors.size());
        room.sensors.push_back(storey.sensor_at[cell]);
        plane.sensors.push_back({{p.probe.x, float(p.floor_y + options.height), p.probe.z}, {0, 1, 0}});
        cx += double(cell % width), cz += double(cell / width);
      }
      cx /= double(in_room.size()), cz /= double(in_room.size());
      // The label on the room's own cell nearest its centroid (an L-shaped room's centroid may lie
      // outside it).
      double nearest = INFINITY;
      for (size_t cell : in_room) {
        const double dx = double(cell % width) - cx, dz = double(cell / width) - cz;
        if (dx * dx + dz * dz < nearest)
          nearest = dx * dx + dz * dz, room.label_column = int(cell % width), room.label_row = int(cell / width);
      }
      plane.rooms.push_back(std::move(room));
    }
    if (numbered > 0) plane.storeys.push_back(std::move(storey));
  }
  return plane;
}

void shift_sensor_indices(WorkPlane& plane, int32_t offset) {
  for (WorkPlaneStorey& storey : plane.storeys)
    for (int32_t& k : storey.sensor_at)
      if (k >= 0) k += offset;
  for (WorkPlaneRoom& room : plane.rooms)
    for (int32_t& k : room.sensors) k += offset;
}

}  // namespace radbake
