#include "baker/surface/nearby_samples.h"

#include <algorithm>
#include <cmath>

namespace radbake {
namespace {

// Cells are this many texels wide, as wide as the searches they serve (element_standing_for looks
// four texels out), so that one looks through the 27 cells round its point; and at most this many
// cells each way, for a search wider than that (a chart coarser than most).
constexpr float kCellTexels = 4;
constexpr int kMostCellsAway = 2;

uint64_t cell_key(int64_t x, int64_t y, int64_t z) {
  constexpr uint64_t kMask = (uint64_t(1) << 21) - 1;  // cells far apart may share a key: only more to check
  return (uint64_t(x) & kMask) << 42 | (uint64_t(y) & kMask) << 21 | (uint64_t(z) & kMask);
}

int64_t cell_of(float coordinate, float cell) { return int64_t(std::floor(coordinate / cell)); }

}  // namespace

void index_samples(Elements& e, const Surface& surface) {
  std::vector<float> sizes;
  for (size_t i = 0; i < e.size(); ++i)
    if (e.valid(i)) sizes.push_back(surface.texel_size(e.triangle[i]));
  e.sample_cell_key.clear();
  e.sample_cell_element.clear();
  if (sizes.empty()) return;
  // By the median texel: most texels', whatever a few distorted triangles' are.
  std::nth_element(sizes.begin(), sizes.begin() + std::ptrdiff_t(sizes.size() / 2), sizes.end());
  e.sample_cell = kCellTexels * sizes[sizes.size() / 2];
  if (!(e.sample_cell > 0) || !std::isfinite(e.sample_cell)) return;
  std::vector<std::pair<uint64_t, uint32_t>> keyed;
  keyed.reserve(sizes.size());
  for (size_t i = 0; i < e.size(); ++i)
    if (e.valid(i)) {
      const Vec3 p = e.position[i];
      keyed.emplace_back(cell_key(cell_of(p.x, e.sample_cell), cell_of(p.y, e.sample_cell), cell_of(p.z, e.sample_cell)),
                         uint32_t(i));
    }
  std::sort(keyed.begin(), keyed.end());
  for (const auto& [key, element] : keyed) {
    e.sample_cell_key.push_back(key);
    e.sample_cell_element.push_back(element);
  }
}

std::vector<uint32_t> samples_near(const Elements& e, Vec3 point, float radius, size_t most) {
  std::vector<std::pair<float, uint32_t>> found;
  if (e.sample_cell_key.empty() || !(radius > 0)) return {};
  const float cell = e.sample_cell;
  const int reach = std::min(kMostCellsAway, int(std::ceil(radius / cell)));
  const int64_t cx = cell_of(point.x, cell), cy = cell_of(point.y, cell), cz = cell_of(point.z, cell);
  for (int64_t x = cx - reach; x <= cx + reach; ++x)
    for (int64_t y = cy - reach; y <= cy + reach; ++y)
      for (int64_t z = cz - reach; z <= cz + reach; ++z) {
        const uint64_t key = cell_key(x, y, z);
        auto [from, to] = std::equal_range(e.sample_cell_key.begin(), e.sample_cell_key.end(), key);
        for (auto it = from; it != to; ++it) {
          const uint32_t k = e.sample_cell_element[size_t(it - e.sample_cell_key.begin())];
          const float distance = length(e.position[k] - point);
          if (distance <= radius) found.emplace_back(distance, k);
        }
      }
  std::sort(found.begin(), found.end());
  std::vector<uint32_t> nearest;
  for (size_t a = 0; a < found.size() && nearest.size() < most; ++a)
    if (a == 0 || found[a].second != found[a - 1].second) nearest.push_back(found[a].second);
  return nearest;
}

}  // namespace radbake
