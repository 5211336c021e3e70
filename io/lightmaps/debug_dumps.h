// Per-stage images for finding lightmap bugs by looking (the role of Godot's DEBUG_TEXTURES):
// light by source, material, normals, sample flags and the patch layout, undilated.
#pragma once

#include <string>
#include <vector>

#include "baker/pipeline/bake_result.h"

namespace radbake {

// Writes debug/NAME_<what>_<page>.exr into `folder`; returns the file names written.
std::vector<std::string> write_debug_dumps(const BakeResult& result, const std::vector<AtlasPage>& pages,
                                           const std::string& folder, const std::string& name);

}  // namespace radbake
