#include "baker/bake.h"

#include <malloc.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <thread>

#include "baker/errors.h"
#include "baker/final_gather.h"
#include "baker/finite_checks.h"
#include "baker/material_sampler.h"
#include "baker/patch_transport.h"
#include "baker/ray_tracer.h"
#include "baker/surface.h"

namespace radbake {
namespace {

class StageClock {
 public:
  explicit StageClock(std::vector<StageTime>& times) : times_(times) {}
  template <typename F>
  auto run(const char* stage, F&& f) {
    auto start = std::chrono::steady_clock::now();
    auto result = f();
    times_.push_back({stage, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()});
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
    return {"interreflection", "stopped after " + what, unshot + ", within the tolerance of " + percent(options.tolerance)};
  return {"interreflection", "stopped after " + what + " by the iteration guard",
          unshot + ", above the tolerance of " + percent(options.tolerance)};
}

// Light between surfaces: patches, form factors and the radiosity solve, then the final gather
// at texel resolution. Adds the indirect light to result.direct into result.irradiance and fills
// the report's solve figures and energy balance.
void interreflect(const Elements& elements, const Surface& surface, const RayTracer& tracer, const BakeOptions& options,
                  const EffectPlan& plan, double delivered_power, const FiniteCheckContext& checked, Progress& progress,
                  const PreviewCallback& on_preview, BakeResult& result) {
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
  SolveOptions solve = options.solve;
  if (plan.one_channel) solve.one_channel_colour = plan.light_colour;
  auto started = std::chrono::steady_clock::now();
  Interreflection light_between = solve_interreflection(elements, surface, tracer, result.direct, options.patches,
                                                        options.form_factors, options.subdivision, solve, options.seed,
                                                        progress, observer);
  const double interreflection_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  report.stage_times.push_back({"patches", interreflection_seconds - light_between.form_factor_seconds -
                                               light_between.solve_seconds});
  report.stage_times.push_back({"form factors", light_between.form_factor_seconds});
  report.stage_times.push_back({"radiosity", light_between.solve_seconds});
  malloc_trim(0);
  const Patches& patches = light_between.patches;
  const RadiositySolution& solution = light_between.solution;
  check_patches("the radiosity solve", patches, light_between.transport, solution.exitance, checked);
  GatherStats gather_stats;
  StageClock clock(report.stage_times);
  GatheredLight gathered = clock.run("final gather", [&] {
    return gather_indirect(elements, patches, surface, tracer, light_between.transport, solution.exitance,
                           result.direct, options.gather_rays, options.near_field, options.seed, progress,
                           &gather_stats);
  });
  result.irradiance = clock.run("gather filter", [&] {
    std::vector<uint8_t> gathering(elements.size());
    for (size_t i = 0; i < elements.size(); ++i) gathering[i] = patches.patch_of_element[i] != UINT32_MAX;
    return filter_gathered(elements, surface, gathered.irradiance, gathered.harmonic_distance, gathering,
                           options.gather_filter);
  });
  check_element_values("the final gather", result.irradiance, checked, patches.patch_of_element);
  for (size_t i = 0; i < elements.size(); ++i) result.irradiance[i] += result.direct[i];
  report.balance = energy_balance(elements, patches, light_between.transport, delivered_power, result.irradiance);

  report.patches = patches.size();
  report.patch_block_size = patches.block_size;
  report.subdivision_rounds = light_between.rounds;
  report.solver_iterations = solution.iterations;
  report.solved_channels = solution.channels;
  report.unshot_relative = solution.relative_unshot;
  report.converged = solution.converged;
  report.ambient = solution.ambient;
  report.gather_back_face_fraction = gather_stats.back_face_fraction;
  report.plan.push_back(solve_outcome(solution, solve));
  if (!solution.converged)
    report.warnings.push_back("the radiosity solve stopped at its iteration guard before reaching the tolerance");
  result.patch_of_element = std::move(light_between.patches.patch_of_element);
}

// The baker's way: direct light from lights and emitting surfaces at every texel, then, when the
// plan calls for it, the light between surfaces (interreflect).
void compute_radiosity(const Scene& scene, const Elements& elements, const Surface& surface,
                       const MaterialSampler& materials, const RayTracer& tracer, const BakeOptions& options,
                       const EffectPlan& plan, const FiniteCheckContext& checked, Progress& progress,
                       const PreviewCallback& on_preview, BakeResult& result) {
  StageClock clock(result.report.stage_times);
  DirectLightOptions direct = options.direct;
  direct.shadow_rays = plan.shadow_rays;
  direct.cull_unlit = !plan.exhaustive;
  direct.light_traced = plan.light_traced;
  std::vector<Rgb> lights_and_sky = clock.run("punctual lights", [&] {
    return punctual_irradiance(elements, surface, scene.lights, tracer, direct, options.seed, progress);
  });
  if (options.sky.enabled) {
    const std::vector<Rgb> sky = clock.run("sky", [&] {
      return sky_irradiance(elements, surface, tracer, options.sky, options.seed, progress);
    });
    for (size_t i = 0; i < elements.size(); ++i) lights_and_sky[i] += sky[i];
  }
  result.direct = clock.run("area lights", [&] {
    return emitter_irradiance(elements, surface, materials, tracer, direct, options.seed, progress);
  });
  // lm, mean of RGB, that punctual lights and the sky land on valid elements (where light passes
  // through, only what stops there: the rest lands further on)
  double delivered_power = 0;
  for (size_t i = 0; i < elements.size(); ++i) {
    const double stops = elements.opacity.empty() ? 1.0 : elements.opacity[i];
    if (elements.valid(i)) delivered_power += stops * double(sum(lights_and_sky[i])) / 3.0 * elements.area[i];
    result.direct[i] += lights_and_sky[i];
  }
  lights_and_sky = {};
  check_element_values("direct light", result.direct, checked);
  if (plan.interreflection) {
    interreflect(elements, surface, tracer, options, plan, delivered_power, checked, progress, on_preview, result);
  } else {
    result.irradiance = result.direct;
    result.patch_of_element.assign(elements.size(), UINT32_MAX);
  }
}

}  // namespace

BakeGeometry bake_geometry(const Scene& scene, const Atlas& atlas, const BakeOptions& options, const EffectPlan& plan,
                           Progress& progress, std::vector<StageTime>& times) {
  StageClock clock(times);
  BakeGeometry g;
  g.surface = clock.run("surface", [&] { return std::make_unique<Surface>(build_surface(scene, atlas)); });
  g.materials = std::make_unique<MaterialSampler>(scene, *g.surface, options.emission_scale, options.glazing_transmittance);
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

BakeResult bake(const Scene& scene, const Atlas& atlas, const BakeOptions& options, const EffectPlan& plan,
                const ProgressCallback& on_progress, const PreviewCallback& on_preview) {
  std::unique_ptr<tbb::global_control> thread_limit;
  if (options.threads > 0)
    thread_limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, options.threads);

  // The loader holds each material's luminance to kMaxLuminance; the emission scale must not
  // multiply it past that.
  for (const Material& m : scene.materials) {
    const double luminance = double(max_component(m.emissive)) * m.emissive_strength * options.emission_scale;
    if (luminance > kMaxLuminance) {
      char text[96];
      std::snprintf(text, sizeof text, "' would glow at %.3g cd/m2 under the emission scale %g, above the %g",
                    luminance, double(options.emission_scale), kMaxLuminance);
      throw InputError("material '" + clipped(m.name) + text + " radbake bakes");
    }
  }

  Progress progress(on_progress);
  BakeResult result;
  BakeReport& report = result.report;
  StageClock clock(report.stage_times);

  BakeGeometry geometry = bake_geometry(scene, atlas, options, plan, progress, report.stage_times);
  const Surface& surface = *geometry.surface;
  const MaterialSampler& materials = *geometry.materials;
  const std::unique_ptr<RayTracer>& tracer = geometry.tracer;
  Elements& elements = geometry.elements;
  if (options.work_plane.enabled) result.work_plane = work_plane(scene, surface, *tracer, options.work_plane);
  const FiniteCheckContext checked{scene, surface, elements};

  const size_t n = elements.size();
  report.plan = plan.decisions;
  report.warnings = plan.warnings;
  if (options.method == Method::PathTrace) {
    PathTraced traced = clock.run("path tracing", [&] {
      return path_trace(elements, surface, materials, scene.lights, &options.sky, *tracer, options.path_trace,
                        options.seed, progress);
    });
    check_element_values("path tracing", traced.irradiance, checked);
    result.irradiance = std::move(traced.irradiance);
    result.standard_error = std::move(traced.standard_error);
    result.patch_of_element.assign(n, UINT32_MAX);
    report.path_samples = traced.samples;
    report.path_relative_noise = traced.relative_noise;
    report.path_mean_vertices = traced.mean_path_vertices;
    report.plan.push_back({"method", "path tracing",
                           "every light and every bounce, whatever the plan would leave out: the reference"});
  } else {
    compute_radiosity(scene, elements, surface, materials, *tracer, options, plan, checked, progress, on_preview, result);
  }
  if (!options.keep_direct) result.direct = {};
  std::vector<Rgb> radiosity;
  if (options.store == StoredQuantity::Radiosity) radiosity = radiosity_of(elements, result.irradiance);
  const std::vector<Rgb>& stored = radiosity.empty() ? result.irradiance : radiosity;
  result.pages = clock.run("dilation", [&] { return compose_pages(elements, stored, surface.pages); });
  result.vertex_values =
      clock.run("vertex values", [&] { return vertex_values(elements, surface, atlas, result.pages, stored); });
  check_vertex_values(result.vertex_values, scene);
  if (!options.sensors.empty() || options.work_plane.enabled) {
    result.sensors = options.sensors;
    if (options.work_plane.enabled) {
      for (int32_t& k : result.work_plane.sensor_at)
        if (k >= 0) k += int32_t(options.sensors.size());
      result.sensors.insert(result.sensors.end(), result.work_plane.sensors.begin(), result.work_plane.sensors.end());
    }
    const std::vector<Rgb> exitance = radiosity.empty() ? radiosity_of(elements, result.irradiance) : radiosity;
    result.sensor_lux = clock.run("sensors", [&] {
      return sensor_illuminance(result.sensors, scene.lights, elements, exitance, surface, *tracer, options.sky,
                                options.sensor, options.seed, progress);
    });
  }
  if (!options.views.empty()) {
    const std::vector<Rgb> exitance = radiosity.empty() ? radiosity_of(elements, result.irradiance) : radiosity;
    clock.run("views", [&] {
      for (const EyeView& eye : options.views) {
        result.views.push_back(render_fisheye(eye, options.view, elements, exitance, surface, *tracer, options.sky, options.seed));
        result.glare.push_back(evaluate_glare(result.views.back()));
        result.perspectives.push_back(render_perspective(eye, options.view, elements, exitance, surface, *tracer, options.sky, options.seed));
      }
      return 0;
    });
  }
  report.surfaces = surface_statistics(scene, surface, elements, result.irradiance);

  for (const AtlasPage& p : surface.pages) report.page_texels += size_t(p.width) * p.height;
  report.elements = n;
  for (size_t i = 0; i < n; ++i) {
    report.valid_elements += elements.valid(i);
    report.buried_elements += !elements.valid(i);
    report.moved_samples += (elements.flags[i] & kPushedOut) != 0;
    report.filtered_texels += (elements.flags[i] & kFiltered) != 0;
  }
  report.rays = tracer->rays_cast();
  result.elements = std::move(elements);
  return result;
}

}  // namespace radbake
