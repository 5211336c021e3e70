// False-colour images of a grid of values (illuminance in lux, daylight factor in %) with a legend,
// for lighting analysis: which desk gets 500 lx is read off the colour, not guessed from a grey
// lightmap. Plain data in and out; callers write the PNG with encode_png (io/lightmaps/lightmap_images.h).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace radbake {

struct FalseColourScale {
  // false: linear from 0 (bottom colour) to `max` (top colour).
  // true: logarithmic over `decades` decades below `max`, so max / 10^decades is the bottom colour.
  bool logarithmic = false;
  // The value at the top of the scale, in the values' unit (lx or %). 0: automatic, the 99th
  // percentile of the finite values rounded up to a nice number (1, 2, 2.5 or 5 x 10^k), so a few
  // hot cells next to a lamp do not wash out the rest.
  double max = 0;
  // Logarithmic only: how many decades the scale spans below `max`, 1 to 30.
  int decades = 3;
  // Printed above the legend's colour bar ("lx" or "%"). The built-in font has digits, space and
  // . - + % / c d e k l m u x; any other character is drawn as a hollow box.
  std::string unit = "lx";
};

// 8-bit RGB, rows top to bottom, 3 bytes a pixel.
struct RgbImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;
};

// A rectangle of pixels: columns [x, x + width), rows [y, y + height).
struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
};

struct FalseColourResult {
  RgbImage image;
  double max = 0;         // the scale's max that was used (the automatic one when scale.max was 0)
  PixelRect colour_bar;   // where the legend's colour bar is: its top row is max, its bottom row the
                          // scale's bottom (0, or max / 10^decades)
};

// The colour of cells that hold NaN ("no data"): a neutral grey no part of the colour map comes
// near, so a cell without data is never read as a dark (low) value.
inline constexpr std::array<uint8_t, 3> kNoDataColour = {128, 128, 128};

// `values`: width x height, rows top to bottom; NaN marks "no data". Each value becomes a square of
// cell_pixels x cell_pixels pixels (>= 1), so small grids stay readable. The legend strip on the
// right holds a vertical colour bar with tick labels and the unit, on a white background; when the
// legend is taller than the grid, the rows under the grid are white too.
// Values above max take the top colour; values <= 0 (or, logarithmic, below max / 10^decades) the
// bottom colour; +infinity the top colour.
// An empty grid (width or height 0) gives the legend alone. With no finite value to take a
// percentile of (empty, all NaN) or none above 0, the automatic max is 1.
// Throws std::invalid_argument when values.size() != width * height, a size or cell_pixels is out of
// range, scale.max is negative or not finite, or a logarithmic scale has decades < 1.
FalseColourResult false_colour(const std::vector<float>& values, int width, int height,
                               const FalseColourScale& scale, int cell_pixels = 1);

// Writes `text` (the built-in font) centred on the grid cell (column, row) of an image false_colour
// made with cell_pixels, in white on a black box so it reads on any colour of the map; the box may
// spill over neighbouring cells and is clipped to the image. For room numbers on a work plane.
void label_cell(RgbImage& image, const std::string& text, int column, int row, int cell_pixels);

// Parts of false_colour, for tests and for callers that draw their own legends.

// The colour map: Google's "turbo" (Anton Mikhailov, "Turbo, An Improved Rainbow Colormap for
// Visualization", Google AI Blog, 2019), by its published polynomial approximation. `fraction` 0
// is the bottom (near black, then dark blue), 1 the top (dark red); clamped to [0, 1].
std::array<uint8_t, 3> turbo_colour(double fraction);

// Where `value` sits on the scale, from 0 (bottom colour) to 1 (top colour), for a scale whose max
// is `max` (> 0). NaN gives NaN.
double scale_fraction(double value, const FalseColourScale& scale, double max);

// The smallest of 1, 2, 2.5, 5 x 10^k that is >= value (value > 0).
double nice_number_at_or_above(double value);

// The automatic max: the 99th percentile (nearest rank) of the finite values, rounded up by
// nice_number_at_or_above; 1 when there is no finite value above 0.
double automatic_scale_max(const std::vector<float>& values);

struct LegendTick {
  double value = 0;
  std::string label;  // e.g. "0", "250", "2.5", "0.001", "10k"
};

// The legend's ticks from bottom to top. Linear: multiples of a nice step (5 or 6 ticks for a nice
// max), and max itself when it is not a multiple. Logarithmic: the bottom (max / 10^decades), each
// power of ten in between, and max. The renderer leaves out a label that would overlap another one.
std::vector<LegendTick> legend_ticks(const FalseColourScale& scale, double max);

}  // namespace radbake
