// Directional lightmap pages as files (--directional, baker/finish/directional_lightmaps.h): each set of
// pages as linear EXR (the values themselves) and as 8-bit PNG packed the way engines store such
// data, linearly: value = offset + scale * png / 255, one scale and offset per set, recorded in
// the glTF's extras.radbake.directional.
#pragma once

#include <string>
#include <vector>

#include "baker/finish/directional_lightmaps.h"

namespace radbake {

struct DirectionalSet {
  std::string coefficient;            // "c0", "c1x", "c1y", "c1z" (sh) or "direction" (dominant)
  std::vector<std::string> exr, png;  // one per lightmap page, inside the output folder
  float scale = 1, offset = 0;        // value = offset + scale * png / 255
};

struct DirectionalFiles {
  std::string mode;  // "sh", "dominant"; empty: none written
  std::vector<DirectionalSet> sets;
};

DirectionalFiles write_directional(Directional mode, const std::vector<std::vector<LightmapPage>>& sets,
                                   const std::string& folder, const std::string& name);

}  // namespace radbake
