#include "baker/finish/lightmap_difference.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "base/errors.h"

namespace radbake {
namespace {

// In double, so that no texel above zero in some channel averages to zero.
struct ComparedTexel {
  size_t index = 0;                     // in its page
  double reference = 0, candidate = 0;  // mean of the RGB channels
  double error = 0;                     // mean of |candidate - reference| over the channels
};

double mean(Rgb c) { return (double(c.x) + double(c.y) + double(c.z)) / 3; }

void check_texels(const LightmapPage& page, size_t p, const char* which) {
  for (size_t t = 0; t < page.texels.size(); ++t) {
    const Rgb c = page.texels[t];
    if (!is_finite(c) || c.x < 0 || c.y < 0 || c.z < 0)
      throw InputError("page " + std::to_string(p) + " of the " + which + " has a negative or non-finite texel at (" +
                       std::to_string(t % size_t(page.width)) + ", " + std::to_string(t / size_t(page.width)) + ")");
  }
}

std::vector<ComparedTexel> compared_texels(const LightmapPage& a, const LightmapPage& b) {
  std::vector<ComparedTexel> out;
  for (size_t t = 0; t < a.texels.size(); ++t) {
    const Rgb ra = a.texels[t], rb = b.texels[t];
    if (max_component(ra) == 0 && max_component(rb) == 0) continue;
    const Rgb d = rb - ra;
    out.push_back({t, mean(ra), mean(rb), mean({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)})});
  }
  return out;
}

// The texel value relative errors are measured against: its own, but never below the floor.
double relative_to(double reference, const DifferenceStats& s, const DifferenceOptions& options) {
  return std::max(reference, options.relative_floor * s.reference_level);
}

DifferenceStats measure(const std::vector<ComparedTexel>& texels, const DifferenceOptions& options) {
  DifferenceStats s;
  s.texels = texels.size();
  if (texels.empty()) return s;
  double sum_a = 0, sum_b = 0, sum_squared = 0;
  for (const ComparedTexel& t : texels) {
    sum_a += t.reference;
    sum_b += t.candidate;
    sum_squared += t.error * t.error;
    s.max_error = std::max(s.max_error, t.error);
  }
  // Compared texels are non-zero in A or B and nothing is negative, so one of the sums is positive.
  s.reference_level = (sum_a > 0 ? sum_a : sum_b) / double(texels.size());
  s.rmse = std::sqrt(sum_squared / double(texels.size())) / s.reference_level;
  std::vector<double> relative(texels.size());
  for (size_t i = 0; i < texels.size(); ++i) relative[i] = texels[i].error / relative_to(texels[i].reference, s, options);
  std::sort(relative.begin(), relative.end());
  // Nearest rank, ceil(percent / 100 x n), in integers so that 95% of 100 texels is rank 95.
  auto percentile = [&](size_t percent) { return relative[(percent * relative.size() + 99) / 100 - 1]; };
  s.p50 = percentile(50);
  s.p95 = percentile(95);
  s.p99 = percentile(99);
  return s;
}

std::vector<uint8_t> difference_image(const LightmapPage& a, const LightmapPage& b,
                                      const std::vector<ComparedTexel>& texels, const DifferenceStats& s,
                                      const DifferenceOptions& options) {
  std::vector<uint8_t> rgb(a.texels.size() * 3, 0);
  for (const ComparedTexel& t : texels) {
    const double signed_relative = mean(b.texels[t.index] - a.texels[t.index]) / relative_to(t.reference, s, options);
    const double k = std::clamp(signed_relative / options.image_scale, -1.0, 1.0);
    // Diverging from white: the other two channels fade as the difference grows.
    const auto fade = uint8_t(std::lround(255.0 * (1.0 - std::fabs(k))));
    uint8_t* px = &rgb[3 * t.index];
    px[0] = k > 0 ? 255 : fade;
    px[1] = fade;
    px[2] = k < 0 ? 255 : fade;
  }
  return rgb;
}

}  // namespace

LightmapDifference compare_lightmaps(const std::vector<LightmapPage>& reference,
                                     const std::vector<LightmapPage>& candidate, const DifferenceOptions& options) {
  assert(options.relative_floor > 0 && options.image_scale > 0);
  if (reference.size() != candidate.size())
    throw InputError("different page counts: " + std::to_string(reference.size()) + " in the reference, " +
                     std::to_string(candidate.size()) + " in the other bake");
  LightmapDifference out;
  std::vector<ComparedTexel> all;
  for (size_t p = 0; p < reference.size(); ++p) {
    const LightmapPage &a = reference[p], &b = candidate[p];
    if (a.width != b.width || a.height != b.height)
      throw InputError("page " + std::to_string(p) + " is " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                       " in the reference but " + std::to_string(b.width) + "x" + std::to_string(b.height) +
                       " in the other bake");
    assert(a.texels.size() == size_t(a.width) * size_t(a.height) && b.texels.size() == a.texels.size());
    check_texels(a, p, "reference");
    check_texels(b, p, "other bake");
    std::vector<ComparedTexel> texels = compared_texels(a, b);
    PageDifference page;
    page.width = a.width;
    page.height = a.height;
    page.stats = measure(texels, options);
    page.image = difference_image(a, b, texels, page.stats, options);
    out.pages.push_back(std::move(page));
    all.insert(all.end(), texels.begin(), texels.end());
  }
  out.all = measure(all, options);
  return out;
}

std::vector<LimitCheck> check_limits(const DifferenceStats& stats, const DifferenceLimits& limits) {
  std::vector<LimitCheck> checks;
  auto check = [&](const char* name, bool fraction, double value, const std::optional<double>& limit) {
    if (limit) checks.push_back({name, fraction, value, *limit, value > *limit});
  };
  check("rmse", true, stats.rmse, limits.rmse);
  check("p50", true, stats.p50, limits.p50);
  check("p95", true, stats.p95, limits.p95);
  check("p99", true, stats.p99, limits.p99);
  check("error", false, stats.max_error, limits.max_error);
  return checks;
}

}  // namespace radbake
