// Parses `radbake bake ...` into the options structs; every option has a default and a unit.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "baker/bake.h"
#include "uv/atlas.h"

namespace radbake {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct BakeCommand {
  std::string input, output;
  AtlasOptions atlas;
  BakeOptions bake;
  float png_scale = 0;  // 0: automatic
  bool quiet = false;
  bool debug_dumps = false;
  std::vector<std::pair<std::string, std::string>> effective;  // every option and its value, for the report
};

enum class Action { Bake, Help, Version };

struct CommandLine {
  Action action = Action::Help;
  BakeCommand bake;
};

// Throws UsageError naming the offending argument.
CommandLine parse_command_line(const std::vector<std::string>& args);

const char* usage_text();

}  // namespace radbake
