#include "io/lightmaps/lightmap_images.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "base/errors.h"

namespace radbake {
namespace {

uint8_t encode_srgb(float linear) {
  float v = std::clamp(std::isfinite(linear) ? linear : 0.0f, 0.0f, 1.0f);
  float s = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
  return uint8_t(std::lround(s * 255.0f));
}

void write_image(const std::string& path, int width, int height, const OIIO::TypeDesc& format, const void* pixels,
                 const OIIO::TypeDesc& pixel_type, bool exr) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw std::runtime_error("cannot create " + path + ": " + OIIO::geterror());
  OIIO::ImageSpec spec(width, height, 3, format);
  if (exr) spec.attribute("compression", "zip");
  if (!out->open(path, spec) || !out->write_image(pixel_type, pixels) || !out->close())
    throw std::runtime_error("cannot write " + path + ": " + out->geterror());
}

}  // namespace

void write_exr(const std::string& path, const LightmapPage& page) {
  static_assert(sizeof(Rgb) == 3 * sizeof(float), "texels are packed float RGB");
  // Half floats end at 65504: fine for interiors, but daylight reaches 100000 lux, so a page with
  // brighter texels is written in full float rather than clipped to infinity.
  constexpr float kLargestHalf = 65504.0f;
  bool fits_half = std::all_of(page.texels.begin(), page.texels.end(),
                               [&](const Rgb& t) { return max_component(t) <= kLargestHalf; });
  write_image(path, page.width, page.height, fits_half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT,
              page.texels.data(), OIIO::TypeDesc::FLOAT, true);
}

void write_png(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb) {
  write_image(path, width, height, OIIO::TypeDesc::UINT8, rgb.data(), OIIO::TypeDesc::UINT8, false);
}

float automatic_png_scale(const std::vector<LightmapPage>& pages) {
  std::vector<float> brightest;
  for (const LightmapPage& page : pages)
    for (size_t t = 0; t < page.texels.size(); ++t)
      if (page.valid[t]) brightest.push_back(max_component(page.texels[t]));
  if (brightest.empty()) return 1.0f;
  size_t k = std::min(brightest.size() - 1, size_t(std::floor(0.999 * double(brightest.size() - 1))));
  std::nth_element(brightest.begin(), brightest.begin() + long(k), brightest.end());
  float scale = brightest[k];
  return scale > 0 && std::isfinite(scale) ? scale : 1.0f;
}

LightmapFiles write_lightmaps(const std::vector<LightmapPage>& pages, const std::string& folder,
                              const std::string& name, const std::string& quantity, const std::string& unit,
                              float png_scale) {
  LightmapFiles files;
  files.quantity = quantity;
  files.unit = unit;
  files.png_scale = png_scale;
  for (size_t p = 0; p < pages.size(); ++p) {
    const LightmapPage& page = pages[p];
    std::string stem = name + "_lightmap_" + std::to_string(p);
    files.exr.push_back(stem + ".exr");
    files.png.push_back(stem + ".png");
    write_exr((std::filesystem::path(folder) / files.exr.back()).string(), page);
    write_lightmap_png((std::filesystem::path(folder) / files.png.back()).string(), page, png_scale);
  }
  return files;
}

namespace {

std::vector<uint8_t> srgb_pixels(const LightmapPage& page, float multiplier) {
  std::vector<uint8_t> encoded(page.texels.size() * 3);
  for (size_t t = 0; t < page.texels.size(); ++t)
    for (int c = 0; c < 3; ++c) encoded[3 * t + size_t(c)] = encode_srgb(page.texels[t][c] * multiplier);
  return encoded;
}

}  // namespace

void write_lightmap_png(const std::string& path, const LightmapPage& page, float scale) {
  write_png(path, page.width, page.height, srgb_pixels(page, 1.0f / scale));
}

std::vector<uint8_t> encode_png(int width, int height, const std::vector<uint8_t>& rgb) {
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput memory(bytes);
  auto out = OIIO::ImageOutput::create("page.png", &memory);
  if (!out) throw std::runtime_error(std::string("cannot create a PNG encoder: ") + OIIO::geterror());
  OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
  if (!out->open("page.png", spec) || !out->write_image(OIIO::TypeDesc::UINT8, rgb.data()) || !out->close())
    throw std::runtime_error("cannot encode a PNG: " + out->geterror());
  return std::vector<uint8_t>(bytes.begin(), bytes.end());
}

std::vector<uint8_t> encode_display_png(const LightmapPage& luminance, float exposure) {
  return encode_png(luminance.width, luminance.height, srgb_pixels(luminance, exposure));
}

LightmapPage read_lightmap_exr(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw InputError("cannot read " + path + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.nchannels < 3)
    throw InputError(path + " has " + std::to_string(spec.nchannels) + " channel(s); a lightmap page is RGB");
  LightmapPage page;
  page.width = spec.width;
  page.height = spec.height;
  std::vector<float> pixels(size_t(spec.width) * spec.height * 3);
  if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, pixels.data()))
    throw InputError("cannot read " + path + ": " + in->geterror());
  page.texels.resize(size_t(spec.width) * spec.height);
  page.valid.assign(page.texels.size(), 1);
  for (size_t t = 0; t < page.texels.size(); ++t) page.texels[t] = {pixels[3 * t], pixels[3 * t + 1], pixels[3 * t + 2]};
  return page;
}

}  // namespace radbake
