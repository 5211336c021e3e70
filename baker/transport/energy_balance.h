// Where the light went: everything the lights put into the scene must be absorbed by surfaces or
// leave it. The terms come from independent estimates (texel-level direct and gathered light on
// one side, patch-level ray counts on the other), so their mismatch measures the solution's error.
#pragma once

#include <vector>

#include "baker/surface/elements.h"
#include "baker/transport/patch_transport.h"
#include "baker/transport/patches.h"

namespace radbake {

// Powers in lumens, the mean of the RGB channels.
struct EnergyBalance {
  double emitted = 0;     // by emitting surfaces (a double-sided one's back-face twin is a surface
                          // of its own), plus what punctual lights and the sky deliver onto surfaces
  double absorbed = 0;    // by front faces: (1 - rho) * irradiance * area over all elements
  double escaped = 0;     // left the scene
  double lost = 0;        // struck back faces (absorbed there) or texels buried inside geometry
  double relative_error = 0;  // (emitted - absorbed - escaped - lost) / emitted
  bool measured = false;  // false when the plan skipped interreflection: no ray measured what escapes
};

// `irradiance`: the final light per element, lux; what leaves each patch is its elements' emission
// plus their reflectance times this.
EnergyBalance energy_balance(const Elements& elements, const Patches& patches, const PatchTransport& transport,
                             double delivered_power, const std::vector<Rgb>& irradiance);

}  // namespace radbake
