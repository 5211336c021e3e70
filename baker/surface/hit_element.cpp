#include "baker/surface/hit_element.h"

#include <algorithm>
#include <cstdlib>

#include "baker/surface/nearby_samples.h"
#include "baker/surface/sampling.h"

namespace radbake {

// Where a wall crosses a texel, the texel's element lies on one side only; a hit on the other side
// belongs to a neighbour on its own side (or to nobody), never to the element behind the wall, or
// light would pass through the wall. Likewise across a cover's edge: a hit in the gap belongs to a
// texel under the cover, one in the open to a texel in the open; where no neighbour holds the
// hit's side, the texel keeps it. What stands between is looked for past the hit's own chart's
// steps and corners (sees_within_texel): a window frame's stepped profile at 19 cm texels hid
// every sample from the faces round it, and the sunlit frames' light was missing from the
// FZK-Haus's rooms at every bounce. A buried texel passes its hits to a neighbour as
// well, two texels out at most, and where its chart has none, a sample of another part in sight of
// the hit, four texels out at most, stands for it (nearby_samples.h).
//
// A gap thinner than a sixteenth of a texel (kUnderCover) is sealed: a ray from the open that
// enters its slit, or one from inside that leaves by it, strikes nobody. Texels cannot resolve the
// light along such a gap, which falls off within a few gap heights of its mouth: what crossed the
// slit was the light of whichever texel's sample sat nearest the edge, so it grew and shrank with
// the texel density (the Cornell box's ceiling beside a double-sided lamp +62% at 100 texels per
// metre, +4% at 200). What a 0.1 mm gap truly lets out is a few tenths of a percent of its lamp.
//
// How far from a hit, in its texels, a sample of another part may stand for it, and how many of the
// nearest are tried.
constexpr float kNearbyTexels = 4;
constexpr size_t kNearbyTries = 12;

HitElement element_standing_for(const Elements& e, const Surface& surface, const RayTracer& tracer, const Hit& hit,
                                uint8_t seen_from) {
  const int64_t j = element_at_point(e, surface, hit.triangle, hit.bary);
  if (j < 0) return {-1, RayFate::NoElement};
  const HitElement sealed{-1, RayFate::SealedGap};
  if (!(e.flags[size_t(j)] & kNearGeometry) && e.valid(size_t(j)))
    return ((e.flags[size_t(j)] ^ seen_from) & kUnderCover) ? sealed : HitElement{j};
  // The texels of the hit's chart around j, nearest first: the ring of 8, then the ring of 16
  // round it (a buried texel's open sliver may lie two texels from the nearest sample in the open).
  const uint32_t width = uint32_t(surface.pages[e.page[size_t(j)]].width);
  const std::vector<int32_t>& grid = e.element_at[e.page[size_t(j)]];
  const int64_t x = e.texel[size_t(j)] % width, y = e.texel[size_t(j)] / width, height = int64_t(grid.size() / width);
  int32_t around[24];
  int count = 0, adjacent = 0;
  for (int64_t ring = 1; ring <= 2; ++ring) {
    for (int64_t dy = -ring; dy <= ring; ++dy)
      for (int64_t dx = -ring; dx <= ring; ++dx) {
        if (std::max(std::abs(dx), std::abs(dy)) != ring || x + dx < 0 || y + dy < 0 || x + dx >= width ||
            y + dy >= height)
          continue;
        const int32_t k = grid[size_t((y + dy) * width + x + dx)];
        if (k >= 0 && surface.chart[e.triangle[size_t(k)]] == surface.chart[hit.triangle]) around[count++] = k;
      }
    if (ring == 1) adjacent = count;
  }
  const Vec3 at = surface.point(hit.triangle, hit.bary) + surface.normal[hit.triangle] * e.offset[size_t(j)];
  auto lifted = [&](size_t k) { return e.position[k] + surface.normal[e.triangle[k]] * e.offset[k]; };
  // Only where a cover's edge passes by (place_samples split the texels there) can the hit lie on
  // the other side of one from j.
  uint8_t side = e.flags[size_t(j)] & kUnderCover;
  if (std::any_of(around, around + adjacent, [&](int32_t k) { return (e.flags[size_t(k)] ^ side) & kUnderCover; }))
    side = under_cover(surface, tracer, hit.triangle, at) ? kUnderCover : 0;
  if (side != (seen_from & kUnderCover)) return sealed;
  auto sees = [&](size_t k) { return sees_within_texel(surface, tracer, at, hit.triangle, lifted(k), e.triangle[k]); };
  const bool sees_j = sees(size_t(j));
  if (sees_j && e.valid(size_t(j)) && (e.flags[size_t(j)] & kUnderCover) == side) return {j};
  for (int k = 0; k < count; ++k)
    if (e.valid(size_t(around[k])) && (e.flags[size_t(around[k])] & kUnderCover) == side &&
        sees(size_t(around[k])))
      return {around[k]};
  if (sees_j && e.valid(size_t(j))) return {j};
  // Past the chart: the nearest sample of any part in sight of the hit, its face less than 120
  // degrees from the hit's (further apart they are two sides of something thin). A sill's strip
  // between a frame and the room has no texel of its own on that side; the frame's, the reveal's
  // or the wall's beside it stands for it. Front faces struck that took no light on the FZK-Haus
  // at production: gather rays 0.41% -> 0.16%, form-factor rays 0.61% -> 0.19%; the interior's
  // light -1.56% -> -1.24% of the path tracer's (within 60 degrees and two texels: -1.51%).
  const Vec3 facing = surface.normal[hit.triangle];
  for (uint32_t k : samples_near(e, at, kNearbyTexels * surface.texel_size(hit.triangle), kNearbyTries))
    if (size_t(k) != size_t(j) && (e.flags[k] & kUnderCover) == side &&
        dot(surface.normal[e.triangle[k]], facing) > -0.5f && sees(k))
      return {int64_t(k)};
  // Past that, most such hits lie inside geometry (the FZK-Haus at the defaults: 74% of its
  // form-factor rays that took nothing, in a bed's stacked boards, a fireplace's inside, the wedge
  // under the roof's eaves): counted apart, with sealed gaps, as the closed spaces they are.
  if (buried_at(tracer, at, facing, uint32_t(mix64(hit.triangle)))) return {-1, RayFate::InsideGeometry};
  return sees_j ? HitElement{-1, RayFate::BuriedElement} : HitElement{-1, RayFate::OtherSide};
}

int64_t element_for_hit(const Elements& e, const Surface& surface, const RayTracer& tracer, const Hit& hit,
                        uint8_t seen_from) {
  return element_standing_for(e, surface, tracer, hit, seen_from).element;
}

}  // namespace radbake
