#include "baker/bake.h"

#include <malloc.h>
#include <tbb/global_control.h>

#include <chrono>
#include <memory>
#include <thread>

#include "baker/errors.h"
#include "baker/final_gather.h"
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

bool anything_emits(const Scene& scene) {
  if (!scene.lights.empty()) return true;
  for (const MeshInstance& inst : scene.instances)
    if (material_of(scene, inst.material).emits() && inst.triangle_count() > 0) return true;
  return false;
}

}  // namespace

BakeResult bake(const Scene& scene, const Atlas& atlas, const BakeOptions& options,
                const ProgressCallback& on_progress) {
  if (!anything_emits(scene))
    throw InputError("nothing in the scene emits light: no KHR_lights_punctual light and no emissive material");
  std::unique_ptr<tbb::global_control> thread_limit;
  if (options.threads > 0)
    thread_limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, options.threads);

  Progress progress(on_progress);
  BakeResult result;
  BakeReport& report = result.report;
  StageClock clock(report.stage_times);

  Surface surface = clock.run("surface", [&] { return build_surface(scene, atlas); });
  auto tracer = clock.run("ray tracer", [&] { return std::make_unique<RayTracer>(surface); });
  MaterialSampler materials(scene, surface, options.emission_scale);
  Elements elements = clock.run("elements", [&] { return build_elements(surface, materials, options.elements, progress); });
  clock.run("sample placement", [&] {
    place_samples(elements, surface, *tracer, options.seed, progress);
    return 0;
  });
  Patches patches = clock.run("patches", [&] { return build_patches(elements, surface, options.patches); });
  if (patches.members.empty())
    throw InputError("no lightmap texel covers a visible surface: raise the texel density or the page size");

  std::vector<Rgb> punctual = clock.run("punctual lights", [&] {
    return punctual_irradiance(elements, surface, scene.lights, *tracer, options.direct, options.seed, progress);
  });
  result.direct = clock.run("area lights", [&] {
    return emitter_irradiance(elements, surface, materials, *tracer, options.direct, options.seed, progress);
  });
  double punctual_power = 0;  // lm, mean of RGB, landing on valid elements
  for (size_t i = 0; i < elements.size(); ++i) {
    if (elements.valid(i)) punctual_power += double(sum(punctual[i])) / 3.0 * elements.area[i];
    result.direct[i] += punctual[i];
  }
  punctual = {};

  std::vector<Rgb> patch_direct(patches.size());
  std::vector<double> first_bounce_power(patches.size());
  for (size_t p = 0; p < patches.size(); ++p) {
    Rgb total{};
    for (uint32_t k = patches.first_member[p]; k < patches.first_member[p + 1]; ++k) {
      uint32_t i = patches.members[k];
      total += result.direct[i] * elements.area[i];
    }
    patch_direct[p] = patches.area[p] > 0 ? total / patches.area[p] : Rgb{};
    Rgb leaving = patches.emission[p] + patches.reflectance[p] * patch_direct[p];
    first_bounce_power[p] = double(sum(leaving)) * patches.area[p];
  }
  PatchTransport transport = clock.run("form factors", [&] {
    return trace_patch_transport(elements, patches, surface, *tracer, options.patch_rays, first_bounce_power,
                                 options.seed, progress);
  });
  RadiositySolution solution =
      clock.run("radiosity", [&] { return solve_radiosity(patches, transport, patch_direct, options.solve, progress); });
  GatherStats gather_stats;
  result.irradiance = clock.run("final gather", [&] {
    return gather_indirect(elements, patches, surface, *tracer, solution.exitance, options.gather_rays, options.seed,
                           progress, &gather_stats);
  });

  const size_t n = elements.size();
  for (size_t i = 0; i < n; ++i) result.irradiance[i] += result.direct[i];
  report.balance = energy_balance(elements, patches, transport, solution.exitance, punctual_power, result.irradiance);
  transport = {};  // the largest patch-level structure; nothing after this needs it
  if (!options.keep_direct) result.direct = {};
  std::vector<Rgb> radiosity;
  if (options.store == StoredQuantity::Radiosity) {
    radiosity.resize(n);
    for (size_t i = 0; i < n; ++i) radiosity[i] = elements.emission[i] + elements.reflectance[i] * result.irradiance[i];
  }
  const std::vector<Rgb>& stored = radiosity.empty() ? result.irradiance : radiosity;
  result.pages = clock.run("dilation", [&] { return compose_pages(elements, stored, surface.pages); });
  result.vertex_values =
      clock.run("vertex values", [&] { return vertex_values(elements, surface, atlas, result.pages, stored); });

  for (const AtlasPage& p : surface.pages) report.page_texels += size_t(p.width) * p.height;
  report.elements = n;
  for (size_t i = 0; i < n; ++i) {
    report.valid_elements += elements.valid(i);
    report.buried_elements += !elements.valid(i);
    report.moved_samples += (elements.flags[i] & kPushedOut) != 0;
  }
  report.patches = patches.size();
  report.patch_block_size = patches.block_size;
  report.rays = tracer->rays_cast();
  report.solver_iterations = solution.iterations;
  report.unshot_relative = solution.relative_unshot;
  report.converged = solution.converged;
  report.ambient = solution.ambient;
  report.gather_back_face_fraction = gather_stats.back_face_fraction;
  if (!solution.converged)
    report.warnings.push_back("the radiosity solve stopped at its iteration guard before reaching the tolerance");
  result.elements = std::move(elements);
  result.patch_of_element = std::move(patches.patch_of_element);
  return result;
}

}  // namespace radbake
