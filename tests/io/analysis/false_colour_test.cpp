// False-colour analysis images: the colour a value gets, where it sits on the legend's bar, how the
// automatic scale is chosen, and that the legend really carries labels.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include "io/analysis/false_colour.h"

namespace radbake {
namespace {

using Colour = std::array<uint8_t, 3>;
const float kNaN = std::numeric_limits<float>::quiet_NaN();

Colour pixel(const RgbImage& image, int x, int y) {
  const uint8_t* p = &image.rgb[(size_t(y) * image.width + x) * 3];
  return {p[0], p[1], p[2]};
}

// Hue in degrees [0, 360), as HSV defines it.
double hue(Colour colour) {
  double r = colour[0] / 255.0, g = colour[1] / 255.0, b = colour[2] / 255.0;
  double high = std::max({r, g, b}), low = std::min({r, g, b}), chroma = high - low;
  if (chroma == 0) return 0;
  double h = high == r ? std::fmod((g - b) / chroma + 6, 6.0) : high == g ? (b - r) / chroma + 2 : (r - g) / chroma + 4;
  return 60 * h;
}

int channel_distance(Colour a, Colour b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

FalseColourScale linear_to(double max, std::string unit = "lx") {
  FalseColourScale scale;
  scale.max = max;
  scale.unit = unit;
  return scale;
}

FalseColourScale logarithmic_to(double max, int decades) {
  FalseColourScale scale;
  scale.logarithmic = true;
  scale.max = max;
  scale.decades = decades;
  return scale;
}

std::vector<std::string> labels_of(const std::vector<LegendTick>& ticks) {
  std::vector<std::string> labels;
  for (const LegendTick& tick : ticks) labels.push_back(tick.label);
  return labels;
}

// Pixels of the legend strip (everything right of the grid) that are ink: the text, the ticks and
// the bar's frame are pure black, which no colour of the map reaches.
int ink_pixels_right_of(const RgbImage& image, int left) {
  int count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = left; x < image.width; ++x)
      if (pixel(image, x, y) == Colour{0, 0, 0}) ++count;
  return count;
}

TEST(FalseColour, ZeroIsTheBottomColourAndMaxTheTopColour) {
  // One row: zero, max, above max, negative, +infinity.
  std::vector<float> values = {0, 1000, 5000, -20, std::numeric_limits<float>::infinity()};
  FalseColourResult result = false_colour(values, 5, 1, linear_to(1000));
  EXPECT_EQ(result.max, 1000);
  EXPECT_EQ(pixel(result.image, 0, 0), turbo_colour(0));
  EXPECT_EQ(pixel(result.image, 1, 0), turbo_colour(1));
  EXPECT_EQ(pixel(result.image, 2, 0), turbo_colour(1));  // clipped to the top
  EXPECT_EQ(pixel(result.image, 3, 0), turbo_colour(0));  // below zero: the bottom
  EXPECT_EQ(pixel(result.image, 4, 0), turbo_colour(1));
  EXPECT_NE(turbo_colour(0), turbo_colour(1));
  // The bar's ends show the same two colours.
  const PixelRect& bar = result.colour_bar;
  EXPECT_EQ(pixel(result.image, bar.x, bar.y), turbo_colour(1));
  EXPECT_EQ(pixel(result.image, bar.x + bar.width - 1, bar.y + bar.height - 1), turbo_colour(0));
}

TEST(FalseColour, TurboMatchesItsPublishedPolynomialAtTheEnds) {
  // The polynomial's constant terms (0.1357, 0.0914, 0.1067) x 255 and its sums at x = 1
  // (0.5659, 0.0505, -0.0255 clamped to 0) x 255, rounded: a check that the coefficients were
  // copied in the right order, not a tolerance.
  EXPECT_EQ(turbo_colour(0), (Colour{35, 23, 27}));
  EXPECT_EQ(turbo_colour(1), (Colour{144, 13, 0}));
  EXPECT_EQ(turbo_colour(-3), turbo_colour(0));  // clamped
  EXPECT_EQ(turbo_colour(7), turbo_colour(1));
}

TEST(FalseColour, ColourMapRunsFromBlueThroughGreenToRed) {
  // Hue falls steadily from blue (~250 degrees) through cyan, green and yellow to red (~5 degrees)
  // above 5 % of the scale; below that the map darkens to near black, where hue means little.
  double previous_hue = 360;
  for (int step = 1; step <= 20; ++step) {
    double fraction = step * 0.05;
    double h = hue(turbo_colour(fraction));
    EXPECT_LT(h, previous_hue) << "at " << fraction;
    previous_hue = h;
  }
  auto dominant = [](Colour c) { return int(std::max_element(c.begin(), c.end()) - c.begin()); };
  EXPECT_EQ(dominant(turbo_colour(0.1)), 2);  // blue low on the scale
  EXPECT_EQ(dominant(turbo_colour(0.4)), 1);  // green in the middle
  EXPECT_EQ(dominant(turbo_colour(0.9)), 0);  // red at the top
}

TEST(FalseColour, DistinctLevelsGetDistinctColours) {
  // 64 evenly spaced levels, as many as anyone tells apart on a legend, all distinct at 8 bits.
  std::set<Colour> colours;
  for (int level = 0; level < 64; ++level) colours.insert(turbo_colour(level / 63.0));
  EXPECT_EQ(colours.size(), 64u);
}

TEST(FalseColour, NoDataCellsAreGrey) {
  std::vector<float> values = {kNaN, 500, 0, kNaN};
  FalseColourResult result = false_colour(values, 2, 2, linear_to(1000));
  EXPECT_EQ(pixel(result.image, 0, 0), kNoDataColour);
  EXPECT_EQ(pixel(result.image, 1, 1), kNoDataColour);
  EXPECT_EQ(pixel(result.image, 1, 0), turbo_colour(0.5));
  // No level of the map comes within 40 of the grey in some channel: bounds how easily a missing
  // cell could be mistaken for a value (the map's near-black bottom is 93 away).
  for (int level = 0; level <= 255; ++level)
    EXPECT_GT(channel_distance(turbo_colour(level / 255.0), kNoDataColour), 40) << "level " << level;
}

TEST(FalseColour, CellPixelsScaleTheGridExactly) {
  std::vector<float> values = {0, 100, 200, 300, 400, kNaN};
  const int cell = 5;
  FalseColourResult small = false_colour(values, 3, 2, linear_to(400), 1);
  FalseColourResult large = false_colour(values, 3, 2, linear_to(400), cell);
  for (int y = 0; y < 2 * cell; ++y)
    for (int x = 0; x < 3 * cell; ++x)
      ASSERT_EQ(pixel(large.image, x, y), pixel(small.image, x / cell, y / cell)) << x << ", " << y;
  // The grid ends exactly at 3 x 5 columns: the next column is the legend's white gap.
  EXPECT_EQ(pixel(large.image, 3 * cell, 0), (Colour{255, 255, 255}));
  EXPECT_EQ(large.colour_bar.x - small.colour_bar.x, 3 * (cell - 1));
}

TEST(FalseColour, NiceNumbersAreOneTwoTwoAndAHalfOrFive) {
  EXPECT_EQ(nice_number_at_or_above(1000), 1000);
  EXPECT_EQ(nice_number_at_or_above(1001), 2000);
  EXPECT_EQ(nice_number_at_or_above(2400), 2500);
  EXPECT_EQ(nice_number_at_or_above(3), 5);
  EXPECT_EQ(nice_number_at_or_above(5.01), 10);
  EXPECT_DOUBLE_EQ(nice_number_at_or_above(0.2), 0.2);  // not pushed up to 0.25 by rounding
  EXPECT_DOUBLE_EQ(nice_number_at_or_above(0.21), 0.25);
  EXPECT_THROW(nice_number_at_or_above(0), std::invalid_argument);
}

TEST(FalseColour, AutomaticMaxIsTheNiceNumberAtOrAboveThe99thPercentile) {
  // 1, 2, ..., 1000 scaled by 0.7: the 99th percentile (nearest rank, the 990th) is 693.
  std::vector<float> values;
  for (int i = 1; i <= 1000; ++i) values.push_back(0.7f * i);
  values.push_back(kNaN);  // no data does not count
  const double percentile = 0.7f * 990;
  FalseColourResult result = false_colour(values, int(values.size()), 1, linear_to(0));
  EXPECT_EQ(result.max, 1000);
  EXPECT_GE(result.max, percentile);
  EXPECT_LT(500, percentile);  // and 1000 is the smallest nice number that covers it

  // A few hot cells beside a lamp (1 % of them) do not set the scale.
  std::vector<float> room(990, 300.0f);
  room.insert(room.end(), 10, 200000.0f);
  EXPECT_EQ(automatic_scale_max(room), 500);

  // Daylight factors in %: 99th percentile 3.2 -> 5.
  std::vector<float> daylight(100, 1.0f);
  std::fill(daylight.begin() + 50, daylight.end(), 3.2f);
  EXPECT_EQ(automatic_scale_max(daylight), 5);
}

TEST(FalseColour, LogScalePutsATenthOfMaxOneDecadeBelowTheTop) {
  const int decades = 3;
  FalseColourScale scale = logarithmic_to(2000, decades);
  const double expected_fraction = double(decades - 1) / decades;
  EXPECT_NEAR(scale_fraction(200, scale, 2000), expected_fraction, 1e-12);  // 1e-12: log10 rounding
  EXPECT_EQ(scale_fraction(2, scale, 2000), 0);                              // the floor, max / 10^3
  EXPECT_EQ(scale_fraction(0.5, scale, 2000), 0);                            // below the floor
  EXPECT_EQ(scale_fraction(2000, scale, 2000), 1);

  // On the image: the cell holding max / 10 has the colour the bar shows (decades - 1) / decades of
  // the way up.
  FalseColourResult result = false_colour({200.0f, 2.0f, 2000.0f}, 3, 1, scale, 4);
  Colour tenth = pixel(result.image, 0, 0);
  EXPECT_EQ(tenth, turbo_colour(expected_fraction));
  EXPECT_EQ(pixel(result.image, 4, 0), turbo_colour(0));
  EXPECT_EQ(pixel(result.image, 8, 0), turbo_colour(1));
  const PixelRect& bar = result.colour_bar;
  int nearest_row = bar.y;
  for (int row = bar.y; row < bar.y + bar.height; ++row)
    if (channel_distance(pixel(result.image, bar.x, row), tenth) <
        channel_distance(pixel(result.image, bar.x, nearest_row), tenth))
      nearest_row = row;
  double expected_row = bar.y + (1 - expected_fraction) * (bar.height - 1);
  // 1 row: the bar quantises the scale to whole pixel rows.
  EXPECT_NEAR(nearest_row, expected_row, 1.0);
}

TEST(FalseColour, LegendTicksAreRoundNumbers) {
  using Labels = std::vector<std::string>;
  EXPECT_EQ(labels_of(legend_ticks(linear_to(1000), 1000)), (Labels{"0", "200", "400", "600", "800", "1000"}));
  EXPECT_EQ(labels_of(legend_ticks(linear_to(2500), 2500)), (Labels{"0", "500", "1000", "1500", "2000", "2500"}));
  EXPECT_EQ(labels_of(legend_ticks(linear_to(20000), 20000)), (Labels{"0", "5k", "10k", "15k", "20k"}));
  EXPECT_EQ(labels_of(legend_ticks(linear_to(5, "%"), 5)), (Labels{"0", "1", "2", "3", "4", "5"}));
  EXPECT_EQ(labels_of(legend_ticks(linear_to(1), 1)), (Labels{"0", "0.2", "0.4", "0.6", "0.8", "1"}));
  // A max the caller chose that is not a multiple of the step still labels the top.
  EXPECT_EQ(labels_of(legend_ticks(linear_to(730), 730)), (Labels{"0", "200", "400", "600", "730"}));
  EXPECT_EQ(labels_of(legend_ticks(logarithmic_to(1000, 3), 1000)), (Labels{"1", "10", "100", "1000"}));
  EXPECT_EQ(labels_of(legend_ticks(logarithmic_to(2500, 3), 2500)), (Labels{"2.5", "10", "100", "1000", "2500"}));
  EXPECT_EQ(labels_of(legend_ticks(logarithmic_to(100000, 4), 100000)), (Labels{"10", "100", "1000", "10k", "100k"}));
  EXPECT_EQ(labels_of(legend_ticks(logarithmic_to(1, 3), 1)), (Labels{"0.001", "0.01", "0.1", "1"}));
}

TEST(FalseColour, LegendLabelsAreDrawn) {
  std::vector<float> values(40 * 30, 250.0f);
  FalseColourResult low = false_colour(values, 40, 30, linear_to(1000), 4);
  FalseColourResult high = false_colour(values, 40, 30, linear_to(5000), 4);
  const int grid_width = 40 * 4;
  ASSERT_EQ(low.image.width, high.image.width);  // "1000" and "5000" are as wide
  ASSERT_EQ(low.image.height, high.image.height);

  // Ink right of the bar and its ticks is text. Six labels of 3 or 4 glyphs, each glyph at least
  // 7 inked cells (the "1") at a text scale of s x s pixels: 6 x 3 x 7 is a floor any drawn text
  // passes and a frame or ticks alone do not reach.
  const int text_scale = std::max(1, 30 * 4 / 120);
  int right_of_ticks = low.colour_bar.x + low.colour_bar.width + 4 * text_scale;
  EXPECT_GT(ink_pixels_right_of(low.image, right_of_ticks), 6 * 3 * 7 * text_scale * text_scale);
  // The unit above the bar is drawn too.
  int ink_above_bar = 0;
  for (int y = 0; y < low.colour_bar.y - 1; ++y)
    for (int x = grid_width; x < low.image.width; ++x) ink_above_bar += pixel(low.image, x, y) == Colour{0, 0, 0};
  EXPECT_GT(ink_above_bar, 0);

  // A different max draws different labels: the legends differ, the grids' colours differ too.
  int differing_legend_pixels = 0;
  for (int y = 0; y < low.image.height; ++y)
    for (int x = right_of_ticks; x < low.image.width; ++x)
      differing_legend_pixels += pixel(low.image, x, y) != pixel(high.image, x, y);
  EXPECT_GT(differing_legend_pixels, 0);

  // Everything in the legend strip is white, ink or a colour of the bar: no stray pixels.
  for (int y = 0; y < low.image.height; ++y)
    for (int x = grid_width; x < low.image.width; ++x) {
      Colour c = pixel(low.image, x, y);
      bool in_bar = x >= low.colour_bar.x && x < low.colour_bar.x + low.colour_bar.width && y >= low.colour_bar.y &&
                    y < low.colour_bar.y + low.colour_bar.height;
      if (!in_bar) {
        ASSERT_TRUE(c == (Colour{255, 255, 255}) || c == (Colour{0, 0, 0})) << x << ", " << y;
      }
    }
}

TEST(FalseColour, SmallGridGetsALegendTallEnoughToRead) {
  // A 2 x 1 grid is 2 pixels tall; the image grows to the legend's height, white under the grid.
  FalseColourResult result = false_colour({100.0f, 900.0f}, 2, 1, linear_to(1000));
  EXPECT_GE(result.colour_bar.height, 6 * 12);  // room for six 7-pixel labels 5 pixels apart
  EXPECT_EQ(pixel(result.image, 0, 1), (Colour{255, 255, 255}));
  EXPECT_EQ(pixel(result.image, 1, 0), turbo_colour(0.9));
}

TEST(FalseColour, ManyDecadesOnASmallImageDoNotCrash) {
  // 13 ticks on a 72-row bar: some labels are left out rather than overprinted.
  FalseColourResult result = false_colour({1e5f, 1.0f}, 2, 1, logarithmic_to(1e5, 12));
  EXPECT_GT(ink_pixels_right_of(result.image, result.colour_bar.x + result.colour_bar.width), 0);
}

TEST(FalseColour, EmptyOrAllNoDataGridsGiveALegendForMaxOne) {
  // Empty: the legend alone, for the automatic fallback max of 1.
  FalseColourResult empty = false_colour({}, 0, 0, linear_to(0));
  EXPECT_EQ(empty.max, 1);
  EXPECT_GT(empty.image.width, 0);
  EXPECT_GT(empty.image.height, 0);
  EXPECT_EQ(empty.image.rgb.size(), size_t(empty.image.width) * empty.image.height * 3);
  EXPECT_GT(ink_pixels_right_of(empty.image, 0), 0);

  // All no data: grey cells and the same fallback max; all zero likewise.
  FalseColourResult no_data = false_colour(std::vector<float>(6, kNaN), 3, 2, linear_to(0), 2);
  EXPECT_EQ(no_data.max, 1);
  EXPECT_EQ(pixel(no_data.image, 5, 3), kNoDataColour);
  EXPECT_EQ(false_colour(std::vector<float>(6, 0.0f), 3, 2, linear_to(0)).max, 1);
  FalseColourScale log_scale = logarithmic_to(0, 3);
  EXPECT_EQ(false_colour(std::vector<float>(6, kNaN), 3, 2, log_scale).max, 1);
}

TEST(FalseColour, BadArgumentsAreRefused) {
  std::vector<float> values(6, 1.0f);
  EXPECT_THROW(false_colour(values, 4, 2, linear_to(1)), std::invalid_argument);     // 6 values for 8 cells
  EXPECT_THROW(false_colour(values, 3, 2, linear_to(1), 0), std::invalid_argument);  // cell_pixels < 1
  EXPECT_THROW(false_colour(values, 3, 2, linear_to(-5)), std::invalid_argument);
  EXPECT_THROW(false_colour(values, 3, 2, linear_to(std::nan(""))), std::invalid_argument);
  EXPECT_THROW(false_colour(values, 3, 2, logarithmic_to(100, 0)), std::invalid_argument);
  EXPECT_THROW(false_colour(values, 3, 2, linear_to(1), 100000), std::invalid_argument);  // 300000 x 200000 px
}

}  // namespace
}  // namespace radbake
