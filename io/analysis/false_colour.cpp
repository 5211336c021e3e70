#include "io/analysis/false_colour.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>

namespace radbake {
namespace {

using Colour = std::array<uint8_t, 3>;

constexpr Colour kInk = {0, 0, 0};  // legend text, ticks and the colour bar's frame

// Beyond this the image would not fit in memory comfortably (3 bytes a pixel: 192 MiB); a grid that
// large is a caller's mistake, not a picture anyone opens.
constexpr int64_t kMostGridPixels = int64_t(1) << 26;
// 10^30 is as far as a logarithmic legend can usefully reach in doubles and in tick labels.
constexpr int kMostDecades = 30;

// ---------------------------------------------------------------------------------------------
// A 5 x 7 bitmap font, only the characters legends need. '#' is ink.

constexpr int kGlyphWidth = 5;
constexpr int kGlyphHeight = 7;
constexpr int kGlyphAdvance = 6;  // one blank column between characters

struct Glyph {
  char character;
  const char* rows[kGlyphHeight];
};

// clang-format off
constexpr Glyph kGlyphs[] = {
  {'0', {".###.", "#...#", "#..##", "#.#.#", "##..#", "#...#", ".###."}},
  {'1', {"..#..", ".##..", "..#..", "..#..", "..#..", "..#..", ".###."}},
  {'2', {".###.", "#...#", "....#", "...#.", "..#..", ".#...", "#####"}},
  {'3', {"#####", "...#.", "..#..", "...#.", "....#", "#...#", ".###."}},
  {'4', {"...#.", "..##.", ".#.#.", "#..#.", "#####", "...#.", "...#."}},
  {'5', {"#####", "#....", "####.", "....#", "....#", "#...#", ".###."}},
  {'6', {"..##.", ".#...", "#....", "####.", "#...#", "#...#", ".###."}},
  {'7', {"#####", "....#", "...#.", "..#..", ".#...", ".#...", ".#..."}},
  {'8', {".###.", "#...#", "#...#", ".###.", "#...#", "#...#", ".###."}},
  {'9', {".###.", "#...#", "#...#", ".####", "....#", "...#.", ".##.."}},
  {'.', {".....", ".....", ".....", ".....", ".....", ".##..", ".##.."}},
  {'-', {".....", ".....", ".....", ".###.", ".....", ".....", "....."}},
  {'+', {".....", "..#..", "..#..", "#####", "..#..", "..#..", "....."}},
  {'%', {"##...", "##..#", "...#.", "..#..", ".#...", "#..##", "...##"}},
  {'/', {".....", "....#", "...#.", "..#..", ".#...", "#....", "....."}},
  {'c', {".....", ".....", ".###.", "#....", "#....", "#...#", ".###."}},
  {'d', {"....#", "....#", ".##.#", "#..##", "#...#", "#...#", ".####"}},
  {'e', {".....", ".....", ".###.", "#...#", "#####", "#....", ".###."}},
  {'k', {"#....", "#....", "#..#.", "#.#..", "##...", "#.#..", "#..#."}},
  // A stem with a foot, so "lx" is not read as "1x".
  {'l', {".#...", ".#...", ".#...", ".#...", ".#...", ".#...", "..##."}},
  {'m', {".....", ".....", "##.#.", "#.#.#", "#.#.#", "#...#", "#...#"}},
  {'u', {".....", ".....", "#...#", "#...#", "#...#", "#..##", ".##.#"}},
  {'x', {".....", ".....", "#...#", ".#.#.", "..#..", ".#.#.", "#...#"}},
  {' ', {".....", ".....", ".....", ".....", ".....", ".....", "....."}},
};
// A character the font lacks still shows up, so a unit like "cd/m²" is visibly wrong, not silently
// shortened.
constexpr Glyph kMissingGlyph =
  {'?', {"#####", "#...#", "#...#", "#...#", "#...#", "#...#", "#####"}};
// clang-format on

const Glyph& glyph_for(char character) {
  for (const Glyph& glyph : kGlyphs)
    if (glyph.character == character) return glyph;
  return kMissingGlyph;
}

int text_width(const std::string& text, int text_scale) {
  if (text.empty()) return 0;
  return (int(text.size()) * kGlyphAdvance - (kGlyphAdvance - kGlyphWidth)) * text_scale;
}

// ---------------------------------------------------------------------------------------------
// Drawing into an RgbImage; everything clips to the image, so a label near an edge cannot write
// outside the buffer.

void set_pixel(RgbImage& image, int x, int y, Colour colour) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
  uint8_t* pixel = &image.rgb[(size_t(y) * image.width + x) * 3];
  pixel[0] = colour[0];
  pixel[1] = colour[1];
  pixel[2] = colour[2];
}

void fill_rect(RgbImage& image, int left, int top, int width, int height, Colour colour) {
  for (int y = top; y < top + height; ++y)
    for (int x = left; x < left + width; ++x) set_pixel(image, x, y, colour);
}

void draw_text(RgbImage& image, const std::string& text, int left, int top, int text_scale, Colour colour) {
  int x = left;
  for (char character : text) {
    const Glyph& glyph = glyph_for(character);
    for (int row = 0; row < kGlyphHeight; ++row)
      for (int column = 0; column < kGlyphWidth; ++column)
        if (glyph.rows[row][column] == '#')
          fill_rect(image, x + column * text_scale, top + row * text_scale, text_scale, text_scale, colour);
    x += kGlyphAdvance * text_scale;
  }
}

// ---------------------------------------------------------------------------------------------
// Tick labels.

// Up to three significant digits, whole numbers in full (2500, not 2.5e3), no trailing zeros.
std::string format_number(double value) {
  if (value == 0) return "0";
  char text[64];
  // Only a logarithmic scale many decades deep gets here; exponent notation stays short.
  if (std::fabs(value) < 1e-4) {
    std::snprintf(text, sizeof text, "%.2g", value);
    return text;
  }
  int magnitude = int(std::floor(std::log10(std::fabs(value))));
  int decimals = std::clamp(2 - magnitude, 0, 6);
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  std::string formatted = text;
  if (formatted.find('.') != std::string::npos) {
    formatted.erase(formatted.find_last_not_of('0') + 1);
    if (formatted.back() == '.') formatted.pop_back();
  }
  return formatted;
}

// `in_thousands`: write the value as thousands with a k (10k, 12.5k), which stays short at daylight
// illuminances (100000 lx).
std::string format_tick_label(double value, bool in_thousands) {
  if (in_thousands && value >= 1000) return format_number(value / 1000) + "k";
  return format_number(value);
}

bool nearly_equal(double a, double b) { return std::fabs(a - b) <= 1e-9 * std::max(std::fabs(a), std::fabs(b)); }

void check_scale(const FalseColourScale& scale) {
  if (!std::isfinite(scale.max) || scale.max < 0)
    throw std::invalid_argument("false colour: the scale's max must be 0 (automatic) or a positive number, not " +
                                std::to_string(scale.max));
  if (scale.logarithmic && (scale.decades < 1 || scale.decades > kMostDecades))
    throw std::invalid_argument("false colour: a logarithmic scale spans 1 to " + std::to_string(kMostDecades) +
                                " decades, not " + std::to_string(scale.decades));
}

// ---------------------------------------------------------------------------------------------
// The legend's layout. Every length is a multiple of the text scale, so the legend grows with the
// image instead of turning into specks next to a large grid.

struct LegendLayout {
  int text_scale = 1;
  int left = 0;  // first column of the legend strip (after the grid)
  int width = 0;
  int minimum_height = 0;  // the image is at least this tall so 6 labels fit beside the bar
  PixelRect bar;
  int heading_top = 0;
  int label_left = 0;
  int tick_left = 0, tick_length = 0;
};

LegendLayout lay_out_legend(int grid_pixel_width, int grid_pixel_height, const std::string& unit,
                            const std::vector<LegendTick>& ticks) {
  LegendLayout layout;
  // 1 up to a grid 240 pixels tall, then a step up for each further 120, so labels stay about as
  // readable as the cells next to them.
  layout.text_scale = std::clamp(grid_pixel_height / 120, 1, 4);
  const int s = layout.text_scale;
  const int gap_after_grid = grid_pixel_width > 0 ? 8 * s : 4 * s;
  const int frame = 1;  // the black outline around the bar, so its near-black bottom has an edge
  layout.left = grid_pixel_width;
  layout.heading_top = 4 * s;
  layout.bar.x = grid_pixel_width + gap_after_grid + frame;
  // Below the unit, with room for the top label, which is centred on the bar's top row.
  layout.bar.y = layout.heading_top + kGlyphHeight * s + 6 * s;
  layout.bar.width = 10 * s;
  const int bottom_margin = 8 * s;
  // Six labels with 5 scaled pixels between them.
  const int minimum_bar_height = 6 * (kGlyphHeight + 5) * s;
  layout.minimum_height = layout.bar.y + minimum_bar_height + bottom_margin;
  layout.bar.height = std::max(grid_pixel_height, layout.minimum_height) - layout.bar.y - bottom_margin;
  layout.tick_left = layout.bar.x + layout.bar.width + frame;
  // A short notch on the frame, then a clear gap: a tick that runs into its label reads as a minus
  // sign ("-5").
  layout.tick_length = 2 * s;
  layout.label_left = layout.tick_left + layout.tick_length + 4 * s;
  int widest_label = 0;
  for (const LegendTick& tick : ticks) widest_label = std::max(widest_label, text_width(tick.label, s));
  int right = std::max(layout.label_left + widest_label, layout.bar.x + text_width(unit, s));
  layout.width = right + 6 * s - layout.left;
  return layout;
}

// The bar's row that shows `fraction` of the scale: the top row is exactly 1, the bottom row 0.
int bar_row(const PixelRect& bar, double fraction) {
  return bar.y + int(std::lround((1 - fraction) * (bar.height - 1)));
}

void draw_legend(RgbImage& image, const LegendLayout& layout, const FalseColourScale& scale, double max,
                 const std::vector<LegendTick>& ticks) {
  const int s = layout.text_scale;
  const PixelRect& bar = layout.bar;
  fill_rect(image, bar.x - 1, bar.y - 1, bar.width + 2, bar.height + 2, kInk);
  for (int row = 0; row < bar.height; ++row) {
    double fraction = 1 - double(row) / (bar.height - 1);
    fill_rect(image, bar.x, bar.y + row, bar.width, 1, turbo_colour(fraction));
  }
  draw_text(image, scale.unit, bar.x, layout.heading_top, s, kInk);

  // The ends first, so they keep their labels; an inner label that would touch one already placed
  // keeps its tick mark but loses its text.
  std::vector<size_t> order;
  if (!ticks.empty()) {
    order.push_back(0);
    if (ticks.size() > 1) order.push_back(ticks.size() - 1);
    for (size_t i = 1; i + 1 < ticks.size(); ++i) order.push_back(i);
  }
  const int label_height = kGlyphHeight * s;
  const int least_gap = 2 * s;
  std::vector<int> placed_tops;
  for (size_t index : order) {
    const LegendTick& tick = ticks[index];
    int row = bar_row(bar, scale_fraction(tick.value, scale, max));
    fill_rect(image, layout.tick_left, row, layout.tick_length, std::max(1, s / 2), kInk);
    int top = row - label_height / 2;
    bool overlaps = std::any_of(placed_tops.begin(), placed_tops.end(), [&](int other) {
      return std::abs(other - top) < label_height + least_gap;
    });
    if (overlaps) continue;
    placed_tops.push_back(top);
    draw_text(image, tick.label, layout.label_left, top, s, kInk);
  }
}

}  // namespace

// ---------------------------------------------------------------------------------------------

std::array<uint8_t, 3> turbo_colour(double fraction) {
  // The polynomial approximation published with turbo (Ruofei Du and Anton Mikhailov, 2019,
  // gist.github.com/mikhailov-work/0d177465a8151eb6ede1768d51d476c7): each channel is a degree-5
  // polynomial in x, coefficients from x^0 up. It strays up to a few percent outside [0, 1] near the
  // ends (blue at x = 1 is -0.03), hence the clamp.
  static constexpr double kRed[6] = {0.13572138, 4.61539260, -42.66032258, 132.13108234, -152.94239396, 59.28637943};
  static constexpr double kGreen[6] = {0.09140261, 2.19418839, 4.84296658, -14.18503333, 4.27729857, 2.82956604};
  static constexpr double kBlue[6] = {0.10667330, 12.64194608, -60.58204836, 110.36276771, -89.90310912, 27.34824973};
  double x = std::isnan(fraction) ? 0.0 : std::clamp(fraction, 0.0, 1.0);
  auto channel = [x](const double (&coefficients)[6]) {
    double sum = 0;
    for (int power = 5; power >= 0; --power) sum = sum * x + coefficients[power];  // Horner
    return uint8_t(std::lround(std::clamp(sum, 0.0, 1.0) * 255));
  };
  return {channel(kRed), channel(kGreen), channel(kBlue)};
}

double scale_fraction(double value, const FalseColourScale& scale, double max) {
  if (std::isnan(value)) return value;
  if (value <= 0) return 0;
  if (!scale.logarithmic) return std::min(value / max, 1.0);
  return std::clamp(1 + std::log10(value / max) / scale.decades, 0.0, 1.0);
}

double nice_number_at_or_above(double value) {
  if (!(value > 0) || !std::isfinite(value))
    throw std::invalid_argument("nice_number_at_or_above needs a positive finite value, not " + std::to_string(value));
  int exponent = int(std::floor(std::log10(value)));
  for (double mantissa : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    // Dividing by an exact power of ten keeps 0.0025 the double nearest 0.0025.
    double candidate = exponent >= 0 ? mantissa * std::pow(10.0, exponent) : mantissa / std::pow(10.0, -exponent);
    // The tolerance absorbs log10 and pow rounding, so 0.2 stays 0.2 instead of becoming 0.25.
    if (candidate >= value * (1 - 1e-12)) return candidate;
  }
  return 10 * std::pow(10.0, exponent);  // not reached: 10 x 10^exponent > value by construction
}

double automatic_scale_max(const std::vector<float>& values) {
  std::vector<float> finite;
  finite.reserve(values.size());
  for (float value : values)
    if (std::isfinite(value)) finite.push_back(value);
  if (finite.empty()) return 1;
  // Nearest rank: the smallest value with at least 99 % of the values at or below it.
  size_t rank = (99 * finite.size() + 99) / 100;  // ceil(0.99 n), in integers so n = 100 gives 99
  auto percentile = finite.begin() + (rank - 1);
  std::nth_element(finite.begin(), percentile, finite.end());
  if (!(*percentile > 0)) return 1;
  return nice_number_at_or_above(*percentile);
}

std::vector<LegendTick> legend_ticks(const FalseColourScale& scale, double max) {
  std::vector<double> values;
  bool in_thousands = false;
  if (!scale.logarithmic) {
    // The smallest nice step that needs at most 5 intervals: a nice max then gets 5 or 6 ticks.
    double step = nice_number_at_or_above(max / 5);
    int intervals = int(std::floor(max / step + 1e-9));
    for (int i = 0; i <= intervals; ++i) values.push_back(i * step);
    if (!nearly_equal(values.back(), max)) values.push_back(max);
    else values.back() = max;
    // Either every label from 1000 up has a k or none does: "5000, 10k" reads as two scales.
    in_thousands = max >= 10000;
  } else {
    double bottom = max / std::pow(10.0, scale.decades);
    values.push_back(bottom);
    int first_power = int(std::ceil(std::log10(bottom) - 1e-9));
    int last_power = int(std::floor(std::log10(max) + 1e-9));
    for (int power = first_power; power <= last_power; ++power) {
      double decade = power >= 0 ? std::pow(10.0, power) : 1 / std::pow(10.0, -power);
      if (!nearly_equal(decade, bottom) && !nearly_equal(decade, max) && decade > bottom && decade < max)
        values.push_back(decade);
    }
    values.push_back(max);
  }
  std::vector<LegendTick> ticks;
  for (double value : values) {
    // On a log scale each label stands alone, so k only from 10000 up (100, 1000, 10k).
    bool thousands = scale.logarithmic ? value >= 10000 : in_thousands;
    ticks.push_back({value, format_tick_label(value, thousands)});
  }
  return ticks;
}

void label_cell(RgbImage& image, const std::string& text, int column, int row, int cell_pixels) {
  const int text_scale = cell_pixels >= 16 ? 2 : 1, margin = text_scale;
  const int width = text_width(text, text_scale), height = kGlyphHeight * text_scale;
  const int left = column * cell_pixels + cell_pixels / 2 - width / 2, top = row * cell_pixels + cell_pixels / 2 - height / 2;
  fill_rect(image, left - margin, top - margin, width + 2 * margin, height + 2 * margin, {0, 0, 0});
  draw_text(image, text, left, top, text_scale, {255, 255, 255});
}

FalseColourResult false_colour(const std::vector<float>& values, int width, int height,
                               const FalseColourScale& scale, int cell_pixels) {
  check_scale(scale);
  if (width < 0 || height < 0)
    throw std::invalid_argument("false colour: a grid of " + std::to_string(width) + " x " + std::to_string(height));
  if (values.size() != size_t(width) * size_t(height))
    throw std::invalid_argument("false colour: " + std::to_string(values.size()) + " values for a grid of " +
                                std::to_string(width) + " x " + std::to_string(height));
  if (cell_pixels < 1)
    throw std::invalid_argument("false colour: cell_pixels must be at least 1, not " + std::to_string(cell_pixels));
  const int64_t grid_pixel_width = int64_t(width) * cell_pixels, grid_pixel_height = int64_t(height) * cell_pixels;
  if (grid_pixel_width * grid_pixel_height > kMostGridPixels || grid_pixel_width > kMostGridPixels ||
      grid_pixel_height > kMostGridPixels)
    throw std::invalid_argument("false colour: " + std::to_string(grid_pixel_width) + " x " +
                                std::to_string(grid_pixel_height) + " pixels is too large an image");

  FalseColourResult result;
  result.max = scale.max > 0 ? scale.max : automatic_scale_max(values);
  const std::vector<LegendTick> ticks = legend_ticks(scale, result.max);
  const LegendLayout layout = lay_out_legend(int(grid_pixel_width), int(grid_pixel_height), scale.unit, ticks);

  RgbImage& image = result.image;
  image.width = layout.left + layout.width;
  image.height = std::max(int(grid_pixel_height), layout.minimum_height);
  image.rgb.assign(size_t(image.width) * image.height * 3, 255);  // white: the legend's background

  for (int row = 0; row < height; ++row)
    for (int column = 0; column < width; ++column) {
      float value = values[size_t(row) * width + column];
      Colour colour = std::isnan(value) ? kNoDataColour : turbo_colour(scale_fraction(value, scale, result.max));
      fill_rect(image, column * cell_pixels, row * cell_pixels, cell_pixels, cell_pixels, colour);
    }
  draw_legend(image, layout, scale, result.max, ticks);
  result.colour_bar = layout.bar;
  return result;
}

}  // namespace radbake
