// Comparing two bakes: statistics with known answers on hand-made pages, the false-colour image,
// and the thresholds.
#include <gtest/gtest.h>

#include <cmath>

#include "baker/finish/lightmap_difference.h"
#include "base/errors.h"

namespace radbake {
namespace {

// Sums of float texels in double: the statistics match the exact answers to this (relative) much.
constexpr double kRounding = 1e-6;

LightmapPage page_of(int width, int height, Rgb value) {
  LightmapPage page;
  page.width = width;
  page.height = height;
  page.texels.assign(size_t(width) * size_t(height), value);
  page.valid.assign(page.texels.size(), 1);
  return page;
}

DifferenceStats stats_of(const LightmapPage& a, const LightmapPage& b, const DifferenceOptions& options = {}) {
  return compare_lightmaps({a}, {b}, options).all;
}

TEST(LightmapDifference, IdenticalPagesDifferByNothing) {
  LightmapPage a = page_of(8, 4, {300, 200, 100});
  a.texels[5] = {1000, 10, 0};
  DifferenceStats s = stats_of(a, a);
  EXPECT_EQ(s.texels, 32u);
  EXPECT_EQ(s.rmse, 0);
  EXPECT_EQ(s.max_error, 0);
  EXPECT_EQ(s.p50, 0);
  EXPECT_EQ(s.p99, 0);
}

TEST(LightmapDifference, AUniformOffsetIsItsOwnRmseAndEveryPercentile) {
  DifferenceStats s = stats_of(page_of(4, 4, {100, 100, 100}), page_of(4, 4, {110, 110, 110}));
  EXPECT_EQ(s.texels, 16u);
  EXPECT_NEAR(s.reference_level, 100, 100 * kRounding);
  EXPECT_NEAR(s.rmse, 0.10, kRounding);
  EXPECT_NEAR(s.max_error, 10, 10 * kRounding);
  EXPECT_NEAR(s.p50, 0.10, kRounding);
  EXPECT_NEAR(s.p95, 0.10, kRounding);
  EXPECT_NEAR(s.p99, 0.10, kRounding);
}

TEST(LightmapDifference, TexelsZeroInBothAreLeftOut) {
  LightmapPage a = page_of(4, 4, {100, 100, 100}), b = page_of(4, 4, {110, 110, 110});
  for (size_t t = 0; t < 8; ++t) a.texels[t] = b.texels[t] = {0, 0, 0};
  a.texels[8] = {0, 0, 0};  // zero in A only: compared
  DifferenceStats s = stats_of(a, b);
  EXPECT_EQ(s.texels, 8u);
  EXPECT_NEAR(s.reference_level, 700.0 / 8, 100 * kRounding);
  EXPECT_NEAR(s.max_error, 110, 110 * kRounding);
}

TEST(LightmapDifference, ErrorIsTheMeanOfTheChannelsAbsoluteDifferences) {
  // A colour shift at equal brightness is an error of 20 lux, though the mean is unchanged.
  DifferenceStats s = stats_of(page_of(2, 2, {100, 100, 100}), page_of(2, 2, {130, 100, 70}));
  EXPECT_NEAR(s.max_error, 20, 20 * kRounding);
  EXPECT_NEAR(s.rmse, 0.20, kRounding);
}

TEST(LightmapDifference, DarkTexelsAreMeasuredAgainstTheFloor) {
  // Texels 100, 100, 100, 0 in A; the dark one is 5 in B. Reference level 75, floor 7.5.
  LightmapPage a = page_of(4, 1, {100, 100, 100}), b = a;
  a.texels[3] = {0, 0, 0};
  b.texels[3] = {5, 5, 5};
  DifferenceStats s = stats_of(a, b);
  EXPECT_EQ(s.texels, 4u);
  EXPECT_NEAR(s.reference_level, 75, 75 * kRounding);
  EXPECT_NEAR(s.p99, 5.0 / 7.5, kRounding);  // not 5 / 0
  EXPECT_EQ(s.p50, 0);
  EXPECT_NEAR(s.rmse, std::sqrt(25.0 / 4) / 75, kRounding);
  DifferenceOptions lower;
  lower.relative_floor = 0.01;
  EXPECT_NEAR(stats_of(a, b, lower).p99, 5.0 / 0.75, kRounding);
}

TEST(LightmapDifference, PercentilesAreByNearestRank) {
  // 100 texels off by 1%, 2%, ..., 100% of their value.
  LightmapPage a = page_of(10, 10, {100, 100, 100}), b = a;
  for (size_t t = 0; t < 100; ++t) b.texels[t] = Rgb{1, 1, 1} * float(101 + t);
  DifferenceStats s = stats_of(a, b);
  EXPECT_NEAR(s.p50, 0.50, kRounding);
  EXPECT_NEAR(s.p95, 0.95, kRounding);
  EXPECT_NEAR(s.p99, 0.99, kRounding);
  EXPECT_NEAR(s.max_error, 100, 100 * kRounding);
}

TEST(LightmapDifference, AllPagesPoolTheirTexels) {
  LightmapDifference d = compare_lightmaps({page_of(4, 4, {100, 100, 100}), page_of(2, 2, {100, 100, 100})},
                                           {page_of(4, 4, {110, 110, 110}), page_of(2, 2, {100, 100, 100})}, {});
  ASSERT_EQ(d.pages.size(), 2u);
  EXPECT_NEAR(d.pages[0].stats.rmse, 0.10, kRounding);
  EXPECT_EQ(d.pages[1].stats.rmse, 0);
  EXPECT_EQ(d.all.texels, 20u);
  EXPECT_NEAR(d.all.rmse, std::sqrt(16 * 100.0 / 20) / 100, kRounding);
  EXPECT_NEAR(d.all.p50, 0.10, kRounding);  // 16 of the 20 texels are 10% off
}

TEST(LightmapDifference, AllBlackReferenceIsMeasuredAgainstTheOtherBake) {
  DifferenceStats s = stats_of(page_of(2, 2, {0, 0, 0}), page_of(2, 2, {10, 10, 10}));
  EXPECT_NEAR(s.reference_level, 10, 10 * kRounding);
  EXPECT_NEAR(s.rmse, 1.0, kRounding);
  EXPECT_NEAR(s.p50, 10.0, kRounding);  // 10 lux over a floor of 10% of 10 lux
}

TEST(LightmapDifference, BothBlackComparesNothing) {
  DifferenceStats s = stats_of(page_of(2, 2, {0, 0, 0}), page_of(2, 2, {0, 0, 0}));
  EXPECT_EQ(s.texels, 0u);
  EXPECT_EQ(s.rmse, 0);
}

TEST(LightmapDifference, ImageIsWhiteWhereEqualRedWhereBrighterBlueWhereDarker) {
  LightmapPage a = page_of(5, 1, {100, 100, 100}), b = a;
  b.texels[1] = {110, 110, 110};  // +10%: full red at the default scale
  b.texels[2] = {80, 80, 80};     // -20%: beyond the scale, full blue
  b.texels[3] = {105, 105, 105};  // +5%: half way from white to red
  a.texels[4] = b.texels[4] = {0, 0, 0};  // not compared
  const std::vector<uint8_t> px = compare_lightmaps({a}, {b}, {}).pages[0].image;
  ASSERT_EQ(px.size(), 15u);
  auto rgb = [&](int t) { return std::vector<int>{px[size_t(3 * t)], px[size_t(3 * t + 1)], px[size_t(3 * t + 2)]}; };
  EXPECT_EQ(rgb(0), (std::vector<int>{255, 255, 255}));
  EXPECT_EQ(rgb(1), (std::vector<int>{255, 0, 0}));
  EXPECT_EQ(rgb(2), (std::vector<int>{0, 0, 255}));
  EXPECT_EQ(rgb(3), (std::vector<int>{255, 128, 128}));
  EXPECT_EQ(rgb(4), (std::vector<int>{0, 0, 0}));
}

TEST(LightmapDifference, MismatchedPagesAndBadTexelsAreInputErrors) {
  const LightmapPage a = page_of(4, 4, {1, 1, 1});
  EXPECT_THROW(compare_lightmaps({a}, {a, a}, {}), InputError);
  EXPECT_THROW(compare_lightmaps({a}, {page_of(4, 2, {1, 1, 1})}, {}), InputError);
  LightmapPage bad = a;
  bad.texels[3].y = std::nanf("");
  EXPECT_THROW(compare_lightmaps({a}, {bad}, {}), InputError);
  bad.texels[3].y = -1;
  EXPECT_THROW(compare_lightmaps({bad}, {a}, {}), InputError);
}

TEST(LightmapDifference, OnlySetLimitsAreCheckedAndOnlyExceededOnesFail) {
  DifferenceStats s;
  s.rmse = 0.03;
  s.p99 = 0.2;
  s.max_error = 50;
  EXPECT_TRUE(check_limits(s, {}).empty());
  DifferenceLimits limits;
  limits.rmse = 0.04;
  limits.p99 = 0.1;
  limits.max_error = 50;  // equal holds
  std::vector<LimitCheck> checks = check_limits(s, limits);
  ASSERT_EQ(checks.size(), 3u);
  EXPECT_EQ(checks[0].name, "rmse");
  EXPECT_FALSE(checks[0].exceeded);
  EXPECT_EQ(checks[1].name, "p99");
  EXPECT_TRUE(checks[1].exceeded);
  EXPECT_EQ(checks[2].name, "error");
  EXPECT_FALSE(checks[2].fraction);
  EXPECT_FALSE(checks[2].exceeded);
}

}  // namespace
}  // namespace radbake
