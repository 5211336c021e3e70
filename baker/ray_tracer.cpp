#include "baker/ray_tracer.h"

#include <embree3/rtcore.h>
#include <tbb/enumerable_thread_specific.h>

#include <cmath>
#include <mutex>
#include <stdexcept>
#include <string>

namespace radbake {

struct RayTracer::Impl {
  const Surface& surface;
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::mutex error_mutex;
  std::string first_error;
  std::vector<uint32_t> triangle_of_primitive;  // back-face twins are not in Embree's scene
  mutable tbb::enumerable_thread_specific<uint64_t> ray_counts;

  explicit Impl(const Surface& s) : surface(s) {}

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
};

RayTracer::RayTracer(const Surface& surface) : impl_(std::make_unique<Impl>(surface)) {
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
    if (!surface.back_face[t]) m.triangle_of_primitive.push_back(t);
  const size_t n = m.triangle_of_primitive.size();
  if (n > 0) {
    RTCGeometry geometry = rtcNewGeometry(m.device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * n));
    auto* indices = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), n));
    if (vertices && indices) {
      for (size_t i = 0; i < 3 * n; ++i) {
        const Vec3 corner = surface.corners[3 * m.triangle_of_primitive[i / 3] + i % 3];
        vertices[3 * i] = corner.x;
        vertices[3 * i + 1] = corner.y;
        vertices[3 * i + 2] = corner.z;
        indices[i] = unsigned(i);
      }
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(m.scene, geometry);
    rtcReleaseGeometry(geometry);
  }
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
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray = make_ray(origin, direction, t_near, t_far);
  rtcOccluded1(impl_->scene, &context, &ray);
  return ray.tfar < 0;  // Embree sets tfar to -inf on a hit
}

Hit RayTracer::intersect(Vec3 origin, Vec3 direction, float t_near, float t_far) const {
  ++impl_->ray_counts.local();
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh;
  rh.ray = make_ray(origin, direction, t_near, t_far);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &context, &rh);
  Hit hit;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
  const Surface& s = impl_->surface;
  hit.triangle = impl_->triangle_of_primitive[rh.hit.primID];
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

uint64_t RayTracer::rays_cast() const {
  uint64_t total = 0;
  for (uint64_t c : impl_->ray_counts) total += c;
  return total;
}

}  // namespace radbake
