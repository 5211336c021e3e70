#include "io/lightmaps/lightmap_images.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "base/errors.h"
#include "io/files/written_file.h"
#include "io/files/regular_file.h"

namespace radbake {
namespace {

// The largest page side radbake writes (--max-page-size's highest value).
constexpr int kLargestPageSide = 16384;

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
  errno = 0;
  if (!out->open(path, spec) || !out->write_image(pixel_type, pixels) || !out->close()) {
    out->geterror();  // OpenImageIO's words, cleared: they name its internals, not the reason
    refuse_unwritten(path);
  }
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

namespace {

// The page size an OpenEXR file's header claims (its dataWindow), read by radbake before OpenEXR
// reads anything: OpenEXR sizes its own tables from it (a line offset per 16 lines), and a header
// that claims 2^31 lines made it allocate gigabytes before a pixel was read. Throws InputError
// for what is not an OpenEXR header or claims more than a page radbake writes.
void check_exr_header(RegularFile& file, const std::string& path) {
  std::string header(size_t(std::min<uint64_t>(file.size(), 1 << 16)), '\0');
  const auto not_exr = [&](const std::string& why) {
    return InputError(clipped(path) + " is not an OpenEXR lightmap page (" + why + ")");
  };
  if (!file.read_at(0, header.data(), header.size())) throw not_exr("it could not be read");
  if (header.size() < 8 || header.compare(0, 4, "\x76\x2f\x31\x01") != 0) throw not_exr("no OpenEXR signature");
  size_t at = 8;
  const auto name_at = [&](size_t from) {
    const size_t end = header.find('\0', from);
    if (end == std::string::npos || end - from > 255) throw not_exr("its header is cut short or malformed");
    return end;
  };
  for (;;) {
    const size_t name_end = name_at(at);
    if (name_end == at) break;  // the header's end
    const std::string name = header.substr(at, name_end - at);
    const size_t type_end = name_at(name_end + 1);
    const std::string type = header.substr(name_end + 1, type_end - name_end - 1);
    int32_t size = 0;
    if (type_end + 1 + 4 > header.size()) throw not_exr("its header is cut short");
    std::memcpy(&size, &header[type_end + 1], 4);
    const size_t value = type_end + 1 + 4;
    if (size < 0 || uint64_t(size) > header.size() - value) throw not_exr("its header is cut short or malformed");
    if (name == "dataWindow") {
      int32_t box[4];
      if (type != "box2i" || size != 16) throw not_exr("its dataWindow is not a box2i");
      std::memcpy(box, &header[value], sizeof box);
      const int64_t width = int64_t(box[2]) - box[0] + 1, height = int64_t(box[3]) - box[1] + 1;
      if (width < 1 || height < 1 || width > kLargestPageSide || height > kLargestPageSide)
        throw InputError(clipped(path) + " claims " + std::to_string(width) + " x " + std::to_string(height) +
                         " texels; radbake's lightmap pages are 1 to " + std::to_string(kLargestPageSide) +
                         " on a side");
      return;
    }
    at = value + size_t(size);
  }
  throw not_exr("its header has no dataWindow");
}

}  // namespace

LightmapPage read_lightmap_exr(const std::string& path) {
  // Opened as a regular file first, and read through that very descriptor.
  RegularFile file(path, "lightmap page");
  check_exr_header(file, path);
  const std::unique_ptr<FILE, int (*)(FILE*)> stream(::fdopen(::dup(file.descriptor()), "rb"), &std::fclose);
  if (!stream) throw InputError("cannot read " + clipped(path) + ": " + std::strerror(errno));
  OIIO::Filesystem::IOFile proxy(stream.get(), OIIO::Filesystem::IOProxy::Read);
  // OpenEXR's own words name its internals; what is left to fail here is damage past the header.
  const std::string damaged = "cannot read " + clipped(path) + ": its pixels are damaged or cut short";
  auto in = OIIO::ImageInput::open(path, nullptr, &proxy);
  if (!in) {
    OIIO::geterror();  // cleared, for the next reader
    throw InputError(damaged);
  }
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.nchannels < 3)
    throw InputError(clipped(path) + " has " + std::to_string(spec.nchannels) + " channel(s); a lightmap page is RGB");
  if (spec.width > kLargestPageSide || spec.height > kLargestPageSide || spec.depth != 1) throw InputError(damaged);
  LightmapPage page;
  page.width = spec.width;
  page.height = spec.height;
  std::vector<float> pixels(size_t(spec.width) * spec.height * 3);
  if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, pixels.data())) {
    in->geterror();
    throw InputError(damaged);
  }
  page.texels.resize(size_t(spec.width) * spec.height);
  page.valid.assign(page.texels.size(), 1);
  for (size_t t = 0; t < page.texels.size(); ++t) page.texels[t] = {pixels[3 * t], pixels[3 * t + 1], pixels[3 * t + 2]};
  return page;
}

}  // namespace radbake
