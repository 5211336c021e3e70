// The quality presets: ray counts, tolerance, patch size and gather filter chosen together, from
// the accuracy-versus-time front measured in docs/accuracy.md (./dev accuracy).
#pragma once

#include <string>
#include <vector>

#include "baker/pipeline/bake_options.h"

namespace radbake {

// The presets' names, fastest first: draft, preview, production, reference.
std::vector<std::string> quality_preset_names();

// Sets the ray counts, tolerance, patch size and gather filter of preset `name` in `bake`, leaving
// everything else as it is. Throws InputError for a name that is no preset.
void apply_quality_preset(const std::string& name, BakeOptions& bake);

}  // namespace radbake
