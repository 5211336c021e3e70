#include "io/lightmaps/lightmap_images.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <Imath/half.h>
#include <png.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csetjmp>
#include <cstring>
#include <filesystem>
#include <fstream>
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

// OpenEXR writes through this, so every failed write (a full disk, also while OpenEXR's
// destructor writes the line offsets and swallows what it throws) leaves the stream failed, for
// close_written to report in radbake's words.
class ExrFileStream : public Imf::OStream {
 public:
  ExrFileStream(std::ofstream& out, const std::string& path) : Imf::OStream(path.c_str()), out_(out) {}
  void write(const char c[], int n) override {
    out_.write(c, n);
    if (!out_) throw std::runtime_error("write failed");
  }
  uint64_t tellp() override { return uint64_t(out_.tellp()); }
  void seekp(uint64_t pos) override {
    out_.seekp(std::streamoff(pos));
    if (!out_) throw std::runtime_error("seek failed");
  }

 private:
  std::ofstream& out_;
};

// PNG's bytes, appended by libpng as it compresses.
void append_png_bytes(png_structp png, png_bytep data, png_size_t length) {
  auto* bytes = static_cast<std::vector<uint8_t>*>(png_get_io_ptr(png));
  bytes->insert(bytes->end(), data, data + length);
}

// libpng reports an error by longjmp back to the setjmp here, so nothing with a destructor is made
// between the two.
bool encode_png_into(std::vector<uint8_t>* bytes, int width, int height, const uint8_t* rgb) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, bytes, append_png_bytes, nullptr);
  png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < height; ++y) png_write_row(png, rgb + size_t(y) * size_t(width) * 3);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

void write_exr(const std::string& path, const LightmapPage& page) {
  static_assert(sizeof(Rgb) == 3 * sizeof(float), "texels are packed float RGB");
  // Half floats end at 65504: fine for interiors, but daylight reaches 100000 lux, so a page with
  // brighter texels is written in full float rather than clipped to infinity.
  constexpr float kLargestHalf = 65504.0f;
  bool fits_half = std::all_of(page.texels.begin(), page.texels.end(),
                               [&](const Rgb& t) { return max_component(t) <= kLargestHalf; });
  // No capture date or other stamp: the same bake writes the same bytes.
  Imf::Header header(page.width, page.height);
  header.compression() = Imf::ZIP_COMPRESSION;
  // OpenEXR writes a channel from texels of its own type only: half floats are made here.
  std::vector<half> halves;
  if (fits_half) {
    halves.reserve(page.texels.size() * 3);
    for (const Rgb& t : page.texels) halves.insert(halves.end(), {half(t.x), half(t.y), half(t.z)});
  }
  const Imf::PixelType type = fits_half ? Imf::HALF : Imf::FLOAT;
  const size_t value_bytes = fits_half ? sizeof(half) : sizeof(float);
  char* first = fits_half ? reinterpret_cast<char*>(halves.data())
                          : const_cast<char*>(reinterpret_cast<const char*>(page.texels.data()));
  Imf::FrameBuffer texels;
  const char* channels[3] = {"R", "G", "B"};
  for (size_t c = 0; c < 3; ++c) {
    header.channels().insert(channels[c], Imf::Channel(type));
    texels.insert(channels[c], Imf::Slice(type, first + c * value_bytes, 3 * value_bytes, 3 * value_bytes * size_t(page.width)));
  }
  std::ofstream out(path, std::ios::binary);
  if (!out) refuse_unwritten(path);
  errno = 0;
  bool written = true;
  try {
    ExrFileStream stream(out, path);
    Imf::OutputFile file(stream, header);
    file.setFrameBuffer(texels);
    file.writePixels(page.height);
  } catch (const std::exception&) {
    written = false;  // OpenEXR's words name its internals; the stream and the disk say why
  }
  if (!written) refuse_unwritten(path);
  close_written(out, path);
}

void write_png(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb) {
  const std::vector<uint8_t> bytes = encode_png(width, height, rgb);
  std::ofstream out(path, std::ios::binary);
  if (!out) refuse_unwritten(path);
  errno = 0;
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  close_written(out, path);
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

void write_coefficients_png(const std::string& path, const LightmapPage& page, float scale, float offset) {
  std::vector<uint8_t> bytes(page.texels.size() * 3);
  for (size_t t = 0; t < page.texels.size(); ++t)
    for (int c = 0; c < 3; ++c) {
      const float unit = scale > 0 ? (page.texels[t][c] - offset) / scale : 0.0f;
      bytes[3 * t + size_t(c)] = uint8_t(std::lround(std::clamp(unit, 0.0f, 1.0f) * 255.0f));
    }
  write_png(path, page.width, page.height, bytes);
}

std::vector<uint8_t> encode_png(int width, int height, const std::vector<uint8_t>& rgb) {
  if (rgb.size() != size_t(width) * size_t(height) * 3) throw std::invalid_argument("PNG pixels do not fill the image");
  std::vector<uint8_t> bytes;
  if (!encode_png_into(&bytes, width, height, rgb.data())) throw std::runtime_error("cannot encode a PNG");
  return bytes;
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

// OpenEXR reads the page through the descriptor radbake opened and checked.
class ExrFileInput : public Imf::IStream {
 public:
  ExrFileInput(RegularFile& file, const std::string& path) : Imf::IStream(path.c_str()), file_(file) {}
  bool read(char c[], int n) override {
    if (n < 0 || !file_.read_at(at_, c, size_t(n))) throw std::runtime_error("cut short");
    at_ += uint64_t(n);
    return at_ < file_.size();
  }
  uint64_t tellg() override { return at_; }
  void seekg(uint64_t pos) override { at_ = pos; }

 private:
  RegularFile& file_;
  uint64_t at_ = 0;
};

constexpr const char* kRgb[3] = {"R", "G", "B"};

void require_rgb(const Imf::ChannelList& channels, const std::string& path) {
  for (const char* c : kRgb)
    if (!channels.findChannel(c)) {
      size_t count = 0;
      for (auto it = channels.begin(); it != channels.end(); ++it) ++count;
      throw InputError(clipped(path) + " has no " + c + " channel (" + std::to_string(count) +
                       " channel(s)); a lightmap page is RGB");
    }
}

// Where OpenEXR puts the R, G and B of `window` as floats: the page's texels. It addresses the
// buffer by pixel coordinates, which start at the window's corner.
Imf::FrameBuffer texels_of(LightmapPage& page, const Imath::Box2i& window) {
  char* origin = reinterpret_cast<char*>(page.texels.data()) -
                 (ptrdiff_t(window.min.x) + ptrdiff_t(window.min.y) * page.width) * ptrdiff_t(sizeof(Rgb));
  Imf::FrameBuffer texels;
  for (size_t c = 0; c < 3; ++c)
    texels.insert(kRgb[c], Imf::Slice(Imf::FLOAT, origin + c * sizeof(float), sizeof(Rgb), sizeof(Rgb) * size_t(page.width)));
  return texels;
}

}  // namespace

LightmapPage read_lightmap_exr(const std::string& path) {
  // Opened as a regular file first, and read through that very descriptor.
  RegularFile file(path, "lightmap page");
  check_exr_header(file, path);
  // OpenEXR's own words name its internals; what is left to fail here is damage past the header.
  const std::string damaged = "cannot read " + clipped(path) + ": its pixels are damaged or cut short";
  LightmapPage page;
  try {
    ExrFileInput stream(file, path);
    Imf::InputFile in(stream);
    const Imath::Box2i window = in.header().dataWindow();
    page.width = window.max.x - window.min.x + 1;
    page.height = window.max.y - window.min.y + 1;
    require_rgb(in.header().channels(), path);
    page.texels.resize(size_t(page.width) * size_t(page.height));
    in.setFrameBuffer(texels_of(page, window));
    in.readPixels(window.min.y, window.max.y);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception&) {
    throw InputError(damaged);
  }
  page.valid.assign(page.texels.size(), 1);
  return page;
}

}  // namespace radbake
