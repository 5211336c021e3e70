#include "support/images.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <png.h>

#include <exception>

namespace radbake::test {

std::vector<uint8_t> read_png_rgb(const std::string& path, int* width, int* height) {
  if (width) *width = -1;
  if (height) *height = -1;
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str())) return {};
  image.format = PNG_FORMAT_RGB;
  std::vector<uint8_t> pixels(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, pixels.data(), 0, nullptr)) {
    png_image_free(&image);
    return {};
  }
  if (width) *width = int(image.width);
  if (height) *height = int(image.height);
  return pixels;
}

ExrStorage exr_storage(const std::string& path) {
  try {
    Imf::InputFile in(path.c_str());
    const Imf::Channel* red = in.header().channels().findChannel("R");
    if (!red) return ExrStorage::Other;
    return red->type == Imf::HALF ? ExrStorage::Half : red->type == Imf::FLOAT ? ExrStorage::Float : ExrStorage::Other;
  } catch (const std::exception&) {
    return ExrStorage::Unreadable;
  }
}

}  // namespace radbake::test
