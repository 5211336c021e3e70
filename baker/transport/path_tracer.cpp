#include "baker/transport/path_tracer.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>

#include "baker/direct/direct_light.h"
#include "baker/surface/sampling.h"

namespace radbake {
namespace {

// Double precision for the spherical geometry: the solid angle of a small or distant triangle is
// a difference of nearly equal angles.
struct D3 {
  double x, y, z;
};
D3 d3(Vec3 v) { return {v.x, v.y, v.z}; }
D3 operator-(D3 a, D3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
D3 operator+(D3 a, D3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
D3 operator*(D3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(D3 a, D3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
D3 cross(D3 a, D3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
D3 unit(D3 a) { return a * (1 / std::sqrt(dot(a, a))); }
double angle_between(D3 a, D3 b) { return std::atan2(std::sqrt(dot(cross(a, b), cross(a, b))), dot(a, b)); }

// A triangle as seen from a point: the unit directions to its corners and its solid angle (Van
// Oosterom and Strackee 1983, exact for any size).
struct SphericalTriangle {
  D3 a, b, c;
  double solid_angle = 0;
};

SphericalTriangle seen_from(D3 x, const Vec3* corners) {
  SphericalTriangle t{unit(d3(corners[0]) - x), unit(d3(corners[1]) - x), unit(d3(corners[2]) - x)};
  t.solid_angle = 2 * std::fabs(std::atan2(dot(t.a, cross(t.b, t.c)), 1 + dot(t.a, t.b) + dot(t.b, t.c) + dot(t.c, t.a)));
  return t;
}

// A direction uniform in the spherical triangle's solid angle (Arvo 1995, "Stratified sampling of
// spherical triangles"): a point near a large emitter gets every direction of it with the same
// weight, where uniform sampling by area sends almost every sample to the far side.
D3 uniform_direction_in(const SphericalTriangle& t, double u1, double u2) {
  // Interior angles at a, b and c: between the great circles meeting there.
  const double alpha = angle_between(cross(t.a, t.b), cross(t.a, t.c));
  const double beta = angle_between(cross(t.b, t.c), cross(t.b, t.a));
  const double gamma = angle_between(cross(t.c, t.a), cross(t.c, t.b));
  const double area = alpha + beta + gamma - kPi;
  // The sub-triangle a, b, c' of area u1 * area; then a point on the arc from c' to b.
  const double part = u1 * area, s = std::sin(part - alpha), cs = std::cos(part - alpha);
  const double u = cs - std::cos(alpha), v = s + std::sin(alpha) * dot(t.a, t.b);
  const double q = std::clamp(((v * cs - u * s) * std::cos(alpha) - v) / ((v * s + u * cs) * std::sin(alpha)), -1.0, 1.0);
  const D3 c_prime = t.a * q + unit(t.c - t.a * dot(t.c, t.a)) * std::sqrt(1 - q * q);
  const double z = 1 - u2 * (1 - dot(c_prime, t.b));
  return t.b * z + unit(c_prime - t.b * dot(c_prime, t.b)) * std::sqrt(std::max(0.0, 1 - z * z));
}

// Under this solid angle (steradians) a triangle is small enough that drawing points by area is
// as good, and Arvo's construction would lose its precision.
constexpr double kSmallSolidAngle = 1e-3;

// Emitting triangles, and how one is drawn for a path vertex. With few of them each is weighed by
// the most light it can send the vertex (solid angle times the brightest its texture allows), so
// near a corner of a glowing box the adjacent wall is drawn as often as it matters; with many,
// by power, whose cost does not grow with their number.
class Emitters {
 public:
  Emitters(const Surface& surface, const MaterialSampler& materials) {
    double total = 0;
    for (uint32_t t = 0; t < surface.triangle_count(); ++t) {
      const double bound = double(sum(materials.emission_bound(t)));
      const double weight = double(surface.area[t]) * bound;
      if (!(weight > 0)) continue;
      triangles_.push_back(t);
      bound_.push_back(bound);
      total += weight;
      power_cumulative_.push_back(total);
    }
    for (double& c : power_cumulative_) c /= total;
  }

  bool empty() const { return triangles_.empty(); }
  size_t size() const { return triangles_.size(); }
  static constexpr size_t kPerVertexLimit = 64;
  bool weighed_per_vertex() const { return triangles_.size() <= kPerVertexLimit; }
  uint32_t triangle(size_t k) const { return triangles_[k]; }
  double bound(size_t k) const { return bound_[k]; }

  // By power: the emitter for u in [0, 1), with the probability it had.
  size_t pick_by_power(double u, double* probability) const {
    size_t k = size_t(std::upper_bound(power_cumulative_.begin(), power_cumulative_.end(), u) - power_cumulative_.begin());
    k = std::min(k, triangles_.size() - 1);
    *probability = power_cumulative_[k] - (k > 0 ? power_cumulative_[k - 1] : 0.0);
    return k;
  }

 private:
  std::vector<uint32_t> triangles_;
  std::vector<double> bound_, power_cumulative_;
};

// A point where a path touches a surface, on the side the path arrived from.
struct PathVertex {
  Vec3 position;
  Vec3 geometric_normal;  // of the side the path is on
  Vec3 shading_normal;
  float offset;           // metres: rays start this far above the surface
  uint32_t triangle;
};

// How far rays leave a surface point the path reached: above what float precision resolves at
// this distance from the origin, and a millionth of the scene, far below the 0.1 mm gaps of
// real models.
float hit_offset(Vec3 p, float scene_extent) {
  const float magnitude = std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
  return std::max(64.0f * magnitude * 1.2e-7f, 1e-6f * scene_extent);
}

// A guard against a path that never ends; with reflectance held under 0.999 and Russian roulette
// on it, the light a path this long still carries is below float precision.
constexpr int kMaxBounces = 100000;

// Independent batches per texel that the noise estimate is taken from.
constexpr uint32_t kBatches = 8;

class PathTracer {
 public:
  PathTracer(const Elements& e, const Surface& surface, const MaterialSampler& materials,
             const std::vector<Light>& lights, const SkyLight* sky, const RayTracer& tracer)
      : e_(e), surface_(surface), materials_(materials), lights_(lights), tracer_(tracer), emitters_(surface, materials) {
    if (sky && sky->enabled) sky_.emplace(*sky);
  }

  // One path's estimate of the irradiance at footprint point u of element i, lux; `bounces`
  // counts the surfaces it reached.
  Rgb estimate(size_t i, Vec2 footprint_u, Vec2 first_direction_u, Rng& rng, uint64_t& bounces) const {
    return estimate_from({footprint_point(e_, surface_, i, footprint_u), surface_.normal[e_.triangle[i]], e_.normal[i],
                          e_.offset[i], e_.triangle[i]},
                         first_direction_u, rng, bounces);
  }

  // The same at a point in the air facing unit `normal` (a light meter, a probe's direction).
  Rgb estimate_at(Vec3 point, Vec3 normal, Vec2 first_direction_u, Rng& rng, uint64_t& bounces) const {
    return estimate_from({point, normal, normal, 0.0f, UINT32_MAX}, first_direction_u, rng, bounces);
  }

 private:
  Rgb estimate_from(PathVertex v, Vec2 first_direction_u, Rng& rng, uint64_t& bounces) const {
    Rgb result = direct_light(v, rng);
    Rgb throughput{1, 1, 1};
    Vec2 u = first_direction_u;
    for (int depth = 0; depth < kMaxBounces; ++depth) {
      const Vec3 direction = hemisphere_direction(v.shading_normal, v.geometric_normal, u);
      const Hit hit =
          tracer_.intersect_light_path(v.position + v.geometric_normal * v.offset, direction, 0.0f, INFINITY);
      // Leaving the scene, the path sees the sky (pi L: directions are cosine-distributed).
      if (hit.missed() && sky_) result += throughput * float(kPi * sky_->luminance(direction));
      // The back of a one-sided surface reflects nothing, as in the bake.
      if (hit.missed() || !hit.front) break;
      ++bounces;
      const Vec3 at = surface_.point(hit.triangle, hit.bary);
      v = {at, surface_.normal[hit.triangle], surface_.shading_normal(hit.triangle, hit.bary),
           hit_offset(at, surface_.scene_extent), hit.triangle};
      // With cosine-distributed directions the irradiance is pi times the mean radiance seen,
      // and a Lambertian surface sends rho E / pi: each hit adds rho times its own irradiance.
      // Its emission is not added: every vertex's next-event estimate already counts emitters.
      const Rgb rho = materials_.reflectance(hit.triangle, hit.bary, 0.0f);
      throughput = throughput * rho;
      if (!(max_component(throughput) > 0)) break;
      result += throughput * direct_light(v, rng);
      // Russian roulette: the light still to come is counted with probability `keep`, divided by it.
      const float keep = std::min(1.0f, max_component(rho));
      if (rng.uniform() >= keep) break;
      throughput = throughput / keep;
      u = {rng.uniform(), rng.uniform()};
    }
    return result;
  }

  // Irradiance at v straight from the light sources: every punctual light, and one point of one
  // emitting triangle, each behind a shadow ray.
  Rgb direct_light(const PathVertex& v, Rng& rng) const {
    Rgb total{};
    const Vec3 origin = v.position + v.geometric_normal * v.offset;
    for (const Light& light : lights_) {
      Vec3 to_light{};
      float distance = 0;
      const Rgb value = punctual_light_irradiance(light, v.position, v.shading_normal, &to_light, &distance);
      if (!(max_component(value) > 0) || dot(v.geometric_normal, to_light) <= 0) continue;
      total += value * tracer_.transmittance(origin, to_light, 0.0f,
                                             std::isfinite(distance) ? distance * (1 - 1e-5f) : INFINITY);
    }
    if (sky_ && sky_->sun_up()) {
      const Vec3 d = sky_->toward_sun({rng.uniform(), rng.uniform()});
      const float incidence = dot(v.shading_normal, d);
      if (incidence > 0 && dot(v.geometric_normal, d) > 0) {
        const float lux = float(sky_->sky().sun_illuminance) * incidence * tracer_.transmittance(origin, d, 0.0f, INFINITY);
        total += Rgb{lux, lux, lux};
      }
    }
    if (emitters_.empty()) return total;
    const D3 x = d3(origin);
    double probability = 0;
    size_t k = 0;
    const double u_pick = rng.uniform();
    if (emitters_.weighed_per_vertex()) {
      // Weights: the solid angle each emitter fills seen from here, times its brightest.
      double weights[Emitters::kPerVertexLimit], total_weight = 0;
      for (size_t j = 0; j < emitters_.size(); ++j) {
        const uint32_t t = emitters_.triangle(j);
        const bool faces = t != v.triangle && faces_vertex(t, v);
        weights[j] = faces ? seen_from(x, &surface_.corners[3 * t]).solid_angle * emitters_.bound(j) : 0.0;
        total_weight += weights[j];
      }
      if (!(total_weight > 0)) return total;
      double pick = u_pick * total_weight;
      for (k = 0; k + 1 < emitters_.size() && (pick >= weights[k] || weights[k] == 0); ++k) pick -= weights[k];
      probability = weights[k] / total_weight;
    } else {
      k = emitters_.pick_by_power(u_pick, &probability);
    }
    const uint32_t t = emitters_.triangle(k);
    const double u1 = rng.uniform(), u2 = rng.uniform();
    if (t == v.triangle || !(probability > 0)) return total;  // a flat triangle does not light itself
    const Vec3* corners = &surface_.corners[3 * t];
    const Vec3 ny = surface_.normal[t];
    if (!faces_vertex(t, v)) return total;
    const SphericalTriangle seen = seen_from(x, corners);
    // The emitter's point y and the weight of the sample: luminance M / pi times cos_x over the
    // density of the direction (1 / solid angle), or over the density of y by area.
    Vec2 bary;
    Vec3 y;
    double weight;
    if (seen.solid_angle > kSmallSolidAngle) {
      const D3 w = uniform_direction_in(seen, u1, u2);
      const D3 n = d3(ny);
      const double along = dot(d3(corners[0]) - x, n) / dot(w, n);
      if (!(along > 0)) return total;
      y = {float(x.x + w.x * along), float(x.y + w.y * along), float(x.z + w.z * along)};
      bary = barycentric(corners, y);
      weight = std::max(0.0, dot(d3(v.shading_normal), w)) * seen.solid_angle / kPi;
    } else {
      bary = uniform_triangle({float(u1), float(u2)});
      y = surface_.point(t, bary);
      const D3 to_y = d3(y) - x;
      const double r2 = dot(to_y, to_y), r = std::sqrt(r2);
      weight = std::max(0.0, dot(d3(v.shading_normal), to_y) / r) * std::max(0.0, -dot(d3(ny), to_y) / r) / (r2 * kPi) *
               surface_.area[t];
    }
    if (!(weight > 0) || dot(v.geometric_normal, y - origin) <= 0) return total;
    // The ray ends just off the emitter on its lit side, so the emitter does not hide itself.
    const Vec3 target = y + ny * hit_offset(y, surface_.scene_extent);
    Vec3 d = target - origin;
    const float r = length(d);
    const float passes = r > 0 ? tracer_.transmittance(origin, d / r, 0.0f, r * (1 - 1e-5f)) : 0.0f;
    if (!(passes > 0)) return total;
    return total + materials_.emission(t, bary, 0.0f) * float(weight * passes / probability);
  }

  // Whether triangle t shows its lit side to the vertex; a triangle in the vertex's own plane (the
  // other half of its quad) does not, however the ray offset lifts the vertex above that plane.
  bool faces_vertex(uint32_t t, const PathVertex& v) const {
    return dot(surface_.normal[t], v.position - surface_.corners[3 * t]) > v.offset;
  }


  const Elements& e_;
  const Surface& surface_;
  const MaterialSampler& materials_;
  const std::vector<Light>& lights_;
  const RayTracer& tracer_;
  Emitters emitters_;
  std::optional<SkyView> sky_;
};

}  // namespace

PathTracedPoints path_trace_points(const std::vector<Vec3>& points, const std::vector<Vec3>& normals, const Elements& e,
                                   const Surface& surface, const MaterialSampler& materials,
                                   const std::vector<Light>& lights, const SkyLight* sky, const RayTracer& tracer,
                                   uint32_t samples, uint64_t seed) {
  const PathTracer tracer_of_paths(e, surface, materials, lights, sky, tracer);
  PathTracedPoints out;
  out.irradiance.assign(points.size(), Rgb{});
  out.standard_error.assign(points.size(), 0.0);
  const uint32_t per_batch = std::max<uint32_t>(1, samples / kBatches);
  tbb::parallel_for(size_t(0), points.size(), [&](size_t i) {
    Rng rng(seed, Stream::PathTrace, (uint64_t(1) << 48) ^ i);
    uint64_t bounces = 0;
    Rgb sum{};
    double sum_photopic = 0, sum_squares = 0;
    for (uint32_t b = 0; b < kBatches; ++b) {
      // Each batch stratified on its own, as path_trace's (below).
      const uint32_t pattern = rng.next_u32();
      Rgb batch{};
      for (uint32_t k = 0; k < per_batch; ++k)
        batch += tracer_of_paths.estimate_at(points[i], normals[i], cmj_sample(k, per_batch, pattern), rng, bounces);
      batch = batch / float(per_batch);
      sum += batch;
      sum_photopic += photopic(batch), sum_squares += photopic(batch) * photopic(batch);
    }
    out.irradiance[i] = sum / float(kBatches);
    const double mean = sum_photopic / kBatches;
    const double variance = std::max(0.0, (sum_squares / kBatches - mean * mean) * kBatches / (kBatches - 1));
    out.standard_error[i] = std::sqrt(variance / kBatches);
  });
  return out;
}

PathTraced path_trace(const Elements& e, const Surface& surface, const MaterialSampler& materials,
                      const std::vector<Light>& lights, const SkyLight* sky, const RayTracer& tracer,
                      const PathTraceOptions& options, uint64_t seed, Progress& progress) {
  PathTraced out;
  out.irradiance.assign(e.size(), Rgb{});
  out.standard_error.assign(e.size(), 0.0f);
  const PathTracer tracer_of_paths(e, surface, materials, lights, sky, tracer);
  const uint32_t batches = std::min(kBatches, std::max<uint32_t>(2, options.samples));
  const uint32_t per_batch = std::max<uint32_t>(2, options.samples) / batches, n = batches * per_batch;
  std::atomic<uint64_t> total_bounces{0};
  auto traced = [&](size_t i) { return e.valid(i) && (options.only.empty() || options.only[i]); };
  progress.begin("path tracing", e.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, e.size(), 16), [&](const tbb::blocked_range<size_t>& r) {
    uint64_t bounces = 0;
    for (size_t i = r.begin(); i < r.end(); ++i) {
      if (!traced(i)) continue;
      Rng rng(seed, Stream::PathTrace, i);
      double sum_rgb[3] = {0, 0, 0}, sum_squares = 0;
      for (uint32_t b = 0; b < batches; ++b) {
        // Each batch is stratified on its own (origins over the footprint, first directions over
        // the hemisphere), so batch means are independent and their spread is the honest error
        // of the stratified whole; the spread of single stratified samples would overstate it.
        const uint32_t footprint_pattern = rng.next_u32(), direction_pattern = rng.next_u32();
        Rgb batch{};
        for (uint32_t k = 0; k < per_batch; ++k)
          batch += tracer_of_paths.estimate(i, cmj_sample(k, per_batch, footprint_pattern),
                                            cmj_sample(k, per_batch, direction_pattern), rng, bounces);
        batch = batch / float(per_batch);
        for (int c = 0; c < 3; ++c) sum_rgb[c] += batch[c];
        const double grey = (double(batch.x) + batch.y + batch.z) / 3;
        sum_squares += grey * grey;
      }
      const double mean_grey = (sum_rgb[0] + sum_rgb[1] + sum_rgb[2]) / (3.0 * batches);
      const double batch_variance =
          std::max(0.0, (sum_squares / batches - mean_grey * mean_grey) * batches / (batches - 1));
      out.irradiance[i] = {float(sum_rgb[0] / batches), float(sum_rgb[1] / batches), float(sum_rgb[2] / batches)};
      out.standard_error[i] = float(std::sqrt(batch_variance / batches));
    }
    total_bounces += bounces;
    progress.advance(r.size());
  });
  progress.end();

  double sum_values = 0, sum_squared_errors = 0;
  size_t valid = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!traced(i)) continue;
    ++valid;
    sum_values += double(sum(out.irradiance[i])) / 3;
    sum_squared_errors += double(out.standard_error[i]) * out.standard_error[i];
  }
  if (valid > 0) {
    out.mean_irradiance = sum_values / double(valid);
    out.relative_noise = out.mean_irradiance > 0 ? std::sqrt(sum_squared_errors / double(valid)) / out.mean_irradiance : 0;
    out.mean_path_vertices = double(total_bounces) / (double(valid) * n);
    out.samples = n;
  }
  return out;
}

}  // namespace radbake
