// Per surface (mesh instance), what its texels received: area, area-weighted mean, least and most
// illuminance, and uniformity (least over mean), as a lighting report tabulates per room surface.
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
};

// Back-face twins count with the instance whose back they are, under its name with " (back)".
std::vector<SurfaceStatistics> surface_statistics(const Scene& scene, const Surface& surface,
                                                  const Elements& elements, const std::vector<Rgb>& irradiance);

}  // namespace radbake
