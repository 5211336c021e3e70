// Directional lightmap pages as files (--directional, baker/finish/directional_lightmaps.h): each set of
// pages in every page encoding (io/lightmaps/page_encodings.h), 8-bit ones packed the way engines
// store such data, linearly: value = offset + scale * png / 255, one scale and offset per set,
// recorded in the glTF's extras.radbake.directional.
#pragma once

#include <string>
#include <vector>

#include "baker/finish/directional_lightmaps.h"

namespace radbake {

struct DirectionalSet {
  std::string coefficient;  // "sh_c0", "sh_c1x", "sh_c1y", "sh_c1z" or "dominant_direction"
  float scale = 1, offset = 0;  // value = offset + scale * png / 255
  // [page][k]: the page's file in page_encodings()[k], inside the output folder.
  std::vector<std::vector<std::string>> files;
};

struct DirectionalFiles {
  std::string mode;  // "sh", "dominant"; empty: none written
  std::vector<DirectionalSet> sets;
};

DirectionalFiles write_directional(Directional mode, const std::vector<std::vector<LightmapPage>>& sets,
                                   const std::string& folder, const std::string& name);

}  // namespace radbake
