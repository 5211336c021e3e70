// Light probes as files (--probes, baker/readings/light_probes.h): NAME_probes.json beside the glTF, and the
// same in the engine glTF's extras.radbake.probes, so viewers and engines find them either way.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "baker/readings/light_probes.h"

namespace radbake {

// The probes with their convention spelled out (units, basis order, how to get irradiance).
nlohmann::ordered_json light_probes_json(const LightProbes& probes);

// Writes NAME_probes.json into `folder`; returns its file name.
std::string write_light_probes(const LightProbes& probes, const std::string& folder, const std::string& name);

}  // namespace radbake
