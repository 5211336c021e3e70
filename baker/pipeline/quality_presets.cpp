#include "baker/pipeline/quality_presets.h"

#include <iterator>

#include "base/errors.h"

namespace radbake {
namespace {

const char* const kPresetNames[] = {"draft", "preview", "production", "reference"};
constexpr size_t kPresets = sizeof kPresetNames / sizeof kPresetNames[0];

// Each row sets one field, by name, to its value at draft, preview, production and reference.
struct PresetRow {
  void (*set)(BakeOptions&, double);
  double value[kPresets];
};

// On the Cornell box at a 256 page, against the path tracer, about 2%, 1%, 0.6% and 0.4%.
// Patches: one per `elements_per_patch` elements, at most `patch_cap` (PatchOptions). On the
// Cornell box at a 256 page, production's 8 and reference's 2 give blocks of 4 and 2 texels a side;
// past the cap, patches keep their size in metres and memory grows with the texels alone. The sky
// rays are per texel; the sensors' own sky rays are not the preset's (SensorOptions).
// Preview (the command line's defaults) casts 16 shadow rays per punctual light: with 4, the sun's
// direct light through the FZK-Haus's windows on its ground floor ranged from 2.0% under to 2.6%
// over the mean of four seeds, and its interior read -0.73% to -1.51% of the path tracer; with 16,
// -1.15% to -1.26%, for 3% more CPU time there and 14% on the arena's 15 lamps.
const PresetRow kRows[] = {
    {[](BakeOptions& b, double v) { b.gather.rays = uint32_t(v); }, {32, 64, 256, 1024}},
    {[](BakeOptions& b, double v) { b.gather.filter.radius = int(v); }, {3, 3, 2, 2}},
    {[](BakeOptions& b, double v) { b.form_factors.rays_per_patch = uint32_t(v); }, {512, 1024, 1024, 4096}},
    {[](BakeOptions& b, double v) { b.direct.area_light_rays = int(v); }, {16, 64, 128, 512}},
    {[](BakeOptions& b, double v) { b.direct.punctual_rays = int(v); }, {1, 16, 16, 64}},
    {[](BakeOptions& b, double v) { b.solve.tolerance = v; }, {1e-2, 1e-3, 1e-4, 1e-5}},
    {[](BakeOptions& b, double v) { b.patches.elements_per_patch = size_t(v); }, {32, 32, 8, 2}},
    {[](BakeOptions& b, double v) { b.patches.patch_cap = size_t(v); }, {4096, 4096, 16384, 32768}},
    {[](BakeOptions& b, double v) { b.sky.rays = uint32_t(v); }, {64, 256, 1024, 4096}},
};

}  // namespace

std::vector<std::string> quality_preset_names() { return {std::begin(kPresetNames), std::end(kPresetNames)}; }

void apply_quality_preset(const std::string& name, BakeOptions& bake) {
  for (size_t p = 0; p < kPresets; ++p)
    if (name == kPresetNames[p]) {
      bake.patches.block_size = 0;
      for (const PresetRow& row : kRows) row.set(bake, row.value[p]);
      return;
    }
  throw InputError("no quality preset is called '" + clipped(name) + "': draft, preview, production or reference");
}

}  // namespace radbake
