#include "io/lightmaps/page_encodings.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "io/lightmaps/lightmap_images.h"

namespace radbake {
namespace {

void write_exr_page(const std::string& path, const LightmapPage& page, const EightBitRange&) { write_exr(path, page); }

void write_png_page(const std::string& path, const LightmapPage& page, const EightBitRange& range) {
  if (range.srgb) write_lightmap_png(path, page, range.scale);
  else write_coefficients_png(path, page, range.scale, range.offset);
}

}  // namespace

const std::vector<PageEncoding>& page_encodings() {
  static const std::vector<PageEncoding> encodings = {
      {"exr", ".exr", "linear half-float RGB, the quantity in its unit", "linear float RGB, the values themselves",
       write_exr_page},
      {"png", ".png", "8-bit sRGB-encoded; quantity = srgb_to_linear(png / 255) * MOZ_lightmap.intensity",
       "8-bit linear (no sRGB curve); value = png_offset + png_scale * png / 255", write_png_page},
  };
  return encodings;
}

const PageEncoding& texture_encoding() {
  static const PageEncoding& png = *std::find_if(page_encodings().begin(), page_encodings().end(),
                                                 [](const PageEncoding& e) { return e.key == "png"; });
  return png;
}

const std::string& LightmapFiles::texture(size_t page) const {
  return files[page][size_t(&texture_encoding() - page_encodings().data())];
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

std::vector<std::vector<std::string>> write_pages(const std::vector<LightmapPage>& pages, const std::string& folder,
                                                  const std::string& stem, const EightBitRange& range) {
  std::vector<std::vector<std::string>> files;
  for (size_t p = 0; p < pages.size(); ++p) {
    files.emplace_back();
    for (const PageEncoding& encoding : page_encodings()) {
      files.back().push_back(stem + "_" + std::to_string(p) + encoding.extension);
      encoding.write((std::filesystem::path(folder) / files.back().back()).string(), pages[p], range);
    }
  }
  return files;
}

LightmapFiles write_lightmaps(const std::vector<LightmapPage>& pages, const std::string& folder,
                              const std::string& name, const std::string& quantity, const std::string& unit,
                              float png_scale) {
  LightmapFiles out;
  out.quantity = quantity;
  out.unit = unit;
  out.png_scale = png_scale;
  out.files = write_pages(pages, folder, name + "_lightmap", EightBitRange{png_scale, 0, true});
  return out;
}

}  // namespace radbake
