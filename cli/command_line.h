// Parses `radbake bake ...` into the options structs; every option has a default and a unit.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "baker/annual_metrics.h"
#include "baker/bake.h"
#include "baker/daylight.h"
#include "baker/exposure.h"
#include "baker/lightmap_difference.h"
#include "cli/view_command.h"
#include "io/analysis_outputs.h"
#include "io/gltf.h"
#include "uv/atlas.h"

namespace radbake {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// What the display file (NAME_display.glb) shows its light with.
enum class DisplayMode {
  Page,    // pre-lit pages on the lightmap UVs
  Vertex,  // the surface's base colour times pre-lit COLOR_0
  None,    // no display file
};

struct BakeCommand {
  std::string input, output;
  LoadOptions load;
  AtlasOptions atlas;
  BakeOptions bake;
  DaylightOptions daylight;  // made into bake.sky by daylight_sky() when the bake starts
  std::string sensor_file;   // CSV of points to measure at; empty: none
  bool daylight_factor = false;
  AnalysisOptions analysis;
  // A year of daylight (--weather): daylight coefficients at the sensors for every hour of the file.
  std::string weather_file;
  int occupied_from = 8, occupied_to = 18;  // occupied hours, local standard time: from FROM:00 to TO:00
  int sky_subdivision = 1;                  // 1: Tregenza's 145 sky patches; m: Reinhart's MF:m
  AnnualMetricsOptions metrics;
  float png_scale = 0;  // 0: automatic
  DisplayMode display = DisplayMode::Page;
  int display_detail = 0;      // pre-lit texels per lightmap texel along a side (1, 2, 4); 0: automatic
  ExposureOptions exposure;    // display units per cd/m2; automatic by default
  Color0 color_0 = Color0::Source;
  size_t vertex_refine_triangles = 0;  // --display vertex: refine the mesh up to this many triangles; 0: as it is
  bool quiet = false;
  bool debug_dumps = false;
  // Checkpoints and slices (docs/distributed.md); the team and the store are made in main.
  std::string checkpoint;   // --checkpoint DIR; empty: none
  bool merge = false;       // `radbake merge`: the final gather comes from the slices in the checkpoint
  std::vector<std::pair<std::string, std::string>> effective;  // every option and its value, for the report
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

// Throws UsageError naming the offending argument.
CommandLine parse_command_line(const std::vector<std::string>& args);

const char* usage_text();

// --quality NAME: sets the ray counts, tolerance and subdivision of a preset in `bake`.
void apply_quality_preset(const std::string& name, BakeOptions& bake);

}  // namespace radbake
