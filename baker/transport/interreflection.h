// Light between surfaces: texels grouped into patches, the form factors between patches (ray
// casting or hemicubes), and the radiosity solve; optionally with adaptive subdivision, which
// starts from coarse patches, solves, and splits patches where neighbours' radiosity differs by
// more than a tolerance (shadow boundaries, corners), down to single texels, measuring form
// factors again only for the new patches.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "baker/sharing/sharing.h"
#include "baker/transport/patch_transport.h"
#include "baker/transport/patches.h"
#include "baker/transport/solve_radiosity.h"

namespace radbake {

enum class FormFactorMethod { RayCast, Hemicube };

struct FormFactorOptions {
  FormFactorMethod method = FormFactorMethod::RayCast;
  uint32_t rays_per_patch = 2048;  // ray casting: rays from each patch (more from patches carrying more light)
  int hemicube_resolution = 64;    // hemicube: pixels per side of the top face (even)
};

struct SubdivisionOptions {
  // Split both patches of a neighbouring pair whose radiosity differs by more than this fraction of
  // the brighter one. 0: no adaptive subdivision.
  double tolerance = 0;
  int max_rounds = 4;  // solve-and-split rounds after the first solve; each halves the split patches' side
};

// How light between surfaces is found: the patches, their form factors, adaptive subdivision, the
// solve, and the seed of the rays that measure them.
struct InterreflectionOptions {
  PatchOptions patches;
  FormFactorOptions form_factors;
  SubdivisionOptions subdivision;
  SolveOptions solve;
  uint64_t seed = 1;
};

struct SubdivisionRound {
  size_t patches = 0;  // patches in this round's solve
  size_t split = 0;    // of them, split after it
};

struct Interreflection {
  Patches patches;
  PatchTransport transport;
  RadiositySolution solution;
  std::vector<SubdivisionRound> rounds;  // one per solve
  double form_factor_seconds = 0, solve_seconds = 0;
  double mean_free_path_m = 0;  // what sized automatic patches (PatchOptions); 0 when not measured
};

// Sees the solve's progressive estimate every `every` shots or sweeps, with the patches and form
// factors it belongs to (they change between subdivision rounds).
struct InterreflectionObserver {
  size_t every = 0;
  std::function<void(const Patches&, const PatchTransport&, const std::vector<Rgb>& exitance, size_t iteration)> see;
};

// `direct`: irradiance per element from lights and emitting surfaces, lux. Shared by a team, the
// rows of form factors are measured by all and solved on the first process: the others get the
// patches and the solved exitance, but no transport.
Interreflection solve_interreflection(const Elements& elements, const Surface& surface, const RayTracer& tracer,
                                      const std::vector<Rgb>& direct, const InterreflectionOptions& options,
                                      Progress& progress, const InterreflectionObserver& observer = {},
                                      const Sharing& sharing = {});

// Irradiance per patch from the other patches' reflected `exitance`: what each gathers, sum over
// q of B_q A_q F_qp / A_p (= F_pq B_q by reciprocity between single-sided patches), lux.
std::vector<Rgb> gathered_irradiance(const Patches& patches, const PatchTransport& transport,
                                     const std::vector<Rgb>& exitance);

// Which patches adaptive subdivision splits after a solve (1 = split): both of every pair of
// neighbouring patches (joined texels across their border) whose radiosity, emission plus
// `exitance`, differs by more than `tolerance` of the brighter, ignoring pairs darker than 1% of the
// area-weighted mean radiosity. Single-texel patches are never marked.
std::vector<uint8_t> patches_to_split(const Elements& elements, const Surface& surface, const Patches& patches,
                                      const std::vector<Rgb>& exitance, double tolerance);

}  // namespace radbake
