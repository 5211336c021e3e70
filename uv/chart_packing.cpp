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

// The lowest place the footprint can drop to, scanning every column (Levy et al. 2002, "Tetris").
Spot lowest_spot(const Page& page, const Footprint& fp, int padding) {
  Spot best;
  int best_top = INT_MAX;
  for (int x = 0; x + fp.width <= page.size; ++x) {
    int y = 0;
    for (int j = 0; j < fp.width + 2 * padding; ++j) {
      int column = x - padding + j;
      if (column < 0 || column >= page.size || fp.pad_bottom[size_t(j)] == INT_MAX) continue;
      y = std::max(y, page.horizon[size_t(column)] - fp.pad_bottom[size_t(j)]);
    }
    int top = y + fp.height;
    if (top > page.size) continue;
    if (y < best.y || (y == best.y && top < best_top)) best = {x, y}, best_top = top;
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
                       int padding, bool may_rotate) {
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

  std::vector<Page> pages;
  const int turns = may_rotate ? 2 : 1;  // upright and a quarter turn; half turns rarely fit better
  for (size_t m : mesh_order) {
    if (charts_of_mesh[m].empty()) continue;
    std::vector<size_t> order = charts_of_mesh[m];
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
      return charts[a].extent.x * charts[a].extent.y > charts[b].extent.x * charts[b].extent.y;
    });
    std::vector<std::vector<Footprint>> shapes(order.size());
    for (size_t k = 0; k < order.size(); ++k)
      for (int r = 0; r < turns; ++r) shapes[k].push_back(footprint(charts[order[k]], mesh_scale[m], r, padding));
    for (size_t p = 0; p <= pages.size(); ++p) {
      if (p == pages.size()) pages.push_back({page_size, std::vector<int>(size_t(page_size), 0), 0, 0});
      Page trial = pages[p];
      std::vector<ChartPlacement> placed(order.size());
      bool fits = true;
      for (size_t k = 0; k < order.size() && fits; ++k) {
        Spot best;
        int best_turn = 0, best_top = INT_MAX;
        for (int r = 0; r < turns; ++r) {
          Spot s = lowest_spot(trial, shapes[k][size_t(r)], padding);
          int top = s.x < 0 ? INT_MAX : s.y + shapes[k][size_t(r)].height;
          if (s.x >= 0 && (top < best_top || (top == best_top && s.y < best.y))) best = s, best_turn = r, best_top = top;
        }
        if (best.x < 0) {
          fits = false;
          break;
        }
        settle(trial, shapes[k][size_t(best_turn)], best);
        placed[k] = {int(p), best.x, best.y, mesh_scale[m], best_turn};
      }
      if (!fits) continue;
      pages[p] = std::move(trial);
      for (size_t k = 0; k < order.size(); ++k) result.placements[order[k]] = placed[k];
      break;
    }
  }
  for (size_t c = 0; c < charts.size(); ++c) result.placements[c].scale = mesh_scale[charts[c].mesh];
  for (const Page& p : pages)
    result.pages.push_back({std::min(page_size, round_up4(p.used_w + padding)), std::min(page_size, round_up4(p.used_h + padding))});
  return result;
}

}  // namespace radbake
