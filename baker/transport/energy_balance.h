// Where the light went: everything the lights put into the scene must be absorbed by surfaces or
// leave it. The terms come from independent estimates (texel-level direct and gathered light on
// one side, ray counts on the other), so their mismatch measures the solution's error.
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

// Per element, where its final gather's rays went: the share that left the scene and the share lost
// (back faces, front faces that took no light). Empty: each element takes its patch's shares from
// the form factors' rays.
struct TexelFates {
  std::vector<float> escaped, lost;
};

// `irradiance`: the final light per element, lux; what leaves each element is its emission plus its
// reflectance times this, and it escapes or is lost in the shares of `fates`. Texel by texel is
// what counts since the final gather takes each struck texel's own direct light: where a patch's
// light is uneven, its bright texels may see more of the open than its dark ones (the sunlit strip
// of a patch at a canopy's edge), and a balance by patches read light as lost there (+2.3% on that
// canopy, +3.9% on a CAD engine under a lamp, +2.2% on a floodlit stadium) that it had counted to
// the patch's mean before.
EnergyBalance energy_balance(const Elements& elements, const Patches& patches, const PatchTransport& transport,
                             double delivered_power, const std::vector<Rgb>& irradiance, const TexelFates& fates = {});

}  // namespace radbake
