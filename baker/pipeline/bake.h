// The bake pipeline over plain data: scene and atlas in, lightmap pages and vertex values out.
// Each stage is its own function (docs/hacking.md); bake() runs them in order and times them. The
// options are bake_options.h's, the results bake_result.h's.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "baker/pipeline/bake_options.h"
#include "baker/pipeline/bake_result.h"
#include "baker/surface/bake_geometry.h"
#include "base/progress.h"
#include "base/scene.h"
#include "uv/atlas.h"

namespace radbake {

// This process's peak resident set so far, bytes (what the report and each rank's share state).
uint64_t peak_resident_bytes();

// Throws InputError when no texel covers a visible surface. Stage times go to `times`.
BakeGeometry bake_geometry(const Scene& scene, const Atlas& atlas, const BakeOptions& options, const EffectPlan& plan,
                           Progress& progress, std::vector<StageTime>& times);

// The progressive estimate while the radiosity solve refines it: direct light at texel resolution
// plus the patches' interreflection so far (no final gather), in the stored quantity, dilated.
using PreviewCallback = std::function<void(const std::vector<LightmapPage>& pages, size_t iteration)>;

// Simulates what `plan` says (plan_effects(scene, options.plan), or a plan a test has changed).
// Throws InputError for options validate() refuses and when no texel covers a visible surface, Cancelled when the callback says so,
// StoppedEarly when options.sharing asks to stop with the checkpoint saved. In a team, only the
// first process's result holds the light; the others return with an empty one.
BakeResult bake(const Scene& scene, const Atlas& atlas, const BakeOptions& options, const EffectPlan& plan,
                const ProgressCallback& on_progress = {}, const PreviewCallback& on_preview = {});

// Plans first; also throws InputError when nothing in the scene emits light.
BakeResult bake(const Scene& scene, const Atlas& atlas, const BakeOptions& options,
                const ProgressCallback& on_progress = {}, const PreviewCallback& on_preview = {});

}  // namespace radbake
