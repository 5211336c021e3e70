// The lightmap pages of a finished bake, read back for comparison (`radbake diff`): either one
// EXR page or a radbake output folder.
#pragma once

#include <string>
#include <vector>

#include "baker/finish/finish.h"

namespace radbake {

struct BakeLightmaps {
  std::vector<LightmapPage> pages;  // by page index N
  std::vector<std::string> files;   // the EXR each page came from
  // From report.json beside the pages; without one, what radbake stores by default.
  std::string quantity = "irradiance";
  std::string unit = "lx";
};

// `path` is an EXR page, or a folder holding NAME_lightmap_N.exr for N = 0, 1, ... (one NAME) and
// usually report.json; nothing else in the folder is read. Throws InputError naming the problem.
BakeLightmaps read_bake_lightmaps(const std::string& path);

}  // namespace radbake
