// Conservative rasterisation of a triangle over a texel grid: every texel the triangle overlaps,
// with the exact overlap area and its centroid (the clipped polygon's), so partly covered texels
// at chart edges count and their sample point stays on the surface.
#pragma once

#include <algorithm>
#include <cmath>

#include "base/math.h"

namespace radbake {

struct TexelPiece {
  int x, y;        // texel column and row
  float area;      // overlap with the texel, in texels^2 (0 < area <= 1)
  Vec2 centroid;   // of the overlap, in texel units of the whole page
};

namespace detail {

// Clips polygon `in` (n vertices) to the half-plane sign * (p[axis] - bound) >= 0.
inline int clip_polygon(const Vec2* in, int n, Vec2* out, int axis, float bound, float sign) {
  int m = 0;
  for (int i = 0; i < n; ++i) {
    Vec2 a = in[i], b = in[(i + 1) % n];
    float da = sign * ((axis == 0 ? a.x : a.y) - bound);
    float db = sign * ((axis == 0 ? b.x : b.y) - bound);
    if (da >= 0) out[m++] = a;
    if ((da >= 0) != (db >= 0)) {
      float t = da / (da - db);
      Vec2 p = a + (b - a) * t;
      if (axis == 0) p.x = bound; else p.y = bound;
      out[m++] = p;
    }
  }
  return m;
}

// Signed area and area-weighted centroid of a polygon.
inline float polygon_area_centroid(const Vec2* p, int n, Vec2& centroid) {
  double a = 0, cx = 0, cy = 0;
  for (int i = 0; i < n; ++i) {
    Vec2 u = p[i], v = p[(i + 1) % n];
    double w = double(u.x) * v.y - double(v.x) * u.y;
    a += w;
    cx += (double(u.x) + v.x) * w;
    cy += (double(u.y) + v.y) * w;
  }
  if (a != 0) centroid = {float(cx / (3 * a)), float(cy / (3 * a))};
  return float(a / 2);
}

}  // namespace detail

// Calls visit(TexelPiece) for each texel of a width x height grid that triangle (a, b, c), given
// in texel units, overlaps with positive area. Winding does not matter.
template <typename Visit>
void for_each_covered_texel(Vec2 a, Vec2 b, Vec2 c, int width, int height, Visit&& visit) {
  float min_x = std::min({a.x, b.x, c.x}), max_x = std::max({a.x, b.x, c.x});
  float min_y = std::min({a.y, b.y, c.y}), max_y = std::max({a.y, b.y, c.y});
  if (!(min_x < max_x) || !(min_y < max_y)) return;  // degenerate or non-finite
  int x0 = std::max(0, int(std::floor(min_x))), x1 = std::min(width - 1, int(std::floor(max_x)));
  int y0 = std::max(0, int(std::floor(min_y))), y1 = std::min(height - 1, int(std::floor(max_y)));
  Vec2 tri[3] = {a, b, c};
  Vec2 row[8], cell[8], tmp[8];
  for (int y = y0; y <= y1; ++y) {
    int n = detail::clip_polygon(tri, 3, tmp, 1, float(y), 1.0f);
    n = detail::clip_polygon(tmp, n, row, 1, float(y + 1), -1.0f);
    if (n < 3) continue;
    for (int x = x0; x <= x1; ++x) {
      int k = detail::clip_polygon(row, n, tmp, 0, float(x), 1.0f);
      k = detail::clip_polygon(tmp, k, cell, 0, float(x + 1), -1.0f);
      if (k < 3) continue;
      Vec2 centroid{x + 0.5f, y + 0.5f};
      float area = std::fabs(detail::polygon_area_centroid(cell, k, centroid));
      if (area > 1e-7f) visit(TexelPiece{x, y, std::min(area, 1.0f), centroid});
    }
  }
}

// Calls visit(y, first, last) with each row y of the grid that triangle (a, b, c) overlaps and the
// columns [first, last] it spans there: every texel for_each_covered_texel visits and, in rare
// cases, a neighbour it touches with almost no area. Cheaper, for packing, where erring towards
// more texels is safe.
template <typename Visit>
void for_each_covered_span(Vec2 a, Vec2 b, Vec2 c, int width, int height, Visit&& visit) {
  float min_x = std::min({a.x, b.x, c.x}), max_x = std::max({a.x, b.x, c.x});
  float min_y = std::min({a.y, b.y, c.y}), max_y = std::max({a.y, b.y, c.y});
  if (!(min_x < max_x) || !(min_y < max_y)) return;  // degenerate or non-finite
  int y0 = std::max(0, int(std::floor(min_y))), y1 = std::min(height - 1, int(std::floor(max_y)));
  Vec2 tri[3] = {a, b, c};
  Vec2 row[8], tmp[8];
  for (int y = y0; y <= y1; ++y) {
    int n = detail::clip_polygon(tri, 3, tmp, 1, float(y), 1.0f);
    n = detail::clip_polygon(tmp, n, row, 1, float(y + 1), -1.0f);
    Vec2 centroid;
    if (n < 3 || std::fabs(detail::polygon_area_centroid(row, n, centroid)) <= 1e-7f) continue;
    float lo = row[0].x, hi = row[0].x;
    for (int k = 1; k < n; ++k) lo = std::min(lo, row[k].x), hi = std::max(hi, row[k].x);
    // The row's piece is convex with some area, so every column strictly between lo and hi cuts
    // some of it.
    int first = std::max(0, int(std::floor(lo))), last = std::min(width - 1, int(std::ceil(hi)) - 1);
    if (first <= last) visit(y, first, last);
  }
}

}  // namespace radbake
