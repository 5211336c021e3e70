// radbake: the command line over the pipeline of docs/hacking.md. Parse, load, unwrap, bake,
// write; or compare two bakes (cli/diff_command).

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <thread>
#include <nlohmann/json.hpp>

#include "baker/pipeline/bake.h"
#include "baker/pipeline/ray_budget.h"
#include "baker/sharing/byte_stream.h"
#include "baker/surface/back_faces.h"
#include "baker/surface/surface.h"
#include "base/errors.h"
#include "base/progress.h"
#include "base/version.h"
#include "cli/command_line.h"
#include "cli/diff_command.h"
#include "cli/interrupts.h"
#include "cli/process_team.h"
#include "cli/progress_display.h"
#include "io/analysis/analysis_outputs.h"
#include "io/analysis/annual_outputs.h"
#include "io/analysis/epw_reader.h"
#include "io/gltf/gltf_loader.h"
#include "io/lightmaps/lightmap_images.h"
#include "io/lightmaps/page_encodings.h"
#include "io/run/bake_outputs.h"
#include "io/run/checkpoint_folder.h"
#include "io/run/output_folder.h"
#include "io/run/report.h"

namespace {


// One line whatever the message quotes: each quoted piece of user text should be clipped where the
// message is made, and this bounds the line when one was not.
void print_error(const std::exception& e) { std::fprintf(stderr, "radbake: error: %s\n", radbake::clipped(e.what(), 600).c_str()); }

// --preview-every: the solve's estimate as PNG pages in OUTDIR/preview/, numbered by shot (or
// sweep), all at the scale of the first so they brighten as light is shot. They are written into
// the staging folder, which is on disk (hidden) during the bake, and move into OUTDIR with the rest.
class PreviewWriter {
 public:
  PreviewWriter(const std::string& folder, const std::string& name, bool quiet)
      : folder_(std::filesystem::path(folder) / "preview"), name_(name), quiet_(quiet) {}

  void write(const std::vector<radbake::LightmapPage>& pages, size_t iteration) {
    if (scale_ == 0) {
      std::filesystem::create_directories(folder_);
      scale_ = radbake::automatic_png_scale(pages);
      if (!quiet_) std::fprintf(stderr, "radbake: previews in %s\n", folder_.c_str());
    }
    char step[32];
    std::snprintf(step, sizeof step, "_step_%08zu", iteration);
    for (size_t p = 0; p < pages.size(); ++p)
      radbake::write_lightmap_png((folder_ / (name_ + step + "_lightmap_" + std::to_string(p) + ".png")).string(), pages[p],
                         scale_);
  }

 private:
  std::filesystem::path folder_;
  std::string name_;
  bool quiet_;
  float scale_ = 0;
};

// One line per set of readings: what a lighting report's summary table gives.
void print_readings(const char* what, const radbake::ReadingSummary& lux, const radbake::ReadingSummary& percent) {
  if (lux.count == 0) return;
  std::fprintf(stderr, "radbake: %s: %zu points, min %.4g lx, mean %.4g lx, max %.4g lx, uniformity %.2f", what,
               lux.count, lux.min, lux.mean, lux.max, lux.uniformity);
  if (percent.count > 0)
    std::fprintf(stderr, "; daylight factor min %.3g%%, mean %.3g%%, max %.3g%%", percent.min, percent.mean, percent.max);
  if (lux.noise > 0) std::fprintf(stderr, "; noise %.2g%% (RMS standard error per point)", 100 * lux.noise);
  std::fprintf(stderr, "\n");
}

// With more than one storey or room, a line per storey and a row per room (work_plane_rooms.csv
// holds the same), and how many floor points were left out as outdoors.
void print_storeys(const radbake::AnalysisFiles& analysis) {
  if (analysis.outdoor_points > 0)
    std::fprintf(stderr, "radbake: work plane: %zu floor points left out as open to the sky or unwalled "
                         "(--work-plane-outdoors measures them)\n", analysis.outdoor_points);
  if (analysis.sliver_points > 0)
    std::fprintf(stderr, "radbake: work plane: %zu points left out in regions under 1 m2 (window reveals, gaps between "
                         "walls)\n", analysis.sliver_points);
  if (analysis.storeys.size() < 2 && analysis.rooms.size() < 2) return;
  const bool percent = analysis.work_plane_daylight_factor.count > 0;
  for (size_t s = 0; s < analysis.storeys.size(); ++s) {
    const radbake::StoreyReadings& storey = analysis.storeys[s];
    std::fprintf(stderr, "radbake: storey %zu (floor at %.2f m, %s):\n", s + 1, storey.floor_height,
                 storey.maps.empty() ? "" : storey.maps.back().c_str());
    std::fprintf(stderr, "  room  points  area m2   min lx  mean lx   max lx    U0%s\n",
                 percent ? "   DF min %  DF mean %  DF max %" : "");
    for (const radbake::RoomReadings& r : analysis.rooms) {
      if (r.storey != int(s)) continue;
      std::fprintf(stderr, "  %4d  %6zu  %7.1f  %7.4g  %7.4g  %7.4g  %4.2f", r.number, r.lux.count, r.area, r.lux.min,
                   r.lux.mean, r.lux.max, r.lux.uniformity);
      if (percent)
        std::fprintf(stderr, "  %9.3g  %9.3g  %8.3g", r.daylight_factor.min, r.daylight_factor.mean, r.daylight_factor.max);
      std::fprintf(stderr, "\n");
    }
  }
}

// A bake's output folder, staged until committed and abandoned on an interrupt, and its progress
// shown on stderr, where the callback also asks whether to stop.
struct OutputSession {
  radbake::StagedFolder folder;
  radbake::AbandonOnInterrupt abandon_on_interrupt{folder};
  radbake::ProgressDisplay display;
  radbake::ProgressCallback progress = [this](const std::string& stage, double fraction) {
    display.update(stage, fraction);
    return !radbake::interrupted();
  };
  OutputSession(const std::string& output, bool quiet) : folder(output), display(!quiet) {}
};

// Before a ray is cast: a stage estimated to cast more than --max-rays is refused, and sensors far
// outside the scene are said (a misplaced file's, in millimetres or another origin).
void refuse_beyond_ray_budget(radbake::Scene& scene, const radbake::Atlas& atlas, const radbake::BakeOptions& options,
                              uint64_t daylit_hours, double max_rays) {
  using namespace radbake;
  const RayCounts counts = ray_counts(scene, atlas, options.sensors, daylit_hours);
  if (counts.sensors_outside > 0)
    scene.warnings.push_back(std::to_string(counts.sensors_outside) + " of the " + std::to_string(counts.sensors) +
                             " sensors lie outside the scene's bounds (by more than a tenth of its size): metres, "
                             "and the scene's origin?");
  check_ray_budget(estimate_stage_rays(options, counts), max_rays);
}

// `radbake bake --weather`: a year of daylight at the sensors, by daylight coefficients.
int run_annual(const radbake::BakeCommand& cmd, std::optional<OutputSession>& session) {
  using namespace radbake;
  const auto start = std::chrono::steady_clock::now();
  LoadedScene loaded = load_gltf(cmd.input, cmd.load);
  check_bake_budget(loaded, cmd.atlas, cmd.load, cmd.input);
  add_back_faces(loaded.scene);
  const Weather weather = read_epw(cmd.weather_file);
  stop_if_interrupted();
  BakeOptions options = cmd.bake;
  if (!cmd.sensor_file.empty()) options.sensors = read_sensor_csv(cmd.sensor_file);
  const AnnualSkies skies = annual_skies(weather, cmd.daylight);
  if (skies.daylit == 0) throw InputError("weather file " + cmd.weather_file + " has no hour with daylight");
  for (const SkyLight& hour : skies.hours)
    if (hour.enabled) {
      options.sky = hour;  // the compass and the rays every hour shares
      break;
    }
  session.emplace(cmd.output, cmd.quiet);
  StagedFolder& folder = session->folder;
  ProgressDisplay& display = session->display;
  const ProgressCallback& progress = session->progress;
  AtlasOptions atlas_options = cmd.atlas;
  atlas_options.progress = progress;
  const Atlas atlas = ensure_lightmap_uvs(mesh_views(loaded.scene), atlas_options);
  refuse_beyond_ray_budget(loaded.scene, atlas, options, skies.daylit, cmd.max_rays);
  std::vector<bool> occupied(weather.hours.size());
  for (size_t h = 0; h < occupied.size(); ++h)  // EPW's hour h ends at h:00
    occupied[h] = weather.hours[h].hour > cmd.occupied_from && weather.hours[h].hour <= cmd.occupied_to;
  AnnualDaylightOptions year;
  year.occupied = occupied;
  year.da_threshold = cmd.metrics.da_threshold;
  year.udi_low = cmd.metrics.udi_supplementary, year.udi_high = cmd.metrics.udi_high;
  year.sky_subdivision = cmd.sky_subdivision;
  const AnnualDaylight annual = annual_daylight(loaded.scene, atlas, options, skies.hours, year, progress);
  display.finish();
  const AnnualMetrics metrics = annual_metrics(annual.lux, annual.sun_lux, annual.sensors.size(), occupied, cmd.metrics);
  const AnnualGlare glare = annual_glare(annual, options.views, skies.hours, occupied);
  AnnualRun run;
  run.input = cmd.input, run.weather_file = cmd.weather_file, run.options = cmd.effective;
  run.name = std::filesystem::path(cmd.input).stem().string();
  run.weather = &weather, run.skies = &skies, run.daylight = &annual, run.metrics = &metrics;
  run.metric_options = &cmd.metrics, run.occupied_from = cmd.occupied_from, run.occupied_to = cmd.occupied_to;
  run.glare = &glare, run.eyes = &options.views;
  run.total_seconds = seconds_since(start);
  run.peak_memory_bytes = radbake::peak_resident_bytes();
  stop_if_interrupted();
  write_annual(run, folder.path());
  folder.commit();
  std::printf("radbake: wrote %s: a year of %s weather at %zu sensors: sDA300/50%% %.1f%%, ASE1000/250h %.1f%%, "
              "mean DA %.1f%% (%zu occupied hours, %.1f s)\n",
              cmd.output.c_str(), weather.place.c_str(), annual.sensors.size(), 100 * metrics.sda, 100 * metrics.ase,
              100 * metrics.mean_daylight_autonomy, metrics.occupied_hours, run.total_seconds);
  return 0;
}

// `radbake merge`: how many slices the checkpoint's final gather was cut into.
int slice_count(const radbake::StageStore& store, const std::string& folder) {
  const std::string prefix = "final gather, slice ";
  int count = 0;
  for (const std::string& name : store.stages(prefix)) {
    int k = 0, n = 0;
    if (std::sscanf(name.c_str() + prefix.size(), "%d of %d", &k, &n) != 2) continue;
    if (count != 0 && n != count)
      throw radbake::InputError("checkpoint " + folder + " holds slices of " + std::to_string(count) + " and of " +
                                std::to_string(n) + " parts: remove one kind");
    count = n;
  }
  if (count == 0) throw radbake::InputError("checkpoint " + folder + " holds no slice of the final gather (bake them with --pages K/N or --texel-range K/N)");
  return count;
}

// A daylight factor is the overcast sky's light alone (CIE: direct sun and artificial light
// excluded), so the scene's own lights and emitting surfaces are left out, and said so.
void leave_out_artificial_light(radbake::Scene& scene) {
  size_t emitting = 0;
  for (radbake::Material& m : scene.materials)
    if (m.emits()) ++emitting, m.emissive_strength = 0;
  if (scene.lights.empty() && emitting == 0) return;
  scene.warnings.push_back("--daylight-factor: the scene's " + std::to_string(scene.lights.size()) + " light" +
                           (scene.lights.size() == 1 ? "" : "s") + " and " + std::to_string(emitting) +
                           " emitting material" + (emitting == 1 ? "" : "s") +
                           " are left out: a daylight factor is the overcast sky's light alone");
  scene.lights.clear();
}

const char* stage_title(const std::string& stage) {
  if (stage == "direct light") return "the direct light";
  if (stage == "form factors") return "the form factors";
  if (stage == "radiosity") return "the radiosity solve";
  return nullptr;
}

// `radbake bake` and `radbake merge`, but for a year of weather.
// The bake's options from the command line, with its sky, sensors and what the analysis files
// need; a daylight factor leaves the scene's own lights out.
struct BakeSetup {
  radbake::BakeOptions options;
  radbake::AnalysisOptions analysis;
};

BakeSetup set_up_bake(const radbake::BakeCommand& cmd, radbake::Scene& scene, radbake::RunInfo& run) {
  using namespace radbake;
  BakeSetup setup{cmd.bake, cmd.analysis};
  const Daylight daylight = daylight_sky(cmd.daylight);
  setup.options.sky = daylight.light;
  setup.options.plan.sky = daylight.light.enabled;
  if (daylight.light.enabled) run.daylight = daylight.summary;
  setup.analysis.lightmap_is_irradiance = cmd.bake.store == StoredQuantity::Irradiance;
  setup.analysis.views = cmd.bake.views;
  if (cmd.daylight_factor) {
    setup.analysis.daylight_factor_reference = daylight_factor_reference(cmd.daylight, daylight);
    leave_out_artificial_light(scene);
  }
  if (!cmd.sensor_file.empty()) setup.options.sensors = read_sensor_csv(cmd.sensor_file);
  setup.options.keep_direct = cmd.debug_dumps;
  return setup;
}

radbake::OutputOptions output_options(const radbake::BakeCommand& cmd, const radbake::AnalysisOptions& analysis,
                                      const std::string& name) {
  radbake::OutputOptions output;
  output.name = name;
  output.store = cmd.bake.store;
  output.directional = cmd.bake.directional;
  output.probes = cmd.bake.probes.enabled;
  output.emission_scale = cmd.bake.emission_scale;
  output.glazing = cmd.bake.glazing;
  output.png_scale = cmd.png_scale;
  output.color_0 = cmd.color_0;
  output.display = cmd.display;
  output.analysis = analysis;
  output.debug_dumps = cmd.debug_dumps;
  output.go_on = [] { return !radbake::interrupted(); };
  return output;
}

// The scene's, the atlas's, the bake's and the writer's warnings, in that order.
std::vector<std::string> all_warnings(const radbake::Scene& scene, const radbake::Atlas& atlas,
                                      const radbake::BakeResult& result, const radbake::WrittenOutputs& written) {
  std::vector<std::string> warnings = scene.warnings;
  warnings.insert(warnings.end(), atlas.warnings.begin(), atlas.warnings.end());
  warnings.insert(warnings.end(), result.report.warnings.begin(), result.report.warnings.end());
  warnings.insert(warnings.end(), written.gltf.warnings.begin(), written.gltf.warnings.end());
  return warnings;
}

// After the bake: its warnings and readings on stderr (unless quiet), and the line saying what was
// written on stdout.
void print_written(const radbake::BakeCommand& cmd, const radbake::RunInfo& run, const radbake::BakeResult& result,
                   const radbake::WrittenOutputs& written, const std::vector<std::string>& warnings) {
  using namespace radbake;
  if (!cmd.quiet) {
    for (const std::string& w : warnings) std::fprintf(stderr, "radbake: warning: %s\n", clipped(w, 600).c_str());
    print_readings("sensors", run.analysis.sensors, run.analysis.sensors_daylight_factor);
    print_readings("work plane", run.analysis.work_plane, run.analysis.work_plane_daylight_factor);
    print_storeys(run.analysis);
    if (result.report.sky_noise > 0)
      std::fprintf(stderr, "radbake: texels' sky light: noise under %.2g%% (RMS standard error over the mean, "
                           "overstated; --sky-rays or --quality production for less)\n", 100 * result.report.sky_noise);
  }
  char balance[64] = "energy balance not measured";
  if (result.report.balance.measured)
    std::snprintf(balance, sizeof balance, "energy balance %.3f%%", 100.0 * result.report.balance.relative_error);
  else if (result.report.path_samples > 0)
    std::snprintf(balance, sizeof balance, "path traced, noise %.2f%%", 100.0 * result.report.path_relative_noise);
  std::printf("radbake: wrote %s/%s (%zu page%s, %zu texels, %s, %.1f s)\n", cmd.output.c_str(),
              written.gltf.gltf_file.c_str(), result.pages.size(), result.pages.size() == 1 ? "" : "s",
              result.report.valid_elements, balance, run.total_seconds);
}

void print_plan(const std::vector<radbake::PlanDecision>& decisions, size_t from, const char* prefix) {
  for (size_t k = from; k < decisions.size(); ++k)
    std::fprintf(stderr, "radbake: %s%s: %s (%s)\n", prefix, decisions[k].effect.c_str(), decisions[k].choice.c_str(),
                 decisions[k].reason.c_str());
}

// The scene read, checked against the bake's budget and given its back faces.
radbake::LoadedScene load_scene(const radbake::BakeCommand& cmd, radbake::RunInfo& run) {
  using namespace radbake;
  const auto t = std::chrono::steady_clock::now();
  LoadedScene loaded = load_gltf(cmd.input, cmd.load);
  check_bake_budget(loaded, cmd.atlas, cmd.load, cmd.input);
  add_back_faces(loaded.scene);
  run.io_times.push_back({"load", seconds_since(t)});
  stop_if_interrupted();
  return loaded;
}

// The team and the checkpoint the bake shares its stages through. Only the first process checks and
// writes the checkpoint; the others hand it their results.
std::unique_ptr<radbake::CheckpointFolder> share_stages(const radbake::BakeCommand& cmd, const radbake::LoadedScene& loaded,
                                                        radbake::Team& team, radbake::BakeOptions& options) {
  using namespace radbake;
  std::unique_ptr<CheckpointFolder> checkpoint;
  if (!cmd.checkpoint.empty())
    checkpoint = std::make_unique<CheckpointFolder>(cmd.checkpoint, bake_fingerprint(loaded, cmd.result_options), cmd.input,
                                                    team.first());
  options.sharing.team = &team;
  options.sharing.store = checkpoint.get();
  if (cmd.merge) options.sharing.merge_slices = slice_count(*checkpoint, cmd.checkpoint);
  return checkpoint;
}

// What a bake stopped on purpose (--stop-after, a slice) says it left in the checkpoint.
void print_stopped(const radbake::StoppedEarly& stopped, const radbake::BakeCommand& cmd) {
  const char* title = stage_title(stopped.what());
  std::printf("radbake: stopped after %s; checkpoint %s holds it (%s)\n", title ? title : stopped.what(),
              cmd.checkpoint.c_str(),
              title ? "go on with --resume, or bake slices of the gather with --pages or --texel-range K/N"
                    : "join the slices with radbake merge");
}

int run_one_bake(const radbake::BakeCommand& cmd, radbake::Team& team, std::optional<OutputSession>& session) {
  using namespace radbake;
  const bool first = team.first();
  const auto start = std::chrono::steady_clock::now();
  RunInfo run;
  run.input = cmd.input;
  run.options = cmd.effective;

  LoadedScene loaded = load_scene(cmd, run);
  // Planned before anything is written or unwrapped, so a scene with no light fails at once.
  BakeSetup setup = set_up_bake(cmd, loaded.scene, run);
  BakeOptions& options = setup.options;
  const EffectPlan plan = plan_effects(loaded.scene, options.plan);
  const bool quiet = cmd.quiet || !first;
  if (!quiet) print_plan(plan.decisions, 0, "plan: ");
  const std::unique_ptr<CheckpointFolder> checkpoint = share_stages(cmd, loaded, team, options);
  // A slice, a stopped bake and the processes after the first write no output folder.
  if (first && !cmd.output.empty()) session.emplace(cmd.output, cmd.quiet);
  ProgressDisplay no_folder_display(!quiet && !session);
  const ProgressCallback no_folder_progress = [&](const std::string& stage, double fraction) {
    no_folder_display.update(stage, fraction);
    return !interrupted();
  };
  ProgressDisplay& display = session ? session->display : no_folder_display;
  const ProgressCallback& progress = session ? session->progress : no_folder_progress;
  auto t = std::chrono::steady_clock::now();
  AtlasOptions atlas_options = cmd.atlas;
  atlas_options.progress = progress;
  Atlas atlas = ensure_lightmap_uvs(mesh_views(loaded.scene), atlas_options);
  run.io_times.push_back({"lightmap uvs", seconds_since(t)});
  refuse_beyond_ray_budget(loaded.scene, atlas, options, 0, cmd.max_rays);
  if (!quiet) {
    display.finish();
    std::fprintf(stderr, "radbake: lightmap: %.4g texels/m, %.3g cm texels (%s)\n", atlas.texel_density,
                 100.0 / atlas.texel_density, atlas.density_choice.c_str());
  }

  const std::string name = std::filesystem::path(cmd.input).stem().string();
  std::optional<PreviewWriter> previews;
  if (session) previews.emplace(session->folder.path(), name, cmd.quiet);
  BakeResult result;
  try {
    result = bake(loaded.scene, atlas, options, plan, progress, [&](const std::vector<LightmapPage>& pages, size_t iteration) {
      if (previews) previews->write(pages, iteration);
    });
  } catch (const StoppedEarly& stopped) {
    display.finish();
    if (first) print_stopped(stopped, cmd);
    return 0;
  }
  display.finish();
  if (!first) return 0;
  StagedFolder& folder = session->folder;
  if (!cmd.quiet) print_plan(result.report.plan, plan.decisions.size(), "");

  t = std::chrono::steady_clock::now();
  const WrittenOutputs written = write_bake_outputs(loaded, atlas, result, output_options(cmd, setup.analysis, name),
                                                    folder.path());
  run.display = written.display;
  run.analysis = written.analysis;
  run.io_times.push_back({"write", seconds_since(t)});

  const std::vector<std::string> warnings = all_warnings(loaded.scene, atlas, result, written);
  run.total_seconds = seconds_since(start);
  run.peak_memory_bytes = radbake::peak_resident_bytes();
  run.files = folder.files();
  run.files.push_back("report.json");  // the list is in it
  write_report((std::filesystem::path(folder.path()) / "report.json").string(), run, loaded.scene, atlas,
               result.report, written.lightmaps, warnings);
  stop_if_interrupted();
  folder.commit();
  print_written(cmd, run, result, written, warnings);
  return 0;
}

// A file that could not be written is named where the user would look for it, OUT/..., not in the
// hidden staging folder it was being written in (removed when this returns).
int run_bake(const radbake::BakeCommand& cmd, radbake::Team& team) {
  using namespace radbake;
  std::optional<OutputSession> session;
  try {
    if (cmd.weather_file.empty()) return run_one_bake(cmd, team, session);
    if (team.size() > 1) throw InputError("--weather bakes a year in one process: run it without mpirun");
    return run_annual(cmd, session);
  } catch (const OutputError& e) {
    if (!session || e.path.empty()) throw;
    throw OutputError(session->folder.as_committed(e.path), e.reason);
  }
}

void print_stats(const radbake::Atlas& atlas, const radbake::UvCommand& cmd, double load_seconds) {
  const radbake::AtlasStats& s = atlas.stats;
  if (cmd.json) {
    nlohmann::ordered_json j = {
        {"input", cmd.input}, {"pages", atlas.pages.size()}, {"page_texels", s.page_texels},
        {"covered_texels", s.covered_texels}, {"texel_density_per_m", atlas.texel_density},
        {"density_lowered", atlas.density_lowered}, {"density_choice", atlas.density_choice}, {"charts", s.charts}, {"utilisation", s.utilisation}, {"utilisation_centres", s.utilisation_centres},
        {"stretch_l2", s.stretch_l2}, {"stretch_max", s.stretch_max}, {"seam_length_m", s.seam_length},
        {"overlapping_texels", s.overlapping_texels}, {"flipped_triangles", s.flipped_triangles},
        {"padding_violations", s.padding_violations}, {"padding", cmd.atlas.padding}, {"seconds", s.seconds},
        {"load_seconds", load_seconds}, {"warnings", atlas.warnings}};
    std::printf("%s\n", j.dump(1).c_str());
    return;
  }
  std::printf("radbake uv: %s\n", cmd.input.c_str());
  std::printf("  pages               %zu (", atlas.pages.size());
  for (size_t p = 0; p < atlas.pages.size(); ++p)
    std::printf("%s%dx%d", p ? ", " : "", atlas.pages[p].width, atlas.pages[p].height);
  std::printf(")\n");
  if (cmd.evaluate_texcoord < 0)
    std::printf("  texel density       %.4g texels/m (%s)\n", atlas.texel_density, atlas.density_choice.c_str());
  std::printf("  charts              %zu\n", s.charts);
  std::printf("  utilisation         %.1f%% (%zu texels touched by a triangle of %zu)\n", 100 * s.utilisation,
              s.covered_texels, s.page_texels);
  std::printf("  centres covered     %.1f%% (%zu texels whose centre a triangle covers)\n", 100 * s.utilisation_centres,
              s.centre_covered_texels);
  std::printf("  L2 stretch          %.4f area-weighted, %.4f worst triangle (1 = none)\n", s.stretch_l2, s.stretch_max);
  if (cmd.evaluate_texcoord < 0) std::printf("  seam length         %.3f m\n", s.seam_length);
  std::printf("  overlapping texels  %zu\n", s.overlapping_texels);
  std::printf("  flipped triangles   %zu\n", s.flipped_triangles);
  std::printf("  padding violations  %zu (padding %d texels)\n", s.padding_violations, cmd.atlas.padding);
  if (cmd.evaluate_texcoord < 0) std::printf("  time                %.3f s\n", s.seconds);
  for (const std::string& w : atlas.warnings) std::fprintf(stderr, "radbake: warning: %s\n", radbake::clipped(w, 600).c_str());
}

int run_uv(const radbake::UvCommand& cmd) {
  using namespace radbake;
  auto t = std::chrono::steady_clock::now();
  LoadedScene loaded = load_gltf(cmd.input, cmd.load);
  check_bake_budget(loaded, cmd.atlas, cmd.load, cmd.input);
  double load_seconds = seconds_since(t);
  if (cmd.evaluate_texcoord < 0) add_back_faces(loaded.scene);  // their charts are part of the cost
  std::vector<MeshView> views = mesh_views(loaded.scene);
  if (cmd.evaluate_texcoord < 0) {
    AtlasOptions options = cmd.atlas;
    options.progress = [](const std::string&, double) { return !interrupted(); };
    print_stats(ensure_lightmap_uvs(views, options), cmd, load_seconds);
    return 0;
  }
  std::vector<const Vec2*> uvs;
  for (const MeshInstance& inst : loaded.scene.instances) {
    const size_t set = size_t(cmd.evaluate_texcoord);
    if (inst.texcoords.size() <= set || inst.texcoords[set].empty())
      throw InputError("mesh '" + inst.name + "' has no TEXCOORD_" + std::to_string(set));
    uvs.push_back(inst.texcoords[set].data());
  }
  Atlas layout = layout_from_uvs(views, uvs, cmd.atlas.max_page_size);
  layout.stats = measure_atlas(views, layout, cmd.atlas.padding);
  print_stats(layout, cmd, load_seconds);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace radbake;
  ProcessTeam process_team(argc, argv);
  Team& team = process_team.team();
  watch_interrupts();
  // In a team, the first process reports the input's errors (every process meets the same ones);
  // any process reports its own failures; then the whole team ends.
  auto fail = [&](const std::exception& e, int status, bool input_error) {
    if (team.first() || !input_error) print_error(e);
    if (team.size() > 1) {
      if (!team.first()) std::this_thread::sleep_for(std::chrono::seconds(1));  // the first's line goes out first
      std::fflush(stderr);
      process_team.abort(status);
    }
    return status;
  };
  try {
    CommandLine cl = parse_command_line(std::vector<std::string>(argv + 1, argv + argc));
    switch (cl.action) {
      case Action::Help: std::fputs(usage_text().c_str(), stdout); return 0;
      case Action::Version: std::printf("radbake %s\n", kRadbakeVersion); return 0;
      case Action::Bake:
      case Action::Merge: return run_bake(cl.bake, team);
      case Action::Uv: return run_uv(cl.uv);
      case Action::Diff: return run_diff(cl.diff);
      case Action::View: return run_view(cl.view);
    }
  } catch (const UsageError& e) {
    return fail(e, 2, true);
  } catch (const InputError& e) {
    return fail(e, 2, true);
  } catch (const OutputError& e) {
    return fail(e, 2, false);
  } catch (const TruncatedBytes& e) {
    (void)e;
    return fail(InputError("the checkpoint holds a stage that ends early (saved by another radbake?): remove the folder"), 2, true);
  } catch (const Cancelled&) {
    if (team.first()) std::fprintf(stderr, "\nradbake: cancelled; nothing was written\n");
    if (team.size() > 1) process_team.abort(interrupted_exit_status());
    return interrupted_exit_status();
  } catch (const std::exception& e) {
    return fail(e, 1, false);
  }
  return 1;
}
