#include "baker/readings/display_camera.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "baker/readings/work_plane.h"
#include "base/errors.h"

namespace radbake {
namespace {

constexpr float kEyeHeight = 1.6f;  // metres: a standing eye
constexpr int kViewRays = 8;        // per side of the grid of rays that judges a view
constexpr int kMostBlendedLayers = 8;  // alpha-blended surfaces a display ray looks through
constexpr float kClearance = 0.05f;    // of the room's length: the least distance from the eye to a surface
constexpr int kBackingSteps = 8;       // positions tried between the room's near end and the wall behind

// What a square grid of kViewRays rays a side over the field of view, looking along `forward`
// with +Y up, meets: each ray's hit, to `seen`.
template <typename Seen>
void view_grid(const RayTracer& tracer, Vec3 eye, Vec3 forward, float yfov, Seen&& seen) {
  const Vec3 right = normalize(cross(forward, {0, 1, 0})), up = cross(right, forward);
  const float half = std::tan(0.5f * yfov);
  for (int i = 0; i < kViewRays; ++i)
    for (int j = 0; j < kViewRays; ++j) {
      const float u = half * (2 * (float(i) + 0.5f) / kViewRays - 1), v = half * (2 * (float(j) + 0.5f) / kViewRays - 1);
      seen(tracer.intersect(eye, normalize(forward + right * u + up * v), 0, INFINITY));
    }
}

// The share of the view grid's rays that strike a surface.
float share_hit(const RayTracer& tracer, Vec3 eye, Vec3 forward, float yfov) {
  int hits = 0;
  view_grid(tracer, eye, forward, yfov, [&](const Hit& hit) { hits += !hit.missed(); });
  return float(hits) / float(kViewRays * kViewRays);
}

// The nearest surface the view grid, and rays straight up, down and to either side, meet from `eye`.
float nearest_hit(const RayTracer& tracer, Vec3 eye, Vec3 forward, float yfov) {
  float nearest = INFINITY;
  auto take = [&](const Hit& hit) {
    if (!hit.missed()) nearest = std::min(nearest, hit.distance);
  };
  view_grid(tracer, eye, forward, yfov, take);
  const Vec3 right = normalize(cross(forward, {0, 1, 0})), up = cross(right, forward);
  for (Vec3 side : {right, -right, up, -up}) take(tracer.intersect(eye, side, 0, INFINITY));
  return nearest;
}

struct Box {
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
};

Box bounds(const Surface& surface) {
  Box b;
  for (const Vec3& c : surface.corners)
    b.lo = {std::min(b.lo.x, c.x), std::min(b.lo.y, c.y), std::min(b.lo.z, c.z)},
    b.hi = {std::max(b.hi.x, c.x), std::max(b.hi.y, c.y), std::max(b.hi.z, c.z)};
  return b;
}

DisplayCamera outside(const Box& box, const std::string& reason) {
  const Vec3 lo = box.lo, hi = box.hi;
  DisplayCamera camera;
  const Vec3 centre = (lo + hi) * 0.5f;
  const float radius = std::max(0.5f * length(hi - lo), 1e-3f);
  const float distance = radius / std::sin(0.5f * camera.yfov);
  camera.forward = normalize(Vec3{0, -0.4f, -1});
  camera.eye = centre - camera.forward * distance;
  camera.znear = std::max(1e-3f, 0.01f * radius);
  camera.why = reason + ": outside, from +Z, the bounding sphere filling the field of view";
  return camera;
}

}  // namespace

DisplayCamera display_camera(const Scene& scene, const Surface& surface, const RayTracer& tracer) {
  const Box box = bounds(surface);
  if (surface.corners.empty()) return outside({{0, 0, 0}, {0, 0, 0}}, "an empty scene");
  const float wide = std::max(box.hi.x - box.lo.x, box.hi.z - box.lo.z);
  WorkPlaneOptions options;
  options.enabled = true;
  options.height = std::min(kEyeHeight, 0.5f * (box.hi.y - box.lo.y));
  options.spacing = std::max(double(wide) / 24, 1e-3);  // a few hundred points, enough to find the rooms
  WorkPlane plane;
  try {
    plane = work_plane(scene, surface, tracer, options);
  } catch (const InputError&) {
    return outside(box, "no floor is enclosed");
  }
  if (plane.rooms.empty()) return outside(box, "no floor is enclosed");
  const WorkPlaneRoom* largest = &plane.rooms[0];
  for (const WorkPlaneRoom& room : plane.rooms)
    if (room.sensors.size() > largest->sensors.size()) largest = &room;
  Vec3 centroid{};
  for (int32_t k : largest->sensors) centroid = centroid + plane.sensors[size_t(k)].position;
  centroid = centroid * (1.0f / float(largest->sensors.size()));

  DisplayCamera best;
  float best_score = -1;
  const Vec3 axes[4] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}};
  float longest = 0;
  float extent[4];
  for (int a = 0; a < 4; ++a) {
    float near = INFINITY, far = -INFINITY;
    for (int32_t k : largest->sensors) {
      const float along = dot(plane.sensors[size_t(k)].position, axes[a]);
      near = std::min(near, along), far = std::max(far, along);
    }
    extent[a] = far - near;
    longest = std::max(longest, extent[a]);
  }
  for (int a = 0; a < 4; ++a) {
    // At the room's near end, on its centre line: the room's own point nearest there (an L-shaped
    // room's centroid may lie outside it).
    const Vec3 wanted = centroid - axes[a] * (0.5f * extent[a]);
    Vec3 eye = centroid;
    float nearest = INFINITY;
    for (int32_t k : largest->sensors) {
      const Vec3 p = plane.sensors[size_t(k)].position;
      if (length(p - wanted) < nearest) nearest = length(p - wanted), eye = p;
    }
    const float score = share_hit(tracer, eye, axes[a], best.yfov) + (1 - share_hit(tracer, eye, -axes[a], best.yfov)) +
                        extent[a] / std::max(longest, 1e-6f);
    if (score > best_score) best_score = score, best.eye = eye, best.forward = axes[a];
  }
  // Then back, to see more of the room: towards the wall behind (stopping short of it), or, where
  // the room is open behind (a set's missing wall), to the scene's bounds; but only as far as
  // nothing comes within kClearance of the room's length of the eye, ahead or beside it (a sloping
  // roof, a gable wall: a view from inside a wall sees one texel of it).
  const Vec3 d = best.forward;
  const Hit behind = tracer.intersect(best.eye, -d, 0, INFINITY);
  const float to_bounds = dot(best.eye, d) - dot(d.x + d.y + d.z > 0 ? box.lo : box.hi, d);
  const float most_back = 0.9f * std::min(behind.missed() ? INFINITY : behind.distance, to_bounds);
  const float clearance = kClearance * longest;
  for (int step = kBackingSteps; step >= 0; --step) {
    const Vec3 eye = best.eye - d * (most_back * float(step) / kBackingSteps);
    if (step == 0 || nearest_hit(tracer, eye, d, best.yfov) >= clearance) {
      best.eye = eye;
      break;
    }
  }
  best.in_room = true;
  best.znear = std::max(1e-3f, 0.002f * longest);
  char why[160];
  std::snprintf(why, sizeof why, "inside the largest enclosed region (%zu of %zu work-plane points, %.3g m across), %.3g m above its floor",
                largest->sensors.size(), plane.sensors.size(), double(longest), options.height);
  best.why = why;
  return best;
}

std::vector<std::vector<float>> display_view(const Scene& scene, const DisplayCamera& added, const Surface& surface,
                                             const RayTracer& tracer) {
  SceneCamera camera;
  camera.eye = added.eye, camera.forward = added.forward, camera.yfov = added.yfov, camera.znear = added.znear;
  camera.up = normalize(cross(normalize(cross(added.forward, {0, 1, 0})), added.forward));
  for (const SceneCamera& c : scene.cameras)
    if (c.usable()) {
      camera = c;
      break;
    }
  const Vec3 right = cross(camera.forward, camera.up);
  // An orthographic camera's view is xmag by ymag; a perspective one's, its aspect ratio or square.
  const float aspect = camera.orthographic ? (camera.ymag > 0 ? camera.xmag / camera.ymag : 1.0f)
                                           : (camera.aspect > 0 ? camera.aspect : 1.0f);
  const int rows = kDisplayViewRays, columns = std::max(1, int(std::lround(kDisplayViewRays * aspect)));
  const float half_height = camera.orthographic ? camera.ymag : std::tan(0.5f * camera.yfov);
  const float half_width = camera.orthographic ? camera.xmag : half_height * aspect;
  const float far = camera.zfar > camera.znear ? camera.zfar : INFINITY;
  std::vector<std::vector<float>> seen(surface.pages.size());
  size_t hits = 0;
  for (size_t p = 0; p < seen.size(); ++p) seen[p].assign(size_t(surface.pages[p].width) * surface.pages[p].height, 0.0f);
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const float u = half_width * (2 * (float(i) + 0.5f) / float(columns) - 1);
      const float v = half_height * (1 - 2 * (float(j) + 0.5f) / float(rows));
      const Vec3 origin = camera.orthographic ? camera.eye + right * u + camera.up * v : camera.eye;
      const Vec3 direction = camera.orthographic ? camera.forward : normalize(camera.forward + right * u + camera.up * v);
      // Through alpha-blended surfaces (the display file blends them too): each takes its alpha
      // of the ray, what is behind the rest.
      float left = 1;
      float near = camera.znear;
      for (int layer = 0; layer < kMostBlendedLayers && left > 0; ++layer) {
        const Hit hit = tracer.intersect(origin, direction, near, far);
        if (hit.missed()) break;
        const Material& m = material_of(scene, surface.material[hit.triangle]);
        const float share = m.alpha_mode == AlphaMode::Blend ? left * std::clamp(m.base_alpha, 0.0f, 1.0f) : left;
        if (surface.chart[hit.triangle] != UINT32_MAX) {
          const AtlasPage& page = surface.pages[surface.page[hit.triangle]];
          const Vec2 at = surface.lightmap_texel(hit.triangle, hit.bary);
          const int x = std::clamp(int(at.x), 0, page.width - 1), y = std::clamp(int(at.y), 0, page.height - 1);
          seen[surface.page[hit.triangle]][size_t(y) * size_t(page.width) + size_t(x)] += share;
          hits += share > 0;
        }
        left -= share;
        near = hit.distance * (1 + 1e-5f) + 1e-5f;
      }
    }
  if (hits == 0) seen.assign(seen.size(), {});
  return seen;
}

}  // namespace radbake
