#include "baker/pipeline/quality_presets.h"

#include "base/errors.h"

namespace radbake {
namespace {

struct Preset {
  const char* name;
  uint32_t gather_rays, patch_rays;
  int area_light_rays, light_rays;
  double tolerance;
  // Patches: one per this many elements, at most `patch_cap` (PatchOptions). On the Cornell box at
  // a 256 page, production's 8 and reference's 2 give blocks of 4 and 2 texels a side; past the
  // cap, patches keep their size in metres and memory grows with the texels alone.
  size_t elements_per_patch, patch_cap;
  int gather_filter;  // texels each side
  uint32_t sky_rays;  // per texel; the sensors' own sky rays are not the preset's (SensorOptions)
};

// On the Cornell box at a 256 page, against the path tracer, about 2%, 1%, 0.6% and 0.4%.
// Preview (the command line's defaults) casts 16 shadow rays per punctual light: with 4, the sun's
// direct light through the FZK-Haus's windows on its ground floor ranged from 2.0% under to 2.6%
// over the mean of four seeds, and its interior read -0.73% to -1.51% of the path tracer; with 16,
// -1.15% to -1.26%, for 3% more CPU time there and 14% on the arena's 15 lamps.
constexpr Preset kPresets[] = {
    {"draft", 32, 512, 16, 1, 1e-2, 32, 4096, 3, 64},
    {"preview", 64, 1024, 64, 16, 1e-3, 32, 4096, 3, 256},
    {"production", 256, 1024, 128, 16, 1e-4, 8, 16384, 2, 1024},
    {"reference", 1024, 4096, 512, 64, 1e-5, 2, 32768, 2, 4096},
};

}  // namespace

std::vector<std::string> quality_preset_names() {
  std::vector<std::string> names;
  for (const Preset& p : kPresets) names.push_back(p.name);
  return names;
}

void apply_quality_preset(const std::string& name, BakeOptions& bake) {
  for (const Preset& p : kPresets)
    if (name == p.name) {
      bake.gather_rays = p.gather_rays;
      bake.gather_filter.radius = p.gather_filter;
      bake.form_factors.rays_per_patch = p.patch_rays;
      bake.direct.area_light_rays = p.area_light_rays;
      bake.direct.punctual_rays = p.light_rays;
      bake.solve.tolerance = p.tolerance;
      bake.patches.block_size = 0;
      bake.patches.elements_per_patch = p.elements_per_patch;
      bake.patches.patch_cap = p.patch_cap;
      bake.sky.rays = p.sky_rays;
      return;
    }
  throw InputError("no quality preset is called '" + clipped(name) + "': draft, preview, production or reference");
}

}  // namespace radbake
