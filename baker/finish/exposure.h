// How scene luminance (cd/m2) becomes a display value in [0, 1]: one linear factor for the whole
// scene, chosen as a photographer's meter would (Reinhard et al. 2002, "Photographic tone
// reproduction": the log-mean luminance maps to the key value, middle grey), or set by the user.
#pragma once

#include <vector>

#include "baker/finish/finish.h"

namespace radbake {

struct ExposureOptions {
  float exposure = 0;  // display units per cd/m2; 0: automatic from the key value
  float key = 0.18f;   // display value (linear) the log-mean luminance is shown at
};

struct Exposure {
  float exposure = 1;               // displayed linear value = luminance in cd/m2 * exposure
  double log_mean_luminance = 0;    // cd/m2, over the covered texels
  bool automatic = true;
};

// `luminance`: pages in cd/m2 whose `valid` marks texels on a surface; only those are metered.
Exposure choose_exposure(const std::vector<LightmapPage>& luminance, const ExposureOptions& options);

}  // namespace radbake
