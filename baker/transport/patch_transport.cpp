#include "baker/transport/patch_transport.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "baker/surface/sampling.h"

namespace radbake {

Landing land(const Elements& elements, const Patches& patches, const Surface& surface, const RayTracer& tracer,
             Vec3 origin, Vec3 direction, uint8_t seen_from) {
  const Hit hit = tracer.intersect_light_path(origin, direction, 0.0f, INFINITY);
  Landing at;
  at.escaped = hit.missed() && !(seen_from & kUnderCover);
  at.distance = hit.missed() ? INFINITY : hit.distance;
  if (hit.missed()) {
    at.fate = at.escaped ? RayFate::Escaped : RayFate::SealedGap;
    return at;
  }
  if (!hit.front) {
    at.fate = RayFate::BackFace;
    return at;
  }
  const HitElement standing = element_standing_for(elements, surface, tracer, hit, seen_from);
  if (standing.element < 0) {
    at.fate = standing.fate;
    return at;
  }
  if (patches.patch_of_element[size_t(standing.element)] == UINT32_MAX) {
    at.fate = RayFate::BuriedElement;
    return at;
  }
  at.fate = RayFate::TookLight;
  at.element = uint32_t(standing.element);
  at.patch = patches.patch_of_element[at.element];
  return at;
}

uint32_t patch_hit(const Elements& elements, const Patches& patches, const Surface& surface,
                   const RayTracer& tracer, Vec3 origin, Vec3 direction, uint8_t seen_from, bool& escaped,
                   RayFates& fates) {
  const Landing at = land(elements, patches, surface, tracer, origin, direction, seen_from);
  escaped = at.escaped;
  fates.add(at.fate);
  return at.patch;
}

namespace {

// Monte Carlo rows sum exactly to what lands, but columns (what each patch receives) carry the
// noise of everyone else's rays, so even a closed box of equal patches solves to radiosities a
// few percent apart. Reciprocity (A_p F_pq = A_q F_qp) cuts that: the power exchange matrix
// G = A F is made symmetric, each pair's exchange the mean of what both measured, and each row is
// then scaled to sum to what its own rays measured landing, so every patch sends exactly the light
// it measured and the pairs stay reciprocal to within their rows' scale, which is near one.
//
// Not scaled as D G D (Knight's symmetric Sinkhorn) until rows and columns both add up: where two
// groups of patches exchange light almost only with each other (a house's outer faces and the
// ground round it), the scale factors of one group can trade against the other's, and they drift
// to whatever clamp holds them (outer faces' factors 47 at the median, the ground's down to
// 0.016). The ground's exchange with a room it lights through a window went down with them: a
// room lit through a window read 6% to 17% darker than the path tracer (bench/window_room), and
// the FZK-Haus's rooms 1.2%.

// One half of A_p F_pq or of A_q F_qp, on row p of the symmetric exchange matrix G.
struct Exchange {
  uint32_t patch;
  float half;
  bool operator<(const Exchange& o) const { return patch < o.patch || (patch == o.patch && half < o.half); }
};

// G in compressed rows, built in place with no row of its own (a million-texel bake has 40,000
// patches of a thousand targets each: vectors per row, doubling as they grow, took gigabytes).
struct ExchangeMatrix {
  std::vector<uint64_t> start;
  std::vector<Exchange> entries;
};

ExchangeMatrix symmetric_exchange(const std::vector<float>& area, const std::vector<MeasuredRow>& rows) {
  const size_t n = rows.size();
  ExchangeMatrix g;
  g.start.assign(n + 1, 0);
  for (size_t p = 0; p < n; ++p)
    for (auto [q, f] : rows[p]) ++g.start[p + 1], ++g.start[q + 1];
  for (size_t p = 0; p < n; ++p) g.start[p + 1] += g.start[p];
  g.entries.resize(g.start[n]);
  std::vector<uint64_t> fill(g.start.begin(), g.start.end() - 1);
  for (size_t p = 0; p < n; ++p)
    for (auto [q, f] : rows[p]) {
      const float half = float(0.5 * double(area[p]) * f);
      g.entries[fill[p]++] = {q, half};
      g.entries[fill[q]++] = {uint32_t(p), half};
    }
  // Merge the two halves of each pair, compacting the rows towards the front.
  uint64_t w = 0;
  for (size_t p = 0; p < n; ++p) {
    const uint64_t begin = g.start[p], end = g.start[p + 1];
    std::sort(g.entries.begin() + std::ptrdiff_t(begin), g.entries.begin() + std::ptrdiff_t(end));
    g.start[p] = w;
    for (uint64_t k = begin; k < end; ++k) {
      if (w > g.start[p] && g.entries[w - 1].patch == g.entries[k].patch) g.entries[w - 1].half += g.entries[k].half;
      else g.entries[w++] = g.entries[k];
    }
  }
  g.start[n] = w;
  g.entries.resize(w);
  return g;
}

// Writes the balanced rows into `out`, F_pq = G_pq / A_p times row p's scale, and frees the
// measured rows as soon as G holds them (at a million texels each takes hundreds of MB).
void balance_reciprocity(const Patches& patches, std::vector<MeasuredRow>&& rows, PatchTransport& out) {
  const size_t n = rows.size();
  // Reciprocity holds between the areas that stop light: a ray meets a pane of glass or a cut-out
  // only where it is opaque (with the probability of its opacity), while the pane's own rays all
  // leave it, so A_p o_p F_pq = A_q o_q F_qp. With every patch opaque, the areas themselves.
  std::vector<float> stopping_area = patches.area;
  for (size_t p = 0; p < patches.opacity.size(); ++p) stopping_area[p] *= patches.opacity[p];
  auto area = [&](size_t p) { return stopping_area[p]; };
  std::vector<double> target(n, 0);
  for (size_t p = 0; p < n; ++p)
    for (auto [q, f] : rows[p]) target[p] += double(area(p)) * f;
  const ExchangeMatrix g = symmetric_exchange(stopping_area, rows);
  std::vector<MeasuredRow>().swap(rows);
  auto row = [&](size_t p) {
    return std::make_pair(g.entries.begin() + std::ptrdiff_t(g.start[p]), g.entries.begin() + std::ptrdiff_t(g.start[p + 1]));
  };
  std::vector<double> scale(n, 0.0);
  uint64_t kept = 0;
  for (size_t p = 0; p < n; ++p) {
    if (target[p] <= 0 || area(p) <= 0) continue;
    double sum = 0;
    for (auto [it, end] = row(p); it != end; ++it) sum += it->half;
    if (!(sum > 0)) continue;
    scale[p] = target[p] / sum / area(p);
    kept += g.start[p + 1] - g.start[p];
  }
  out.row_start.assign(n + 1, 0);
  out.target.reserve(kept);
  out.form_factor.reserve(kept);
  for (size_t p = 0; p < n; ++p) {
    if (scale[p] > 0)
      for (auto [it, end] = row(p); it != end; ++it) {
        out.target.push_back(it->patch);
        out.form_factor.push_back(float(it->half * scale[p]));
      }
    out.row_start[p + 1] = out.target.size();
  }
}

}  // namespace

Enclosures find_enclosures(const PatchTransport& t) {
  const size_t n = t.row_start.empty() ? 0 : t.row_start.size() - 1;
  std::vector<uint32_t> parent(n);
  for (size_t p = 0; p < n; ++p) parent[p] = uint32_t(p);
  auto find = [&](uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (size_t p = 0; p < n; ++p)
    for (uint64_t k = t.row_start[p]; k < t.row_start[p + 1]; ++k) {
      uint32_t a = find(uint32_t(p)), b = find(t.target[k]);
      parent[std::max(a, b)] = std::min(a, b);
    }
  Enclosures out;
  out.of_patch.resize(n);
  std::vector<uint32_t> number(n, UINT32_MAX);
  for (size_t p = 0; p < n; ++p) {
    uint32_t root = find(uint32_t(p));
    if (number[root] == UINT32_MAX) number[root] = uint32_t(out.count++);
    out.of_patch[p] = number[root];
  }
  return out;
}

IncomingRows incoming_rows(const Patches& patches, const PatchTransport& t) {
  const size_t n = patches.size();
  IncomingRows in;
  in.start.assign(n + 1, 0);
  for (uint32_t q : t.target) ++in.start[q + 1];
  for (size_t q = 0; q < n; ++q) in.start[q + 1] += in.start[q];
  in.source.resize(t.target.size());
  in.weight.resize(t.target.size());
  std::vector<uint64_t> fill(in.start.begin(), in.start.end() - 1);
  for (size_t p = 0; p < n; ++p)
    for (uint64_t k = t.row_start[p]; k < t.row_start[p + 1]; ++k) {
      const uint32_t q = t.target[k];
      in.source[fill[q]] = uint32_t(p);
      in.weight[fill[q]++] = t.form_factor[k] * patches.area[p] / patches.area[q];
    }
  return in;
}

std::vector<uint32_t> all_patches(size_t n) {
  std::vector<uint32_t> which(n);
  for (size_t p = 0; p < n; ++p) which[p] = uint32_t(p);
  return which;
}

PatchTransport balanced_transport(const Patches& patches, MeasuredRows measured) {
  PatchTransport out;
  out.escaped = std::move(measured.escaped);
  out.lost = std::move(measured.lost);
  out.rays = std::move(measured.rays);
  for (const RayFates& f : measured.fates) out.fates += f;
  balance_reciprocity(patches, std::move(measured.rows), out);
  return out;
}

void measure_ray_cast_rows(const Elements& elements, const Patches& patches, const Surface& surface,
                           const RayTracer& tracer, uint32_t rays_per_patch, const std::vector<double>& power,
                           const std::vector<uint32_t>& which, uint64_t seed, Progress& progress, MeasuredRows& out) {
  const size_t patch_count = patches.size();
  double total_power = 0;
  for (double p : power) total_power += p;
  for (uint32_t p : which) {
    double extra = total_power > 0 ? double(rays_per_patch) * double(patch_count) * power[p] / total_power : 0;
    out.rays[p] = uint32_t(std::min<double>(16.0 * rays_per_patch, rays_per_patch + std::round(extra)));
  }

  struct Scratch {
    RowTally tally;
    std::vector<double> cumulative_area;
  };
  tbb::enumerable_thread_specific<Scratch> scratch;
  progress.begin("form factors", which.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, which.size(), 8), [&](const tbb::blocked_range<size_t>& r) {
    Scratch& s = scratch.local();
    for (size_t w = r.begin(); w < r.end(); ++w) {
      const uint32_t p = which[w];
      const uint32_t* first = &patches.members[patches.first_member[p]];
      const size_t member_count = patches.first_member[p + 1] - patches.first_member[p];
      s.cumulative_area.resize(member_count);
      double total = 0;
      for (size_t m = 0; m < member_count; ++m) s.cumulative_area[m] = total += elements.area[first[m]];

      const uint32_t rays = out.rays[p];
      Rng rng(seed, Stream::PatchRays, p);
      const uint32_t origin_pattern = rng.next_u32(), direction_pattern = rng.next_u32();
      uint32_t escaped = 0, lost = 0;
      RayFates fates;
      for (uint32_t k = 0; k < rays; ++k) {
        // Stratified over the patch's area, then within the chosen element's footprint.
        double pick = (k + rng.uniform()) / rays * total;
        size_t m = size_t(std::lower_bound(s.cumulative_area.begin(), s.cumulative_area.end(), pick) -
                          s.cumulative_area.begin());
        const uint32_t i = first[std::min(m, member_count - 1)];
        const Vec3 ng = surface.normal[elements.triangle[i]];
        Vec3 origin = footprint_point(elements, surface, i, cmj_sample(k, rays, origin_pattern));
        origin += ng * elements.offset[i];
        Vec3 dir = hemisphere_direction(elements.normal[i], ng, cmj_sample(k, rays, direction_pattern));
        bool left;
        uint32_t q = patch_hit(elements, patches, surface, tracer, origin, dir, elements.flags[i], left, fates);
        if (q == UINT32_MAX) {
          escaped += left;
          lost += !left;
          continue;
        }
        s.tally.add(q, 1, patch_count);
      }
      s.tally.take(out.rows[p], float(rays));
      out.escaped[p] = float(escaped) / float(rays);
      out.lost[p] = float(lost) / float(rays);
      out.fates[p] = fates;
    }
    progress.advance(r.size());
  });
  progress.end();
}

PatchTransport trace_patch_transport(const Elements& elements, const Patches& patches, const Surface& surface,
                                     const RayTracer& tracer, uint32_t rays_per_patch,
                                     const std::vector<double>& power, uint64_t seed, Progress& progress) {
  MeasuredRows rows;
  rows.resize(patches.size());
  measure_ray_cast_rows(elements, patches, surface, tracer, rays_per_patch, power, all_patches(patches.size()), seed,
                        progress, rows);
  return balanced_transport(patches, std::move(rows));
}

}  // namespace radbake
