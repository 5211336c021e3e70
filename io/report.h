// report.json: what went in, what the bake did and how long it took, whether light was conserved.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "baker/bake.h"
#include "io/gltf.h"

namespace radbake {

struct RunInfo {
  std::string input;
  std::vector<std::pair<std::string, std::string>> options;  // as the user gave them, defaults filled in
  std::vector<StageTime> io_times;                           // loading, unwrapping, writing
  double total_seconds = 0;
  size_t peak_memory_bytes = 0;
  std::vector<std::string> files;  // everything written into the output folder, relative to it
};

void write_report(const std::string& path, const RunInfo& run, const Scene& scene, const Atlas& atlas,
                  const BakeReport& bake, const LightmapFiles& lightmaps, const std::vector<std::string>& warnings);

}  // namespace radbake
