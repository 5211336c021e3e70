#include "baker/pipeline/annual_daylight.h"

#include <Eigen/Core>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include "baker/direct/sky_light.h"
#include "baker/finish/finish.h"
#include "baker/pipeline/bake.h"
#include "baker/surface/sampling.h"
#include "baker/transport/patch_transport.h"
#include "baker/transport/solve_columns.h"
#include "base/progress.h"
#include "daylight/sky_patches.h"

namespace radbake {
namespace {

// The scene's up, north and east (from BakeOptions::sky), to turn directions into altitude and
// azimuth and back.
struct Compass {
  Vec3 up, north, east;
  explicit Compass(const SkyLight& sky)
      : up(normalize(sky.up)), north(normalize(sky.north)), east(normalize(cross(north, up))) {}
  // The patch of `patches` that a direction above the horizon falls in.
  size_t patch(const SkyPatches& patches, Vec3 d) const {
    const double altitude = std::asin(std::clamp(double(dot(d, up)), -1.0, 1.0));
    return patches.patch_at(altitude, std::atan2(double(dot(d, east)), double(dot(d, north))));
  }
  Vec3 direction(double altitude, double azimuth) const {
    return normalize(up * float(std::sin(altitude)) +
                     (north * float(std::cos(azimuth)) + east * float(std::sin(azimuth))) * float(std::cos(altitude)));
  }
};

// A patch's mean luminance under an hour's sky: a 4 x 4 grid over its altitudes and azimuths,
// weighted by the solid angle each cell spans.
double patch_luminance(const SkyPatches& patches, size_t k, const SkyView& view, const Compass& compass) {
  double a0, a1, z0, z1;
  patches.bounds(k, &a0, &a1, &z0, &z1);
  double sum = 0, weights = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double altitude = a0 + (a1 - a0) * (i + 0.5) / 4, azimuth = z0 + (z1 - z0) * (j + 0.5) / 4;
      const double w = std::cos(altitude);
      sum += w * view.luminance(compass.direction(altitude, azimuth));
      weights += w;
    }
  return sum / weights;
}

// Per sensor, the sky it sees itself: (patch of `fine`, lux per cd/m2) for each patch its sky rays
// reach, and the ground's share. The rays a single bake's sensor casts.
struct DirectSky {
  std::vector<std::pair<uint32_t, float>> patches;
  float ground = 0;
};

DirectSky direct_sky(const Sensor& s, size_t index, const SkyPatches& fine, const Compass& compass,
                     const Surface& surface, const RayTracer& tracer, const SkyPortals& portals, uint32_t rays,
                     uint64_t seed) {
  const Vec3 origin = sensor_origin(s.position, s.normal, surface.scene_extent);
  Rng rng(seed, Stream::SensorSky, index);
  const SensorRayPatterns pattern(rng);
  std::map<uint32_t, float> seen;
  DirectSky out;
  const SkyRaySet set(portals, rays_per_batch(rays), origin, s.normal);
  for (uint32_t b = 0; b < kSensorBatches; ++b)
    for (uint32_t k = 0; k < rays_per_batch(rays); ++k) {
      const Vec3 d = set.direction(k, s.normal, s.normal, origin, pattern.batch[b]);
      const double weight = set.lux_per_luminance(d, s.normal, s.normal, origin);
      if (!(weight > 0)) continue;
      const float passes = tracer.transmittance(origin, d, 0.0f, INFINITY);
      if (!(passes > 0)) continue;
      const float lux_per_luminance = float(weight * passes / kSensorBatches);
      if (dot(d, compass.up) > 0) seen[uint32_t(compass.patch(fine, d))] += lux_per_luminance;
      else out.ground += lux_per_luminance;
    }
  out.patches.assign(seen.begin(), seen.end());
  return out;
}

// The sun's direct illuminance at a sensor per lux of direct normal illuminance: its shadow rays
// to the disc, as a single bake's sensor casts them.
double direct_sun(const Sensor& s, size_t index, const SkyView& view, const Surface& surface, const RayTracer& tracer,
                  uint32_t sun_rays, uint64_t seed) {
  const Vec3 origin = sensor_origin(s.position, s.normal, surface.scene_extent);
  Rng rng(seed, Stream::SensorSky, index);
  const SkyRayPatterns pattern(rng);
  double seen = 0;
  for (uint32_t k = 0; k < sun_rays; ++k) {
    const Vec3 d = view.toward_sun(cmj_sample(k, sun_rays, pattern.sun_disc));
    const float incidence = dot(s.normal, d);
    if (incidence > 0) seen += incidence * tracer.transmittance(origin, d, 0.0f, INFINITY);
  }
  return seen / sun_rays;
}

// The share of the sun's disc an eye sees: in front of it, through what lies between.
double sun_seen(const Sensor& eye, const SkyView& view, const Surface& surface, const RayTracer& tracer,
                uint32_t sun_rays, uint64_t seed) {
  if (!(dot(sun_direction(view.sky()), eye.normal) > 0)) return 0;
  Rng rng(seed, Stream::View, uint64_t(-2));
  return sun_disc_seen(view, tracer, sensor_origin(eye.position, eye.normal, surface.scene_extent), sun_rays, rng.next_u32());
}

// An hour's sun bins (columns after the sky's) and their weights: its reflected sunlight is
// interpolated between the solves of the bins around its sun (SkyPatches::interpolation), so a
// sunlit patch on a wall moves with the hour's sun, not from bin centre to bin centre.
using SunColumns = std::vector<std::pair<size_t, float>>;

// Each texel's year from its coefficients, over the occupied daylit hours, into pages. The sky's
// part of every texel-hour is one matrix product, 64 texels at a time (texels x sky columns times
// sky columns x hours: the hours' luminances are read once per 64 texels, not once per texel, and
// the product runs on SIMD); the sun's up to 4 bins per hour are added after.
void texel_maps(const Elements& e, const Surface& surface, const std::vector<float>& coefficient, size_t columns,
                size_t bins, const std::vector<float>& hour_luminance, const std::vector<float>& hour_sun,
                const std::vector<SunColumns>& sun_columns_of_hour, const std::vector<SkyLight>& hours,
                const AnnualDaylightOptions& annual, AnnualDaylight& out) {
  using Matrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic>;
  using RowMajor = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  std::vector<size_t> counted;
  for (size_t h = 0; h < hours.size(); ++h)
    if (hours[h].enabled && h < annual.occupied.size() && annual.occupied[h]) counted.push_back(h);
  const size_t n = e.size();
  std::vector<Rgb> autonomy(n), useful(n), mean(n);
  Matrix luminance(Eigen::Index(bins), Eigen::Index(counted.size()));  // sky column x counted hour
  for (size_t j = 0; j < counted.size(); ++j)
    for (size_t b = 0; b < bins; ++b) luminance(Eigen::Index(b), Eigen::Index(j)) = hour_luminance[counted[j] * bins + b];
  constexpr size_t kTexels = 64;
  tbb::parallel_for(size_t(0), counted.empty() ? 0 : (n + kTexels - 1) / kTexels, [&](size_t block) {
    const size_t first = block * kTexels, rows = std::min(kTexels, n - first);
    const Eigen::Map<const RowMajor, 0, Eigen::OuterStride<>> sky_coefficients(
        &coefficient[first * columns], Eigen::Index(rows), Eigen::Index(bins), Eigen::OuterStride<>(Eigen::Index(columns)));
    const RowMajor sky_lux = sky_coefficients * luminance;  // texel x counted hour
    for (size_t r = 0; r < rows; ++r) {
      const size_t i = first + r;
      if (!e.valid(i)) continue;
      const float* c = &coefficient[i * columns];
      size_t over = 0, within = 0;
      double total = 0;
      for (size_t j = 0; j < counted.size(); ++j) {
        const size_t h = counted[j];
        float lux = sky_lux(Eigen::Index(r), Eigen::Index(j));
        if (hour_sun[h] > 0)
          for (auto [column, weight] : sun_columns_of_hour[h]) lux += hour_sun[h] * weight * c[bins + column];
        over += lux >= annual.da_threshold;
        within += lux >= annual.udi_low && lux <= annual.udi_high;
        total += lux;
      }
      const float k = 100.0f / float(counted.size());
      autonomy[i] = Rgb{1, 1, 1} * (float(over) * k), useful[i] = Rgb{1, 1, 1} * (float(within) * k);
      mean[i] = Rgb{1, 1, 1} * float(total / double(counted.size()));
    }
  });
  out.texel_daylight_autonomy = compose_pages(e, autonomy, surface.pages);
  out.texel_udi = compose_pages(e, useful, surface.pages);
  out.texel_mean_lux = compose_pages(e, mean, surface.pages);
}

// What every phase of the year reads: the scene as a bake sees it, the compass and the patches of
// the sky (`sky`: the surfaces' light; `fine`: the sky a sensor sees itself; `sun_bins`).
struct YearScene {
  const Elements& e;
  const Surface& surface;
  const RayTracer& tracer;
  Compass compass;
  SkyPatches sky, fine, sun_bins;
  size_t bins;  // the sky's patches, then the ground
  uint64_t seed;
};

// Each element's sky, by the rays the sky's irradiance casts: lux per cd/m2 of each bin,
// [element * bins + bin].
std::vector<float> sky_response(const YearScene& y, uint32_t rays, Progress& progress) {
  const Elements& e = y.e;
  const size_t n = e.size(), bins = y.bins;
  std::vector<float> response(n * bins, 0.0f);
  progress.begin("sky patches", n);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 64), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i) {
      if (!e.valid(i)) continue;
      const Vec3 ng = y.surface.normal[e.triangle[i]];
      Rng rng(y.seed, Stream::Sky, i);
      const SkyRayPatterns pattern(rng);
      for (uint32_t k = 0; k < rays; ++k) {
        const Vec3 origin = footprint_point(e, y.surface, i, cmj_sample(k, rays, pattern.origin)) + ng * e.offset[i];
        const Vec3 d = hemisphere_direction(e.normal[i], ng, cmj_sample(k, rays, pattern.direction));
        const float passes = y.tracer.transmittance(origin, d, 0.0f, INFINITY);
        if (!(passes > 0)) continue;
        const size_t bin = dot(d, y.compass.up) > 0 ? y.compass.patch(y.sky, d) : bins - 1;
        response[i * bins + bin] += float(M_PI) * passes / float(rays);
      }
    }
    progress.advance(r.size());
  });
  progress.end();
  return response;
}

// The sun bins around the year's suns, each solved once: per hour its columns (SunColumns), and
// the bin of sun_bins each column stands for.
struct YearSuns {
  std::vector<SunColumns> columns_of_hour;
  std::vector<size_t> bin_of_column;
};

YearSuns year_suns(const std::vector<SkyLight>& hours, const SkyPatches& sun_bins) {
  YearSuns out;
  out.columns_of_hour.resize(hours.size());
  std::map<size_t, size_t> solved_bin;  // bin of sun_bins -> column
  for (size_t h = 0; h < hours.size(); ++h) {
    const SkyLight& hour = hours[h];
    if (!hour.enabled || !(hour.sun_illuminance > 0) || !(hour.sun_zenith < M_PI / 2)) continue;
    for (auto [bin, weight] : sun_bins.interpolation(M_PI / 2 - hour.sun_zenith, hour.sun_azimuth))
      if (weight > 1e-6) out.columns_of_hour[h].push_back({solved_bin.emplace(bin, solved_bin.size()).first->second, float(weight)});
  }
  out.bin_of_column.resize(solved_bin.size());
  for (auto [bin, column] : solved_bin) out.bin_of_column[column] = bin;
  return out;
}

// What each sensor's gather rays strike, and the sky it sees itself.
struct SensorRays {
  std::vector<std::vector<int64_t>> hits;
  std::vector<DirectSky> seen_sky;
};

SensorRays sensor_rays(const YearScene& y, const std::vector<Sensor>& sensors, const SkyPortals& portals,
                       const BakeOptions& options) {
  SensorRays out;
  out.hits.resize(sensors.size());
  out.seen_sky.resize(sensors.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, sensors.size(), 4), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t s = r.begin(); s < r.end(); ++s) {
      out.hits[s] = sensor_gather_hits(sensors[s], s, y.e, y.surface, y.tracer, options.sensor.rays, y.seed).elements;
      out.seen_sky[s] = direct_sky(sensors[s], s, y.fine, y.compass, y.surface, y.tracer, portals, options.sensor.sky_rays, y.seed);
    }
  });
  return out;
}

// Column c's direct light on each element per unit of it: a sky bin's from the response, a sun
// bin's by shadow rays toward the bin's centre (per lux of direct normal sun).
std::vector<float> column_direct(const YearScene& y, const std::vector<float>& response, const YearSuns& suns,
                                 uint32_t bin_sun_rays, size_t c) {
  const Elements& e = y.e;
  const size_t n = e.size(), bins = y.bins;
  std::vector<float> direct(n, 0.0f);
  if (c < bins) {
    for (size_t i = 0; i < n; ++i) direct[i] = response[i * bins + c];
    return direct;
  }
  double altitude = 0, azimuth = 0;
  y.sun_bins.centre(suns.bin_of_column[c - bins], &altitude, &azimuth);
  const Vec3 d = y.compass.direction(altitude, azimuth);
  const uint32_t k_rays = std::max<uint32_t>(1, bin_sun_rays);
  for (size_t i = 0; i < n; ++i) {
    if (!e.valid(i)) continue;
    const Vec3 ng = y.surface.normal[e.triangle[i]];
    const float incidence = dot(e.normal[i], d);
    if (!(incidence > 0) || !(dot(ng, d) > 0)) continue;
    Rng rng(y.seed, Stream::Sky, uint64_t(c) << 40 ^ i);
    const uint32_t pattern = rng.next_u32();
    float passes = 0;
    for (uint32_t k = 0; k < k_rays; ++k)
      passes += y.tracer.transmittance(footprint_point(e, y.surface, i, cmj_sample(k, k_rays, pattern)) + ng * e.offset[i],
                                       d, 0.0f, INFINITY);
    direct[i] = incidence * passes / float(k_rays);
  }
  return direct;
}

// Each patch's area-weighted mean of its members' direct light.
// Patch p's area-weighted mean of `direct`, per element, into column c of `patch_direct`.
void patch_means(const Patches& patches, const Elements& e, const std::vector<float>& direct, size_t columns,
                 size_t c, std::vector<float>& patch_direct) {
  for (size_t p = 0; p < patches.size(); ++p) {
    double total = 0;
    for (uint32_t k = patches.first_member[p]; k < patches.first_member[p + 1]; ++k)
      total += double(direct[patches.members[k]]) * e.area[patches.members[k]];
    patch_direct[p * columns + c] = patches.area[p] > 0 ? float(total / patches.area[p]) : 0.0f;
  }
}

// What a sensor's gather rays take from the elements they struck, per column: each one's rho
// times `light` (lux), photopic, per gather ray.
template <typename Light>
float sent_to_sensor(const Elements& e, const std::vector<int64_t>& hits, uint32_t gather_rays, const Light& light) {
  Rgb sent{};
  for (int64_t j : hits) sent += e.reflectance[size_t(j)] * light(size_t(j));
  return float(photopic(sent) / gather_rays);
}

// One radiosity solve per sky patch, the ground and each sun bin, all solved together
// (solve_columns): the coefficients of what the surfaces send each sensor, lux per cd/m2 (sky,
// ground) or per lux of direct normal sun, [sensor * columns + column]; and, when
// `texel_coefficient` is not empty, what each column brings each element, [element * columns +
// column]. Each column's direct light is found once: its share of the coefficients is kept, its
// patch means go to the solve, and the light the surfaces pass on is added after.
std::vector<float> daylight_coefficients(const YearScene& y, const Interreflection& light_between,
                                         const std::vector<float>& response, const YearSuns& suns,
                                         const SensorRays& rays, const BakeOptions& options,
                                         const AnnualDaylightOptions& annual, std::vector<float>& texel_coefficient,
                                         Progress& progress) {
  const Elements& e = y.e;
  const Patches& patches = light_between.patches;
  const size_t n = e.size(), sensors = rays.hits.size(), columns = y.bins + suns.bin_of_column.size();
  const uint32_t gather_rays = rays_per_batch(options.sensor.rays) * kSensorBatches;
  const bool texels = !texel_coefficient.empty();
  std::vector<float> coefficient(sensors * columns, 0.0f), patch_direct(patches.size() * columns, 0.0f);
  progress.begin("daylight coefficients", columns);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, columns, 1), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t c = r.begin(); c < r.end(); ++c) {
      const std::vector<float> direct = column_direct(y, response, suns, annual.bin_sun_rays, c);
      patch_means(patches, e, direct, columns, c, patch_direct);
      if (texels)
        for (size_t i = 0; i < n; ++i) texel_coefficient[i * columns + c] = direct[i];
      for (size_t s = 0; s < sensors; ++s)
        coefficient[s * columns + c] = sent_to_sensor(e, rays.hits[s], gather_rays, [&](size_t j) {
          return Rgb{direct[j], direct[j], direct[j]};
        });
      progress.advance();
    }
  });
  const ColumnSolution solved = solve_columns(patches, light_between.transport, patch_direct, columns, options.solve);
  auto gathered = [&](size_t i, size_t c) {
    const uint32_t p = patches.patch_of_element[i];
    return p == UINT32_MAX ? Rgb{} : solved.gathered[p * columns + c];
  };
  tbb::parallel_for(tbb::blocked_range<size_t>(0, columns, 1), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t c = r.begin(); c < r.end(); ++c) {
      if (texels)
        for (size_t i = 0; i < n; ++i) texel_coefficient[i * columns + c] += float(photopic(gathered(i, c)));
      for (size_t s = 0; s < sensors; ++s)
        coefficient[s * columns + c] +=
            sent_to_sensor(e, rays.hits[s], gather_rays, [&](size_t j) { return gathered(j, c); });
    }
  });
  progress.end();
  return coefficient;
}

// Every hour: the patches' luminance under its sky, summed with the coefficients into out.lux,
// out.sun_lux and out.eye_sun_seen; each hour's bin luminances and sun (for the texel maps) into
// `hour_luminance` and `hour_sun`.
void hour_sums(const YearScene& y, const std::vector<Sensor>& sensors, const std::vector<SkyLight>& hours,
               const BakeOptions& options, const YearSuns& suns, const SensorRays& rays,
               const std::vector<float>& coefficient, std::vector<float>& hour_luminance, std::vector<float>& hour_sun,
               AnnualDaylight& out, Progress& progress) {
  const size_t bins = y.bins, columns = bins + suns.bin_of_column.size();
  const uint32_t sun_rays = std::max<uint32_t>(1, options.sky.sun_rays);
  std::vector<uint8_t> fine_used(y.fine.size(), 0);
  for (const DirectSky& d : rays.seen_sky)
    for (auto [q, w] : d.patches) fine_used[q] = 1;
  out.lux.assign(hours.size() * sensors.size(), 0.0f);
  out.sun_lux.assign(hours.size() * sensors.size(), 0.0f);
  out.eye_sun_seen.assign(hours.size() * out.eyes, 0.0f);
  hour_luminance.assign(hours.size() * bins, 0.0f);
  hour_sun.assign(hours.size(), 0.0f);
  progress.begin("hours", hours.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, hours.size(), 8), [&](const tbb::blocked_range<size_t>& r) {
    std::vector<double> fine_luminance(y.fine.size()), coarse(bins);
    for (size_t h = r.begin(); h < r.end(); ++h) {
      const SkyLight& hour = hours[h];
      if (!hour.enabled) continue;
      SkyLight shaped = hour;
      shaped.up = options.sky.up, shaped.north = options.sky.north;
      const SkyView view(shaped);
      for (size_t q = 0; q < y.fine.size(); ++q) {
        if (!fine_used[q]) continue;
        double altitude = 0, azimuth = 0;
        y.fine.centre(q, &altitude, &azimuth);
        fine_luminance[q] = view.luminance(y.compass.direction(altitude, azimuth));
      }
      for (size_t p = 0; p + 1 < bins; ++p) coarse[p] = patch_luminance(y.sky, p, view, y.compass);
      coarse[bins - 1] = view.luminance(y.compass.up * -1.0f);
      const double sun = view.sun_up() ? hour.sun_illuminance : 0.0;
      for (size_t b = 0; b < bins; ++b) hour_luminance[h * bins + b] = float(coarse[b]);
      hour_sun[h] = suns.columns_of_hour[h].empty() ? 0.0f : float(sun);
      for (size_t s = 0; s < sensors.size(); ++s) {
        double lux = rays.seen_sky[s].ground * coarse[bins - 1];
        for (auto [q, w] : rays.seen_sky[s].patches) lux += w * fine_luminance[q];
        const float* c = &coefficient[s * columns];
        for (size_t b = 0; b < bins; ++b) lux += c[b] * coarse[b];
        if (sun > 0 && !suns.columns_of_hour[h].empty()) {
          const double direct = sun * direct_sun(sensors[s], s, view, y.surface, y.tracer, sun_rays, y.seed);
          out.sun_lux[h * sensors.size() + s] = float(direct);
          lux += direct;
          for (auto [column, weight] : suns.columns_of_hour[h]) lux += sun * weight * c[bins + column];
        }
        out.lux[h * sensors.size() + s] = float(lux);
      }
      for (size_t k = 0; k < out.eyes && sun > 0; ++k)
        out.eye_sun_seen[h * out.eyes + k] =
            float(sun_seen(sensors[sensors.size() - out.eyes + k], view, y.surface, y.tracer, sun_rays, y.seed));
    }
    progress.advance(r.size());
  });
  progress.end();
}

// The eyes' columns (the last out.eyes of `sensors` of every hour) moved out of the sensors' series
// into out.eye_lux.
void split_off_eyes(size_t sensors, AnnualDaylight& out) {
  if (out.eyes == 0) return;
  const size_t listed = out.sensors.size();
  std::vector<float> lux, sun_lux;
  out.eye_lux.resize(out.hours * out.eyes);
  for (size_t h = 0; h < out.hours; ++h) {
    const float* row = &out.lux[h * sensors];
    lux.insert(lux.end(), row, row + listed);
    sun_lux.insert(sun_lux.end(), &out.sun_lux[h * sensors], &out.sun_lux[h * sensors] + listed);
    std::copy(row + listed, row + sensors, &out.eye_lux[h * out.eyes]);
  }
  out.lux = std::move(lux), out.sun_lux = std::move(sun_lux);
}

}  // namespace

AnnualDaylight annual_daylight(const Scene& scene, const Atlas& atlas, const BakeOptions& options,
                               const std::vector<SkyLight>& hours, const AnnualDaylightOptions& annual,
                               const ProgressCallback& on_progress) {
  const auto started = std::chrono::steady_clock::now();
  Progress progress(on_progress);
  PlanOptions plan_options = options.plan;
  plan_options.sky = true;
  std::vector<StageTime> times;
  BakeGeometry geometry = bake_geometry(scene, atlas, options, plan_effects(scene, plan_options), progress, times);
  const Surface& surface = *geometry.surface;
  const RayTracer& tracer = *geometry.tracer;
  const SkyPortals portals(surface, *geometry.materials);
  const Elements& e = geometry.elements;
  AnnualDaylight out;
  out.sensors = options.sensors;
  if (options.work_plane.enabled) {
    out.work_plane = work_plane(scene, surface, tracer, options.work_plane);
    shift_sensor_indices(out.work_plane, int32_t(options.sensors.size()));
    out.sensors.insert(out.sensors.end(), out.work_plane.sensors.begin(), out.work_plane.sensors.end());
  }
  // The eyes of BakeOptions::views are sensors facing where they look, split off at the end.
  std::vector<Sensor> sensors = out.sensors;
  for (const EyeView& eye : options.views) sensors.push_back({eye.position, normalize(eye.direction)});
  out.eyes = options.views.size();
  const SkyPatches sky(annual.sky_subdivision);
  const YearScene year{e,   surface, tracer, Compass(options.sky), sky, SkyPatches(annual.direct_subdivision),
                       SkyPatches(annual.sun_subdivision), sky.size() + 1, options.seed};

  const std::vector<float> response = sky_response(year, std::max<uint32_t>(1, options.sky.rays), progress);
  // One set of patches and form factors for every sky: their rays weighted by a uniform sky's light.
  std::vector<Rgb> uniform(e.size());
  for (size_t i = 0; i < e.size(); ++i) {
    float sum = 0;
    for (size_t b = 0; b < year.bins; ++b) sum += response[i * year.bins + b];
    uniform[i] = Rgb{sum, sum, sum};
  }
  InterreflectionOptions interreflection = interreflection_options(options);
  interreflection.subdivision = {};  // the coefficients' patches stay as first made: one set for every column
  const Interreflection light_between = solve_interreflection(e, surface, tracer, uniform, interreflection, progress);
  const YearSuns suns = year_suns(hours, year.sun_bins);
  const SensorRays rays = sensor_rays(year, sensors, portals, options);
  const size_t columns = year.bins + suns.bin_of_column.size();
  const bool texels = !annual.occupied.empty();
  std::vector<float> texel_coefficient(texels ? e.size() * columns : 0, 0.0f);
  const std::vector<float> coefficient =
      daylight_coefficients(year, light_between, response, suns, rays, options, annual, texel_coefficient, progress);

  out.hours = hours.size();
  out.sky_patches = year.bins, out.sun_bins = suns.bin_of_column.size();
  out.coefficient_seconds = seconds_since(started);
  const auto hours_started = std::chrono::steady_clock::now();
  std::vector<float> hour_luminance, hour_sun;  // for the texels
  hour_sums(year, sensors, hours, options, suns, rays, coefficient, hour_luminance, hour_sun, out, progress);
  if (texels)
    texel_maps(e, surface, texel_coefficient, columns, year.bins, hour_luminance, hour_sun, suns.columns_of_hour, hours,
               annual, out);
  split_off_eyes(sensors.size(), out);
  out.hours_seconds = seconds_since(hours_started);
  return out;
}

}  // namespace radbake
