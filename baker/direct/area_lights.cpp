#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "baker/direct/direct_light.h"
#include "baker/surface/sampling.h"

namespace radbake {
namespace {

struct Emitter {
  uint32_t triangle;
  Vec3 corner[3];
  Vec3 normal;
  bool uniform;
  Rgb emission;  // lm/m2, exact when uniform
};

std::vector<Emitter> collect_emitters(const Surface& surface, const MaterialSampler& materials) {
  std::vector<Emitter> out;
  for (uint32_t t = 0; t < surface.triangle_count(); ++t) {
    if (!materials.emits(t) || !(surface.area[t] > 0)) continue;
    Emitter em{t, {surface.corners[3 * t], surface.corners[3 * t + 1], surface.corners[3 * t + 2]},
               surface.normal[t], materials.is_uniform(t), materials.emission(t, {1.0f / 3, 1.0f / 3}, 1.0f)};
    out.push_back(em);
  }
  return out;
}

// Points per texel at which each emitter's form factor is averaged, stratified 4 x 4: fewer leave
// percent-level noise on texels that a close emitter's light edge crosses.
constexpr uint32_t kFormFactorPoints = 16;

// Clips the polygon to the half-space above the plane through x with normal n.
int clip_to_hemisphere(Vec3 x, Vec3 n, const Vec3* in, int count, Vec3* out) {
  int m = 0;
  for (int i = 0; i < count; ++i) {
    Vec3 a = in[i], b = in[(i + 1) % count];
    float da = dot(n, a - x), db = dot(n, b - x);
    if (da >= 0) out[m++] = a;
    if ((da >= 0) != (db >= 0)) out[m++] = a + (b - a) * (da / (da - db));
  }
  return m;
}

// The part of the emitter above the horizon of point x (unit normal n), as a polygon of up to 4
// corners; fewer than 3 when the emitter shows x its back, lies below x's horizon, or is edge-on:
// x within `offset` (the receiver's ray offset) of its plane, as the emitter's own other
// triangles are (and its back-face twin).
int visible_part(const Emitter& em, Vec3 x, Vec3 n, float offset, Vec3* polygon) {
  if (!(dot(x - em.corner[0], em.normal) > offset)) return 0;
  return clip_to_hemisphere(x, n, em.corner, 3, polygon);
}

// A point of a convex polygon (fanned from vertex 0) for a unit-square sample, uniform by area;
// `area` gets the polygon's area.
Vec3 polygon_point(const Vec3* p, int count, Vec2 u, float* area) {
  float areas[4] = {}, total = 0;
  for (int k = 1; k + 1 < count; ++k) total += areas[k - 1] = length(cross(p[k] - p[0], p[k + 1] - p[0]));
  *area = 0.5f * total;
  float pick = u.x * total;
  int k = 1;
  while (k + 2 < count && pick > areas[k - 1]) pick -= areas[k - 1], ++k;
  float ux = areas[k - 1] > 0 ? std::clamp(pick / areas[k - 1], 0.0f, 0.99999994f) : 0.0f;
  Vec2 b = uniform_triangle({ux, u.y});
  return p[0] * (1 - b.x - b.y) + p[k] * b.x + p[k + 1] * b.y;
}

Vec3 polygon_centroid(const Vec3* p, int count) {
  Vec3 sum{};
  for (int k = 0; k < count; ++k) sum += p[k];
  return sum / float(count);
}

}  // namespace

namespace {

// Lambert's contour integral without the receiver's normal, 2 pi times the vector form factor:
// the sum over edges of the angle they subtend times the unit normal of the plane through x and
// the edge. In double: the edge terms of a small or distant polygon (a 1 cm lamp 3 m away) nearly
// cancel, and in float what is left was off by a percent.
struct D3 {
  double x, y, z;
};
D3 contour_integral(Vec3 x, const Vec3* polygon, int count) {
  auto unit_toward = [&](Vec3 p) {
    D3 d{double(p.x) - x.x, double(p.y) - x.y, double(p.z) - x.z};
    double len = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    return D3{d.x / len, d.y / len, d.z / len};
  };
  D3 sum{0, 0, 0};
  for (int i = 0; i < count; ++i) {
    const D3 a = unit_toward(polygon[i]), b = unit_toward(polygon[(i + 1) % count]);
    const D3 c{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
    const double len = std::sqrt(c.x * c.x + c.y * c.y + c.z * c.z);
    if (!(len > 1e-15)) continue;
    const double angle = std::atan2(len, a.x * b.x + a.y * b.y + a.z * b.z) / len;
    sum = {sum.x + angle * c.x, sum.y + angle * c.y, sum.z + angle * c.z};
  }
  return sum;
}

}  // namespace

double polygon_form_factor(Vec3 x, Vec3 n, const Vec3* polygon, int count) {
  const D3 v = contour_integral(x, polygon, count);
  return std::fabs(n.x * v.x + n.y * v.y + n.z * v.z) / (2.0 * 3.14159265358979323846);
}

Vec3 polygon_light_direction(Vec3 x, const Vec3* polygon, int count) {
  const D3 v = contour_integral(x, polygon, count);
  Vec3 d = normalize(Vec3{float(v.x), float(v.y), float(v.z)});
  // The winding decides the sign: the light comes from the polygon's side.
  Vec3 toward{};
  for (int i = 0; i < count; ++i) toward += polygon[i] - x;
  return dot(d, toward) < 0 ? -d : d;
}

std::vector<Rgb> emitter_irradiance(const Elements& e, const Surface& surface, const MaterialSampler& materials,
                                    const RayTracer& tracer, const DirectLightOptions& options, uint64_t seed,
                                    Progress& progress, ElementRange range, std::vector<LightDirection>* directions) {
  range = range.within(e.size());
  std::vector<Rgb> irradiance(range.size());
  if (directions) directions->assign(range.size(), {});
  const std::vector<Emitter> emitters = collect_emitters(surface, materials);
  if (emitters.empty()) return irradiance;
  // Rays are shared out among the emitters by their unoccluded contribution, so a hundred small
  // emitting triangles cost about what one bright one does (at most about twice the budget).
  const int budget = 2 * std::max(1, options.area_light_rays);
  progress.begin("area lights", range.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(range.begin, range.end, 64), [&](const tbb::blocked_range<size_t>& r) {
    std::vector<double> factor(emitters.size());
    std::vector<Vec3> toward(directions ? emitters.size() : 0);  // per emitter, where its seen part lies
    for (size_t i = r.begin(); i < r.end(); ++i) {
      if (!e.valid(i)) continue;
      const Vec3 n = e.normal[i], ng = surface.normal[e.triangle[i]];
      Rng rng(seed, Stream::AreaLight, i);
      // Each emitter's unoccluded form factor is the mean over points spread over the texel, the
      // same points for every emitter: at the sample point alone, a texel across a sharp edge of
      // an emitter's light (a lamp close to a wall) would count all or none of it over its whole
      // area; at points of its own per emitter, the form factors of a closed room's walls would
      // no longer add up to one.
      Vec3 points[kFormFactorPoints];
      const uint32_t point_pattern = rng.next_u32();
      for (uint32_t m = 0; m < kFormFactorPoints; ++m)
        points[m] = footprint_point(e, surface, i, cmj_sample(m, kFormFactorPoints, point_pattern));
      double total = 0;
      int contributing = 0;
      for (size_t k = 0; k < emitters.size(); ++k) {
        factor[k] = 0;
        if (directions) toward[k] = {};
        if (emitters[k].triangle == e.triangle[i]) continue;
        for (const Vec3& x : points) {
          Vec3 polygon[4];
          const int corners = visible_part(emitters[k], x, n, e.offset[i], polygon);
          if (corners < 3) continue;
          const double f = polygon_form_factor(x, n, polygon, corners);
          factor[k] += f / kFormFactorPoints;
          if (directions) toward[k] += polygon_light_direction(x, polygon, corners) * float(f);
        }
        total += factor[k] * sum(emitters[k].emission);
        contributing += factor[k] > 0;
      }
      if (total <= 0) continue;
      // Every emitter gets at least an even share of the budget: its light may matter far more
      // than its unoccluded share says (the bright one may be behind a wall).
      const int least = std::clamp(budget / std::max(1, contributing), 1, options.area_light_rays);
      Rgb h{};
      LightDirection from{};
      for (size_t k = 0; k < emitters.size(); ++k) {
        if (factor[k] <= 0) continue;
        const Emitter& em = emitters[k];
        const Rgb before = h;
        if (em.uniform && !options.shadow_rays) {  // nothing can come between: the exact form factor
          h += em.emission * float(factor[k]);
          if (directions) from.add(h - before, normalize(toward[k]));
          continue;
        }
        double share = factor[k] * sum(em.emission) / total;
        const int rays = std::clamp(int(std::ceil(budget * share)), least, options.area_light_rays);
        const uint32_t probe_patterns[2] = {rng.next_u32(), rng.next_u32()};
        const uint32_t full_patterns[2] = {rng.next_u32(), rng.next_u32()};
        // The seen fraction: shadow rays from points of the texel to points of the emitter spread
        // by area, each weighted by the form factor kernel there, cos cos / r^2 times the area it
        // was drawn from. So it is the kernel's fraction, not the area's (a stand hiding the near
        // half of a floodlight hides most of its light), and exactly 1 when nothing is in the way.
        double weights = 0;
        Rgb seen{};
        int visible = 0, hidden = 0;
        auto trace = [&](int count, const uint32_t* patterns) {
          weights = 0;
          seen = {};
          visible = hidden = 0;
          const uint32_t origin_pattern = patterns[0], target_pattern = patterns[1];
          for (int j = 0; j < count; ++j) {
            const Vec3 from = footprint_point(e, surface, i, cmj_sample(uint32_t(j), uint32_t(count), origin_pattern));
            Vec3 polygon[4];
            const int corners = visible_part(em, from, n, e.offset[i], polygon);
            if (corners < 3) continue;
            float area;
            Vec3 y = polygon_point(polygon, corners, cmj_sample(uint32_t(j), uint32_t(count), target_pattern), &area);
            // A hair inside the emitter's edges: where it meets a wall (a glowing ceiling), a ray
            // to a point on the edge itself ends in the wall's plane and may strike it.
            y += (polygon_centroid(polygon, corners) - y) * 1e-4f;
            const Vec3 to_y = y - from;
            const double r2 = dot(to_y, to_y);
            const double weight = std::max(0.0f, dot(n, to_y)) * std::max(0.0f, -dot(em.normal, to_y)) / (r2 * r2) * area;
            if (!(weight > 0)) continue;
            weights += weight;
            const Vec3 origin = from + ng * e.offset[i];
            // The ray ends just off the emitter, on the receiver's side: stopping a fraction short
            // along the ray is not enough at grazing angles, where that point is still within
            // rounding of the emitter's plane and the emitter would occlude itself.
            Vec3 target = y + em.normal * std::max(e.offset[i], 1e-5f * length(y - origin));
            // Nor may it end lower over the receiver's plane than the ray starts: a target in that
            // plane (an emitter meeting the receiver at an edge, or a distant one that merely lies
            // in the plane extended) would have the ray graze the receiver, or slip between a wall
            // and the surface it stands on, past every wall in the way.
            const float lift = e.offset[i] - dot(target - from, ng);
            if (lift > 0) target += ng * lift;
            Vec3 d = target - origin;
            float dist = length(d);
            const float passes = dist > 0 && options.shadow_rays ? tracer.transmittance(origin, d / dist, 0.0f, dist) : 1.0f;
            if (passes <= 0) {
              ++hidden;
              continue;
            }
            ++visible;
            seen += (em.uniform ? em.emission : materials.emission(em.triangle, barycentric(em.corner, y), 1.0f)) *
                    float(weight * passes);
          }
        };
        // Rays go where the shadow's edge is: a quarter of them first, and all of them only when
        // those disagree, the texel in a penumbra. At least 16 first: 4 of 16 missed the edge of a
        // block's shadow across a texel often enough to raise the Cornell box's error from 1.3% to
        // 1.7%.
        const int probe = std::max(16, rays / 4);
        if (probe < rays) trace(probe, probe_patterns);
        if (probe >= rays || (visible > 0 && hidden > 0)) trace(rays, full_patterns);
        if (weights > 0) h += seen * float(factor[k] / weights);
        if (directions) from.add(h - before, normalize(toward[k]));
      }
      irradiance[i - range.begin] = h;
      if (directions) (*directions)[i - range.begin] = from;
    }
    progress.advance(r.size());
  });
  progress.end();
  return irradiance;
}

}  // namespace radbake
