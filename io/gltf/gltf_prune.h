// Removes what nothing in a glTF document references any more (the glTF-Validator's
// UNUSED_OBJECT): materials, textures, images, samplers, accessors, buffer views and buffers,
// renumbering every reference to what stays.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace radbake {

// References are followed through the core schema and the extensions radbake knows. A document
// using any other extension may hold indices where this cannot see them, so it is left as it is
// (and a warning says so).
void prune_unused_objects(nlohmann::ordered_json& doc, std::vector<std::string>& warnings);

// Removes doc[kind][i] where !keep[i] (keep has one entry per object), renumbering the references
// to what stays. Nothing may refer to a removed object any more.
void remove_objects(nlohmann::ordered_json& doc, const char* kind, const std::vector<uint8_t>& keep);

}  // namespace radbake
