// report.json: what went in, what the bake did and how long it took, whether light was conserved.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "baker/finish/exposure.h"
#include "baker/pipeline/bake_result.h"
#include "daylight/daylight_sky.h"
#include "io/analysis/analysis_outputs.h"
#include "io/lightmaps/page_encodings.h"

namespace radbake {

// The display file and the exposure both files record.
struct DisplaySummary {
  std::string file;  // empty: none written
  std::string shows; // "pre-lit pages" or "vertex light"
  int prelit_detail = 0;
  Exposure exposure;              // what both files record, and how it was metered
  size_t triangles = 0;
  std::string camera;  // which camera the display file opens on, and why
  std::optional<DisplayCamera> added_camera;  // the one it opens on, when the input had none
  // Vertex light against the lightmap as the mesh is refined: (triangles, area-weighted RMS
  // difference relative to the mean light).
  std::vector<std::pair<size_t, double>> refinement;
};

struct RunInfo {
  std::string input;
  std::vector<std::pair<std::string, std::string>> options;  // as the user gave them, defaults filled in
  std::vector<StageTime> io_times;                           // loading, unwrapping, writing
  double total_seconds = 0;
  size_t peak_memory_bytes = 0;
  std::vector<std::string> files;  // everything written into the output folder, relative to it
  DisplaySummary display;
  std::optional<DaylightSummary> daylight;  // with a sky
  AnalysisFiles analysis;
};

void write_report(const std::string& path, const RunInfo& run, const Scene& scene, const Atlas& atlas,
                  const BakeReport& bake, const LightmapFiles& lightmaps, const std::vector<std::string>& warnings);

}  // namespace radbake
