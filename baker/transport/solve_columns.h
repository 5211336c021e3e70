// The radiosity equation of solve_radiosity.h for many grey sources of direct light over one set
// of patches and form factors: a year of daylight solves one per sky patch and sun bin (877 for
// the classroom). Solved one by one, by shooting, they took 68% of the year; solved together by
// Gauss-Seidel sweeps, each row of the transport is read once per sweep for a block of columns
// at a time. Each column stops where solve_radiosity stops (no patch may still change by more
// than the tolerance of its own light) and gets the same ambient term per enclosure.
#pragma once

#include <cstddef>
#include <vector>

#include "baker/transport/patch_transport.h"
#include "baker/transport/patches.h"
#include "baker/transport/solve_radiosity.h"
#include "base/math.h"

namespace radbake {

struct ColumnSolution {
  size_t columns = 0;
  // [patch * columns + column]: the irradiance each patch gathers from the others' reflected
  // exitance, ambient term included, lux (gathered_irradiance of each column's solution).
  std::vector<Rgb> gathered;
  bool converged = false;  // every column within the tolerance before options.max_iterations sweeps
};

// `direct`: [patch * columns + column], each patch's area-weighted mean direct irradiance under
// that column's source, lux, the same in every channel. Reads options.tolerance, ambient_term and
// max_iterations (as sweeps); the solver is always Gauss-Seidel. The result does not depend on
// the number of threads.
ColumnSolution solve_columns(const Patches& patches, const PatchTransport& transport, const std::vector<float>& direct,
                             size_t columns, const SolveOptions& options);

}  // namespace radbake
