#include "baker/transport/patches.h"

#include <algorithm>
#include <numeric>

namespace radbake {
namespace {

struct Keyed {
  uint64_t key;  // wall group (bits 58-63), log2 block side (54-57), chart (32-53), block row, block column
  uint32_t element;
};

int log2_side(int side) {
  int k = 0;
  while ((1 << (k + 1)) <= side) ++k;
  return k;
}

// `side_of(i)`: the block side (a power of two) element i is grouped by.
template <typename SideOf>
std::vector<Keyed> block_keys(const Elements& e, const Surface& surface, SideOf side_of) {
  std::vector<Keyed> keys;
  keys.reserve(e.size());
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i)) continue;
    uint32_t width = uint32_t(surface.pages[e.page[i]].width);
    int k = log2_side(side_of(i));
    uint64_t bx = (e.texel[i] % width) >> k, by = (e.texel[i] / width) >> k;
    keys.push_back({uint64_t(k) << 54 | uint64_t(surface.chart[e.triangle[i]]) << 32 | by << 16 | bx, uint32_t(i)});
  }
  std::sort(keys.begin(), keys.end(), [](const Keyed& a, const Keyed& b) {
    return a.key != b.key ? a.key < b.key : a.element < b.element;
  });
  return keys;
}

size_t distinct_keys(const std::vector<Keyed>& keys) {
  size_t count = 0;
  for (size_t i = 0; i < keys.size(); ++i) count += i == 0 || keys[i].key != keys[i - 1].key;
  return count;
}

// A block that a wall crosses holds texels from both sides; mixing them would carry one side's
// light to the other. Each block is cut into the groups its elements' joins connect, and every
// group gets a key of its own (the block key plus the group's number in the top bits).
void split_at_walls(const Elements& e, const Surface& surface, std::vector<Keyed>& keys) {
  std::vector<uint32_t> local(e.size(), UINT32_MAX), parent;
  auto find = [&](uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (size_t begin = 0; begin < keys.size();) {
    size_t end = begin;
    while (end < keys.size() && keys[end].key == keys[begin].key) ++end;
    parent.resize(end - begin);
    for (size_t k = begin; k < end; ++k) {
      local[keys[k].element] = uint32_t(k - begin);
      parent[k - begin] = uint32_t(k - begin);
    }
    for (size_t k = begin; k < end; ++k) {
      uint32_t i = keys[k].element;
      uint32_t width = uint32_t(surface.pages[e.page[i]].width);
      const std::vector<int32_t>& at = e.element_at[e.page[i]];
      for (auto [bit, step] : {std::pair<uint8_t, uint32_t>{kJoinsRight, 1}, {kJoinsDown, width}}) {
        if (!(e.flags[i] & bit)) continue;
        int32_t j = at[e.texel[i] + step];
        if (j >= 0 && local[size_t(j)] != UINT32_MAX) parent[find(local[i])] = find(local[size_t(j)]);
      }
    }
    std::vector<uint32_t> group_of_root(end - begin, UINT32_MAX);
    uint32_t groups = 0;
    for (size_t k = begin; k < end; ++k) {
      uint32_t root = find(uint32_t(k - begin));
      if (group_of_root[root] == UINT32_MAX) group_of_root[root] = groups++;
      keys[k].key |= uint64_t(group_of_root[root]) << 58;  // chart ids stay far below 2^26
    }
    for (size_t k = begin; k < end; ++k) local[keys[k].element] = UINT32_MAX;
    begin = end;
  }
  std::sort(keys.begin(), keys.end(), [](const Keyed& a, const Keyed& b) {
    return a.key != b.key ? a.key < b.key : a.element < b.element;
  });
}

Patches patches_from_keys(const Elements& e, const Surface& surface, std::vector<Keyed> keys, int block) {
  split_at_walls(e, surface, keys);
  Patches p;
  p.block_size = block;
  p.patch_of_element.assign(e.size(), UINT32_MAX);
  for (size_t i = 0; i < keys.size(); ++i) {
    if (i == 0 || keys[i].key != keys[i - 1].key) {
      p.first_member.push_back(uint32_t(i));
      p.area.push_back(0);
      if (!e.opacity.empty()) p.opacity.push_back(0);
      p.reflectance.push_back({});
      p.emission.push_back({});
      p.side.push_back(uint16_t(1u << ((keys[i].key >> 54) & 15)));
    }
    uint32_t el = keys[i].element;
    size_t patch = p.area.size() - 1;
    p.members.push_back(el);
    p.patch_of_element[el] = uint32_t(patch);
    p.area[patch] += e.area[el];
    if (!e.opacity.empty()) p.opacity[patch] += e.opacity[el] * e.area[el];
    p.reflectance[patch] += e.reflectance[el] * e.area[el];
    p.emission[patch] += e.emission[el] * e.area[el];
  }
  p.first_member.push_back(uint32_t(keys.size()));
  for (size_t q = 0; q < p.size(); ++q) {
    float inv = p.area[q] > 0 ? 1.0f / p.area[q] : 0.0f;
    p.reflectance[q] *= inv;
    if (!p.opacity.empty()) p.opacity[q] = p.area[q] > 0 ? p.opacity[q] * inv : 1.0f;
    p.emission[q] *= inv;
  }
  return p;
}

// Metres per texel side, area-weighted over the valid elements.
double mean_texel_size(const Elements& e, const Surface& surface) {
  double sum = 0, area = 0;
  for (size_t i = 0; i < e.size(); ++i)
    if (e.valid(i)) {
      sum += double(surface.texel_size(e.triangle[i])) * e.area[i];
      area += e.area[i];
    }
  return area > 0 ? sum / area : 0;
}

}  // namespace

size_t patch_budget(const PatchOptions& options, size_t elements) {
  if (options.max_patches > 0) return options.max_patches;
  const size_t cap = std::max<size_t>(options.patch_cap, 64);
  return std::clamp<size_t>(elements / std::max<size_t>(options.elements_per_patch, 1), 64, cap);
}

Patches build_patches(const Elements& e, const Surface& surface, const PatchOptions& options) {
  int block = options.block_size > 0 ? 1 << log2_side(options.block_size) : 1;
  auto uniform = [&](size_t) { return block; };
  std::vector<Keyed> keys = block_keys(e, surface, uniform);
  const size_t max_patches = patch_budget(options, keys.size());
  // Pages are at most 16384 texels, so blocks stay under 2^16 per side in the key.
  while (options.block_size <= 0 && distinct_keys(keys) > max_patches && block < 16384) {
    block *= 2;
    keys = block_keys(e, surface, uniform);
  }
  // Blocks the budget made wider than the mean free path give way to the widest within it, if
  // those are at most twice the budget. On the FZK-Haus (19 cm texels, its surfaces 2.3 m apart on
  // average) the defaults' budget alone made 6.2 m patches, and an inner wall read 6% to 9% dark
  // with the seed; with 1.5 m patches, within 4% (docs/accuracy.md, change 10).
  const double texel = mean_texel_size(e, surface), free_path = options.mean_free_path_m;
  if (options.block_size <= 0 && free_path > 0 && block * texel > free_path) {
    int narrower = block;
    while (narrower > 1 && narrower * texel > free_path) narrower /= 2;
    std::vector<Keyed> narrower_keys = block_keys(e, surface, [&](size_t) { return narrower; });
    if (narrower * texel <= free_path && distinct_keys(narrower_keys) <= 2 * max_patches) {
      block = narrower;
      keys = std::move(narrower_keys);
    }
  }
  return patches_from_keys(e, surface, std::move(keys), block);
}

Patches split_patches(const Elements& e, const Surface& surface, const Patches& patches,
                      const std::vector<uint8_t>& split) {
  auto side_of = [&](size_t i) {
    uint32_t p = patches.patch_of_element[i];
    return split[p] && patches.side[p] > 1 ? patches.side[p] / 2 : patches.side[p];
  };
  return patches_from_keys(e, surface, block_keys(e, surface, side_of), patches.block_size);
}

}  // namespace radbake
