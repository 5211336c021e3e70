// Lightmap pages as files: linear OpenEXR (the values themselves; half float when they fit, else
// full float) and 8-bit PNG (sRGB-encoded value / scale, for viewers and engines that take
// ordinary images).
#pragma once

#include <string>
#include <vector>

#include "baker/finish/finish.h"

namespace radbake {

// One page as linear EXR: half float when every texel fits (up to 65504), full float otherwise.
void write_exr(const std::string& path, const LightmapPage& page);

// One page as sRGB PNG, `scale` (lux or lm/m2) encoded as white.
void write_lightmap_png(const std::string& path, const LightmapPage& page, float scale);

// One page of coefficients as linear 8-bit PNG: byte = 255 * (value - offset) / scale, clipped.
void write_coefficients_png(const std::string& path, const LightmapPage& page, float scale, float offset);

// 8-bit RGB pixels, rows top to bottom, as a PNG (written as they are: no encoding).
void write_png(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb);

// 8-bit RGB pixels, rows top to bottom, as the bytes of a PNG file.
std::vector<uint8_t> encode_png(int width, int height, const std::vector<uint8_t>& rgb);

// A page of luminance (cd/m2) as a display image: sRGB-encoded luminance * exposure, clipped to 1.
std::vector<uint8_t> encode_display_png(const LightmapPage& luminance, float exposure);

// Reads an EXR page back (RGB, linear); for tests and `radbake diff`. Throws InputError naming the
// file when it is not a readable RGB image.
LightmapPage read_lightmap_exr(const std::string& path);

}  // namespace radbake
