#include <algorithm>
#include <climits>
#include <cmath>
#include <numeric>

#include "uv/charts.h"
#include "uv/texel_coverage.h"

namespace radbake {
namespace {

Vec2 turned(Vec2 p, Vec2 extent, int quarter_turns) {
  switch (quarter_turns & 3) {
    case 1: return {extent.y - p.y, p.x};
    case 2: return {extent.x - p.x, extent.y - p.y};
    case 3: return {p.y, extent.x - p.x};
    default: return p;
  }
}

// A chart's texels at one scale and turn: which it covers, and per column the lowest and highest
// covered row and the lowest row its padding reaches.
struct Footprint {
  int width = 0, height = 0;  // covered grid, texels
  Vec2 shift;                 // added to the turned, scaled chart to centre it in its grid
  std::vector<int> cover_bottom, cover_top;  // per covered column; INT_MAX / INT_MIN when empty
  std::vector<int> pad_bottom;               // per column of the padded grid (width + 2 padding)
};

Footprint footprint(const Chart& chart, float scale, int turns, int padding) {
  Vec2 extent = chart.extent * scale;
  if (turns & 1) std::swap(extent.x, extent.y);
  Footprint fp;
  fp.width = std::max(1, int(std::ceil(extent.x)));
  fp.height = std::max(1, int(std::ceil(extent.y)));
  // Centred in its texels, so the partly covered texels on both sides are alike.
  fp.shift = {(float(fp.width) - extent.x) / 2, (float(fp.height) - extent.y) / 2};
  fp.cover_bottom.assign(size_t(fp.width), INT_MAX);
  fp.cover_top.assign(size_t(fp.width), INT_MIN);
  for (size_t t = 0; t < chart.triangles.size(); ++t) {
    Vec2 c[3];
    for (int k = 0; k < 3; ++k) c[k] = turned(chart.corner_uv[3 * t + k] * scale, chart.extent * scale, turns) + fp.shift;
    for_each_covered_texel(c[0], c[1], c[2], fp.width, fp.height, [&](const TexelPiece& p) {
      fp.cover_bottom[size_t(p.x)] = std::min(fp.cover_bottom[size_t(p.x)], p.y);
      fp.cover_top[size_t(p.x)] = std::max(fp.cover_top[size_t(p.x)], p.y);
    });
  }
  fp.pad_bottom.assign(size_t(fp.width + 2 * padding), INT_MAX);
  for (int x = 0; x < fp.width; ++x) {
    if (fp.cover_bottom[size_t(x)] == INT_MAX) continue;
    for (int d = 0; d <= 2 * padding; ++d)
      fp.pad_bottom[size_t(x + d)] = std::min(fp.pad_bottom[size_t(x + d)], fp.cover_bottom[size_t(x)] - padding);
  }
  return fp;
}

// A page's horizon: per column, the first row above everything placed there.
struct Page {
  int size;
  std::vector<int> horizon;
  int used_w = 0, used_h = 0;
};

struct Spot {
  int x = -1, y = INT_MAX;
};

// Where the footprint drops best (Levy et al. 2002, "Tetris"): at each column it falls onto the
// horizon; of those drops, the one that leaves the least empty space under it, lowest on ties.
Spot best_drop(const Page& page, const Footprint& fp, int padding) {
  Spot best;
  double best_score = INFINITY;
  for (int x = 0; x + fp.width <= page.size; ++x) {
    int y = 0;
    for (int j = 0; j < fp.width + 2 * padding; ++j) {
      int column = x - padding + j;
      if (column < 0 || column >= page.size || fp.pad_bottom[size_t(j)] == INT_MAX) continue;
      y = std::max(y, page.horizon[size_t(column)] - fp.pad_bottom[size_t(j)]);
    }
    if (y + fp.height > page.size) continue;
    double waste = 0;
    for (int j = 0; j < fp.width; ++j)
      if (fp.cover_bottom[size_t(j)] != INT_MAX) waste += y + fp.cover_bottom[size_t(j)] - page.horizon[size_t(x + j)];
    // Height counts too, so an empty page fills from the bottom instead of anywhere.
    double score = waste + 0.25 * double(y) * fp.width;
    if (score < best_score) best_score = score, best = {x, y};
  }
  return best;
}

void settle(Page& page, const Footprint& fp, Spot at) {
  for (int j = 0; j < fp.width; ++j)
    if (fp.cover_top[size_t(j)] != INT_MIN)
      page.horizon[size_t(at.x + j)] = std::max(page.horizon[size_t(at.x + j)], at.y + fp.cover_top[size_t(j)] + 1);
  page.used_w = std::max(page.used_w, at.x + fp.width);
  page.used_h = std::max(page.used_h, at.y + fp.height);
}

int round_up4(int v) { return (v + 3) / 4 * 4; }

}  // namespace

Vec2 placed_corner(const Chart& chart, const ChartPlacement& at, size_t corner) {
  Vec2 extent = chart.extent * at.scale;
  Vec2 turned_extent = (at.quarter_turns & 1) ? Vec2{extent.y, extent.x} : extent;
  Vec2 shift{(std::max(1.0f, std::ceil(turned_extent.x)) - turned_extent.x) / 2,
             (std::max(1.0f, std::ceil(turned_extent.y)) - turned_extent.y) / 2};
  return turned(chart.corner_uv[corner] * at.scale, extent, at.quarter_turns) + shift + Vec2{float(at.x), float(at.y)};
}

PackResult pack_charts(const std::vector<Chart>& charts, size_t mesh_count, float texel_density, int page_size,
                       int padding, bool may_rotate, UnwrapProgress& progress) {
  PackResult result;
  result.placements.assign(charts.size(), ChartPlacement{});
  std::vector<std::vector<size_t>> charts_of_mesh(mesh_count);
  for (size_t c = 0; c < charts.size(); ++c) charts_of_mesh[charts[c].mesh].push_back(c);

  // A mesh whose largest chart cannot fit a page at this density is shrunk, and reported: all
  // charts of a mesh share one page, since a page is bound per material.
  std::vector<float> mesh_scale(mesh_count, texel_density);
  std::vector<double> mesh_area(mesh_count, 0);
  for (size_t m = 0; m < mesh_count; ++m) {
    float largest = 0;
    for (size_t c : charts_of_mesh[m]) {
      Vec2 e = charts[c].extent;
      largest = std::max({largest, e.x, e.y});
      mesh_area[m] += double(e.x) * e.y;
    }
    float limit = float(page_size - 2 * padding - 2);
    if (largest * texel_density > limit) {
      mesh_scale[m] = limit / largest;
      result.downscaled_meshes.push_back(uint32_t(m));
    }
  }
  std::vector<size_t> mesh_order(mesh_count);
  std::iota(mesh_order.begin(), mesh_order.end(), 0);
  std::stable_sort(mesh_order.begin(), mesh_order.end(), [&](size_t a, size_t b) {
    return mesh_area[a] * mesh_scale[a] * mesh_scale[a] > mesh_area[b] * mesh_scale[b] * mesh_scale[b];
  });

  const int turns = may_rotate ? 2 : 1;  // upright and a quarter turn; half turns rarely fit better
  // Places `order` (charts, largest first) on `page`, or returns false leaving it as it was.
  auto place_on = [&](Page& page, int page_index, const std::vector<size_t>& order) {
    Page trial = page;
    std::vector<ChartPlacement> placed(order.size());
    for (size_t k = 0; k < order.size(); ++k) {
      progress.poll();
      const Chart& chart = charts[order[k]];
      const float scale = mesh_scale[chart.mesh];
      Spot best;
      int best_turn = 0, best_top = INT_MAX;
      Footprint best_shape;
      for (int r = 0; r < turns; ++r) {
        Footprint shape = footprint(chart, scale, r, padding);
        Spot s = best_drop(trial, shape, padding);
        int top = s.x < 0 ? INT_MAX : s.y + shape.height;
        if (s.x >= 0 && (top < best_top || (top == best_top && s.y < best.y)))
          best = s, best_turn = r, best_top = top, best_shape = std::move(shape);
      }
      if (best.x < 0) return false;
      settle(trial, best_shape, best);
      placed[k] = {page_index, best.x, best.y, scale, best_turn};
    }
    page = std::move(trial);
    for (size_t k = 0; k < order.size(); ++k) result.placements[order[k]] = placed[k];
    return true;
  };
  auto largest_first = [&](std::vector<size_t>& order) {
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
      float sa = mesh_scale[charts[a].mesh], sb = mesh_scale[charts[b].mesh];
      return charts[a].extent.x * charts[a].extent.y * sa * sa > charts[b].extent.x * charts[b].extent.y * sb * sb;
    });
  };

  // Everything on one page if it fits: then meshes need not go one after another, and all
  // charts are packed largest first together, which packs tighter.
  std::vector<size_t> all(charts.size());
  std::iota(all.begin(), all.end(), 0);
  largest_first(all);
  std::vector<Page> pages(1, Page{page_size, std::vector<int>(size_t(page_size), 0), 0, 0});
  if (charts.empty() || !place_on(pages[0], 0, all)) {
    pages.clear();
    for (size_t m : mesh_order) {
      if (charts_of_mesh[m].empty()) continue;
      std::vector<size_t> order = charts_of_mesh[m];
      largest_first(order);
      bool placed = false;
      for (size_t p = 0; p < pages.size() && !placed; ++p) placed = place_on(pages[p], int(p), order);
      // Not even an empty page holds the mesh at this scale: it shrinks until one does.
      for (bool shrunk = false; !placed; shrunk = true) {
        Page empty{page_size, std::vector<int>(size_t(page_size), 0), 0, 0};
        if (place_on(empty, int(pages.size()), order)) {
          pages.push_back(std::move(empty));
          placed = true;
        } else {
          mesh_scale[m] *= 0.9f;
        }
        if (shrunk && (result.downscaled_meshes.empty() || result.downscaled_meshes.back() != m))
          result.downscaled_meshes.push_back(uint32_t(m));
      }
    }
  }
  for (size_t c = 0; c < charts.size(); ++c) result.placements[c].scale = mesh_scale[charts[c].mesh];
  for (const Page& p : pages)
    result.pages.push_back({std::min(page_size, round_up4(p.used_w + padding)), std::min(page_size, round_up4(p.used_h + padding))});
  return result;
}

}  // namespace radbake
