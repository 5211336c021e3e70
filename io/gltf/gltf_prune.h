// Removes what nothing in a glTF document references any more (the glTF-Validator's
// UNUSED_OBJECT): materials, textures, images, samplers, accessors, buffer views and buffers,
// renumbering every reference to what stays.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace radbake {

// References are followed through the core schema and the extensions radbake knows. A document
// using any other extension may hold indices where this cannot see them, so it is left as it is
// (and a warning says so).
void prune_unused_objects(nlohmann::ordered_json& doc, std::vector<std::string>& warnings);

}  // namespace radbake
