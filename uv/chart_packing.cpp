#include <algorithm>
#include <climits>
#include <cmath>
#include <numeric>
#include <unordered_map>

#include "uv/charts.h"
#include "uv/page_bitmap.h"
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

// A chart's texels at one scale and turn, row by row: the spans it covers.
struct Footprint {
  int width = 0, height = 0;  // covered grid, texels
  Vec2 shift;                 // added to the turned, scaled chart to centre it in its grid
  std::vector<int> row_start;                 // height + 1 offsets into spans
  std::vector<std::pair<int, int>> spans;     // covered columns [first, last], row by row
  std::vector<int> widest;                    // per row: its widest span
  std::vector<int> widest_first;              // rows, widest span first
  uint64_t shape = 0;                         // a hash of all the above but shift: equal shapes search alike
};

Footprint footprint(const Chart& chart, float scale, int turns) {
  Vec2 extent = chart.extent * scale;
  if (turns & 1) std::swap(extent.x, extent.y);
  Footprint fp;
  fp.width = std::max(1, int(std::ceil(extent.x)));
  fp.height = std::max(1, int(std::ceil(extent.y)));
  // Centred in its texels, so the partly covered texels on both sides are alike.
  fp.shift = {(float(fp.width) - extent.x) / 2, (float(fp.height) - extent.y) / 2};
  std::vector<uint8_t> covered(size_t(fp.width) * size_t(fp.height), 0);
  for (size_t t = 0; t < chart.triangles.size(); ++t) {
    Vec2 c[3];
    for (int k = 0; k < 3; ++k) c[k] = turned(chart.corner_uv[3 * t + k] * scale, chart.extent * scale, turns) + fp.shift;
    for_each_covered_span(c[0], c[1], c[2], fp.width, fp.height, [&](int y, int first, int last) {
      std::fill_n(&covered[size_t(y) * size_t(fp.width) + size_t(first)], last - first + 1, uint8_t(1));
    });
  }
  uint64_t hash = 1469598103934665603ull;  // FNV-1a over the spans
  auto mix = [&](uint64_t v) { hash = (hash ^ v) * 1099511628211ull; };
  mix(uint64_t(fp.width)), mix(uint64_t(fp.height));
  fp.widest.assign(size_t(fp.height), 0);
  for (int y = 0; y < fp.height; ++y) {
    fp.row_start.push_back(int(fp.spans.size()));
    const uint8_t* row = &covered[size_t(y) * size_t(fp.width)];
    for (int x = 0; x < fp.width;) {
      if (!row[x]) { ++x; continue; }
      int last = x;
      while (last + 1 < fp.width && row[last + 1]) ++last;
      fp.spans.push_back({x, last});
      fp.widest[size_t(y)] = std::max(fp.widest[size_t(y)], last - x + 1);
      mix(uint64_t(y) << 40 | uint64_t(x) << 20 | uint64_t(last));
      x = last + 1;
    }
  }
  fp.row_start.push_back(int(fp.spans.size()));
  fp.shape = hash;
  fp.widest_first.resize(size_t(fp.height));
  std::iota(fp.widest_first.begin(), fp.widest_first.end(), 0);
  std::stable_sort(fp.widest_first.begin(), fp.widest_first.end(), [&](int a, int b) { return fp.widest[size_t(a)] > fp.widest[size_t(b)]; });
  return fp;
}

struct Spot {
  int x = 0, y = 0;
};

// A page as a bitmap of where a chart's texels may not go: the texels of the charts placed so
// far, grown by the padding. A new chart fits where none of its own texels is blocked, so it can
// go anywhere there is room: inside a ring-shaped chart, under an overhang, between two others.
struct Page {
  // The bitmap is square, the page's longer side; texels outside width x height start taken.
  Page(int width, int height)
      : width(width), height(height), blocked(std::max(width, height)), free_run(size_t(blocked.size()), width) {
    for (int y = 0; y < blocked.size(); ++y) {
      if (y >= height) blocked.take(y, 0, blocked.size() - 1), free_run[size_t(y)] = 0;
      else if (width < blocked.size()) blocked.take(y, width, blocked.size() - 1);
    }
  }
  int width, height;
  PageBitmap blocked;
  std::vector<int> free_run;  // per row, its longest run of free texels
  // Per shape, where it was last placed: texels only get blocked, so no spot before it fits it.
  std::unordered_map<uint64_t, Spot> resume;
  std::vector<uint64_t> fits;  // fit_in_row's scratch
  int used_w = 0, used_h = 0;
};

// The leftmost x at or after `x` where the footprint's texels are all free with its bottom row on
// row y, or -1. Every x of the row is tried at once, as a bitmask narrowed span by span, widest row
// first, until one is left or none.
int fit_in_row(Page& page, const Footprint& fp, int y, int x) {
  const int last_x = page.width - fp.width;
  if (x > last_x) return -1;
  for (int r : fp.widest_first)
    if (fp.widest[size_t(r)] > page.free_run[size_t(y + r)]) return -1;
  int w0 = x >> 6, w1 = last_x >> 6;
  std::vector<uint64_t>& fits = page.fits;
  fits.assign(size_t(w1) + 1, ~uint64_t(0));
  fits[size_t(w0)] &= ~uint64_t(0) << (x & 63);
  fits[size_t(w1)] &= ~uint64_t(0) >> (63 - (last_x & 63));
  for (int r : fp.widest_first) {
    for (int s = fp.row_start[size_t(r)]; s < fp.row_start[size_t(r) + 1]; ++s) {
      auto [first, last] = fp.spans[size_t(s)];
      page.blocked.keep_fitting(y + r, first, last - first + 1, fits.data(), w0, w1);
    }
    while (w0 <= w1 && !fits[size_t(w0)]) ++w0;
    while (w1 >= w0 && !fits[size_t(w1)]) --w1;
    if (w0 > w1) return -1;
  }
  return (w0 << 6) + __builtin_ctzll(fits[size_t(w0)]);
}

// Where the search for a footprint may start: where this shape was last placed, since no spot
// before it fitted then.
Spot search_start(const Page& page, const Footprint& fp) {
  auto resumed = page.resume.find(fp.shape);
  return resumed != page.resume.end() ? resumed->second : Spot{0, 0};
}

// Of the turns of a chart, the one whose top ends lowest where it first fits, and where: the turns
// are searched together, row by row, so a turn that would end higher than one already found is
// not searched further. Returns the turn, or -1 when none fits.
int lowest_turn(Page& page, const Footprint* shapes, int turns, Spot& at) {
  Spot start[2];
  int last_row[2] = {-1, -1}, best = -1;
  for (int t = 0; t < turns; ++t) {
    start[t] = search_start(page, shapes[t]);
    last_row[t] = page.height - shapes[t].height;
  }
  for (int y = std::min(start[0].y, turns > 1 ? start[1].y : INT_MAX); y <= std::max(last_row[0], last_row[1]); ++y)
    for (int t = 0; t < turns; ++t) {
      if (y < start[t].y || y > last_row[t]) continue;
      const int x = fit_in_row(page, shapes[t], y, y == start[t].y ? start[t].x : 0);
      if (x < 0) continue;
      best = t, at = {x, y};
      for (int u = 0; u < turns; ++u) last_row[u] = std::min(last_row[u], y + shapes[t].height - shapes[u].height - 1);
    }
  return best;
}

void settle(Page& page, const Footprint& fp, Spot at, int padding) {
  for (int r = 0; r < fp.height; ++r)
    for (int s = fp.row_start[size_t(r)]; s < fp.row_start[size_t(r) + 1]; ++s)
      for (int d = -padding; d <= padding; ++d)
        page.blocked.take(at.y + r + d, at.x + fp.spans[size_t(s)].first - padding, at.x + fp.spans[size_t(s)].second + padding);
  for (int y = std::max(0, at.y - padding); y < std::min(page.height, at.y + fp.height + padding); ++y)
    page.free_run[size_t(y)] = page.blocked.longest_free_run(y);
  page.resume[fp.shape] = at;
  page.used_w = std::max(page.used_w, at.x + fp.width);
  page.used_h = std::max(page.used_h, at.y + fp.height);
}

int round_up4(int v) { return (v + 3) / 4 * 4; }

// Up to this many charts, packing one page takes milliseconds, and other arrangements are tried.
constexpr size_t kFewCharts = 256;

}  // namespace

Vec2 placed_corner(const Chart& chart, const ChartPlacement& at, size_t corner) {
  Vec2 extent = chart.extent * at.scale;
  Vec2 turned_extent = (at.quarter_turns & 1) ? Vec2{extent.y, extent.x} : extent;
  Vec2 shift{(std::max(1.0f, std::ceil(turned_extent.x)) - turned_extent.x) / 2,
             (std::max(1.0f, std::ceil(turned_extent.y)) - turned_extent.y) / 2};
  return turned(chart.corner_uv[corner] * at.scale, extent, at.quarter_turns) + shift + Vec2{float(at.x), float(at.y)};
}

PackResult pack_charts(const std::vector<Chart>& charts, size_t mesh_count, float texel_density, AtlasPage page_size,
                       int padding, bool may_rotate, PackGoal goal, UnwrapProgress& progress) {
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
    float limit = float(std::min(page_size.width, page_size.height) - 2 * padding - 2);
    if (largest * texel_density > limit) {
      mesh_scale[m] = limit / largest;
      result.downscaled_meshes.push_back(uint32_t(m));
    }
  }
  if (goal == PackGoal::OnePageOrNothing && !result.downscaled_meshes.empty()) return result;
  std::vector<size_t> mesh_order(mesh_count);
  std::iota(mesh_order.begin(), mesh_order.end(), 0);
  std::stable_sort(mesh_order.begin(), mesh_order.end(), [&](size_t a, size_t b) {
    return mesh_area[a] * mesh_scale[a] * mesh_scale[a] > mesh_area[b] * mesh_scale[b] * mesh_scale[b];
  });

  const int turns = may_rotate ? 2 : 1;  // upright and a quarter turn; half turns rarely fit better
  // Places `order` (charts, largest first) on `page`, or returns false leaving it as it was.
  double placed_area = 0, total_area = 0;  // texels^2 of chart extents, for placed_share
  auto extent_area = [&](size_t c) {
    const float scale = mesh_scale[charts[c].mesh];
    return double(charts[c].extent.x * scale) * double(charts[c].extent.y * scale);
  };
  // With first_turn >= 0 the first chart is placed at that turn only.
  auto place_on = [&](Page& page, int page_index, const std::vector<size_t>& order, int first_turn = -1) {
    Page trial = page;
    std::vector<ChartPlacement> placed(order.size());
    placed_area = 0;
    for (size_t k = 0; k < order.size(); ++k) {
      progress.poll();
      const Chart& chart = charts[order[k]];
      const float scale = mesh_scale[chart.mesh];
      const bool forced = k == 0 && first_turn >= 0;
      Footprint shapes[2];
      for (int r = 0; r < (forced ? 1 : turns); ++r) shapes[r] = footprint(chart, scale, forced ? first_turn : r);
      Spot best;
      const int found = lowest_turn(trial, shapes, forced ? 1 : turns, best);
      if (found < 0) return false;
      settle(trial, shapes[found], best, padding);
      placed[k] = {page_index, best.x, best.y, scale, forced ? first_turn : found};
      placed_area += extent_area(order[k]);
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
  // charts are packed largest first together, which packs tighter. A few large charts (a room's
  // floor and walls) can block each other where another arrangement fits: when packing takes
  // milliseconds, the largest chart turned the other way, and charts longest side first, are
  // tried too.
  std::vector<size_t> all(charts.size());
  std::iota(all.begin(), all.end(), 0);
  largest_first(all);
  for (size_t c : all) total_area += extent_area(c);
  if (charts.empty()) return result;
  std::vector<Page> pages(1, Page(page_size.width, page_size.height));
  bool on_one_page = place_on(pages[0], 0, all);
  const double largest_first_share = placed_area / total_area;
  if (!on_one_page && charts.size() <= kFewCharts) {
    std::vector<size_t> longest_side_first = all;
    std::stable_sort(longest_side_first.begin(), longest_side_first.end(), [&](size_t a, size_t b) {
      Vec2 ea = charts[a].extent * mesh_scale[charts[a].mesh], eb = charts[b].extent * mesh_scale[charts[b].mesh];
      return std::max(ea.x, ea.y) > std::max(eb.x, eb.y);
    });
    for (int turn = 0; turn < turns && !on_one_page; ++turn) on_one_page = place_on(pages[0], 0, all, turn);
    on_one_page = on_one_page || place_on(pages[0], 0, longest_side_first);
  }
  if (!on_one_page && goal == PackGoal::OnePageOrNothing) {
    result.placed_share = largest_first_share;
    return result;
  }
  if (!on_one_page) {
    pages.clear();
    for (size_t m : mesh_order) {
      if (charts_of_mesh[m].empty()) continue;
      std::vector<size_t> order = charts_of_mesh[m];
      largest_first(order);
      bool placed = false;
      for (size_t p = 0; p < pages.size() && !placed; ++p) placed = place_on(pages[p], int(p), order);
      // Not even an empty page holds the mesh at this scale: it shrinks until one does.
      for (bool shrunk = false; !placed; shrunk = true) {
        Page empty(page_size.width, page_size.height);
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
    result.pages.push_back({std::min(page_size.width, round_up4(p.used_w + padding)),
                            std::min(page_size.height, round_up4(p.used_h + padding))});
  return result;
}

}  // namespace radbake
