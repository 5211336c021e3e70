#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "baker/surface/elements.h"
#include "baker/surface/nearby_samples.h"
#include "baker/surface/ray_tracer.h"
#include "baker/surface/sampling.h"

namespace radbake {
namespace {

constexpr int kTangentProbes = 8;
constexpr int kBurialProbes = 16;
constexpr int kFootprintCells = 4;  // per side: the grid of Elements::visible_cells
// Bakery's rule of thumb: a sample that sees back faces in half its hemisphere is inside geometry.
constexpr float kBuriedBackfaceFraction = 0.5f;
// Texels: how close over a point another surface covers it (under_cover), so that a texel across
// the cover's edge is split. The light in a gap that thin stays in it: the slit out is a sixteenth
// of a texel high. From a thicker gap much of it gets out round the edge (a lamp facing a ceiling
// 1 cm over it, under 8 cm texels, lit the ceiling beside it so), and split texels there would
// lose that light: 3% of the lamp's.
constexpr float kCoverReach = 1.0f / 16;
// Texels: how close over a sample a cover keeps it out of the patches of samples in the open. A
// patch is many texels wide, and most of the light in a gap under it, even one thicker than
// kCoverReach, stays there; shot from a patch that also holds the open surface beside the gap, it
// would light the room.
constexpr float kPatchCoverReach = 0.5f;
// Stratified points measuring the shares of a texel on either side of a cover's edge.
constexpr uint32_t kCoverShareProbes = 64;

}  // namespace

bool under_cover(const Surface& surface, const RayTracer& tracer, uint32_t triangle, Vec3 point) {
  return tracer.occluded(point, surface.normal[triangle], 0.0f, kCoverReach * surface.texel_size(triangle));
}

bool sees_within_texel(const Surface& surface, const RayTracer& tracer, Vec3 from, uint32_t from_triangle, Vec3 to,
                       uint32_t to_triangle) {
  Vec3 d = to - from;
  const float distance = length(d);
  if (!(distance > 0)) return true;
  d = d / distance;
  const uint32_t chart = surface.chart[from_triangle];
  if (chart != surface.chart[to_triangle] || dot(surface.normal[from_triangle], surface.normal[to_triangle]) < -0.5f)
    return !tracer.occluded(from, d, 0.0f, distance);
  float start = 0;
  for (int crossed = 0; crossed < 16; ++crossed) {
    const Hit hit = tracer.intersect(from, d, start, distance);
    if (hit.missed()) return true;
    if (surface.chart[hit.triangle] != chart) return false;
    start = std::nextafter(hit.distance, INFINITY);
  }
  return false;
}

bool buried_at(const RayTracer& tracer, Vec3 point, Vec3 ng, uint32_t pattern) {
  int back = 0;
  for (int k = 0; k < kBurialProbes; ++k) {
    const Hit hit = tracer.intersect(point, cosine_direction(ng, cmj_sample(uint32_t(k), kBurialProbes, pattern)), 0.0f, INFINITY);
    back += !hit.missed() && !hit.front;
  }
  return back >= kBuriedBackfaceFraction * kBurialProbes;
}

namespace {

// A texel across a cover's edge: it keeps the cells and the share of its area on its sample's
// side; the rest of its area goes to `taker`, a valid neighbour on the far side, or, with none
// (the far side buried: the gap under a single-sided lamp), to nobody, as behind a wall.
struct CoverSplit {
  bool split = false;
  int32_t taker = -1;
  float near_share = 1;
  uint16_t far_cells = 0;
};

// How element i splits at a cover's edge, if one crosses its footprint and a neighbour lies on the
// far side: rays then start only on its sample's side, so the gap's light does not leave from the
// open side, nor the open's from the gap. The shares are measured at 64 stratified points, not by
// cell centres, which place the edge only to a quarter texel: the area across it carries the
// gap's light into the energy count (an edge a tenth of a texel off the centres lost 1% of all the
// light), and a sliver of gap between the centres would still be lit and shine into the open.
CoverSplit split_at_cover(const Elements& e, const Surface& surface, const RayTracer& tracer, size_t i,
                          uint32_t pattern) {
  const uint32_t width = uint32_t(surface.pages[e.page[i]].width);
  const int64_t x = e.texel[i] % width, y = e.texel[i] / width;
  const std::vector<int32_t>& at = e.element_at[e.page[i]];
  const int64_t height = int64_t(at.size() / width);
  auto neighbour = [&](int64_t dx, int64_t dy) {
    if (x + dx < 0 || y + dy < 0 || x + dx >= int64_t(width) || y + dy >= height) return int32_t(-1);
    return at[size_t((y + dy) * int64_t(width) + x + dx)];
  };
  auto across = [&](int32_t j) {
    return j >= 0 && size_t(j) != i && ((e.flags[size_t(j)] ^ e.flags[i]) & kUnderCover) &&
           surface.chart[e.triangle[size_t(j)]] == surface.chart[e.triangle[i]];
  };
  bool any = false;
  for (int64_t dy = -1; dy <= 1; ++dy)
    for (int64_t dx = -1; dx <= 1; ++dx) any |= across(neighbour(dx, dy));
  if (!any) return {};

  const uint32_t t = e.triangle[i];
  const Vec3 lift = surface.normal[t] * e.offset[i];
  const bool covered = e.flags[i] & kUnderCover;
  enum Side { kOffSurface, kNear, kFar };
  auto side_at = [&](Vec2 u) {
    Vec3 p;
    if (!footprint_surface_point(e, surface, i, u, p)) return kOffSurface;
    return under_cover(surface, tracer, t, p + lift) == covered ? kNear : kFar;
  };
  constexpr int k = kFootprintCells;
  int near_count = 0, far_count = 0;
  float far_x = 0, far_y = 0;  // sum of the far side's points, in texels from the texel's centre
  uint16_t centre_far = 0, touched = 0;  // cells whose centre, or any of whose points, is across
  for (uint32_t m = 0; m < kCoverShareProbes; ++m) {
    const Vec2 u = cmj_sample(m, kCoverShareProbes, pattern);
    const int cell = std::min(k - 1, int(u.y * k)) * k + std::min(k - 1, int(u.x * k));
    const Side side = e.visible_cells[i] >> cell & 1 ? side_at(u) : kOffSurface;
    near_count += side == kNear;
    if (side != kFar) continue;
    ++far_count;
    far_x += u.x - 0.5f, far_y += u.y - 0.5f;
    touched |= uint16_t(1u << cell);
  }
  for (int c = 0; c < k * k; ++c)
    if ((e.visible_cells[i] >> c & 1) && side_at({(c % k + 0.5f) / k, (c / k + 0.5f) / k}) == kFar)
      centre_far |= uint16_t(1u << c);
  // Rays start (and direct light is taken) at the centres of the cells kept, so a cell the edge
  // crosses goes too: its centre may lie a hair from the slit, where the light escaping from the
  // gap is concentrated (taken there for a quarter texel, it lit the room 0.5% more). Unless that
  // leaves the sample's side no cell; then the cells whose centres are on it stay. With none of
  // those, or no point on its side (a sample on a sliver of it), the texel stays whole.
  CoverSplit split;
  split.far_cells = (e.visible_cells[i] & ~(centre_far | touched)) ? centre_far | touched : centre_far;
  if (far_count == 0 || near_count == 0 || !(e.visible_cells[i] & ~split.far_cells)) return {};

  float nearest = INFINITY;
  for (int64_t dy = -1; dy <= 1; ++dy)
    for (int64_t dx = -1; dx <= 1; ++dx) {
      const int32_t j = neighbour(dx, dy);
      const float distance = std::hypot(float(dx) - far_x / float(far_count), float(dy) - far_y / float(far_count));
      if (across(j) && e.valid(size_t(j)) && distance < nearest) nearest = distance, split.taker = j;
    }
  // A buried texel's far part matters only as a taker's area.
  split.split = e.valid(i) || split.taker >= 0;
  split.near_share = float(near_count) / float(near_count + far_count);
  return split;
}


// Settles element i's sample where it lies: pushed past a wall standing on the surface, marked
// near geometry, under a cover or buried, its footprint cut to the cells the sample sees along the
// surface (its area scaled to match). Returns its cover: 0 in the open, 1 under a cover within
// kPatchCoverReach, 2 within kCoverReach.
uint8_t settle_sample(Elements& e, const Surface& surface, const RayTracer& tracer, size_t i, uint32_t pattern) {
  const uint32_t t = e.triangle[i];
  const Vec3 ng = surface.normal[t];
  const float texel_size = surface.texel_size(t);
  const float eps = e.offset[i];
  Vec3 tangent, bitangent;
  orthonormal_basis(ng, tangent, bitangent);

  // Along the surface, half a texel diagonal each way: a back face that close means the texel
  // centre lies behind a wall standing on this surface; step past the nearest one.
  const float reach = 0.75f * texel_size;
  Vec3 origin = e.position[i] + ng * eps;
  float nearest_back = INFINITY;
  Vec3 escape{};
  for (int k = 0; k < kTangentProbes; ++k) {
    float angle = 2.0f * kPi * k / kTangentProbes;
    Vec3 dir = tangent * std::cos(angle) + bitangent * std::sin(angle);
    Hit hit = tracer.intersect(origin, dir, 0.0f, reach);
    if (hit.missed()) continue;
    e.flags[i] |= kNearGeometry;
    if (!hit.front && hit.distance < nearest_back) {
      nearest_back = hit.distance;
      escape = dir;
    }
  }
  if (std::isfinite(nearest_back)) {
    e.position[i] = e.position[i] + escape * (nearest_back + 2 * eps);
    e.flags[i] |= kPushedOut;
  }
  // The tangent probes pass under a cover (a lamp 0.1 mm under the ceiling): look along the normal.
  uint8_t cover = 0;
  const Hit over = tracer.intersect(e.position[i] + ng * eps, ng, 0.0f, kPatchCoverReach * texel_size);
  if (!over.missed()) cover = over.distance < kCoverReach * texel_size ? 2 : 1;
  if (cover == 2) e.flags[i] |= kUnderCover;

  // Part of a texel that straddles a wall lies behind it and gets no light from this side:
  // keep only the area the sample point can see along the surface, or light is
  // over-counted (the energy balance shows it) on every texel around a block's foot.
  if (e.flags[i] & kNearGeometry) {
    const int k = kFootprintCells;
    int on_surface = 0, visible = 0;
    e.visible_cells[i] = 0;
    for (int sy = 0; sy < k; ++sy)
      for (int sx = 0; sx < k; ++sx) {
        Vec3 p;
        if (!footprint_surface_point(e, surface, i, {(sx + 0.5f) / k, (sy + 0.5f) / k}, p)) continue;
        ++on_surface;
        const Vec3 from = e.position[i] + ng * eps, to = p + ng * eps;
        if (length(to - from) <= eps || sees_within_texel(surface, tracer, from, t, to, t)) {
          ++visible;
          e.visible_cells[i] |= uint16_t(1u << (sy * k + sx));
        }
      }
    if (on_surface > 0) e.area[i] *= float(visible) / float(on_surface);
    if (visible == 0) e.flags[i] |= kBuried;  // all of it is behind the wall
  }

  if (buried_at(tracer, e.position[i] + ng * eps, ng, pattern)) e.flags[i] |= kBuried;
  return cover;
}

// What settle_sample changes of an element.
struct Sample {
  uint32_t triangle;
  Vec3 position, normal;
  float offset, area;
  uint8_t flags;
  uint16_t visible_cells;

  static Sample of(const Elements& e, size_t i) {
    return {e.triangle[i], e.position[i], e.normal[i], e.offset[i], e.area[i], e.flags[i], e.visible_cells[i]};
  }
  void put(Elements& e, size_t i) const {
    e.triangle[i] = triangle, e.position[i] = position, e.normal[i] = normal, e.offset[i] = offset;
    e.area[i] = area, e.flags[i] = flags, e.visible_cells[i] = visible_cells;
  }
};

// Element i's pieces in Elements::other_pieces (sorted by element).
std::pair<const Elements::Piece*, const Elements::Piece*> pieces_of(const Elements& e, size_t i) {
  const Elements::Piece *begin = e.other_pieces.data(), *end = begin + e.other_pieces.size();
  const Elements::Piece* first =
      std::lower_bound(begin, end, uint32_t(i), [](const Elements::Piece& p, uint32_t k) { return p.element < k; });
  const Elements::Piece* last = first;
  while (last != end && last->element == i) ++last;
  return {first, last};
}

// Element i's sample at `position` on triangle t, with the shading normal there (the geometric one
// where the shading normal turns away from it).
void sample_at(Elements& e, const Surface& surface, size_t i, uint32_t t, Vec3 position) {
  e.triangle[i] = t;
  e.position[i] = position;
  e.normal[i] = surface.shading_normal(t, barycentric(&surface.corners[3 * t], position));
  if (!(dot(e.normal[i], surface.normal[t]) > 0)) e.normal[i] = surface.normal[t];
}

// A texel whose sample lies buried may still hold surface in the open: another of its pieces (a
// window frame's face pressed against its reveal, its profile hinged onto it) or the rest of its
// own triangle (a slab's texel half under a wall). Left buried, every ray striking the open part
// took no light, and the light a path tracer finds reflected there was missing from the rooms at
// every bounce. The sample moves to the largest other piece, then to the first quarter of its own
// triangle's footprint, that settles unburied; `buried` is the sample as it first settled, put
// back when none does. Returns the cover where it settles.
uint8_t move_buried_sample(Elements& e, const Surface& surface, const RayTracer& tracer, size_t i, uint32_t pattern,
                           const Sample& buried) {
  const uint8_t kept_flags = buried.flags & (kFiltered | kFlatTexel);
  const float area = e.area[i];
  auto settled_at = [&](uint32_t t, Vec3 position, bool on_own_triangle) {
    sample_at(e, surface, i, t, position);
    e.offset[i] = ray_offset(position, surface.texel_size(t));
    // On its own triangle the texel straddles what buried its centre: near geometry, whatever the
    // tangent probes from a quarter point find, so only the cells the new sample sees are its
    // footprint (from a quarter point 3.1 cm from a wall, with 3.1 cm probes, a floor texel took
    // the light of its part behind the wall). On another piece (a frame's profile) the texel's
    // other pieces are open surface too, and its whole area stands for them.
    e.flags[i] = kept_flags | kPushedOut | (on_own_triangle ? kNearGeometry : 0);
    e.visible_cells[i] = 0xffff;
    e.area[i] = area;
    const uint8_t cover = settle_sample(e, surface, tracer, i, pattern);
    if (!e.valid(i) || !(e.area[i] > 0)) return std::optional<uint8_t>();
    if (!on_own_triangle) return std::optional<uint8_t>(cover);
    // The sample goes where the light of the cells it keeps is centred, if it sees that point: a
    // quarter point is not, and where the light changes fast across the texel its value would not
    // be the light at its sample (2.9% off beside a wall, 4 cm texels).
    constexpr int k = kFootprintCells;
    Vec3 sum{};
    int count = 0;
    for (int c = 0; c < k * k; ++c) {
      Vec3 point;
      if ((e.visible_cells[i] >> c & 1) && footprint_surface_point(e, surface, i, {(c % k + 0.5f) / k, (c / k + 0.5f) / k}, point))
        sum += point, ++count;
    }
    const uint32_t settled = e.triangle[i];
    const Vec3 lift = surface.normal[settled] * e.offset[i], centre = count > 0 ? sum / float(count) : e.position[i];
    if (count > 0 && sees_within_texel(surface, tracer, e.position[i] + lift, settled, centre + lift, settled))
      sample_at(e, surface, i, settled, centre);
    return std::optional<uint8_t>(cover);
  };
  const auto [first, last] = pieces_of(e, i);
  for (const Elements::Piece* p = first; p != last; ++p)
    if (p->triangle != buried.triangle)
      if (auto cover = settled_at(p->triangle, surface.point(p->triangle, p->bary), false)) return *cover;
  for (Vec2 u : {Vec2{0.25f, 0.25f}, Vec2{0.75f, 0.25f}, Vec2{0.25f, 0.75f}, Vec2{0.75f, 0.75f}}) {
    buried.put(e, i);
    e.area[i] = area;
    Vec3 point;
    if (!footprint_surface_point(e, surface, i, u, point)) continue;
    if (auto cover = settled_at(buried.triangle, point, true)) return *cover;
  }
  buried.put(e, i);
  return 0;
}

// Neighbouring samples facing further apart than 60 degrees never share a patch (below).
constexpr float kJoinsFacingApart = 0.5f;

}  // namespace

void place_samples(Elements& e, const Surface& surface, const RayTracer& tracer, uint64_t seed, Progress& progress) {
  const size_t n = e.size();
  // Per element: 0 in the open, 1 under a cover within kPatchCoverReach, 2 within kCoverReach.
  std::vector<uint8_t> cover(n, 0);
  progress.begin("sample placement", n);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 512), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i) {
      const uint32_t pattern = Rng(seed, Stream::Probe, i).next_u32();
      const float area = e.area[i];
      cover[i] = settle_sample(e, surface, tracer, i, pattern);
      if (e.valid(i)) continue;
      Sample buried = Sample::of(e, i);
      e.area[i] = area;
      cover[i] = move_buried_sample(e, surface, tracer, i, pattern, buried);
    }
    progress.advance(r.size());
  });

  // Texels across a cover's edge, once every sample's side is known; buried ones too (a ceiling
  // texel whose sample sees the back of a single-sided lamp just under it may lie half in the
  // open). Their far parts' areas go to the takers after every split, in order, so the same areas
  // come out every run.
  std::vector<CoverSplit> splits(n);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 512), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i)
      splits[i] = split_at_cover(e, surface, tracer, i, Rng(seed, Stream::Cover, i).next_u32());
  });
  std::vector<float> far_area(n, 0);
  for (size_t i = 0; i < n; ++i) {
    if (!splits[i].split) continue;
    far_area[i] = e.area[i] * (1 - splits[i].near_share);
    e.area[i] *= splits[i].near_share;
    e.visible_cells[i] &= uint16_t(~splits[i].far_cells);
    e.flags[i] |= kNearGeometry;
  }
  for (size_t i = 0; i < n; ++i)
    if (splits[i].taker >= 0) e.area[size_t(splits[i].taker)] += far_area[i];

  // Joins to the right and lower neighbours, once every sample has its final place. Only texels
  // near geometry can have a wall between them and a neighbour; the rest join without a ray. A
  // texel under a cover and one in the open (or under a cover of the other reach) never join: a
  // patch holding both would shine the gap's light into the open. Nor do two whose samples face
  // more than 60 degrees apart: on the FZK-Haus a ceiling's texels over a wall's top had their
  // samples moved onto a face of the lit room beside it, and the ray between those and the dark
  // room's ceiling texels next to them ran along the seam where the wall meets the slab; joined,
  // the patch shone the lit room's light into the dark one (1.1 lx there by the path tracer, 6.8
  // lx baked at the defaults, 3.0 since).
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 512), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i) {
      if (!e.valid(i)) continue;
      const uint32_t width = uint32_t(surface.pages[e.page[i]].width);
      const uint32_t x = e.texel[i] % width, y = e.texel[i] / width;
      const std::vector<int32_t>& at = e.element_at[e.page[i]];
      const size_t height = at.size() / width;
      const uint8_t bits[2] = {kJoinsRight, kJoinsDown};
      for (int k = 0; k < 2; ++k) {
        uint32_t nx = x + (k == 0), ny = y + (k == 1);
        if (nx >= width || ny >= height) continue;
        int32_t j = at[size_t(ny) * width + nx];
        if (j < 0 || !e.valid(size_t(j)) || surface.chart[e.triangle[size_t(j)]] != surface.chart[e.triangle[i]] ||
            cover[i] != cover[size_t(j)] ||
            dot(surface.normal[e.triangle[i]], surface.normal[e.triangle[size_t(j)]]) < kJoinsFacingApart)
          continue;
        bool joined = true;
        if ((e.flags[i] | e.flags[size_t(j)]) & kNearGeometry) {
          const Vec3 from = e.position[i] + surface.normal[e.triangle[i]] * e.offset[i];
          const Vec3 to = e.position[size_t(j)] + surface.normal[e.triangle[size_t(j)]] * e.offset[size_t(j)];
          joined = sees_within_texel(surface, tracer, from, e.triangle[i], to, e.triangle[size_t(j)]);
        }
        if (joined) e.flags[i] |= bits[k];
      }
    }
  });
  std::vector<Elements::Piece>().swap(e.other_pieces);
  index_samples(e, surface);
  progress.end();
}

}  // namespace radbake
