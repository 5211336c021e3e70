#include <algorithm>
#include <cmath>
#include <numeric>

#include "uv/charts.h"

namespace radbake {
namespace {

struct Rect {
  size_t chart;
  int w, h;  // texels, padding included
};

// Shelf packing, tallest first. Returns false when the rectangles do not fit a size x size page.
struct Spot {
  size_t chart;
  int x, y;
};

bool shelf_pack(std::vector<Rect> rects, int size, int padding, std::vector<Spot>& spots, int& used_w,
                int& used_h) {
  std::stable_sort(rects.begin(), rects.end(), [](const Rect& a, const Rect& b) { return a.h > b.h; });
  int x = padding, y = padding, shelf_h = 0;
  used_w = used_h = 0;
  spots.clear();
  for (const Rect& r : rects) {
    if (r.w + padding > size || r.h + padding > size) return false;
    if (x + r.w > size) {
      y += shelf_h;
      x = padding;
      shelf_h = 0;
    }
    if (y + r.h > size) return false;
    spots.push_back({r.chart, x, y});
    used_w = std::max(used_w, x + r.w);
    used_h = std::max(used_h, y + r.h);
    x += r.w;
    shelf_h = std::max(shelf_h, r.h);
  }
  return true;
}

int round_up4(int v) { return (v + 3) / 4 * 4; }

}  // namespace

PackResult pack_charts(const std::vector<Chart>& charts, size_t mesh_count, float texel_density,
                       int page_size, int padding) {
  PackResult result;
  result.placements.assign(charts.size(), ChartPlacement{});
  std::vector<std::vector<size_t>> charts_of_mesh(mesh_count);
  for (size_t c = 0; c < charts.size(); ++c) charts_of_mesh[charts[c].mesh].push_back(c);

  // A mesh whose largest chart cannot fit a page at the requested density is shrunk, and the
  // atlas reports it: all its charts must share one page, since a page is bound per material.
  std::vector<float> mesh_scale(mesh_count, texel_density);
  for (size_t m = 0; m < mesh_count; ++m) {
    float largest = 0;
    for (size_t c : charts_of_mesh[m]) largest = std::max({largest, charts[c].extent.x, charts[c].extent.y});
    float limit = float(page_size - 2 * padding - 1);
    if (largest * texel_density > limit) {
      mesh_scale[m] = limit / largest;
      result.downscaled_meshes.push_back(uint32_t(m));
    }
  }
  auto rect_of = [&](size_t c) {
    float s = mesh_scale[charts[c].mesh];
    return Rect{c, std::max(1, int(std::ceil(charts[c].extent.x * s))) + padding,
                std::max(1, int(std::ceil(charts[c].extent.y * s))) + padding};
  };

  // Meshes go to the first page their charts still fit on, largest meshes first.
  std::vector<size_t> order(mesh_count);
  std::iota(order.begin(), order.end(), 0);
  std::vector<double> mesh_area(mesh_count, 0);
  for (size_t c = 0; c < charts.size(); ++c) {
    Rect r = rect_of(c);
    mesh_area[charts[c].mesh] += double(r.w) * r.h;
  }
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return mesh_area[a] > mesh_area[b]; });
  std::vector<std::vector<Rect>> page_rects;
  std::vector<std::pair<int, int>> page_used;
  for (size_t m : order) {
    if (charts_of_mesh[m].empty()) continue;
    std::vector<Rect> mine;
    for (size_t c : charts_of_mesh[m]) mine.push_back(rect_of(c));
    bool placed = false;
    for (size_t p = 0; p <= page_rects.size() && !placed; ++p) {
      if (p == page_rects.size()) page_rects.emplace_back(), page_used.emplace_back(0, 0);
      std::vector<Rect> trial = page_rects[p];
      trial.insert(trial.end(), mine.begin(), mine.end());
      int w, h;
      std::vector<Spot> spots;
      if (shelf_pack(trial, page_size, padding, spots, w, h)) {
        for (const Spot& s : spots) result.placements[s.chart] = {int(p), s.x, s.y, 1};
        page_rects[p] = std::move(trial);
        page_used[p] = {w, h};
        placed = true;
      }
    }
  }
  for (size_t c = 0; c < charts.size(); ++c) result.placements[c].scale = mesh_scale[charts[c].mesh];
  for (auto [w, h] : page_used)
    result.pages.push_back({std::min(page_size, round_up4(w + padding)), std::min(page_size, round_up4(h + padding))});
  return result;
}

}  // namespace radbake
