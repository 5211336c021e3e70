// The bake pipeline over plain data: scene and atlas in, lightmap pages and vertex values out.
// Each stage is its own function (see DESIGN.md); this file only runs them in order and times them.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "baker/direct_light.h"
#include "baker/directional_lightmaps.h"
#include "baker/elements.h"
#include "baker/energy_balance.h"
#include "baker/finish.h"
#include "baker/gather_filter.h"
#include "baker/glare.h"
#include "baker/interreflection.h"
#include "baker/light_probes.h"
#include "baker/luminance_view.h"
#include "baker/material_sampler.h"
#include "baker/path_tracer.h"
#include "baker/patches.h"
#include "baker/plan.h"
#include "baker/progress.h"
#include "baker/ray_tracer.h"
#include "baker/scene.h"
#include "baker/sensor_points.h"
#include "baker/sharing.h"
#include "baker/sky_light.h"
#include "baker/surface.h"
#include "baker/solve_radiosity.h"
#include "baker/surface_statistics.h"
#include "baker/work_plane.h"
#include "uv/atlas.h"

namespace radbake {

// What a lightmap texel and a COLOR_0 value hold.
enum class StoredQuantity {
  Irradiance,  // lux (lm/m2 arriving): what a light meter lying on the surface reads
  Radiosity,   // lm/m2 leaving: emission plus reflected light
};

// How the light at each texel is computed.
enum class Method {
  Radiosity,  // patches, form factors, the radiosity solve and a final gather: the baker
  PathTrace,  // unbiased Monte Carlo per texel: the independent reference the baker is measured against
};

struct BakeOptions {
  Method method = Method::Radiosity;
  PathTraceOptions path_trace;  // with Method::PathTrace
  PlanOptions plan;
  ElementOptions elements;
  PatchOptions patches;
  DirectLightOptions direct;
  FormFactorOptions form_factors;
  SubdivisionOptions subdivision;
  SolveOptions solve;
  uint32_t gather_rays = 256;   // hemisphere rays per texel for indirect light
  GatherFilterOptions gather_filter;  // texel-space filtering of the gather's noise
  bool near_field = true;       // gather rays landing close by take the texel's exitance (final_gather.h)
  SkyLight sky;                 // a sky lighting the scene besides its lamps (sky_light.h); radiosity only
  std::vector<Sensor> sensors;  // points in the air to measure illuminance at (sensor_points.h)
  std::vector<EyeView> views;   // eyes to render a fisheye luminance image and its glare for (luminance_view.h)
  ViewOptions view;
  WorkPlaneOptions work_plane;  // and a grid of them over the floors
  SensorOptions sensor;
  uint64_t seed = 1;            // same seed, same input: bit-identical output, whatever the thread count
  int threads = 0;              // 0: all cores
  StoredQuantity store = StoredQuantity::Irradiance;
  float emission_scale = 1;     // multiplies glTF emission before it is read as cd/m2 (see README)
  // Visible transmittance of glazing (KHR_materials_transmission) whose material has no
  // extras.visible_transmittance, 0..1; < 0: a clear pane of the material's index of refraction.
  float glazing_transmittance = -1;
  bool keep_direct = false;     // keep BakeResult::direct (for debug dumps); costs 12 bytes per texel
  size_t preview_every = 0;     // with a preview callback: pages of the estimate every N shots or sweeps
  Sharing sharing;              // a team of processes, a checkpoint, a slice of the gather (sharing.h)
  Directional directional = Directional::None;  // pages of where the light comes from (directional_lightmaps.h)
  ProbeOptions probes;          // light probes in the empty space (light_probes.h)
};

struct StageTime {
  std::string stage;
  double seconds = 0;
};

struct BakeReport {
  size_t page_texels = 0, elements = 0, valid_elements = 0, buried_elements = 0, moved_samples = 0;
  size_t patches = 0;
  int patch_block_size = 0;
  std::vector<SubdivisionRound> subdivision_rounds;
  uint64_t rays = 0;
  std::vector<StageTime> stage_times;
  std::vector<PlanDecision> plan;  // what was simulated and why, with how the interreflection solve ended
  size_t solver_iterations = 0;
  int solved_channels = 0;     // 0 when the plan skipped interreflection
  size_t filtered_texels = 0;  // elements whose material was box-filtered over their footprint
  double unshot_relative = 0;  // unshot power / power the direct light brings in
  bool converged = false;
  Rgb ambient{};
  EnergyBalance balance;
  double gather_back_face_fraction = 0;
  // Method::PathTrace: paths per texel, and the noise estimate (PathTraced::relative_noise).
  uint32_t path_samples = 0;
  double path_relative_noise = 0;
  double path_mean_vertices = 0;
  std::vector<SurfaceStatistics> surfaces;  // per instance, lux
  std::vector<std::string> warnings;
  size_t light_probes = 0;             // with BakeOptions::probes: how many, and at what spacing (m)
  float light_probe_spacing = 0;
  int processes = 1;                   // the team that baked it
  std::vector<StageTraffic> traffic;   // per shared stage: bytes exchanged, compute and busiest seconds
  std::vector<uint64_t> process_peak_bytes;  // per process, its peak resident set before the first writes
};

struct BakeResult {
  std::vector<LightmapPage> pages;                 // the stored quantity per texel
  std::vector<std::vector<Rgb>> vertex_values;     // per instance, per atlas output vertex
  Elements elements;                               // kept for reports, tests and debug dumps
  std::vector<Rgb> irradiance;                     // per element, lux
  std::vector<Rgb> direct;                         // its direct part, lux; empty unless keep_direct
  std::vector<LightDirection> light_directions;    // with BakeOptions::directional: per element, where its light comes from
  std::vector<std::vector<LightmapPage>> directional;  // BakeOptions::directional's pages (directional_pages)
  std::vector<uint32_t> patch_of_element;          // UINT32_MAX for buried elements
  std::vector<float> standard_error;               // Method::PathTrace: per element, lux; else empty
  std::vector<Sensor> sensors;                     // BakeOptions::sensors, then the work plane's
  std::vector<double> sensor_lux;                  // per sensor
  std::vector<FisheyeImage> views;                 // per BakeOptions::views
  std::vector<PerspectiveImage> perspectives;      // per BakeOptions::views, the same eye
  std::vector<Glare> glare;                        // per view
  LightProbes probes;                              // with BakeOptions::probes
  WorkPlane work_plane;                            // its sensor_at indexes `sensors`
  BakeReport report;
};

// What every stage needs before the light: the surface, its materials, the ray tracer and the
// elements with their samples placed (held by pointer: the sampler and the tracer refer to the
// surface).
struct BakeGeometry {
  std::unique_ptr<Surface> surface;
  std::unique_ptr<MaterialSampler> materials;
  std::unique_ptr<RayTracer> tracer;
  Elements elements;
};

// This process's peak resident set so far, bytes (what the report and each rank's share state).
uint64_t peak_resident_bytes();

// Throws InputError when no texel covers a visible surface. Stage times go to `times`.
BakeGeometry bake_geometry(const Scene& scene, const Atlas& atlas, const BakeOptions& options, const EffectPlan& plan,
                           Progress& progress, std::vector<StageTime>& times);

// The progressive estimate while the radiosity solve refines it: direct light at texel resolution
// plus the patches' interreflection so far (no final gather), in the stored quantity, dilated.
using PreviewCallback = std::function<void(const std::vector<LightmapPage>& pages, size_t iteration)>;

// Simulates what `plan` says (plan_effects(scene, options.plan), or a plan a test has changed).
// Throws InputError when no texel covers a visible surface, Cancelled when the callback says so,
// StoppedEarly when options.sharing asks to stop with the checkpoint saved. In a team, only the
// first process's result holds the light; the others return with an empty one.
BakeResult bake(const Scene& scene, const Atlas& atlas, const BakeOptions& options, const EffectPlan& plan,
                const ProgressCallback& on_progress = {}, const PreviewCallback& on_preview = {});

// Plans first; also throws InputError when nothing in the scene emits light.
BakeResult bake(const Scene& scene, const Atlas& atlas, const BakeOptions& options,
                const ProgressCallback& on_progress = {}, const PreviewCallback& on_preview = {});

}  // namespace radbake
