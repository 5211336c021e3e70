// Compares two bakes of the same scene texel by texel (`radbake diff`, the golden-image tests):
// how far the candidate's lightmap pages are from the reference's, as statistics and as a
// false-colour picture of where. Pure computation over LightmapPage; reading and writing is io/'s.
//
// Definitions (also in `radbake diff --help` and the README):
// - A texel is compared unless it is zero in every channel of both pages: unused page space, or a
//   surface no light reaches in either, where they agree exactly and would dilute the statistics.
// - Its value is the mean of its RGB channels; its error |B - A| is the mean over the channels of
//   the absolute difference, in the pages' unit (lux for irradiance).
// - Its relative error is error / max(A, floor x reference level), where the reference level is
//   the mean of A's values over the compared texels (B's, where A is black throughout), so dark
//   texels are not divided by almost nothing.
// - Relative RMSE: root mean square of the errors over the reference level.
// - Percentiles: nearest rank over the compared texels' relative errors.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "baker/finish/finish.h"

namespace radbake {

struct DifferenceOptions {
  double relative_floor = 0.1;  // fraction of the reference level under which a texel's relative
                                // error is taken against that floor instead of its own value
  double image_scale = 0.1;     // signed relative difference (fraction) shown at full colour
};

struct DifferenceStats {
  size_t texels = 0;           // compared texels
  double reference_level = 0;  // mean value of the compared texels (see above), pages' unit
  double rmse = 0;             // relative RMSE, fraction of the reference level
  double max_error = 0;        // largest texel error, pages' unit
  double p50 = 0, p95 = 0, p99 = 0;  // percentiles of the relative error, fractions
};

struct PageDifference {
  DifferenceStats stats;
  int width = 0, height = 0;
  // 8-bit RGB, rows top to bottom: white where the pages agree, towards red where the candidate
  // is brighter and blue where it is darker, full colour at image_scale; black where not compared.
  std::vector<uint8_t> image;
};

struct LightmapDifference {
  std::vector<PageDifference> pages;
  DifferenceStats all;  // over the compared texels of every page together
};

// Pages are matched by index. Throws InputError when the page counts or sizes differ, or when a
// texel is negative or not finite (no lightmap holds one).
LightmapDifference compare_lightmaps(const std::vector<LightmapPage>& reference,
                                     const std::vector<LightmapPage>& candidate, const DifferenceOptions& options);

// Thresholds on the all-pages statistics; an unset one is not checked.
struct DifferenceLimits {
  std::optional<double> rmse;       // fraction
  std::optional<double> p50, p95, p99;  // fractions
  std::optional<double> max_error;  // pages' unit
};

struct LimitCheck {
  std::string name;      // "rmse", "p50", "p95", "p99" or "error" (the largest texel error)
  bool fraction = true;  // value and limit are fractions; else in the pages' unit
  double value = 0, limit = 0;
  bool exceeded = false;
};

// One check per set limit, in the order of DifferenceLimits.
std::vector<LimitCheck> check_limits(const DifferenceStats& stats, const DifferenceLimits& limits);

}  // namespace radbake
