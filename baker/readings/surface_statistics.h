// Per surface (mesh instance), what its texels received: area, area-weighted mean, least and most
// illuminance, and uniformity (least over mean), as a lighting report tabulates per room surface;
// and how much of the open it sees, which tells a building's outside from its rooms.
#pragma once

#include <string>
#include <vector>

#include "baker/surface/elements.h"
#include "baker/surface/surface.h"
#include "base/scene.h"

namespace radbake {

struct SurfaceStatistics {
  std::string name;  // the instance's (node's) name
  int instance = -1;
  double area = 0;   // m^2 of valid texels
  double mean = 0, min = 0, max = 0;  // lux (photopic, per texel)
  double uniformity = 0;  // min / mean; 0 when the mean is 0
  // Area-weighted mean of its texels' open view (GatheredLight::open_view); NaN when not measured.
  double open_view = 0;
  // A path-traced bake's: the standard error of `mean`, lux, from its texels' own (independent
  // paths: sqrt(sum (A_i s_i)^2) / sum A_i); NaN for other bakes.
  double standard_error = 0;
};

// Back-face twins count with the instance whose back they are, under its name with " (back)".
// `open_view`: per element, or empty when the bake had no final gather; `standard_error`: per
// element, lux, or empty when it was not path traced.
std::vector<SurfaceStatistics> surface_statistics(const Scene& scene, const Surface& surface,
                                                  const Elements& elements, const std::vector<Rgb>& irradiance,
                                                  const std::vector<float>& open_view,
                                                  const std::vector<float>& standard_error);

}  // namespace radbake
