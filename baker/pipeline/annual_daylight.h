// A year of daylight at sensors by daylight coefficients (Tregenza and Waters 1983; Reinhart and
// Herkel 2000; what Radiance's rcontrib and dctimestep do). The interreflection is solved once per
// sky patch, for the ground, and per sun bin, all over one set of patches and form factors; every
// hour is then a weighted sum:
//
//   E(sensor, hour) = sum over fine patches q of D(q) L(q)       the sky the sensor sees itself
//                   + sum over sky patches p of C(p) L(p)        the sky by way of the surfaces
//                   + (D(ground) + C(ground)) L(ground)          the ground beyond the scene
//                   + E_sun (direct at the sensor + C(sun bin))  the sun: its shadow rays per hour,
//                                                                its reflections by the bin it is in
//
// D and the sensor's sun rays are the rays a single bake's sensor casts (same seed, same rays);
// only their luminance is taken from patches. C comes from the patch-level solve: each surface a
// sensor's gather ray strikes sends rho (direct + what its patch gathers).
#pragma once

#include <cstdint>
#include <vector>

#include "baker/finish/finish.h"
#include "baker/pipeline/bake_options.h"
#include "baker/readings/sensor_points.h"
#include "baker/readings/work_plane.h"
#include "base/progress.h"
#include "base/scene.h"
#include "daylight/sky.h"
#include "uv/atlas.h"

namespace radbake {

struct AnnualDaylightOptions {
  int sky_subdivision = 1;     // sky patches for the light surfaces pass on: 1 = Tregenza's 145, m: Reinhart MF:m
  int direct_subdivision = 4;  // patches for the sky a sensor sees directly (4: 2305 patches of about 3 degrees)
  int sun_subdivision = 4;     // sun bins (Reinhart MF:m patches the year's suns fall in)
  uint32_t bin_sun_rays = 4;   // per texel per sun bin, toward the bin's centre
  // Per texel, over the hours `occupied` marks (parallel to the hours; empty: no texel maps): the
  // share at da_threshold lux or more, the share in udi_low..udi_high, the mean illuminance. A
  // texel's light is its coefficients' (the sky by the 145 patches, the sun by its bin's centre).
  std::vector<bool> occupied;
  double da_threshold = 300, udi_low = 300, udi_high = 3000;  // lux
};

struct AnnualDaylight {
  std::vector<Sensor> sensors;  // BakeOptions::sensors, then the work plane's
  WorkPlane work_plane;         // its storeys and rooms index `sensors`
  size_t hours = 0;
  std::vector<float> lux;       // [hour * sensors + sensor], lux
  std::vector<float> sun_lux;   // the same, the sun's direct light alone (for annual sun exposure)
  // Per BakeOptions::views eye, [hour * eyes + eye]: the vertical illuminance at the eye facing
  // where it looks, and the share of the sun's disc it sees (0 when the sun is behind it or down).
  size_t eyes = 0;
  std::vector<float> eye_lux, eye_sun_seen;
  // With AnnualDaylightOptions::occupied: lightmap pages (the atlas's) of each texel's daylight
  // autonomy and UDI share (percent of the occupied daylit hours) and mean illuminance (lux).
  std::vector<LightmapPage> texel_daylight_autonomy, texel_udi, texel_mean_lux;
  size_t sky_patches = 0;       // solved, the ground included
  size_t sun_bins = 0;          // solved
  double coefficient_seconds = 0, hours_seconds = 0;
};

// Illuminance at options.sensors and, when asked, a work plane's (options.work_plane) for every one
// of `hours` (each a SkyLight: its sky, sun and ground; `enabled` false for a dark hour). The
// scene's geometry, materials, patches and form factors come from `options` as for a bake, and
// the rays and the compass from options.sky; its lamps are left out. Throws InputError as a bake
// does.
AnnualDaylight annual_daylight(const Scene& scene, const Atlas& atlas, const BakeOptions& options,
                               const std::vector<SkyLight>& hours, const AnnualDaylightOptions& annual,
                               const ProgressCallback& on_progress = {});

}  // namespace radbake
