#include "baker/energy_balance.h"

namespace radbake {
namespace {
double mean(Rgb v) { return (double(v.x) + v.y + v.z) / 3.0; }
}  // namespace

EnergyBalance energy_balance(const Elements& e, const Patches& patches, const PatchTransport& transport,
                             const std::vector<Rgb>& patch_reflected_exitance, double punctual_power,
                             const std::vector<Rgb>& irradiance) {
  EnergyBalance b;
  b.measured = true;
  b.emitted = punctual_power;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i)) continue;
    b.emitted += mean(e.emission[i]) * e.area[i];
    Rgb absorbed = (Rgb{1, 1, 1} - e.reflectance[i]) * irradiance[i];
    b.absorbed += mean(absorbed) * e.area[i];
  }
  for (size_t q = 0; q < patches.size(); ++q) {
    double leaving = mean(patches.emission[q] + patch_reflected_exitance[q]) * patches.area[q];
    b.escaped += leaving * transport.escaped[q];
    b.lost += leaving * transport.lost[q];
  }
  b.relative_error = b.emitted > 0 ? (b.emitted - b.absorbed - b.escaped - b.lost) / b.emitted : 0.0;
  return b;
}

}  // namespace radbake
