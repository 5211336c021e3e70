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

struct Sample {
  double value, weight;
};

// The q-quantile of the weighted `samples` (reordered): the least value with at least q of the
// weight at or below it; 0 when empty.
double quantile(std::vector<Sample>& samples, double q) {
  if (samples.empty()) return 0;
  std::sort(samples.begin(), samples.end(), [](const Sample& a, const Sample& b) { return a.value < b.value; });
  double total = 0;
  for (const Sample& s : samples) total += s.weight;
  double below = 0;
  for (const Sample& s : samples)
    if ((below += s.weight) >= q * total) return s.value;
  return samples.back().value;
}

}  // namespace

Exposure choose_exposure(const std::vector<LightmapPage>& luminance, const ExposureOptions& options,
                         const std::vector<std::vector<float>>* seen) {
  bool view = seen != nullptr;
  auto weight = [&](size_t page, size_t i) {
    return view ? (page < seen->size() && i < (*seen)[page].size() ? double((*seen)[page][i]) : 0.0) : 1.0;
  };
  std::vector<Sample> all;
  auto gather = [&] {
    for (size_t p = 0; p < luminance.size(); ++p)
      for (size_t i = 0; i < luminance[p].texels.size(); ++i)
        if (luminance[p].valid[i] && weight(p, i) > 0)
          all.push_back({std::max(0.0, luminance_of(luminance[p].texels[i])), weight(p, i)});
  };
  gather();
  // A view that sees no surface (an empty one, or a camera looking away) leaves the covered area.
  if (view && all.empty()) {
    view = false;
    gather();
  }
  double metered = 0;
  for (const Sample& s : all) metered += s.weight;
  const double lit_floor = kLitFraction * quantile(all, kHighlightQuantile);
  std::vector<Sample> lit, lit_channel;
  double lit_weight = 0;
  for (size_t p = 0; p < luminance.size(); ++p)
    for (size_t i = 0; i < luminance[p].texels.size(); ++i) {
      const double w = weight(p, i);
      if (!luminance[p].valid[i] || !(w > 0)) continue;
      const double y = luminance_of(luminance[p].texels[i]);
      if (!(y > lit_floor)) continue;
      lit.push_back({y, w});
      lit_channel.push_back({brightest_channel(luminance[p].texels[i]), w});
      lit_weight += w;
    }
  Exposure out;
  out.metered_view = view;
  out.lit_share = metered > 0 ? lit_weight / metered : 0;
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
    const char* what = view ? "of what the display camera sees" : "of the covered area";
    if (out.limited_by_highlights)
      std::snprintf(method, sizeof method,
                    "automatic: the brightest %.3g%% %s set it (at the key %.3g its median lit surface would "
                    "have clipped more)",
                    100.0 * options.max_clipped_share, what, options.key);
    else
      std::snprintf(method, sizeof method, "automatic: the median lit surface %s (%.3g%% of it is lit) shows at the key %.3g",
                    what, 100.0 * out.lit_share, options.key);
  }
  out.method = method;
  return out;
}

}  // namespace radbake
