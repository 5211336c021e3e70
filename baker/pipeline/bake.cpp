#include "baker/pipeline/bake.h"

#include <malloc.h>
#include <sys/resource.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <thread>

#include "baker/direct/sky_light.h"
#include "baker/gather/final_gather.h"
#include "baker/pipeline/finite_checks.h"
#include "baker/sharing/byte_stream.h"
#include "baker/sharing/shared_stage.h"
#include "baker/surface/material_sampler.h"
#include "baker/surface/ray_tracer.h"
#include "baker/surface/surface.h"
#include "baker/transport/patch_transport.h"
#include "base/errors.h"
#include "base/progress.h"

namespace radbake {
namespace {

class StageClock {
 public:
  explicit StageClock(std::vector<StageTime>& times) : times_(times) {}
  template <typename F>
  auto run(const char* stage, F&& f) {
    auto start = std::chrono::steady_clock::now();
    auto result = f();
    times_.push_back({stage, seconds_since(start)});
    // Stages free large scratch arrays; hand those pages back so the next stage's peak starts
    // from what is live, not from what the allocator keeps cached.
    malloc_trim(0);
    return result;
  }

 private:
  std::vector<StageTime>& times_;
};

// Radiosity from irradiance: emission plus reflected light, lm/m2.
std::vector<Rgb> radiosity_of(const Elements& elements, const std::vector<Rgb>& irradiance) {
  std::vector<Rgb> radiosity(irradiance.size());
  for (size_t i = 0; i < radiosity.size(); ++i)
    radiosity[i] = elements.emission[i] + elements.reflectance[i] * irradiance[i];
  return radiosity;
}

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g%%", 100 * fraction);
  return text;
}

// How the interreflection solve ended, for the plan: the tolerance on unshot light is what stops
// it, never a bounce count; the iteration guard is named when it was reached instead.
PlanDecision solve_outcome(const RadiositySolution& s, const SolveOptions& options) {
  std::string what = std::to_string(s.iterations) + (options.solver == Solver::Shooting ? " shots" : " sweeps");
  std::string unshot = "unshot light " + percent(s.relative_unshot) + " of what the lights brought in";
  if (s.converged)
    return {"interreflection", "stopped after " + what,
            unshot + "; every patch's within the tolerance of " + percent(options.tolerance) + " of its own light"};
  return {"interreflection", "stopped after " + what + " by the iteration guard",
          unshot + "; some patch's above the tolerance of " + percent(options.tolerance) + " of its own light"};
}

// The chunks a texel stage is shared in: about 256, of 1,024 texels or more, whole blocks of 256
// (the gather's), none across a page when `by_page`.
std::vector<size_t> texel_chunk_starts(const Elements& elements, bool by_page) {
  const size_t n = elements.size();
  std::vector<size_t> page_starts;
  if (by_page)
    for (size_t i = 1; i < n; ++i)
      if (elements.page[i] != elements.page[i - 1]) page_starts.push_back(i);
  return chunk_starts(n, n / 256, 1024, 256, page_starts);
}

// Direct light from lights, the sky and emitting surfaces, in chunks of texels shared by the team;
// every process gets all of it (the form factors and the gather read it anywhere). Also the lm,
// mean of RGB, that punctual lights and the sky land on valid elements (where light passes
// through, only what stops there: the rest lands further on), summed chunk by chunk.
std::vector<Rgb> shared_direct_light(const Scene& scene, const BakeGeometry& geometry, const BakeOptions& options,
                                     const EffectPlan& plan, Progress& progress, double& delivered_power,
                                     std::vector<LightDirection>& directions, double& sky_noise) {
  const Elements& elements = geometry.elements;
  const Surface& surface = *geometry.surface;
  const MaterialSampler& materials = *geometry.materials;
  const RayTracer& tracer = *geometry.tracer;
  DirectLightOptions direct = options.direct;
  direct.shadow_rays = plan.shadow_rays;
  direct.cull_unlit = !plan.exhaustive;
  direct.light_traced = plan.light_traced;
  const size_t n = elements.size();
  const std::vector<size_t> starts = texel_chunk_starts(elements, false);
  std::vector<Rgb> irradiance(n);
  const bool directional = options.directional != Directional::None;
  if (directional) directions.assign(n, {});
  std::vector<double> delivered(starts.size() - 1, 0.0);
  // Per chunk, over its valid elements: area, sky irradiance x area, its standard error^2 x area.
  std::vector<std::array<double, 3>> sky_spread(starts.size() - 1, {0, 0, 0});
  const SkyPortals portals = options.sky.enabled ? SkyPortals(surface, materials) : SkyPortals();
  SharedStage stage;
  stage.name = "direct light";
  stage.chunks = starts.size() - 1;
  stage.results_to_all = true;
  stage.compute = [&](size_t chunk) {
    const ElementRange range{starts[chunk], starts[chunk + 1]};
    Progress quiet;
    std::vector<LightDirection> from_lights, from_sky, from;
    std::vector<Rgb> lights_and_sky = punctual_irradiance(elements, surface, scene.lights, tracer, direct, options.seed,
                                                          quiet, range, directional ? &from_lights : nullptr);
    std::array<double, 3> spread{0, 0, 0};
    if (options.sky.enabled) {
      std::vector<float> error;
      const std::vector<Rgb> sky = sky_irradiance(elements, surface, tracer, options.sky, portals, options.seed, quiet,
                                                  range, directional ? &from_sky : nullptr, &error);
      for (size_t k = 0; k < range.size(); ++k) {
        lights_and_sky[k] += sky[k];
        const size_t i = range.begin + k;
        if (!elements.valid(i)) continue;
        const double a = elements.area[i];
        spread[0] += a, spread[1] += double(sky[k].x) * a, spread[2] += double(error[k]) * error[k] * a;
      }
    }
    std::vector<Rgb> total = emitter_irradiance(elements, surface, materials, tracer, direct, options.seed, quiet, range,
                                                directional ? &from : nullptr);
    for (size_t k = 0; k < from.size(); ++k) {
      from[k] += from_lights[k];
      if (!from_sky.empty()) from[k] += from_sky[k];
    }
    double power = 0;
    for (size_t k = 0; k < range.size(); ++k) {
      const size_t i = range.begin + k;
      const double stops = elements.opacity.empty() ? 1.0 : elements.opacity[i];
      if (elements.valid(i)) power += stops * double(sum(lights_and_sky[k])) / 3.0 * elements.area[i];
      total[k] += lights_and_sky[k];
    }
    ByteWriter out;
    out.put(power);
    for (double v : spread) out.put(v);
    out.put_vector(total);
    out.put_vector(from);
    return out.bytes();
  };
  stage.take = [&](size_t chunk, const Bytes& result) {
    ByteReader in(result);
    delivered[chunk] = in.get<double>();
    for (double& v : sky_spread[chunk]) v = in.get<double>();
    const std::vector<Rgb> values = in.get_vector<Rgb>();
    const std::vector<LightDirection> from = in.get_vector<LightDirection>();
    const size_t count = starts[chunk + 1] - starts[chunk];
    if (values.size() != count || from.size() != (directional ? count : 0)) throw TruncatedBytes();
    std::copy(values.begin(), values.end(), irradiance.begin() + std::ptrdiff_t(starts[chunk]));
    if (directional) std::copy(from.begin(), from.end(), directions.begin() + std::ptrdiff_t(starts[chunk]));
  };
  run_shared_stage(stage, *options.sharing.team, options.sharing.store, options.sharing.resume, tracer, progress);
  delivered_power = 0;
  for (double d : delivered) delivered_power += d;
  std::array<double, 3> spread{0, 0, 0};
  for (const auto& s : sky_spread)
    for (int k = 0; k < 3; ++k) spread[size_t(k)] += s[size_t(k)];
  sky_noise = spread[1] > 0 ? std::sqrt(spread[2] / spread[0]) / (spread[1] / spread[0]) : 0.0;
  return irradiance;
}

// The chunks of a gather slice: whole pages, or runs of texels, in `count` parts of about equal
// numbers of gathering elements.
std::vector<size_t> slice_chunks(const Elements& elements, const Patches& patches, const std::vector<size_t>& starts,
                                 const GatherSlice& slice) {
  const size_t chunks = starts.size() - 1;
  std::vector<double> weight(chunks, 0.0);
  double total = 0;
  for (size_t c = 0; c < chunks; ++c) {
    for (size_t i = starts[c]; i < starts[c + 1]; ++i)
      weight[c] += elements.valid(i) && patches.patch_of_element[i] != UINT32_MAX;
    total += weight[c];
  }
  std::vector<size_t> wanted;
  double before = 0;
  for (size_t c = 0; c < chunks;) {
    // A page's chunks go together when slicing by pages.
    size_t end = c + 1;
    if (slice.by == GatherSlice::By::Pages)
      while (end < chunks && elements.page[starts[end]] == elements.page[starts[c]]) ++end;
    double w = 0;
    for (size_t k = c; k < end; ++k) w += weight[k];
    const int part = total > 0 ? std::min(slice.count - 1, int((before + w / 2) / total * slice.count)) : 0;
    if (part == slice.index)
      for (size_t k = c; k < end; ++k) wanted.push_back(k);
    before += w;
    c = end;
  }
  return wanted;
}

std::string slice_stage_name(int index, int count) {
  return "final gather, slice " + std::to_string(index + 1) + " of " + std::to_string(count);
}

// The final gather in chunks of texels (never across a page) shared by the team; the first
// process joins them and finishes the gather (finish_gather). The others, and a run that bakes a
// slice (then StoppedEarly), get nothing. With merge_slices, the chunks come from the slices saved
// in the store instead.
std::optional<GatheredLight> shared_gather(const BakeGeometry& geometry, const Patches& patches,
                                           const PatchTransport& transport, const std::vector<Rgb>& patch_exitance,
                                           const std::vector<Rgb>& direct, const BakeOptions& options,
                                           Progress& progress, GatherStats* stats) {
  const Elements& elements = geometry.elements;
  const Surface& surface = *geometry.surface;
  const RayTracer& tracer = *geometry.tracer;
  const Sharing& sharing = options.sharing;
  Team& team = *sharing.team;
  ByteWriter indirect;
  if (team.first()) indirect.put_vector(gathered_irradiance(patches, transport, patch_exitance));
  team.broadcast_from_first("final gather", indirect.bytes());
  const GatherInputs inputs =
      gather_inputs(elements, patches, surface, ByteReader(indirect.bytes()).get_vector<Rgb>(), direct);
  const size_t n = elements.size();
  const bool directional = options.directional != Directional::None;
  const std::vector<size_t> starts = texel_chunk_starts(elements, true);
  const size_t chunks = starts.size() - 1;
  GatherTrace whole;
  std::vector<std::vector<NearLanding>> landings(chunks);
  if (team.first()) {
    whole.irradiance.resize(n);
    whole.harmonic_distance.assign(n, INFINITY);
    whole.open_view.assign(n, 0.0f);
    whole.lost_share.assign(n, 0.0f);
    whole.far_beyond_mean.assign(n, Rgb{});
    if (directional) whole.mean_direction.resize(n);
  }
  SharedStage stage;
  stage.name = "final gather";
  stage.chunks = chunks;
  stage.compute = [&](size_t chunk) {
    const GatherTrace t = trace_gather(geometry, patches, inputs, patch_exitance, direct, options.gather, options.seed,
                                       ElementRange{starts[chunk], starts[chunk + 1]}, directional);
    ByteWriter out;
    out.put_vector(t.irradiance);
    out.put_vector(t.harmonic_distance);
    out.put_vector(t.open_view);
    out.put_vector(t.lost_share);
    out.put_vector(t.far_beyond_mean);
    out.put_vector(t.mean_direction);
    out.put_vector(t.landings);
    out.put(t.fates);
    return out.bytes();
  };
  stage.take = [&](size_t chunk, const Bytes& result) {
    ByteReader in(result);
    const std::vector<Rgb> irradiance = in.get_vector<Rgb>();
    const std::vector<float> distance = in.get_vector<float>();
    const std::vector<float> open_view = in.get_vector<float>();
    const std::vector<float> lost_share = in.get_vector<float>();
    const std::vector<Rgb> far_beyond_mean = in.get_vector<Rgb>();
    const std::vector<LightDirection> mean_direction = in.get_vector<LightDirection>();
    landings[chunk] = in.get_vector<NearLanding>();
    const size_t count = starts[chunk + 1] - starts[chunk];
    if (irradiance.size() != count || distance.size() != count || open_view.size() != count ||
        lost_share.size() != count || far_beyond_mean.size() != count ||
        mean_direction.size() != (directional ? count : 0))
      throw TruncatedBytes();
    if (!mean_direction.empty())
      std::copy(mean_direction.begin(), mean_direction.end(), whole.mean_direction.begin() + std::ptrdiff_t(starts[chunk]));
    for (const NearLanding& l : landings[chunk])
      if (l.receiver < starts[chunk] || l.receiver >= starts[chunk + 1] || l.struck >= n) throw TruncatedBytes();
    std::copy(irradiance.begin(), irradiance.end(), whole.irradiance.begin() + std::ptrdiff_t(starts[chunk]));
    std::copy(distance.begin(), distance.end(), whole.harmonic_distance.begin() + std::ptrdiff_t(starts[chunk]));
    std::copy(open_view.begin(), open_view.end(), whole.open_view.begin() + std::ptrdiff_t(starts[chunk]));
    std::copy(lost_share.begin(), lost_share.end(), whole.lost_share.begin() + std::ptrdiff_t(starts[chunk]));
    std::copy(far_beyond_mean.begin(), far_beyond_mean.end(), whole.far_beyond_mean.begin() + std::ptrdiff_t(starts[chunk]));
    whole.fates += in.get<RayFates>();
  };
  if (sharing.merge_slices > 0) {
    if (team.first()) {
      std::vector<uint8_t> taken(chunks, 0);
      for (int k = 0; k < sharing.merge_slices; ++k) {
        const std::string name = slice_stage_name(k, sharing.merge_slices);
        std::optional<Bytes> saved = sharing.store->load(name + " waves");
        if (!saved) throw InputError("the checkpoint holds no " + name + ": bake it with --pages or --texel-range " +
                                     std::to_string(k + 1) + "/" + std::to_string(sharing.merge_slices));
        for (size_t c : take_saved_stage(stage, *saved)) {
          if (taken[c]) throw InputError("the checkpoint's slices overlap: slice " + std::to_string(k + 1) +
                                         " bakes texels another has baked (slices of different kinds?)");
          taken[c] = 1;
        }
      }
      if (std::count(taken.begin(), taken.end(), uint8_t(1)) != std::ptrdiff_t(chunks))
        throw InputError("the checkpoint's slices do not cover every texel: a slice was stopped before it ended");
    }
  } else {
    if (sharing.slice.by != GatherSlice::By::Everything) {
      stage.name = slice_stage_name(sharing.slice.index, sharing.slice.count);
      stage.only = slice_chunks(elements, patches, starts, sharing.slice);
    }
    run_shared_stage(stage, team, sharing.store, sharing.resume, tracer, progress);
    if (sharing.slice.by != GatherSlice::By::Everything) throw StoppedEarly(stage.name);
  }
  if (!team.first()) return std::nullopt;
  for (const auto& l : landings) whole.landings.insert(whole.landings.end(), l.begin(), l.end());
  return finish_gather(elements, patches, transport, inputs, patch_exitance, direct, options.gather, std::move(whole),
                       stats);
}

// Light between surfaces: patches, form factors and the radiosity solve, then the final gather
// at texel resolution. Adds the indirect light to result.direct into result.irradiance and fills
// the report's solve figures and energy balance.
void interreflect(const BakeGeometry& geometry, const BakeOptions& options, const EffectPlan& plan,
                  double delivered_power, const FiniteCheckContext& checked, Progress& progress,
                  const PreviewCallback& on_preview, BakeResult& result) {
  const Elements& elements = geometry.elements;
  const Surface& surface = *geometry.surface;
  const RayTracer& tracer = *geometry.tracer;
  BakeReport& report = result.report;
  InterreflectionObserver observer;
  if (on_preview && options.preview_every > 0) {
    observer.every = options.preview_every;
    observer.see = [&](const Patches& patches, const PatchTransport& transport, const std::vector<Rgb>& exitance,
                       size_t iteration) {
      std::vector<Rgb> gathered = gathered_irradiance(patches, transport, exitance);
      std::vector<Rgb> estimate = result.direct;
      for (size_t i = 0; i < estimate.size(); ++i)
        if (patches.patch_of_element[i] != UINT32_MAX) estimate[i] += gathered[patches.patch_of_element[i]];
      if (options.store == StoredQuantity::Radiosity) estimate = radiosity_of(elements, estimate);
      on_preview(compose_pages(elements, estimate, surface.pages), iteration);
    };
  }
  InterreflectionOptions interreflection = interreflection_options(options);
  if (plan.one_channel) interreflection.solve.one_channel_colour = plan.light_colour;
  auto started = std::chrono::steady_clock::now();
  Team& team = *options.sharing.team;
  Interreflection light_between =
      solve_interreflection(elements, surface, tracer, result.direct, interreflection, progress, observer, options.sharing);
  if (options.sharing.stop_after == StopAfter::Radiosity) throw StoppedEarly("radiosity");
  const double interreflection_seconds = seconds_since(started);
  report.stage_times.push_back({"patches", interreflection_seconds - light_between.form_factor_seconds -
                                               light_between.solve_seconds});
  report.stage_times.push_back({"form factors", light_between.form_factor_seconds});
  report.stage_times.push_back({"radiosity", light_between.solve_seconds});
  malloc_trim(0);
  const Patches& patches = light_between.patches;
  const RadiositySolution& solution = light_between.solution;
  if (team.first()) check_patches("the radiosity solve", patches, light_between.transport, solution.exitance, checked);
  GatherStats gather_stats;
  StageClock clock(report.stage_times);
  std::optional<GatheredLight> gathered = clock.run("final gather", [&] {
    return shared_gather(geometry, patches, light_between.transport, solution.exitance, result.direct, options, progress,
                         &gather_stats);
  });
  if (!gathered) return;
  result.open_view = std::move(gathered->open_view);
  result.irradiance = clock.run("gather filter", [&] {
    std::vector<uint8_t> gathering(elements.size());
    for (size_t i = 0; i < elements.size(); ++i) gathering[i] = patches.patch_of_element[i] != UINT32_MAX;
    return filter_gathered(elements, surface, gathered->irradiance, gathered->harmonic_distance, gathering,
                           options.gather.filter);
  });
  check_element_values("the final gather", result.irradiance, checked, patches.patch_of_element);
  if (options.directional != Directional::None)
    result.light_directions = total_light_directions(result.light_directions, gathered->mean_direction, result.irradiance);
  for (size_t i = 0; i < elements.size(); ++i) result.irradiance[i] += result.direct[i];
  const TexelFates fates = options.gather.rays > 0 ? TexelFates{result.open_view, gathered->lost_share} : TexelFates{};
  report.balance = energy_balance(elements, patches, light_between.transport, delivered_power, result.irradiance, fates);

  report.patches = patches.size();
  report.patch_block_size = patches.block_size;
  report.mean_free_path_m = light_between.mean_free_path_m;
  report.subdivision_rounds = light_between.rounds;
  report.solver_iterations = solution.iterations;
  report.solved_channels = solution.channels;
  report.unshot_relative = solution.relative_unshot;
  report.converged = solution.converged;
  report.ambient = solution.ambient;
  report.gather_rays = gather_stats.fates;
  report.form_factor_rays = light_between.transport.fates;
  report.plan.push_back(solve_outcome(solution, interreflection.solve));
  if (!solution.converged)
    report.warnings.push_back("the radiosity solve stopped at its iteration guard before reaching the tolerance");
  result.patch_of_element = std::move(light_between.patches.patch_of_element);
}

// The baker's way: direct light from lights and emitting surfaces at every texel, then, when the
// plan calls for it, the light between surfaces (interreflect).
void compute_radiosity(const Scene& scene, const BakeGeometry& geometry, const BakeOptions& options,
                       const EffectPlan& plan, const FiniteCheckContext& checked, Progress& progress,
                       const PreviewCallback& on_preview, BakeResult& result) {
  const Elements& elements = geometry.elements;
  StageClock clock(result.report.stage_times);
  double delivered_power = 0;
  result.direct = clock.run("direct light", [&] {
    return shared_direct_light(scene, geometry, options, plan, progress, delivered_power, result.light_directions,
                               result.report.sky_noise);
  });
  check_element_values("direct light", result.direct, checked);
  if (options.sharing.stop_after == StopAfter::DirectLight) throw StoppedEarly("direct light");
  if (plan.interreflection) {
    interreflect(geometry, options, plan, delivered_power, checked, progress, on_preview, result);
  } else {
    result.irradiance = result.direct;
    result.patch_of_element.assign(elements.size(), UINT32_MAX);
  }
}

// The loader holds each material's luminance to kMaxLuminance; the emission scale must not
// multiply it past that.
void refuse_overbright_materials(const Scene& scene, float emission_scale) {
  for (const Material& m : scene.materials) {
    const double luminance = double(max_component(m.emissive)) * m.emissive_strength * emission_scale;
    if (luminance > kMaxLuminance) {
      char text[96];
      std::snprintf(text, sizeof text, "' would glow at %.3g cd/m2 under the emission scale %g, above the %g",
                    luminance, double(emission_scale), kMaxLuminance);
      throw InputError("material '" + clipped(m.name) + text + " radbake bakes");
    }
  }
}

// The reference's way: every light and every bounce by the path tracer, whatever the plan says.
void compute_path_traced(const Scene& scene, const BakeGeometry& geometry, const BakeOptions& options,
                         const FiniteCheckContext& checked, Progress& progress, BakeResult& result) {
  const Elements& elements = geometry.elements;
  const Surface& surface = *geometry.surface;
  const MaterialSampler& materials = *geometry.materials;
  const RayTracer& tracer = *geometry.tracer;
  BakeReport& report = result.report;
  StageClock clock(report.stage_times);
  PathTraced traced = clock.run("path tracing", [&] {
    return path_trace(elements, surface, materials, scene.lights, &options.sky, tracer, options.path_trace,
                      options.seed, progress);
  });
  check_element_values("path tracing", traced.irradiance, checked);
  result.irradiance = std::move(traced.irradiance);
  result.standard_error = std::move(traced.standard_error);
  result.patch_of_element.assign(elements.size(), UINT32_MAX);
  report.path_samples = traced.samples;
  report.path_relative_noise = traced.relative_noise;
  report.path_mean_vertices = traced.mean_path_vertices;
  report.plan.push_back({"method", "path tracing",
                         "every light and every bounce, whatever the plan would leave out: the reference"});
}

// What is read from the finished light, by the surfaces' `exitance` (lm/m2): the sensors and the
// work plane, the eyes' views and glare, the light probes.
void take_readings(const Scene& scene, const BakeGeometry& geometry, const BakeOptions& options,
                   const std::vector<Rgb>& exitance, Progress& progress, BakeResult& result) {
  const Elements& elements = geometry.elements;
  const Surface& surface = *geometry.surface;
  const MaterialSampler& materials = *geometry.materials;
  const RayTracer& tracer = *geometry.tracer;
  BakeReport& report = result.report;
  StageClock clock(report.stage_times);
  if (!options.sensors.empty() || options.work_plane.enabled) {
    result.sensors = options.sensors;
    if (options.work_plane.enabled) {
      shift_sensor_indices(result.work_plane, int32_t(options.sensors.size()));
      result.sensors.insert(result.sensors.end(), result.work_plane.sensors.begin(), result.work_plane.sensors.end());
    }
    SensorReadings readings = clock.run("sensors", [&] {
      if (options.method != Method::PathTrace)
        return sensor_illuminance(result.sensors, scene.lights, geometry, exitance, options.sky,
                                  options.sky.enabled ? SkyPortals(surface, materials) : SkyPortals(), options.sensor,
                                  options.seed, progress);
      // The reference: whole paths from each sensor, as many as its sky rays, sharing nothing
      // with the sensors' own sampling.
      std::vector<Vec3> points, normals;
      for (const Sensor& s : result.sensors)
        points.push_back(sensor_origin(s.position, s.normal, surface.scene_extent)), normals.push_back(s.normal);
      PathTracedPoints traced = path_trace_points(points, normals, elements, surface, materials, scene.lights, &options.sky,
                                                  tracer, options.sensor.sky_rays, options.seed);
      SensorReadings out;
      for (const Rgb& e : traced.irradiance) out.lux.push_back(photopic(e));
      out.standard_error = std::move(traced.standard_error);
      return out;
    });
    result.sensor_lux = std::move(readings.lux);
    result.sensor_standard_error = std::move(readings.standard_error);
  }
  if (!options.views.empty()) {
    clock.run("views", [&] {
      for (const EyeView& eye : options.views) {
        result.views.push_back(render_fisheye(eye, options.view, elements, exitance, surface, tracer, options.sky, options.seed));
        result.glare.push_back(evaluate_glare(result.views.back()));
        result.perspectives.push_back(render_perspective(eye, options.view, elements, exitance, surface, tracer, options.sky, options.seed));
      }
      return 0;
    });
  }
  if (options.probes.enabled) {
    result.probes = clock.run("light probes", [&] {
      LightProbes probes = place_probes(surface, tracer, options.probes);
      light_probes(probes, geometry, exitance, scene.lights, options.sky, options.probes, options.seed, progress);
      return probes;
    });
    report.light_probes = result.probes.probes.size();
    report.light_probe_spacing = result.probes.spacing;
  }
}

}  // namespace

uint64_t peak_resident_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return uint64_t(usage.ru_maxrss) * 1024;
}

BakeGeometry bake_geometry(const Scene& scene, const Atlas& atlas, const BakeOptions& options, const EffectPlan& plan,
                           Progress& progress, std::vector<StageTime>& times) {
  StageClock clock(times);
  BakeGeometry g;
  g.surface = clock.run("surface", [&] { return std::make_unique<Surface>(build_surface(scene, atlas)); });
  g.materials = std::make_unique<MaterialSampler>(scene, *g.surface, options.emission_scale, options.glazing);
  g.tracer = clock.run("ray tracer", [&] { return std::make_unique<RayTracer>(*g.surface, g.materials.get()); });
  ElementOptions element_options = options.elements;
  if (plan.exhaustive) element_options.filter = FootprintFilter::Everywhere;
  else if (!plan.texture_sampling) element_options.filter = FootprintFilter::BetweenMaterials;
  g.elements = clock.run("elements", [&] { return build_elements(*g.surface, *g.materials, element_options, progress); });
  clock.run("sample placement", [&] {
    place_samples(g.elements, *g.surface, *g.tracer, options.seed, progress);
    return 0;
  });
  check_elements(FiniteCheckContext{scene, *g.surface, g.elements});
  if (std::none_of(g.elements.flags.begin(), g.elements.flags.end(), [](uint8_t f) { return !(f & kBuried); }))
    throw InputError("no lightmap texel covers a visible surface: raise the texel density or the page size");
  return g;
}

BakeResult bake(const Scene& scene, const Atlas& atlas, const BakeOptions& options,
                const ProgressCallback& on_progress, const PreviewCallback& on_preview) {
  PlanOptions plan = options.plan;
  plan.sky = options.sky.enabled;
  return bake(scene, atlas, options, plan_effects(scene, plan), on_progress, on_preview);
}

BakeResult bake(const Scene& scene, const Atlas& atlas, const BakeOptions& given, const EffectPlan& plan,
                const ProgressCallback& on_progress, const PreviewCallback& on_preview) {
  SoloTeam alone;
  BakeOptions options = given;
  if (!options.sharing.team) options.sharing.team = &alone;
  Team& team = *options.sharing.team;
  validate(options);
  const bool sliced = options.sharing.slice.by != GatherSlice::By::Everything || options.sharing.merge_slices > 0;
  if (sliced && (options.method != Method::Radiosity || !plan.interreflection))
    throw InputError("this bake has no final gather to slice: the plan simulates direct light only");
  if (team.size() > 1 && options.method == Method::PathTrace)
    throw InputError("the path tracer bakes in one process: run it without mpirun");
  std::unique_ptr<tbb::global_control> thread_limit;
  if (options.threads > 0)
    thread_limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, options.threads);

  refuse_overbright_materials(scene, options.emission_scale);

  Progress progress(on_progress);
  BakeResult result;
  BakeReport& report = result.report;
  StageClock clock(report.stage_times);

  BakeGeometry geometry = bake_geometry(scene, atlas, options, plan, progress, report.stage_times);
  const Surface& surface = *geometry.surface;
  const std::unique_ptr<RayTracer>& tracer = geometry.tracer;
  Elements& elements = geometry.elements;
  if (options.work_plane.enabled) result.work_plane = work_plane(scene, surface, *tracer, options.work_plane);
  const FiniteCheckContext checked{scene, surface, elements};

  const size_t n = elements.size();
  report.plan = plan.decisions;
  report.warnings = plan.warnings;
  if (options.method == Method::PathTrace) {
    compute_path_traced(scene, geometry, options, checked, progress, result);
  } else {
    compute_radiosity(scene, geometry, options, plan, checked, progress, on_preview, result);
  }
  // The team's rays (the others' counted here, the first's at the end: it goes on to the sensors)
  // and each process's peak memory so far, for the report.
  ByteWriter mine;
  mine.put(team.first() ? uint64_t(0) : tracer->rays_cast());
  mine.put(peak_resident_bytes());
  uint64_t others_rays = 0;
  for (const Bytes& b : team.gather_to_first("report", mine.bytes())) {
    ByteReader in(b);
    others_rays += in.get<uint64_t>();
    report.process_peak_bytes.push_back(in.get<uint64_t>());
  }
  report.processes = team.size();
  report.traffic = team.traffic();
  if (!team.first()) return {};
  if (!options.keep_direct) result.direct = {};
  std::vector<Rgb> radiosity;
  if (options.store == StoredQuantity::Radiosity) radiosity = radiosity_of(elements, result.irradiance);
  const std::vector<Rgb>& stored = radiosity.empty() ? result.irradiance : radiosity;
  result.pages = clock.run("dilation", [&] { return compose_pages(elements, stored, surface.pages); });
  if (options.directional != Directional::None)
    result.directional = clock.run("directional pages", [&] {
      return directional_pages(options.directional, elements, result.irradiance, result.light_directions, surface.pages);
    });
  result.vertex_values =
      clock.run("vertex values", [&] { return vertex_values(elements, surface, atlas, result.pages, stored); });
  check_vertex_values(result.vertex_values, scene);
  if (!options.sensors.empty() || options.work_plane.enabled || !options.views.empty() || options.probes.enabled) {
    const std::vector<Rgb> exitance = radiosity.empty() ? radiosity_of(elements, result.irradiance) : radiosity;
    take_readings(scene, geometry, options, exitance, progress, result);
  }
  result.display_camera = clock.run("display camera", [&] { return display_camera(scene, surface, *tracer); });
  result.display_view = clock.run("display view", [&] { return display_view(scene, result.display_camera, surface, *tracer); });
  report.surfaces =
      surface_statistics(scene, surface, elements, result.irradiance, result.open_view, result.standard_error);

  for (const AtlasPage& p : surface.pages) report.page_texels += size_t(p.width) * p.height;
  report.elements = n;
  for (size_t i = 0; i < n; ++i) {
    report.valid_elements += elements.valid(i);
    report.buried_elements += !elements.valid(i);
    report.moved_samples += (elements.flags[i] & kPushedOut) != 0;
    report.filtered_texels += (elements.flags[i] & kFiltered) != 0;
  }
  report.rays = tracer->rays_cast() + others_rays;
  result.elements = std::move(elements);
  return result;
}

}  // namespace radbake
