#include "baker/finish/exposure.h"

#include <cmath>

namespace radbake {
namespace {

// Reinhard's delta: keeps unlit texels (luminance 0) from sending the log-mean to zero. A
// millionth of a cd/m2 is far below anything a display shows at any exposure worth choosing.
constexpr double kLogFloor = 1e-6;

}  // namespace

Exposure choose_exposure(const std::vector<LightmapPage>& luminance, const ExposureOptions& options) {
  double log_sum = 0;
  size_t count = 0;
  for (const LightmapPage& page : luminance)
    for (size_t i = 0; i < page.texels.size(); ++i) {
      if (!page.valid[i]) continue;
      const Rgb& c = page.texels[i];
      const double y = 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;  // Rec. 709 luminance of linear RGB
      log_sum += std::log(kLogFloor + std::max(0.0, y));
      ++count;
    }
  Exposure out;
  out.log_mean_luminance = count ? std::exp(log_sum / double(count)) : 0;
  if (options.exposure > 0) {
    out.exposure = options.exposure;
    out.automatic = false;
  } else {
    out.exposure = out.log_mean_luminance > kLogFloor ? float(options.key / out.log_mean_luminance) : 1.0f;
  }
  return out;
}

}  // namespace radbake
