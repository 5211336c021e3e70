#include "io/run/report.h"
#include "io/files/written_file.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace radbake {

namespace {

nlohmann::ordered_json daylight_json(const std::optional<DaylightSummary>& daylight) {
  if (!daylight) return nullptr;
  const DaylightSummary& d = *daylight;
  nlohmann::ordered_json out = {{"sky", d.sky},
                                {"zenith_luminance_cd_m2", d.zenith_luminance},
                                {"sky_horizontal_illuminance_lx", d.sky_illuminance},
                                {"sun_direct_normal_illuminance_lx", d.sun_illuminance},
                                {"exterior_horizontal_illuminance_lx", d.exterior_horizontal_illuminance}};
  if (d.perez_clearness > 0) {
    out["perez_clearness_epsilon"] = d.perez_clearness;
    out["perez_brightness_delta"] = d.perez_brightness;
  }
  if (d.sun_known) {
    out["sun_zenith_deg"] = d.sun_zenith;
    out["sun_azimuth_deg_from_north_eastward"] = d.sun_azimuth;
  }
  return out;
}

nlohmann::ordered_json readings_json(const ReadingSummary& lux, const ReadingSummary& percent) {
  if (lux.count == 0) return nullptr;
  nlohmann::ordered_json out = {{"points", lux.count}, {"min_lx", lux.min}, {"mean_lx", lux.mean},
                                {"max_lx", lux.max}, {"uniformity_min_over_mean", lux.uniformity},
                                {"noise_rms_standard_error_over_mean", lux.noise}};
  if (percent.count > 0)
    out["daylight_factor_percent"] = {{"min", percent.min}, {"mean", percent.mean}, {"max", percent.max}};
  return out;
}

// The whole plane's readings, then per storey its readings, maps and rooms.
nlohmann::ordered_json work_plane_json(const AnalysisFiles& analysis) {
  nlohmann::ordered_json out = readings_json(analysis.work_plane, analysis.work_plane_daylight_factor);
  if (out.is_null()) return out;
  out["outdoor_points_left_out"] = analysis.outdoor_points;
  out["points_in_regions_under_1_m2_left_out"] = analysis.sliver_points;
  out["storeys"] = nlohmann::ordered_json::array();
  for (size_t s = 0; s < analysis.storeys.size(); ++s) {
    const StoreyReadings& storey = analysis.storeys[s];
    nlohmann::ordered_json j = {{"storey", s + 1}, {"floor_height_m", storey.floor_height}};
    j.update(readings_json(storey.lux, storey.daylight_factor));
    j["maps"] = storey.maps;
    j["rooms"] = nlohmann::ordered_json::array();
    for (const RoomReadings& room : analysis.rooms) {
      if (room.storey != int(s)) continue;
      nlohmann::ordered_json r = {{"room", room.number}, {"area_m2", room.area}, {"centre_x", room.centre_x},
                                  {"centre_z", room.centre_z}};
      r.update(readings_json(room.lux, room.daylight_factor));
      j["rooms"].push_back(r);
    }
    out["storeys"].push_back(j);
  }
  return out;
}

// Per view: the eye, the vertical illuminance and the glare its fisheye shows (baker/readings/glare.h).
nlohmann::ordered_json views_json(const std::vector<ViewGlare>& views) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const ViewGlare& v : views) {
    nlohmann::ordered_json sources = nlohmann::ordered_json::array();
    for (const GlareSource& s : v.glare.sources)
      sources.push_back({{"luminance_cd_per_m2", s.luminance}, {"solid_angle_sr", s.solid_angle},
                         {"position_index", s.position_index}, {"direction", {s.direction.x, s.direction.y, s.direction.z}}});
    out.push_back({{"position", {v.eye.position.x, v.eye.position.y, v.eye.position.z}},
                   {"direction", {v.eye.direction.x, v.eye.direction.y, v.eye.direction.z}},
                   {"vertical_illuminance_lux", v.glare.vertical_illuminance},
                   {"mean_luminance_cd_per_m2", v.glare.mean_luminance},
                   {"glare_threshold_cd_per_m2", v.glare.threshold},
                   {"dgp", v.glare.dgp},
                   {"glare_sources", sources}});
  }
  return out;
}

nlohmann::ordered_json surfaces_json(const std::vector<SurfaceStatistics>& surfaces) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const SurfaceStatistics& s : surfaces)
    out.push_back({{"name", s.name}, {"area_m2", s.area}, {"mean_lx", s.mean}, {"min_lx", s.min},
                   {"max_lx", s.max}, {"uniformity_min_over_mean", s.uniformity},
                   {"open_view", std::isfinite(s.open_view) ? nlohmann::ordered_json(s.open_view) : nullptr},
                   {"standard_error_lx",
                    std::isfinite(s.standard_error) ? nlohmann::ordered_json(s.standard_error) : nullptr}});
  return out;
}

// Shares of all rays; null when the bake cast none (no interreflection, or the path tracer).
nlohmann::ordered_json ray_fates_json(const RayFates& fates) {
  if (fates.total() == 0) return nullptr;
  nlohmann::ordered_json out = {{"rays", fates.total()}};
  for (size_t k = 0; k < kRayFateCount; ++k) out[kRayFateNames[k]] = fates.share(RayFate(k));
  out["front_face_took_none"] = double(fates.front_face_took_none()) / double(fates.total());
  return out;
}

}  // namespace

void write_report(const std::string& path, const RunInfo& run, const Scene& scene, const Atlas& atlas,
                  const BakeReport& bake, const LightmapFiles& lightmaps, const std::vector<std::string>& warnings) {
  using json = nlohmann::ordered_json;
  json options = json::object();
  for (const auto& [key, value] : run.options) options[key] = value;
  size_t kept = 0;
  for (const AtlasMesh& m : atlas.meshes) kept += m.kept_input_uvs;
  json pages = json::array();
  for (size_t p = 0; p < atlas.pages.size(); ++p) {
    json page = {{"width", atlas.pages[p].width}, {"height", atlas.pages[p].height}};
    for (size_t k = 0; k < page_encodings().size(); ++k) page[page_encodings()[k].key] = lightmaps.files[p][k];
    pages.push_back(page);
  }
  json stages = json::object();
  for (const StageTime& t : run.io_times) stages[t.stage] = t.seconds;
  for (const StageTime& t : bake.stage_times) stages[t.stage] = t.seconds;
  // What the processes of the team exchanged and computed per shared stage (docs/distributed.md).
  json shared = json::array();
  for (const StageTraffic& t : bake.traffic)
    shared.push_back({{"stage", t.stage}, {"bytes_exchanged", t.bytes}, {"exchanges", t.exchanges},
                      {"compute_seconds", t.compute_seconds}, {"busiest_process_seconds", t.busiest_seconds}});
  const json distribution = {{"processes", bake.processes}, {"stages", shared},
                             {"peak_memory_bytes_per_process", bake.process_peak_bytes}};
  // One entry per radiosity solve: a single one unless adaptive subdivision split patches.
  json subdivision = json::array();
  for (const SubdivisionRound& r : bake.subdivision_rounds)
    subdivision.push_back({{"patches", r.patches}, {"split_after_solve", r.split}});
  json plan = json::array();
  for (const PlanDecision& d : bake.plan) plan.push_back({{"effect", d.effect}, {"choice", d.choice}, {"reason", d.reason}});
  json balance = {{"measured", bake.balance.measured}};
  if (bake.balance.measured)
    balance.update({{"emitted_lm", bake.balance.emitted}, {"absorbed_lm", bake.balance.absorbed},
                    {"escaped_lm", bake.balance.escaped}, {"lost_lm", bake.balance.lost},
                    {"relative_error", bake.balance.relative_error},
                    {"note", "mean of RGB channels; emitted counts emitting surfaces (the back faces of "
                             "double-sided ones given texels of their own included) and what punctual lights "
                             "deliver onto surfaces; lost is light striking back faces or buried texels"}});
  else
    balance["note"] = bake.path_samples > 0 ? "path tracing does not follow the light that escapes"
                                            : "the plan skipped interreflection, so no ray measured the light that escapes";
  const SceneSummary& s = scene.summary;
  const DisplaySummary& d = run.display;
  json refinement = json::array();
  for (const auto& [triangles, rms] : d.refinement) refinement.push_back({{"triangles", triangles}, {"rms_relative", rms}});
  json display = {{"file", d.file.empty() ? json(nullptr) : json(d.file)},
                  {"shows", d.shows},
                  {"exposure_per_cd_m2", d.exposure.exposure},
                  {"exposure_automatic", d.exposure.automatic},
                  {"exposure_method", d.exposure.method},
                  {"lit_share", d.exposure.lit_share},
                  {"median_lit_luminance_cd_m2", d.exposure.median_lit_luminance},
                  {"highlight_channel_cd_m2", d.exposure.highlight_channel},
                  {"triangles", d.triangles}};
  if (!d.file.empty()) display["camera"] = d.camera;
  // For `radbake view`, whose page opens the engine file, which holds no camera of radbake's.
  if (d.added_camera)
    display["camera_view"] = {{"eye", {d.added_camera->eye.x, d.added_camera->eye.y, d.added_camera->eye.z}},
                              {"forward", {d.added_camera->forward.x, d.added_camera->forward.y, d.added_camera->forward.z}},
                              {"yfov", d.added_camera->yfov}, {"znear", d.added_camera->znear},
                              {"in_room", d.added_camera->in_room}};
  if (d.prelit_detail > 0) display["prelit_detail"] = d.prelit_detail;
  if (!refinement.empty()) display["vertex_light_vs_lightmap"] = refinement;
  json report = {
      {"generator", "radbake"},
      {"input", {{"file", run.input}, {"nodes", s.nodes}, {"meshes", s.meshes}, {"primitives", s.primitives},
                 {"skipped_primitives", s.skipped_primitives}, {"instances", scene.instances.size()},
                 {"triangles", s.triangles}, {"materials", s.materials}, {"textures", s.textures},
                 {"lights", s.lights}}},
      {"options", options},
      {"plan", plan},
      {"atlas", {{"texel_density_per_m", atlas.texel_density}, {"requested_density_per_m", atlas.requested_density},
                 {"density_lowered_to_fit_one_page", atlas.density_lowered}, {"density_choice", atlas.density_choice},
                 {"surface_area_m2", atlas.surface_area}, {"charts", atlas.chart_count},
                 {"meshes_with_kept_uvs", kept}, {"pages", pages}, {"utilisation", atlas.stats.utilisation},
                 {"stretch_l2", atlas.stats.stretch_l2}, {"stretch_max", atlas.stats.stretch_max},
                 {"seam_length_m", atlas.stats.seam_length}, {"overlapping_texels", atlas.stats.overlapping_texels},
                 {"flipped_triangles", atlas.stats.flipped_triangles},
                 {"padding_violations", atlas.stats.padding_violations}}},
      {"counts", {{"page_texels", bake.page_texels}, {"elements", bake.elements},
                  {"valid_elements", bake.valid_elements}, {"buried_elements", bake.buried_elements},
                  {"moved_samples", bake.moved_samples}, {"filtered_texels", bake.filtered_texels},
                  {"patches", bake.patches},
                  {"patch_block_texels", bake.patch_block_size},
                  {"mean_free_path_m", bake.mean_free_path_m > 0 ? json(bake.mean_free_path_m) : json(nullptr)},
                  {"rays", bake.rays},
                  {"gather_rays", ray_fates_json(bake.gather_rays)},
                  {"form_factor_rays", ray_fates_json(bake.form_factor_rays)}}},
      {"subdivision", subdivision},
      {"seconds", stages},
      {"distribution", distribution},
      {"light_probes", bake.light_probes == 0 ? json(nullptr)
                                              : json{{"count", bake.light_probes}, {"spacing_m", bake.light_probe_spacing}}},
      {"total_seconds", run.total_seconds},
      {"peak_memory_bytes", run.peak_memory_bytes},
      {"solver", {{"iterations", bake.solver_iterations}, {"channels", bake.solved_channels},
                  {"unshot_relative", bake.unshot_relative},
                  {"converged", bake.converged},
                  {"ambient_lm_per_m2", {bake.ambient.x, bake.ambient.y, bake.ambient.z}}}},
      {"energy_balance", balance},
      {"path_tracing", bake.path_samples == 0 ? json(nullptr)
                                              : json{{"samples_per_texel", bake.path_samples},
                                                     {"relative_noise", bake.path_relative_noise},
                                                     {"surface_hits_per_path", bake.path_mean_vertices},
                                                     {"note", "relative_noise: RMS of the texels' standard errors "
                                                              "(from each texel's own paths) over the mean texel "
                                                              "value, what the noise adds to a relative RMSE "
                                                              "against this bake"}}},
      {"lightmaps", {{"quantity", lightmaps.quantity}, {"unit", lightmaps.unit},
                     {"png_intensity", lightmaps.png_scale}}},
      {"display", display},
      {"daylight", daylight_json(run.daylight)},
      {"sky_noise", bake.sky_noise > 0 ? json{{"texels_rms_standard_error_over_mean", bake.sky_noise},
                                              {"note", "the texels' sky irradiance: the RMS of their standard "
                                                       "errors over its mean, area weighted, each estimated from "
                                                       "the spread of its sky rays' interleaved eighths, which "
                                                       "overstates it; the gather's noise comes on top"}}
                                       : json(nullptr)},
      {"sensors", readings_json(run.analysis.sensors, run.analysis.sensors_daylight_factor)},
      {"work_plane", work_plane_json(run.analysis)},
      {"views", views_json(run.analysis.views)},
      {"surfaces", surfaces_json(bake.surfaces)},
      {"warnings", warnings},
      {"files", run.files},
  };
  std::ofstream out(path);
  out << report.dump(2) << "\n";
  close_written(out, path);
}

}  // namespace radbake
