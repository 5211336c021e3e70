#include "baker/surface/elements.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "uv/texel_coverage.h"

namespace radbake {
namespace {

struct Piece {
  uint32_t page, texel, triangle;
  float area;     // texels^2
  Vec2 centroid;  // page texel units
};

// Barycentrics (b1, b2) of point p in the triangle's lightmap coordinates.
Vec2 lightmap_bary(const Surface& s, uint32_t t, Vec2 p) {
  const Vec2* c = &s.corner_lightmap[3 * t];
  float det = cross2(c[1] - c[0], c[2] - c[0]);
  if (det == 0) return {1.0f / 3, 1.0f / 3};
  Vec2 d = p - c[0];
  return {cross2(d, c[2] - c[0]) / det, cross2(c[1] - c[0], d) / det};
}

bool inside(Vec2 bary, float slack = 0) {
  return bary.x >= -slack && bary.y >= -slack && bary.x + bary.y <= 1 + slack;
}

}  // namespace

float ray_offset(Vec3 p, float texel_size) {
  float magnitude = std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
  return std::max(1e-3f * texel_size, 64.0f * magnitude * 1.2e-7f);
}

Elements build_elements(const Surface& surface, const MaterialSampler& materials, const ElementOptions& options,
                        Progress& progress) {
  const size_t triangle_count = surface.triangle_count();
  progress.begin("elements", triangle_count + 1);
  // One list, filled in triangle order: rasterising is quick next to the sort, and a second copy
  // of the pieces (per thread, then merged) would double this stage's memory peak.
  std::vector<Piece> pieces;
  for (size_t t = 0; t < triangle_count; ++t) {
    if (!(surface.area[t] > 0) || surface.chart[t] == UINT32_MAX) continue;
    const AtlasPage& page = surface.pages[surface.page[t]];
    const Vec2* c = &surface.corner_lightmap[3 * t];
    for_each_covered_texel(c[0], c[1], c[2], page.width, page.height, [&](const TexelPiece& p) {
      pieces.push_back({surface.page[t], uint32_t(p.y * page.width + p.x), uint32_t(t), p.area, p.centroid});
    });
    if (t % 4096 == 0) progress.advance(4096);
  }
  std::sort(pieces.begin(), pieces.end(), [](const Piece& a, const Piece& b) {
    return a.page != b.page ? a.page < b.page : a.texel != b.texel ? a.texel < b.texel : a.triangle < b.triangle;
  });

  // Group pieces by texel.
  std::vector<uint32_t> group_start;
  for (size_t i = 0; i < pieces.size(); ++i)
    if (i == 0 || pieces[i].page != pieces[i - 1].page || pieces[i].texel != pieces[i - 1].texel)
      group_start.push_back(uint32_t(i));
  group_start.push_back(uint32_t(pieces.size()));
  const size_t n = group_start.size() - 1;

  Elements e;
  e.position.resize(n);
  e.normal.resize(n);
  e.area.resize(n);
  e.reflectance.resize(n);
  e.emission.resize(n);
  e.triangle.resize(n);
  e.page.resize(n);
  e.texel.resize(n);
  e.flags.assign(n, 0);
  e.offset.resize(n);
  e.visible_cells.assign(n, 0xffff);
  e.element_at.resize(surface.pages.size());
  for (size_t p = 0; p < surface.pages.size(); ++p)
    e.element_at[p].assign(size_t(surface.pages[p].width) * surface.pages[p].height, -1);

  bool any_see_through = false;
  for (uint32_t t = 0; t < surface.triangle_count() && !any_see_through; ++t) any_see_through = materials.see_through(t);
  if (any_see_through) e.opacity.assign(n, 1.0f);
  const int k = std::max(1, options.footprint_samples);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 1024), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i) {
      const Piece* first = &pieces[group_start[i]];
      const Piece* last = &pieces[group_start[i + 1]];
      const Piece* largest = first;
      double area = 0;
      bool uniform = options.filter != FootprintFilter::Everywhere, flat = true;
      double covered = 0;  // texels^2
      const uint32_t t0 = first->triangle;
      for (const Piece* p = first; p != last; ++p) {
        covered += p->area;
        const uint32_t tp = p->triangle;
        flat &= surface.chart[tp] == surface.chart[t0] && dot(surface.normal[tp], surface.normal[t0]) > 0.9999f &&
                std::fabs(dot(surface.corners[3 * tp] - surface.corners[3 * t0], surface.normal[t0])) <=
                    1e-4f * std::sqrt(surface.area[t0] + surface.area[tp]);
        const Vec2* c = &surface.corner_lightmap[3 * p->triangle];
        float lm_area = 0.5f * std::fabs(cross2(c[1] - c[0], c[2] - c[0]));
        area += double(p->area) * surface.area[p->triangle] / lm_area;
        if (p->area > largest->area) largest = p;
        uniform &= surface.material[p->triangle] == surface.material[first->triangle] &&
                   (options.filter == FootprintFilter::BetweenMaterials || materials.is_uniform(p->triangle));
      }
      uint32_t t = largest->triangle;
      const bool whole_plane = flat && covered > 0.999;
      // A texel one plane covers whole has its sample at its centre, where its mean lies.
      const uint32_t width = uint32_t(surface.pages[largest->page].width);
      const Vec2 centre{float(largest->texel % width) + 0.5f, float(largest->texel / width) + 0.5f};
      Vec2 bary = lightmap_bary(surface, t, whole_plane ? centre : largest->centroid);
      e.position[i] = surface.point(t, bary);
      e.normal[i] = surface.shading_normal(t, bary);
      e.area[i] = float(area);
      e.triangle[i] = t;
      e.page[i] = largest->page;
      e.texel[i] = largest->texel;
      e.offset[i] = ray_offset(e.position[i], surface.texel_size(t));
      if (whole_plane) e.flags[i] |= kFlatTexel;

      if (uniform) {
        if (any_see_through) e.opacity[i] = 1 - materials.diffuse_transmittance(t, bary);
        e.reflectance[i] = materials.reflectance(t, bary, 1.0f);
        e.emission[i] = materials.emission(t, bary, 1.0f);
        continue;
      }
      // Box filter over the footprint: k x k points, each on whichever piece's triangle holds it.
      e.flags[i] |= kFiltered;
      const AtlasPage& page = surface.pages[largest->page];
      Vec2 corner{float(largest->texel % uint32_t(page.width)), float(largest->texel / uint32_t(page.width))};
      Rgb rho{}, emit{};
      float stops = 0;
      int hits = 0;
      for (int sy = 0; sy < k; ++sy)
        for (int sx = 0; sx < k; ++sx) {
          Vec2 at{corner.x + (sx + 0.5f) / k, corner.y + (sy + 0.5f) / k};
          for (const Piece* p = first; p != last; ++p) {
            Vec2 b = lightmap_bary(surface, p->triangle, at);
            if (!inside(b)) continue;
            rho += materials.reflectance(p->triangle, b, 1.0f / k);
            emit += materials.emission(p->triangle, b, 1.0f / k);
            if (any_see_through) stops += 1 - materials.diffuse_transmittance(p->triangle, b);
            ++hits;
            break;
          }
        }
      if (hits == 0) {  // a sliver between the sample points: its own sample point decides
        rho = materials.reflectance(t, bary, 1.0f);
        emit = materials.emission(t, bary, 1.0f);
        if (any_see_through) stops = 1 - materials.diffuse_transmittance(t, bary);
        hits = 1;
      }
      e.reflectance[i] = rho / float(hits);
      e.emission[i] = emit / float(hits);
      if (any_see_through) e.opacity[i] = stops / float(hits);
    }
  });
  for (size_t i = 0; i < n; ++i) e.element_at[e.page[i]][e.texel[i]] = int32_t(i);
  for (size_t i = 0; i < n; ++i) {
    if ((e.flags[i] & kFlatTexel) || group_start[i + 1] - group_start[i] < 2) continue;
    const size_t first = e.other_pieces.size();
    for (uint32_t k = group_start[i]; k < group_start[i + 1]; ++k)
      e.other_pieces.push_back({uint32_t(i), pieces[k].triangle, lightmap_bary(surface, pieces[k].triangle, pieces[k].centroid),
                                pieces[k].area});
    std::sort(e.other_pieces.begin() + std::ptrdiff_t(first), e.other_pieces.end(),
              [](const Elements::Piece& a, const Elements::Piece& b) { return a.area > b.area; });
  }
  progress.end();
  return e;
}

int64_t element_at_point(const Elements& elements, const Surface& surface, uint32_t triangle, Vec2 bary) {
  const uint32_t page_index = surface.page[triangle];
  const AtlasPage& page = surface.pages[page_index];
  const std::vector<int32_t>& at = elements.element_at[page_index];
  Vec2 p = surface.lightmap_texel(triangle, bary);
  int x = std::clamp(int(std::floor(p.x)), 0, page.width - 1), y = std::clamp(int(std::floor(p.y)), 0, page.height - 1);
  int32_t found = at[size_t(y) * page.width + x];
  if (found >= 0) return found;
  // Rounding can put a hit on the edge of a chart just outside its covered texels.
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      int nx = x + dx, ny = y + dy;
      if (nx < 0 || ny < 0 || nx >= page.width || ny >= page.height) continue;
      int32_t j = at[size_t(ny) * page.width + nx];
      if (j >= 0 && surface.chart[elements.triangle[size_t(j)]] == surface.chart[triangle]) return j;
    }
  return -1;
}

bool footprint_surface_point(const Elements& elements, const Surface& surface, size_t i, Vec2 u, Vec3& point) {
  const AtlasPage& page = surface.pages[elements.page[i]];
  uint32_t t = elements.triangle[i];
  Vec2 at{float(elements.texel[i] % uint32_t(page.width)) + u.x, float(elements.texel[i] / uint32_t(page.width)) + u.y};
  Vec2 b = lightmap_bary(surface, t, at);
  // Outside the element's triangle, a flat texel's point is still on the surface, in the plane.
  if (!inside(b) && !(elements.flags[i] & kFlatTexel)) return false;
  point = surface.point(t, b);
  return true;
}

Vec3 footprint_point(const Elements& elements, const Surface& surface, size_t i, Vec2 u) {
  int cx = std::min(3, int(u.x * 4)), cy = std::min(3, int(u.y * 4));
  const uint16_t visible = elements.visible_cells[i];
  if (visible == 0) return elements.position[i];
  // A cell the sample does not see passes its share to the visible ones in turn, so the points stay
  // spread over the footprint kept: on a texel split at a cover's edge the sample point lies on the
  // edge itself, and half of all rays started there put the slit's light into the texel's.
  if (!(visible >> (cy * 4 + cx) & 1)) {
    const int count = __builtin_popcount(visible);
    int turn = (cy * 4 + cx) % count;
    int cell = 0;
    while (!(visible >> cell & 1) || turn-- > 0) ++cell;
    cx = cell % 4, cy = cell / 4;
    u = {(cx + u.x * 4 - std::floor(u.x * 4)) / 4, (cy + u.y * 4 - std::floor(u.y * 4)) / 4};
  }
  // Near geometry only the cell centres were checked (a wall may cross a cell): use those.
  if (elements.flags[i] & kNearGeometry) u = {(cx + 0.5f) / 4, (cy + 0.5f) / 4};
  Vec3 p;
  if (!footprint_surface_point(elements, surface, i, u, p)) return elements.position[i];
  // A point on the chart's very edge can lie in the plane of a wall standing there, where a ray
  // may slip through the wall; pulled a little toward the sample point, it is clear of it.
  Vec3 inward = elements.position[i] - p;
  float gap = length(inward), pull = 2 * elements.offset[i];
  return gap > pull ? p + inward * (pull / gap) : elements.position[i];
}

}  // namespace radbake
