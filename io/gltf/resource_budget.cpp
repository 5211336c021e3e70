// What a bake will hold, estimated from the file before it is read, and the limits it is held to.
#include <unistd.h>

#include <cmath>
#include <cstdio>

#include "base/errors.h"
#include "io/gltf/gltf_loader.h"
#include "io/gltf/gltf_source.h"

namespace radbake {
namespace {

// radbake holds 129 MB before it reads a scene (README, "Measured"). The rest are upper estimates
// of what a bake's peak grows by: per triangle and vertex after instancing (scene, atlas and
// half-edge mesh, Embree's BVH, the surface tables) and per lightmap page texel (measured 130
// bytes for a floor filling a 1024-texel page, draft quality; the README's million-texel bench
// peaks at 153 a covered texel). They are meant to refuse what cannot fit, not to predict to the
// megabyte.
constexpr uint64_t kBaselineBytes = uint64_t(130) << 20;
constexpr uint64_t kBytesPerTriangle = 600;
constexpr uint64_t kBytesPerVertex = 150;
constexpr uint64_t kBytesPerTexel = 300;
// --density with charts packed at about this share of their pages (the atlas's typical utilisation).
constexpr double kPackedShare = 0.5;

uint64_t physical_memory() {
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page_size > 0 ? uint64_t(pages) * uint64_t(page_size) : uint64_t(4) << 30;
}

std::string gigabytes(uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f GB", double(bytes) / 1e9);
  return text;
}

uint64_t saturated(double v) { return v >= 1.8e19 ? UINT64_MAX : uint64_t(v); }

}  // namespace

uint64_t memory_limit(uint64_t max_memory_bytes) {
  return max_memory_bytes == 0 ? physical_memory() / 2 : max_memory_bytes;
}

uint64_t ResourceEstimate::bytes() const {
  return saturated(double(kBaselineBytes) + double(data_bytes) + double(triangles) * kBytesPerTriangle +
                   double(vertices) * kBytesPerVertex + double(texels) * kBytesPerTexel);
}

void check_budget(const ResourceEstimate& e, const LoadOptions& options, const std::string& file) {
  if (e.triangles > options.max_triangles)
    refuse(file, "/", "the scene has " + std::to_string(e.triangles) + " triangles after instancing, more than " +
                          "--max-triangles " + std::to_string(options.max_triangles) + " allows (raise it to bake it)");
  const bool automatic = options.max_memory_bytes == 0;
  const uint64_t limit = memory_limit(options.max_memory_bytes);
  if (e.bytes() > limit)
    refuse(file, "/", "the bake would need about " + gigabytes(e.bytes()) + " (" + std::to_string(e.triangles) +
                          " triangles, " + std::to_string(e.texels) + " lightmap texels, " + gigabytes(e.data_bytes) +
                          " of file data and images), more than --max-memory " + gigabytes(limit) +
                          (automatic ? " (half the physical memory)" : "") +
                          " allows (raise it, or lower --max-page-size or --density)");
}

ResourceEstimate check_bake_budget(const LoadedScene& loaded, const AtlasOptions& atlas, const LoadOptions& options,
                                   const std::string& path) {
  ResourceEstimate e = loaded.estimate;
  const double page = double(atlas.max_page_size) * atlas.max_page_size;
  if (atlas.texel_density > 0 && !atlas.fit_one_page) {
    double area = 0;
    for (const MeshInstance& inst : loaded.scene.instances)
      for (size_t t = 0; t < inst.triangle_count(); ++t) {
        const Vec3 a = inst.positions[inst.triangles[3 * t]];
        area += 0.5 * double(length(cross(inst.positions[inst.triangles[3 * t + 1]] - a,
                                          inst.positions[inst.triangles[3 * t + 2]] - a)));
      }
    const double texels = area * double(atlas.texel_density) * atlas.texel_density / kPackedShare;
    e.texels = saturated(std::ceil(std::max(texels, 1.0) / page) * page);  // whole pages
  } else {
    e.texels = saturated(page);
  }
  check_budget(e, options, path);
  return e;
}

}  // namespace radbake
