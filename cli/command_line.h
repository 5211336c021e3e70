// Parses the radbake commands into their options structs, by the option tables of
// cli/command_line.cpp: every option has a default and a unit, and report.json echoes it.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "baker/finish/display.h"
#include "baker/finish/lightmap_difference.h"
#include "baker/pipeline/bake_options.h"
#include "cli/option_table.h"
#include "cli/view_command.h"
#include "daylight/annual_metrics.h"
#include "daylight/daylight_sky.h"
#include "io/analysis/analysis_outputs.h"
#include "io/gltf/gltf_loader.h"
#include "io/gltf/gltf_writer.h"
#include "uv/atlas.h"

namespace radbake {

// The site and moment as typed; finish_site() makes DaylightOptions::site of them once every
// option is read (the four that place the sun come as a set).
struct SiteInput {
  bool latitude = false, longitude = false, date = false, time = false, utc_offset = false;
  SiteAndTime site;
  bool given() const { return latitude || longitude || date || time || utc_offset; }
};

struct BakeCommand {
  std::string input, output;
  LoadOptions load;
  AtlasOptions atlas;
  std::string quality = "preview";  // the preset the bake options start from
  BakeOptions bake;
  DaylightOptions daylight;  // made into bake.sky by daylight_sky() when the bake starts
  SiteInput site_input;
  std::string sensor_file;   // CSV of points to measure at; empty: none
  bool daylight_factor = false;
  AnalysisOptions analysis;
  // A year of daylight (--weather): daylight coefficients at the sensors for every hour of the file.
  std::string weather_file;
  int occupied_from = 8, occupied_to = 18;  // occupied hours, local standard time: from FROM:00 to TO:00
  int sky_subdivision = 1;                  // 1: Tregenza's 145 sky patches; m: Reinhart's MF:m
  AnnualMetricsOptions metrics;
  float png_scale = 0;  // 0: automatic
  DisplayOptions display;
  Color0 color_0 = Color0::Source;
  bool quiet = false;
  bool debug_dumps = false;
  // The most rays a stage may be estimated to cast (ray_budget.h): about an hour on 2 cores at the
  // 3 to 4 million rays a second the samples' bakes measure there.
  double max_rays = 1e10;
  // Checkpoints and slices (docs/distributed.md); the team and the store are made in main.
  std::string checkpoint;   // --checkpoint DIR; empty: none
  bool merge = false;       // `radbake merge`: the final gather comes from the slices in the checkpoint
  // Every option and the value in effect, for the report; and those that change what the bake
  // computes, for the checkpoint's fingerprint.
  std::vector<std::pair<std::string, std::string>> effective, result_options;
};

// `radbake uv`: the lightmap atlas alone, and what it is worth.
struct UvCommand {
  std::string input;
  LoadOptions load;
  AtlasOptions atlas;
  bool json = false;           // machine-readable statistics
  int evaluate_texcoord = -1;  // measure the input's TEXCOORD_n as one page instead of unwrapping
};

// `radbake diff`: how far a bake is from a reference bake of the same scene.
struct DiffCommand {
  std::string reference, candidate;  // each an EXR page or an output folder
  DifferenceOptions difference;
  DifferenceLimits limits;
  std::string image_folder;  // where the false-colour difference pages go; empty: not written
  bool json = false;         // machine-readable statistics
};

enum class Action { Bake, Merge, Uv, Diff, View, Help, Version };

struct CommandLine {
  Action action = Action::Help;
  BakeCommand bake;
  UvCommand uv;
  DiffCommand diff;
  ViewCommand view;
};

// Throws UsageError naming the offending argument (InputError for options the baker's validate()
// refuses together).
CommandLine parse_command_line(const std::vector<std::string>& args);

// The whole --help text, its options' lines made from the tables.
std::string usage_text();

// The option tables, for the help and for the tests that hold every row to its help and its echo.
const OptionTable<BakeCommand>& bake_options();
const OptionTable<UvCommand>& uv_options();
const OptionTable<DiffCommand>& diff_options();
const OptionTable<ViewCommand>& view_options();

}  // namespace radbake
