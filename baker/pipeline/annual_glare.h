// A year of glare at an eye, by the enhanced simplified DGP (Wienold 2009): each hour's vertical
// illuminance at the eye from the daylight coefficients, and, as the one glare source, the sun's
// disc when the eye sees it (its luminance the direct normal illuminance over the disc's 6.8e-5
// sr, times the share seen). Bright sky in a window is not a source here, as in Wienold's method:
// its light is in Ev only.
#pragma once

#include <vector>

#include "baker/pipeline/annual_daylight.h"
#include "baker/readings/luminance_view.h"

namespace radbake {

struct EyeGlareSummary {
  size_t occupied_hours = 0;                   // occupied hours with daylight
  double mean_dgp = 0;                         // over those
  double over_035 = 0, over_040 = 0, over_045 = 0;  // shares of those: perceptible, disturbing, intolerable
};

struct AnnualGlare {
  std::vector<float> dgp;              // [hour * eyes + eye]; 0 for a dark hour
  std::vector<EyeGlareSummary> eyes;
};

AnnualGlare annual_glare(const AnnualDaylight& daylight, const std::vector<EyeView>& eyes,
                         const std::vector<SkyLight>& hours, const std::vector<bool>& occupied);

}  // namespace radbake
