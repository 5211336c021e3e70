// How scene luminance (cd/m2) becomes a display value in [0, 1]: one linear factor for the whole
// scene, chosen as a spot meter would on what is lit, or set by the user.
//
// The meter reads the lit surface only. A log-mean over every texel (Reinhard et al. 2002) is
// dragged down by texels no light reaches (the inside of a CAD part, the floor under a block),
// which then sets the exposure so high that everything lit shows white: 2CylinderEngine under one
// lamp had 14% of its texels at exactly 0 and 80% of its pixels clipped. So the median of the lit
// area is placed at the key value, unless that would clip more than a small share of the lit
// area's brightest channel, in which case the highlights set it.
//
// What is metered is what is seen where the display file opens: each texel counts as often as the
// display camera's rays strike it (baker/readings/display_camera.h display_view). A building's
// sunlit outside, most of its lit area, does not then set the exposure of a view of its attic.
#pragma once

#include <string>
#include <vector>

#include "baker/finish/finish.h"

namespace radbake {

struct ExposureOptions {
  float exposure = 0;  // display units per cd/m2; 0: automatic, metered as below
  float key = 0.18f;   // display value (linear) the median lit luminance is shown at (mid-grey)
  // Automatic: at most this share of the lit area shows any channel clipped (at 1).
  float max_clipped_share = 0.02f;
};

struct Exposure {
  float exposure = 1;                 // displayed linear value = luminance in cd/m2 * exposure
  bool automatic = true;
  // What the meter read, over the texels seen (weighted by the rays that see each), or, with no
  // view, over covered texels (each counts once: generated charts share one density, so this
  // weights by surface area). Lit: brighter than 1/1000 of the highlights (the 99th percentile),
  // ten stops down, black on any display.
  bool metered_view = false;          // on what the display camera sees
  double lit_share = 0;               // of what was metered
  double median_lit_luminance = 0;    // cd/m2
  double highlight_channel = 0;       // cd/m2: the lit area's (1 - max_clipped_share) quantile of max(R, G, B)
  bool limited_by_highlights = false; // the key would have clipped more than max_clipped_share
  std::string method;                 // how the exposure was chosen, one sentence for the report
};

// `luminance`: pages in cd/m2 whose `valid` marks texels on a surface; only those are metered.
// `seen`, when given and not empty: per page, per texel, how much the view sees it (pages of the
// same size as `luminance`); texels it does not see are not metered.
Exposure choose_exposure(const std::vector<LightmapPage>& luminance, const ExposureOptions& options,
                         const std::vector<std::vector<float>>* seen = nullptr);

}  // namespace radbake
