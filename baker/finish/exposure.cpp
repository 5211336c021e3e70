#include "baker/finish/exposure.h"

#include <algorithm>
#include <cstdio>

namespace radbake {
namespace {

// Lit: within ten stops of the highlights. What is darker shows black at any exposure that keeps
// the highlights, so metering it would only pull the median down.
constexpr double kLitFraction = 1e-3;
constexpr double kHighlightQuantile = 0.99;

double luminance_of(const Rgb& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }  // Rec. 709
double brightest_channel(const Rgb& c) { return std::max({double(c.x), double(c.y), double(c.z)}); }

// The q-quantile of `values` (reordered), 0 when empty.
double quantile(std::vector<double>& values, double q) {
  if (values.empty()) return 0;
  const size_t k = std::min(values.size() - 1, size_t(q * double(values.size())));
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
  return values[k];
}

}  // namespace

Exposure choose_exposure(const std::vector<LightmapPage>& luminance, const ExposureOptions& options) {
  std::vector<double> all;
  for (const LightmapPage& page : luminance)
    for (size_t i = 0; i < page.texels.size(); ++i)
      if (page.valid[i]) all.push_back(std::max(0.0, luminance_of(page.texels[i])));
  const size_t covered = all.size();
  const double lit_floor = kLitFraction * quantile(all, kHighlightQuantile);
  std::vector<double> lit, lit_channel;
  for (const LightmapPage& page : luminance)
    for (size_t i = 0; i < page.texels.size(); ++i) {
      if (!page.valid[i]) continue;
      const double y = luminance_of(page.texels[i]);
      if (!(y > lit_floor)) continue;
      lit.push_back(y);
      lit_channel.push_back(brightest_channel(page.texels[i]));
    }
  Exposure out;
  out.lit_share = covered ? double(lit.size()) / double(covered) : 0;
  out.median_lit_luminance = quantile(lit, 0.5);
  out.highlight_channel = quantile(lit_channel, 1.0 - double(options.max_clipped_share));
  char method[240];
  if (options.exposure > 0) {
    out.exposure = options.exposure;
    out.automatic = false;
    std::snprintf(method, sizeof method, "given (--exposure)");
  } else if (out.median_lit_luminance <= 0) {
    out.exposure = 1;
    std::snprintf(method, sizeof method, "nothing is lit: 1 per cd/m2");
  } else {
    const double at_key = options.key / out.median_lit_luminance;
    const double at_highlights = out.highlight_channel > 0 ? 1.0 / out.highlight_channel : at_key;
    out.limited_by_highlights = at_highlights < at_key;
    out.exposure = float(std::min(at_key, at_highlights));
    if (out.limited_by_highlights)
      std::snprintf(method, sizeof method,
                    "automatic: the brightest %.3g%% of the lit area set it (at the key %.3g the median "
                    "lit surface would have clipped more)",
                    100.0 * options.max_clipped_share, options.key);
    else
      std::snprintf(method, sizeof method,
                    "automatic: the median lit surface (%.3g%% of the covered area is lit) shows at the key %.3g",
                    100.0 * out.lit_share, options.key);
  }
  out.method = method;
  return out;
}

}  // namespace radbake
