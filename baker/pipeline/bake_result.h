// What a bake gives back: the lightmap pages, the vertex values, the readings, and the report of
// what it did. All that io/ needs to write a bake.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "baker/finish/finish.h"
#include "baker/pipeline/plan.h"
#include "baker/readings/display_camera.h"
#include "baker/readings/glare.h"
#include "baker/readings/light_probes.h"
#include "baker/readings/luminance_view.h"
#include "baker/readings/sensor_points.h"
#include "baker/readings/surface_statistics.h"
#include "baker/readings/work_plane.h"
#include "baker/sharing/team.h"
#include "baker/surface/elements.h"
#include "baker/surface/light_direction.h"
#include "baker/transport/energy_balance.h"
#include "baker/transport/interreflection.h"
#include "baker/surface/ray_fates.h"
#include "base/math.h"

namespace radbake {

struct StageTime {
  std::string stage;
  double seconds = 0;
};

struct BakeReport {
  size_t page_texels = 0, elements = 0, valid_elements = 0, buried_elements = 0, moved_samples = 0;
  size_t patches = 0;
  int patch_block_size = 0;
  double mean_free_path_m = 0;  // 0: not measured (a patch size given, or no light between surfaces)
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
  RayFates gather_rays, form_factor_rays;  // where the final gather's and the form factors' rays ended
  // Method::PathTrace: paths per texel, and the noise estimate (PathTraced::relative_noise).
  uint32_t path_samples = 0;
  double path_relative_noise = 0;
  // The texels' sky noise: the RMS of their sky irradiance's standard errors over its mean, area
  // weighted (sky_light.h); 0 without a sky.
  double sky_noise = 0;
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
  std::vector<float> open_view;                    // per element, GatheredLight's; empty without a final gather
  std::vector<Sensor> sensors;                     // BakeOptions::sensors, then the work plane's
  std::vector<double> sensor_lux;                  // per sensor
  std::vector<double> sensor_standard_error;       // per sensor, lux: its rays' noise (sensor_points.h)
  std::vector<FisheyeImage> views;                 // per BakeOptions::views
  std::vector<PerspectiveImage> perspectives;      // per BakeOptions::views, the same eye
  std::vector<Glare> glare;                        // per view
  LightProbes probes;                              // with BakeOptions::probes
  WorkPlane work_plane;                            // its storeys and rooms index `sensors`
  DisplayCamera display_camera;                    // for a display file whose input has no camera
  std::vector<std::vector<float>> display_view;    // per page, per texel: the display camera's rays on it
  BakeReport report;
};

}  // namespace radbake
