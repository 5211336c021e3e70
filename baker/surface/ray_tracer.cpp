#include "baker/surface/ray_tracer.h"

#include <embree3/rtcore.h>
#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <string>

#include "baker/surface/material_sampler.h"
#include "baker/surface/sampling.h"

namespace radbake {
namespace {

enum class Query { Solid, Transmittance, LightPath };

// Embree hands the context back to the filter, so what a query needs rides along after it.
struct QueryContext {
  RTCIntersectContext embree;  // first, so the filter can cast back
  Query query = Query::Solid;
  const MaterialSampler* materials = nullptr;
  const uint32_t* triangle_of_primitive = nullptr;  // of the see-through geometry
  float transmittance = 1;
  // A spatial-split BVH may report one triangle twice; each multiplies the transmittance once.
  static constexpr int kRemembered = 16;
  uint32_t passed[kRemembered];
  int passed_count = 0;
};

uint32_t float_bits(float f) {
  uint32_t bits;
  std::memcpy(&bits, &f, sizeof bits);
  return bits;
}

// The same ray and triangle always give the same number in [0, 1).
float pass_chance(RTCRayN* ray, unsigned n, uint32_t primitive) {
  uint64_t h = mix64(primitive + 0x9e3779b97f4a7c15ull);
  for (float f : {RTCRayN_org_x(ray, n, 0), RTCRayN_org_y(ray, n, 0), RTCRayN_org_z(ray, n, 0), RTCRayN_dir_x(ray, n, 0),
                  RTCRayN_dir_y(ray, n, 0), RTCRayN_dir_z(ray, n, 0)})
    h = mix64(h ^ float_bits(f));
  return float(h >> 40) * 0x1p-24f;
}

void see_through_filter(const RTCFilterFunctionNArguments* args) {
  auto* c = reinterpret_cast<QueryContext*>(args->context);
  if (c->query == Query::Solid || args->valid[0] == 0) return;
  const uint32_t primitive = RTCHitN_primID(args->hit, args->N, 0);
  const uint32_t triangle = c->triangle_of_primitive[primitive];
  const Vec3 direction{RTCRayN_dir_x(args->ray, args->N, 0), RTCRayN_dir_y(args->ray, args->N, 0),
                       RTCRayN_dir_z(args->ray, args->N, 0)};
  const float passes = c->materials->transmittance(
      triangle, {RTCHitN_u(args->hit, args->N, 0), RTCHitN_v(args->hit, args->N, 0)}, direction);
  if (c->query == Query::LightPath) {
    if (pass_chance(args->ray, args->N, primitive) < passes) args->valid[0] = 0;
    return;
  }
  if (std::find(c->passed, c->passed + c->passed_count, primitive) != c->passed + c->passed_count) {
    args->valid[0] = 0;
    return;
  }
  if (!(passes > 0)) return;  // opaque here: the hit stands and ends the query
  c->transmittance *= passes;
  if (c->passed_count < QueryContext::kRemembered) c->passed[c->passed_count++] = primitive;
  args->valid[0] = 0;
}

}  // namespace

struct RayTracer::Impl {
  const Surface& surface;
  const MaterialSampler* materials;
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::mutex error_mutex;
  std::string first_error;
  // Per Embree geometry (solid, see-through): its primitives' triangles. Back-face twins are not
  // in Embree's scene.
  std::vector<uint32_t> triangle_of_primitive[2];
  unsigned geometry_id[2] = {RTC_INVALID_GEOMETRY_ID, RTC_INVALID_GEOMETRY_ID};
  mutable tbb::enumerable_thread_specific<uint64_t> ray_counts;

  Impl(const Surface& s, const MaterialSampler* m) : surface(s), materials(m) {}

  static void on_error(void* self, RTCError code, const char* message) {
    auto* impl = static_cast<Impl*>(self);
    std::lock_guard<std::mutex> lock(impl->error_mutex);
    if (impl->first_error.empty())
      impl->first_error = "Embree error " + std::to_string(int(code)) + ": " + (message ? message : "");
  }
  void throw_if_failed() {
    std::lock_guard<std::mutex> lock(error_mutex);
    if (!first_error.empty()) throw std::runtime_error(first_error);
  }

  void add_geometry(int kind) {
    const std::vector<uint32_t>& triangles = triangle_of_primitive[kind];
    const size_t n = triangles.size();
    if (n == 0) return;
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * n));
    auto* indices = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), n));
    if (vertices && indices) {
      for (size_t i = 0; i < 3 * n; ++i) {
        const Vec3 corner = surface.corners[3 * triangles[i / 3] + i % 3];
        vertices[3 * i] = corner.x;
        vertices[3 * i + 1] = corner.y;
        vertices[3 * i + 2] = corner.z;
        indices[i] = unsigned(i);
      }
    }
    if (kind == 1) {
      rtcSetGeometryIntersectFilterFunction(geometry, &see_through_filter);
      rtcSetGeometryOccludedFilterFunction(geometry, &see_through_filter);
    }
    rtcCommitGeometry(geometry);
    geometry_id[kind] = rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
  }

  QueryContext context(Query query) const {
    QueryContext c;
    rtcInitIntersectContext(&c.embree);
    c.query = query;
    c.materials = materials;
    c.triangle_of_primitive = triangle_of_primitive[1].data();
    return c;
  }

  Hit intersect(Vec3 origin, Vec3 direction, float t_near, float t_far, Query query) const;
};

RayTracer::RayTracer(const Surface& surface, const MaterialSampler* materials)
    : impl_(std::make_unique<Impl>(surface, materials)) {
  Impl& m = *impl_;
  m.device = rtcNewDevice(nullptr);
  if (!m.device) throw std::runtime_error("cannot create an Embree device");
  rtcSetDeviceErrorFunction(m.device, &Impl::on_error, &m);
  m.scene = rtcNewScene(m.device);
  // Robust mode keeps rays from slipping through edges shared by two triangles: a closed room
  // must stay closed, or light leaks and the energy balance breaks.
  rtcSetSceneFlags(m.scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(m.scene, RTC_BUILD_QUALITY_HIGH);
  for (uint32_t t = 0; t < surface.triangle_count(); ++t)
    if (!surface.back_face[t]) m.triangle_of_primitive[materials && materials->see_through(t) ? 1 : 0].push_back(t);
  m.add_geometry(0);
  m.add_geometry(1);
  rtcCommitScene(m.scene);
  m.throw_if_failed();
}

RayTracer::~RayTracer() {
  if (impl_->scene) rtcReleaseScene(impl_->scene);
  if (impl_->device) rtcReleaseDevice(impl_->device);
}

namespace {
RTCRay make_ray(Vec3 o, Vec3 d, float t_near, float t_far) {
  RTCRay ray;
  ray.org_x = o.x, ray.org_y = o.y, ray.org_z = o.z;
  ray.dir_x = d.x, ray.dir_y = d.y, ray.dir_z = d.z;
  ray.tnear = t_near;
  ray.tfar = t_far;
  ray.time = 0;
  ray.mask = 0xffffffffu;
  ray.id = 0;
  ray.flags = 0;
  return ray;
}
}  // namespace

bool RayTracer::occluded(Vec3 origin, Vec3 direction, float t_near, float t_far) const {
  ++impl_->ray_counts.local();
  QueryContext context = impl_->context(Query::Solid);
  RTCRay ray = make_ray(origin, direction, t_near, t_far);
  rtcOccluded1(impl_->scene, &context.embree, &ray);
  return ray.tfar < 0;  // Embree sets tfar to -inf on a hit
}

float RayTracer::transmittance(Vec3 origin, Vec3 direction, float t_near, float t_far) const {
  ++impl_->ray_counts.local();
  QueryContext context = impl_->context(Query::Transmittance);
  RTCRay ray = make_ray(origin, direction, t_near, t_far);
  rtcOccluded1(impl_->scene, &context.embree, &ray);
  return ray.tfar < 0 ? 0.0f : context.transmittance;
}

Hit RayTracer::Impl::intersect(Vec3 origin, Vec3 direction, float t_near, float t_far, Query query) const {
  ++ray_counts.local();
  QueryContext c = context(query);
  RTCRayHit rh;
  rh.ray = make_ray(origin, direction, t_near, t_far);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene, &c.embree, &rh);
  Hit hit;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
  const Surface& s = surface;
  hit.triangle = triangle_of_primitive[rh.hit.geomID == geometry_id[1] ? 1 : 0][rh.hit.primID];
  hit.bary = {rh.hit.u, rh.hit.v};
  hit.distance = rh.ray.tfar;
  hit.front = dot(direction, s.normal[hit.triangle]) < 0;
  if (!hit.front && s.twin[hit.triangle] != UINT32_MAX) {
    // The twin winds (0, 2, 1): corners 1 and 2 trade places, and so do their weights.
    hit.triangle = s.twin[hit.triangle];
    hit.bary = {rh.hit.v, rh.hit.u};
    hit.front = true;
  }
  return hit;
}

Hit RayTracer::intersect(Vec3 origin, Vec3 direction, float t_near, float t_far) const {
  return impl_->intersect(origin, direction, t_near, t_far, Query::Solid);
}

Hit RayTracer::intersect_light_path(Vec3 origin, Vec3 direction, float t_near, float t_far) const {
  return impl_->intersect(origin, direction, t_near, t_far, Query::LightPath);
}

uint64_t RayTracer::rays_cast() const {
  uint64_t total = 0;
  for (uint64_t c : impl_->ray_counts) total += c;
  return total;
}

}  // namespace radbake
