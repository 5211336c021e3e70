#include "baker/transport/energy_balance.h"

namespace radbake {
namespace {
double mean(Rgb v) { return (double(v.x) + v.y + v.z) / 3.0; }
}  // namespace

EnergyBalance energy_balance(const Elements& e, const Patches& patches, const PatchTransport& transport,
                             double delivered_power, const std::vector<Rgb>& irradiance, const TexelFates& fates) {
  EnergyBalance b;
  b.measured = true;
  b.emitted = delivered_power;
  // What each patch's texels send out, emitted and reflected, from the final irradiance: the near
  // field and the final gather change what texels reflect after the patch solve.
  std::vector<double> leaving(patches.size(), 0);
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i)) continue;
    b.emitted += mean(e.emission[i]) * e.area[i];
    // Of the light arriving, a see-through texel stops its opacity's share (the rest goes on, to
    // be counted where it lands), reflects rho of it and absorbs the difference.
    const float stops = e.opacity.empty() ? 1.0f : e.opacity[i];
    Rgb absorbed = (Rgb{stops, stops, stops} - e.reflectance[i]) * irradiance[i];
    b.absorbed += mean(absorbed) * e.area[i];
    const uint32_t q = patches.patch_of_element[i];
    if (q == UINT32_MAX) continue;
    const double sends = mean(e.emission[i] + e.reflectance[i] * irradiance[i]) * e.area[i];
    if (fates.escaped.empty()) {
      leaving[q] += sends;
    } else {
      b.escaped += sends * fates.escaped[i];
      b.lost += sends * fates.lost[i];
    }
  }
  for (size_t q = 0; q < patches.size(); ++q) {
    b.escaped += leaving[q] * transport.escaped[q];
    b.lost += leaving[q] * transport.lost[q];
  }
  b.relative_error = b.emitted > 0 ? (b.emitted - b.absorbed - b.escaped - b.lost) / b.emitted : 0.0;
  return b;
}

}  // namespace radbake
