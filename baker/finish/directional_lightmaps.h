// Directional lightmaps (--directional): besides a texel's irradiance, where its light comes
// from, so a normal-mapped surface shows its bumps under baked light. From the directions the
// direct light and the final gather already trace (light_direction.h), not a second bake.
//
// `sh`: per texel and colour channel, the irradiance for any normal n as an L1 spherical-harmonic
// function E(n) = max(0, c0 + c1 . n) (lux; c1 in world space): the order-0 and order-1 terms of
// the irradiance's spherical-harmonic expansion, with the clamped-cosine convolution folded in
// (Ramamoorthi and Hanrahan's irradiance coefficients: c0 = 0.282095 E_00, c1 = 0.488603
// (E_11, E_1-1, E_10)). They are fitted so that:
// - at the surface's own normal E(n) is the texel's irradiance, exactly (the plain lightmap);
// - light from one direction d is exact for every normal: c0 = 0, c1 = E_perp d;
// - light from the whole hemisphere alike (an overcast sky, an evenly lit room) is exact too:
//   c0 = c1 . n_s = E / 2, E(n) = E (1 + n . n_s) / 2;
// and light between the two is blended by how directional it is: the length of its
// irradiance-weighted mean direction, 1 for one direction and 2/3 for an even hemisphere.
//
// `dominant`: Unity's directional mode: the plain lightmap plus a page of the luminance-weighted
// mean direction of the arriving light (length: its directionality), which Unity's shader reads as
// E(n) = E (n . dir + 0.5) / max(1e-4, |dir|) with dir as stored here (its PNG holds dir / 2 + 0.5).
#pragma once

#include <vector>

#include "baker/finish/finish.h"
#include "baker/surface/elements.h"
#include "baker/surface/light_direction.h"

namespace radbake {

enum class Directional { None, SphericalHarmonics, Dominant };

// One texel's L1 irradiance function, per channel: E(n) = max(0, c0 + c1 . n).
struct IrradianceSh {
  Rgb c0{}, c1x{}, c1y{}, c1z{};
  Rgb at(Vec3 n) const;
};

// `irradiance` lux at the surface's shading `normal`, arriving as `from` says.
IrradianceSh fit_irradiance_sh(Rgb irradiance, const LightDirection& from, Vec3 normal);

// The luminance-weighted mean direction of the arriving light (length <= 1).
Vec3 dominant_direction(Rgb irradiance, const LightDirection& from);

// Per element: where its light comes from, the direct light's (in lux) plus the gathered light's
// mean direction times its final irradiance; `indirect` is that irradiance, lux.
std::vector<LightDirection> total_light_directions(const std::vector<LightDirection>& direct,
                                                   const std::vector<LightDirection>& gathered_mean,
                                                   const std::vector<Rgb>& indirect);

// The pages of `mode`, dilated like the lightmap: for sh four sets (c0, c1x, c1y, c1z), for
// dominant one (the direction).
std::vector<std::vector<LightmapPage>> directional_pages(Directional mode, const Elements& elements,
                                                         const std::vector<Rgb>& irradiance,
                                                         const std::vector<LightDirection>& from,
                                                         const std::vector<AtlasPage>& pages);

}  // namespace radbake
