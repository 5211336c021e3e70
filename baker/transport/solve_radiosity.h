// The radiosity equation at patch level for reflected light: B_p = rho_p (D_p + sum_q F_pq B_q),
// with D_p the direct irradiance (from lights and emitting surfaces) and F the ray-cast transport.
// Solved by progressive shooting (Cohen et al. 1988) or by Jacobi / Gauss-Seidel gathering; all
// stop when no patch has more than a tolerance of its own light still to come, never after a
// fixed number of bounces, so a dim room beside a bright one is solved as finely as if it were
// alone. Enclosures (patches that exchange light, find_enclosures) are each given an ambient term
// for what is left.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "baker/sharing/stage_store.h"
#include "baker/transport/patch_transport.h"
#include "baker/transport/patches.h"
#include "base/math.h"
#include "base/progress.h"

namespace radbake {

enum class Solver { Shooting, GaussSeidel, Jacobi };

struct SolveOptions {
  Solver solver = Solver::Shooting;
  double tolerance = 1e-3;  // stop when, in every patch, unshot exitance <= tolerance * its exitance
  bool ambient_term = true; // add Cohen's ambient estimate of the light still unshot to the result
  // A guard against a solve that cannot converge (it never should with reflectance < 1); reaching
  // it is reported as non-convergence, not passed off as a result.
  size_t max_iterations = 50'000'000;
  // Set from the effect plan: every reflectance is grey and all direct light has this colour
  // (largest component exactly 1), so one channel is solved and scaled by it. Zero: three channels.
  Rgb one_channel_colour{0, 0, 0};
};

struct RadiositySolution {
  std::vector<Rgb> exitance;   // reflected exitance per patch, lm/m2 (emission not included)
  size_t iterations = 0;       // shots, or sweeps for the gathering solvers
  int channels = 3;            // solved: 1 when the plan found grey materials under one light colour
  double unshot_power = 0;     // lm (mean of the RGB channels) still to be distributed
  double input_power = 0;      // lm (mean of the RGB channels) the direct light brings in
  double relative_unshot = 0;  // unshot_power / input_power
  bool converged = false;
  Rgb ambient{};               // lm/m2 added through the ambient term, area-weighted mean over the enclosures
};

// Sees the progressive estimate every `every` shots (or sweeps): reflected exitance per patch,
// with the ambient term when it is on, so even the first estimates are plausible (Lightscape's
// early images). 0: never.
struct SolveObserver {
  size_t every = 0;
  std::function<void(const std::vector<Rgb>& exitance, size_t iteration)> see;
};

// Where the solve saves its state now and then (every shot's or sweep's data, so a resumed
// solve goes on exactly as it would have), and takes it back from when resuming.
struct SolveSaving {
  StageStore* store = nullptr;
  std::string key;
  bool resume = false;
  double every_seconds = 60;  // at most this often, checked every 1024 shots or each sweep; 0: each time
};

// `direct` is the area-weighted mean direct irradiance of each patch in lux.
RadiositySolution solve_radiosity(const Patches& patches, const PatchTransport& transport,
                                  const std::vector<Rgb>& direct, const SolveOptions& options, Progress& progress,
                                  const SolveObserver& observer = {}, const SolveSaving& saving = {});

}  // namespace radbake
