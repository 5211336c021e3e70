#include "io/lightmaps/debug_dumps.h"

#include <filesystem>

#include "baker/surface/sampling.h"
#include "io/lightmaps/lightmap_images.h"

namespace radbake {

std::vector<std::string> write_debug_dumps(const BakeResult& r, const std::vector<AtlasPage>& pages,
                                           const std::string& folder, const std::string& name) {
  const Elements& e = r.elements;
  const size_t n = e.size();
  std::vector<Rgb> indirect(n), normals(n), flags(n), patch_colour(n);
  const bool has_direct = r.direct.size() == n;  // path tracing does not separate direct light
  std::vector<Rgb> standard_error(r.standard_error.size());
  for (size_t i = 0; i < standard_error.size(); ++i) standard_error[i] = Rgb{1, 1, 1} * r.standard_error[i];
  for (size_t i = 0; i < n; ++i) {
    if (has_direct) indirect[i] = r.irradiance[i] - r.direct[i];
    normals[i] = e.normal[i] * 0.5f + Rgb{0.5f, 0.5f, 0.5f};
    flags[i] = {(e.flags[i] & kBuried) ? 1.0f : 0.0f, (e.flags[i] & kPushedOut) ? 1.0f : 0.0f,
                (e.flags[i] & kNearGeometry) ? 1.0f : 0.0f};
    uint64_t h = mix64(r.patch_of_element[i]);
    patch_colour[i] = {float(h & 255) / 255, float((h >> 8) & 255) / 255, float((h >> 16) & 255) / 255};
  }
  std::vector<std::pair<std::string, const std::vector<Rgb>*>> dumps = {
      {"irradiance", &r.irradiance}, {"reflectance", &e.reflectance}, {"emission", &e.emission},
      {"normals", &normals}, {"patches", &patch_colour}};
  if (has_direct) dumps.insert(dumps.end(), {{"direct", &r.direct}, {"indirect", &indirect}});
  if (!standard_error.empty()) dumps.push_back({"standard_error", &standard_error});
  std::filesystem::path dir = std::filesystem::path(folder) / "debug";
  std::filesystem::create_directories(dir);
  std::vector<std::string> written;
  // Flags are drawn for every element, valid or not (buried ones are the point of the image).
  Elements all = e;
  std::fill(all.flags.begin(), all.flags.end(), uint8_t(0));
  for (const auto& [what, values] : dumps) {
    std::vector<LightmapPage> p = compose_pages(e, *values, pages, false);
    for (size_t k = 0; k < p.size(); ++k) {
      std::string file = "debug/" + name + "_" + what + "_" + std::to_string(k) + ".exr";
      write_exr((std::filesystem::path(folder) / file).string(), p[k]);
      written.push_back(file);
    }
  }
  std::vector<LightmapPage> p = compose_pages(all, flags, pages, false);
  for (size_t k = 0; k < p.size(); ++k) {
    std::string file = "debug/" + name + "_flags_" + std::to_string(k) + ".exr";
    write_exr((std::filesystem::path(folder) / file).string(), p[k]);
    written.push_back(file);
  }
  return written;
}

}  // namespace radbake
