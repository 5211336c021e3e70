// A time budget beside the memory budget: the rays each stage that scales with an option will
// cast, estimated once the scene is read and unwrapped and before any of them is cast, so that
// `--hemicube-resolution 4096` or `--probe-rays 1000000` is refused in a second, naming the
// option, instead of running for hours with nothing said. The estimates count what the stages'
// loops cast (rays per texel, per patch, per probe, per sensor, per sensor and daylit hour); they
// are meant to catch what cannot finish, not to predict to the minute.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "baker/pipeline/bake_options.h"
#include "base/scene.h"
#include "uv/atlas.h"

namespace radbake {

// What the stages' loops run over, known before the bake.
struct RayCounts {
  uint64_t texels = 0;           // covered lightmap texels
  uint64_t sensors = 0;          // points given with --sensors
  uint64_t sensors_outside = 0;  // of them, those beyond the scene's bounds by more than a tenth of its size
  Vec3 extent{};                 // the scene's bounds, for the probes' grid
  uint64_t daylit_hours = 0;     // with --weather: the year's hours with the sun or sky up
};

RayCounts ray_counts(const Scene& scene, const Atlas& atlas, const std::vector<Sensor>& sensors, uint64_t daylit_hours);

struct StageRays {
  std::string stage;   // as the progress line names it, with its count where one scales it
  std::string option;  // the option that scales it, as the command line spells it
  double rays = 0;
};

// The stages `options` will run, each with its estimate.
std::vector<StageRays> estimate_stage_rays(const BakeOptions& options, const RayCounts& counts);

// Throws InputError for the first stage whose estimate exceeds `max_rays`, naming the stage, its
// option and the estimate, and how to go on (lower the option or raise --max-rays).
void check_ray_budget(const std::vector<StageRays>& stages, double max_rays);

}  // namespace radbake
