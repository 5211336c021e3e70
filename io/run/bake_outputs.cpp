#include "io/run/bake_outputs.h"

#include "base/errors.h"
#include "io/gltf/display_gltf.h"
#include "io/lightmaps/debug_dumps.h"
#include "io/lightmaps/directional_outputs.h"
#include "io/lightmaps/light_probe_outputs.h"

namespace radbake {
namespace {

void stop_unless(const OutputOptions& options) {
  if (!options.go_on()) throw Cancelled();
}

// The exposure both files record, metered on the pre-lit light, and the display file.
DisplaySummary write_display(const LoadedScene& loaded, const Atlas& atlas, const BakeResult& result,
                             const OutputOptions& options, const std::string& folder) {
  const Scene& scene = loaded.scene;
  const bool irradiance = options.store == StoredQuantity::Irradiance;
  const bool sh = options.directional == Directional::SphericalHarmonics;
  const DisplayLight light = display_light(scene, atlas, result.pages, result.vertex_values,
                                           sh ? &result.directional : nullptr, options.emission_scale, irradiance,
                                           options.glazing, &result.display_view, options.display);
  DisplaySummary summary;
  summary.exposure = light.exposure;
  if (options.display.mode == DisplayMode::None) return summary;
  const bool vertex_lit = options.display.mode == DisplayMode::Vertex;
  if (vertex_lit)
    for (size_t k = 0; k < light.refined.curve.triangles.size(); ++k)
      summary.refinement.push_back({light.refined.curve.triangles[k], light.refined.curve.rms_relative[k]});
  DisplayInput input;
  input.scene = &scene;
  input.atlas = &atlas;
  input.pages = &light.pages;
  input.meshes = &light.refined.meshes;
  input.vertex_lit = vertex_lit;
  input.lightmap_is_irradiance = irradiance;
  input.emission_scale = options.emission_scale;
  input.exposure = light.exposure;
  input.source = loaded.source.get();
  input.camera = &result.display_camera;
  stop_unless(options);
  const DisplayOutput written = write_display_gltf(input, folder, options.name);
  summary.file = written.file;
  summary.shows = vertex_lit ? "vertex light" : "pre-lit pages";
  summary.prelit_detail = vertex_lit ? 0 : light.pages.detail;
  summary.triangles = written.triangles;
  summary.camera = written.camera;
  if (written.camera_added) summary.added_camera = result.display_camera;
  return summary;
}

}  // namespace

WrittenOutputs write_bake_outputs(const LoadedScene& loaded, const Atlas& atlas, BakeResult& result,
                                  const OutputOptions& options, const std::string& folder) {
  const std::string& name = options.name;
  const bool irradiance = options.store == StoredQuantity::Irradiance;
  if (options.debug_dumps) write_debug_dumps(result, atlas.pages, folder, name);
  result.elements = {};
  result.irradiance = {};
  result.direct = {};
  const float scale = options.png_scale > 0 ? options.png_scale : automatic_png_scale(result.pages);
  stop_unless(options);
  WrittenOutputs out;
  out.lightmaps = write_lightmaps(result.pages, folder, name, irradiance ? "irradiance" : "radiosity",
                                  irradiance ? "lx" : "lm/m2", scale);
  stop_unless(options);
  EngineFileOptions engine;
  engine.color_0 = options.color_0;
  engine.directional = write_directional(options.directional, result.directional, folder, name);
  if (options.probes) {
    engine.probes = &result.probes;
    engine.probes_file = write_light_probes(result.probes, folder, name);
  }
  stop_unless(options);
  out.display = write_display(loaded, atlas, result, options, folder);
  engine.display_exposure = out.display.exposure.exposure;
  engine.display_file = out.display.file;
  stop_unless(options);
  out.gltf = write_gltf(*loaded.source, loaded.scene, atlas, result.vertex_values, out.lightmaps, folder, name, engine);
  out.analysis = write_analysis(result, folder, name, options.analysis);
  return out;
}

}  // namespace radbake
