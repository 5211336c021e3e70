// The write stage of a bake: everything its output folder receives, written from the bake's
// result as plain options say. The command line parses, calls this and write_report, and prints.
#pragma once

#include <functional>
#include <string>

#include "baker/finish/display.h"
#include "baker/pipeline/bake_options.h"
#include "baker/pipeline/bake_result.h"
#include "io/analysis/analysis_outputs.h"
#include "io/gltf/gltf_loader.h"
#include "io/gltf/gltf_writer.h"
#include "io/lightmaps/page_encodings.h"
#include "io/run/report.h"
#include "uv/atlas.h"

namespace radbake {

struct OutputOptions {
  std::string name;  // the files' stem: NAME.gltf, NAME_lightmap_0.exr, ...
  // The bake's own options the files describe: what the pages hold, what rides with them, and
  // what the display file's light is made from.
  StoredQuantity store = StoredQuantity::Irradiance;
  Directional directional = Directional::None;
  bool probes = false;
  float emission_scale = 1;
  Glazing glazing;
  float png_scale = 0;  // the linear value PNG white stands for; 0: automatic_png_scale
  Color0 color_0 = Color0::Source;
  DisplayOptions display;
  AnalysisOptions analysis;
  bool debug_dumps = false;
  // Asked between files: false stops the write by throwing Cancelled (the caller's staged folder
  // leaves nothing behind).
  std::function<bool()> go_on = [] { return true; };
};

struct WrittenOutputs {
  LightmapFiles lightmaps;
  GltfOutput gltf;  // the engine file
  DisplaySummary display;
  AnalysisFiles analysis;
};

// Writes into `folder`, in this order: debug dumps (when asked), the pages, directional pages,
// probes, the display file, the engine glTF and the analysis files. The result's per-element data
// (elements, irradiance, direct light) is freed first: nothing here needs it, and freeing it keeps
// the write out of the bake's peak memory.
WrittenOutputs write_bake_outputs(const LoadedScene& loaded, const Atlas& atlas, BakeResult& result,
                                  const OutputOptions& options, const std::string& folder);

}  // namespace radbake
