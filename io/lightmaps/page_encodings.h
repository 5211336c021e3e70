// The files each page of light is written as: lightmap pages and directional pages alike. An
// encoding is a key, a file extension, how its values read back and the function that writes one
// page; write_pages writes every page in every encoding here, in this order. A new encoding (KTX2,
// RGBM) is its writer in a file of its own and one entry in page_encodings().
#pragma once

#include <string>
#include <vector>

#include "baker/finish/finish.h"

namespace radbake {

// How a file of 8-bit channels stores a page's linear values: value = offset + scale *
// decode(byte / 255), decode the sRGB curve for light (lightmaps, which viewers show as images) and
// none for coefficients (directional pages, which are not colours). Float encodings ignore it.
struct EightBitRange {
  float scale = 1;
  float offset = 0;
  bool srgb = true;
};

struct PageEncoding {
  std::string key;        // report.json's and extras.radbake's name for a page's file: "exr"
  std::string extension;  // of the file, with its dot
  // How the values of a lightmap page and of a directional page read back, for extras.radbake.
  std::string light_read_back;
  std::string coefficients_read_back;
  void (*write)(const std::string& path, const LightmapPage& page, const EightBitRange& range);
};

const std::vector<PageEncoding>& page_encodings();

// The encoding engines sample as the glTF's lightmap texture (MOZ_lightmap): PNG.
const PageEncoding& texture_encoding();

// What the lightmap files are and how their values read back.
struct LightmapFiles {
  // [page][k]: the page's file in page_encodings()[k], a name inside the output folder.
  std::vector<std::vector<std::string>> files;
  float png_scale = 1;     // linear value = sRGB-decoded PNG value * png_scale
  std::string quantity;    // "irradiance" or "radiosity"
  std::string unit;        // "lx" or "lm/m2"

  // The page's file in texture_encoding().
  const std::string& texture(size_t page) const;
};

// The PNG scale when none is given: the 99.9th percentile of the brightest channel over all
// covered texels, so a few hot texels next to a lamp do not darken the whole page.
float automatic_png_scale(const std::vector<LightmapPage>& pages);

// Writes page P as STEM_P in every encoding, page by page: [page][k] the file in page_encodings()[k],
// a name inside `folder`.
std::vector<std::vector<std::string>> write_pages(const std::vector<LightmapPage>& pages, const std::string& folder,
                                                  const std::string& stem, const EightBitRange& range);

// Writes NAME_lightmap_P in every encoding, page by page.
LightmapFiles write_lightmaps(const std::vector<LightmapPage>& pages, const std::string& folder,
                              const std::string& name, const std::string& quantity, const std::string& unit,
                              float png_scale);

}  // namespace radbake
