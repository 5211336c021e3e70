#include "baker/gather/final_gather.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "baker/surface/sampling.h"
#include "baker/transport/interreflection.h"

namespace radbake {

namespace {

// How far out the near field reaches from each patch, metres: a receiver nearer than a few patch
// widths still sees the patch's texels unevenly (at a block's foot, the floor's first rows darker
// than the rest of their patch), and the patch's mean exitance is the wrong answer there. Three
// widths, measured on the Cornell box at production (4-texel patches): the foot of the short
// block came out +1.4% against the path tracer with two, +0.5% with three, +0.7% with four. But
// texels are noisier to gather than patch means, so beyond the first width no further than 12
// texels: with the automatic 16-texel patches of a 64 page, three widths (the whole box) doubled
// the seed-to-seed noise, 1.0% to 2.0%.
std::vector<float> near_reach(const Elements& e, const Patches& patches, const Surface& surface) {
  std::vector<float> reach(patches.size());
  for (size_t p = 0; p < patches.size(); ++p) {
    const float side = float(patches.side[p]);
    reach[p] = std::max(side, std::min(3 * side, 12.0f)) *
               surface.texel_size(e.triangle[patches.members[patches.first_member[p]]]);
  }
  return reach;
}

// Lumens per channel, summed in double: many small shares of a patch's light.
struct Lumens {
  double c[3] = {};
  void add(double share, Rgb v) {
    c[0] += share * v.x;
    c[1] += share * v.y;
    c[2] += share * v.z;
  }
  Rgb rgb() const { return {float(c[0]), float(c[1]), float(c[2])}; }
};
// What the near field took from one patch q into the texels of patch p, lm, and the share of p's
// hemisphere it came through, A_p-weighted (m^2).
struct NearExchange {
  double share = 0;
  Lumens excess;         // beyond what far rays take from the same texels: balanced over far receivers
  Lumens direct_beyond;  // the struck texels' reflected direct light beyond their patch's mean
};
using NearTally = std::map<std::pair<uint32_t, uint32_t>, NearExchange>;  // by (p, q)

// Per entry k of row p of the form factors, the share of p's hemisphere through which its far rays
// reach the entry's target: F_pq less what the near field carried.
std::vector<float> far_form_factors(const Patches& patches, const PatchTransport& transport, const NearTally& near) {
  std::vector<float> far(transport.form_factor.size());
  tbb::parallel_for(size_t(0), patches.size(), [&](size_t p) {
    std::vector<std::pair<uint32_t, double>> near_shares;  // (q, share of p's hemisphere), by q
    for (auto it = near.lower_bound({uint32_t(p), 0}); it != near.end() && it->first.first == p; ++it)
      near_shares.emplace_back(it->first.second, it->second.share / patches.area[p]);
    for (uint64_t k = transport.row_start[p]; k < transport.row_start[p + 1]; ++k) {
      auto it = std::lower_bound(near_shares.begin(), near_shares.end(), std::make_pair(transport.target[k], 0.0));
      const double near_share = it != near_shares.end() && it->first == transport.target[k] ? it->second : 0.0;
      far[k] = float(std::max(0.0, double(transport.form_factor[k]) - near_share));
    }
  });
  return far;
}

// The near field moves light, it must not make any: what receivers near a patch took beyond its
// texels' mean is what its far receivers get less of. (Where that mean itself differs from the
// patch's, `level_change`, q's texels send that much more or less to everyone: that reaches far
// receivers as a bounce, near_field_bounces, and is not balanced here.) Their share of the patch's
// light, F_pq less what the near field carried, is known from the form factors; each far receiving
// patch p gives up sum over q of f_pq c_q, with c_q chosen so that q's far receivers give up its
// excess exactly.
std::vector<Rgb> far_field_correction(const Patches& patches, const PatchTransport& transport, const NearTally& near,
                                      const std::vector<float>& far_share, const std::vector<Rgb>& level_change) {
  const size_t n = patches.size();
  std::vector<std::array<double, 3>> excess(n, {0, 0, 0});
  for (const auto& [pq, x] : near) {
    Lumens beyond_level = x.excess;
    beyond_level.add(-x.share, level_change[pq.second]);
    for (int c = 0; c < 3; ++c) excess[pq.second][size_t(c)] += beyond_level.c[c];
  }
  // sum over p of A_p f_pq, and of A_p F_pq: a patch that only near receivers see (every F_pq
  // taken up by the near field) has its excess shared by all its receivers instead.
  std::vector<double> far_area(n, 0), seen_area(n, 0);
  for (size_t p = 0; p < n; ++p)
    for (uint64_t k = transport.row_start[p]; k < transport.row_start[p + 1]; ++k) {
      far_area[transport.target[k]] += patches.area[p] * far_share[k];
      seen_area[transport.target[k]] += double(patches.area[p]) * transport.form_factor[k];
    }
  std::vector<uint8_t> only_near(n);
  for (size_t q = 0; q < n; ++q) only_near[q] = !(far_area[q] > 1e-3 * seen_area[q]);
  std::vector<Rgb> correction(n);
  for (size_t p = 0; p < n; ++p) {
    double sum[3] = {};
    for (uint64_t k = transport.row_start[p]; k < transport.row_start[p + 1]; ++k) {
      const uint32_t q = transport.target[k];
      if (!(seen_area[q] > 0)) continue;
      const double f = only_near[q] ? transport.form_factor[k] / seen_area[q] : far_share[k] / far_area[q];
      for (int c = 0; c < 3; ++c) sum[c] += f * excess[q][size_t(c)];
    }
    correction[p] = Rgb{float(-sum[0]), float(-sum[1]), float(-sum[2])};
  }
  return correction;
}

// The near field changes what patches receive, and so what they reflect, which the solve did not
// know. Two kinds of change: `in_texels`, per patch p the mean change its texels' gathered light
// already holds (struck texels' own light in place of their patches'), and `applied`, what is still
// to be added to them (the far correction). Near rays took the struck texels' own light, so the
// in_texels change of a patch reaches others first through their far rays only; counted through
// the whole form factor it came twice, and in a room that the near field covers nearly whole
// (the defaults' 6-texel patches on the FZK-Haus) an inner wall lost 24% of its light to it.
// Every change beyond that first reflection reaches near and far rays alike: the bounce solved
// is dR_p = rho_p (applied_p + first_p + sum_q F_pq dR_q), first_p = sum_q f_pq rho_q in_texels_q
// with f the far share (Gauss-Seidel; it converges as the solve did, rho F < 1), and each patch
// receives first_p + sum_q F_pq dR_q. Without it the extra light a lamp's near texels take from
// the ceiling over it would still be reflected into the room as well.
std::vector<Rgb> near_field_bounces(const Patches& patches, const PatchTransport& transport,
                                    const std::vector<float>& far_share, const std::vector<Rgb>& in_texels,
                                    const std::vector<Rgb>& applied) {
  const size_t n = patches.size();
  std::vector<Rgb> source = applied, first(n);
  for (size_t p = 0; p < n; ++p) {
    for (uint64_t k = transport.row_start[p]; k < transport.row_start[p + 1]; ++k) {
      const uint32_t q = transport.target[k];
      first[p] += patches.reflectance[q] * in_texels[q] * far_share[k];
    }
    source[p] += first[p];
  }
  std::vector<Rgb> reflected(n);
  float largest = 0;
  for (size_t p = 0; p < n; ++p) {
    reflected[p] = patches.reflectance[p] * source[p];
    largest = std::max({largest, std::fabs(reflected[p].x), std::fabs(reflected[p].y), std::fabs(reflected[p].z)});
  }
  if (!(largest > 0)) return first;
  for (int sweep = 0; sweep < 500; ++sweep) {
    float change = 0;
    for (size_t p = 0; p < n; ++p) {
      Rgb incoming = source[p];
      for (uint64_t k = transport.row_start[p]; k < transport.row_start[p + 1]; ++k)
        incoming += reflected[transport.target[k]] * transport.form_factor[k];
      const Rgb b = patches.reflectance[p] * incoming, d = b - reflected[p];
      change = std::max({change, std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
      reflected[p] = b;
    }
    if (change <= 1e-5f * largest) break;
  }
  std::vector<Rgb> bounces = gathered_irradiance(patches, transport, reflected);
  for (size_t p = 0; p < n; ++p) bounces[p] += first[p];
  return bounces;
}

// Texels in a corner light each other: what the floor's first row reflects onto the foot of a
// block depends on what that foot reflects back, and both are darker than their patches. So the
// near field takes each struck texel's own gathered light, rho_j (D_j + H_j), and the H of the
// texels with near landings are solved together, H_i = far_i + sum_j (n_ij / rays) rho_j (D_j + H_j),
// `irradiance` coming in with the struck texels' patch H in place of H_j. Jacobi sweeps (each
// reads only the last), so threads do not change the result; rho times the near share of a
// hemisphere is below one, so they converge.
void solve_near_indirect(const Elements& e, const Patches& patches, const std::vector<Rgb>& patch_indirect,
                         const std::vector<NearLanding>& landings, uint32_t rays, std::vector<Rgb>& irradiance) {
  const float per_ray = 1.0f / float(rays);
  std::vector<Rgb> fixed = irradiance;
  float largest = 0;
  for (const NearLanding& l : landings) {
    fixed[l.receiver] -= e.reflectance[l.struck] * patch_indirect[patches.patch_of_element[l.struck]] *
                         (float(l.count) * per_ray);
    const Rgb& h = irradiance[l.receiver];
    largest = std::max({largest, h.x, h.y, h.z});
  }
  // Blocks of landings that begin with a receiver's first, so each receiver is one block's.
  constexpr size_t kBlock = 1024;
  std::vector<size_t> block_start;
  for (size_t a = 0; a < landings.size(); ++a)
    if (block_start.empty() || (a - block_start.back() >= kBlock && landings[a].receiver != landings[a - 1].receiver))
      block_start.push_back(a);
  block_start.push_back(landings.size());
  const size_t blocks = block_start.size() - 1;
  std::vector<Rgb> next = irradiance;
  std::vector<float> block_change(blocks);
  for (int sweep = 0; sweep < 200 && blocks > 0; ++sweep) {
    tbb::parallel_for(size_t(0), blocks, [&](size_t block) {
      float change = 0;
      for (size_t a = block_start[block], b; a < block_start[block + 1]; a = b) {
        const uint32_t i = landings[a].receiver;
        Rgb h = fixed[i];
        for (b = a; b < block_start[block + 1] && landings[b].receiver == i; ++b)
          h += e.reflectance[landings[b].struck] * irradiance[landings[b].struck] * (float(landings[b].count) * per_ray);
        const Rgb d = h - irradiance[i];
        change = std::max({change, std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
        next[i] = h;
      }
      block_change[block] = change;
    });
    for (const NearLanding& l : landings) irradiance[l.receiver] = next[l.receiver];
    if (*std::max_element(block_change.begin(), block_change.end()) <= 1e-5f * largest) break;
  }
}

// What a ray landing beyond the near field takes from element `struck` of patch `q`: the texel's
// own reflected direct light and its patch's reflected indirect light (the patch's exitance less its
// texels' mean reflected direct light). Where the sun lights part of a patch, the receivers that
// see that part best take its light, and no more of it than its texels send their way: a far ray
// strikes each texel by what the receiver sees of it, as the path tracer's would.
Rgb far_exitance(const Elements& e, const GatherInputs& inputs, const std::vector<Rgb>& patch_exitance,
                 const std::vector<Rgb>& direct, uint32_t struck, uint32_t q) {
  const Rgb own = patch_exitance[q] - inputs.reflected_direct[q] + e.reflectance[struck] * direct[struck];
  return {std::max(own.x, 0.0f), std::max(own.y, 0.0f), std::max(own.z, 0.0f)};
}

// What the near field took beyond what far rays take from the same texels (their own indirect light
// in place of their patch's), by (receiving patch, struck patch).
NearTally tally_near_field(const Elements& e, const Patches& patches, const GatherInputs& inputs,
                           const std::vector<Rgb>& patch_exitance, const std::vector<Rgb>& direct,
                           const std::vector<Rgb>& irradiance, const std::vector<NearLanding>& landings,
                           uint32_t rays) {
  NearTally near;
  for (const NearLanding& l : landings) {
    const uint32_t q = patches.patch_of_element[l.struck];
    const Rgb beyond = e.reflectance[l.struck] * (direct[l.struck] + irradiance[l.struck]) -
                       far_exitance(e, inputs, patch_exitance, direct, l.struck, q);
    const double share = double(e.area[l.receiver]) * l.count / rays;
    NearExchange& exchange = near[{patches.patch_of_element[l.receiver], q}];
    exchange.share += share;
    exchange.excess.add(share, beyond);
    exchange.direct_beyond.add(share, e.reflectance[l.struck] * direct[l.struck] - inputs.reflected_direct[q]);
  }
  return near;
}

// Adds each patch's change of irradiance to its texels: a gain evenly, a loss in proportion to
// what each texel gathered, so that no texel goes below zero while the patch still gives up the
// whole loss (taken evenly, a dark texel's share would be clamped away and light created: 1.3%
// of a CAD engine's light, full of crevices where most light is near field).
void apply_patch_changes(const Elements& e, const Patches& patches, const std::vector<Rgb>& change,
                         std::vector<Rgb>& irradiance) {
  std::vector<Rgb> mean(patches.size());
  for (size_t i = 0; i < e.size(); ++i)
    if (e.valid(i) && patches.patch_of_element[i] != UINT32_MAX)
      mean[patches.patch_of_element[i]] += irradiance[i] * e.area[i];
  for (size_t p = 0; p < patches.size(); ++p)
    if (patches.area[p] > 0) mean[p] = mean[p] / patches.area[p];
  auto changed = [](float value, float mean, float change) {  // at least 0: the near solve rounds
    if (change >= 0) return std::max(0.0f, value + change);
    return mean > 0 ? std::max(0.0f, value) * std::max(0.0f, 1 + change / mean) : 0.0f;
  };
  for (size_t i = 0; i < e.size(); ++i)
    if (e.valid(i) && patches.patch_of_element[i] != UINT32_MAX) {
      const uint32_t p = patches.patch_of_element[i];
      irradiance[i] = Rgb{changed(irradiance[i].x, mean[p].x, change[p].x), changed(irradiance[i].y, mean[p].y, change[p].y),
                          changed(irradiance[i].z, mean[p].z, change[p].z)};
    }
}

}  // namespace

GatherInputs gather_inputs(const Elements& e, const Patches& patches, const Surface& surface,
                           std::vector<Rgb> patch_indirect, const std::vector<Rgb>& direct) {
  std::vector<Rgb> reflected_direct(patches.size());
  for (size_t p = 0; p < patches.size(); ++p) {
    for (uint32_t k = patches.first_member[p]; k < patches.first_member[p + 1]; ++k) {
      const uint32_t i = patches.members[k];
      reflected_direct[p] += e.reflectance[i] * direct[i] * e.area[i];
    }
    if (patches.area[p] > 0) reflected_direct[p] = reflected_direct[p] / patches.area[p];
  }
  return {std::move(patch_indirect), near_reach(e, patches, surface), std::move(reflected_direct)};
}

GatherTrace trace_gather(const BakeGeometry& geometry, const Patches& patches, const GatherInputs& inputs,
                         const std::vector<Rgb>& patch_exitance, const std::vector<Rgb>& direct,
                         const GatherOptions& options, uint64_t seed, ElementRange range, bool directions) {
  const Elements& e = geometry.elements;
  const Surface& surface = *geometry.surface;
  const RayTracer& tracer = *geometry.tracer;
  const uint32_t rays = options.rays;
  const bool near_field = options.near_field;
  range = range.within(e.size());
  GatherTrace out;
  out.irradiance.resize(range.size());
  out.harmonic_distance.assign(range.size(), INFINITY);
  out.open_view.assign(range.size(), 0.0f);
  out.lost_share.assign(range.size(), 0.0f);
  out.far_beyond_mean.assign(range.size(), Rgb{});
  if (directions) out.mean_direction.resize(range.size());
  // Fixed blocks of elements, each with its own list of near landings, joined in block order: the
  // same list whatever the threads.
  constexpr size_t kBlock = 256;
  std::vector<std::vector<NearLanding>> landings((range.size() + kBlock - 1) / kBlock);
  std::vector<RayFates> fates(landings.size());
  tbb::parallel_for(size_t(0), landings.size(), [&](size_t block) {
    std::vector<uint32_t> struck;
    const size_t begin = range.begin + block * kBlock, end = std::min(range.end, begin + kBlock);
    for (size_t i = begin; i < end; ++i) {
      if (!e.valid(i) || rays == 0 || patches.patch_of_element[i] == UINT32_MAX) continue;
      const Vec3 ng = surface.normal[e.triangle[i]];
      Rng rng(seed, Stream::Gather, i);
      const uint32_t origin_pattern = rng.next_u32(), direction_pattern = rng.next_u32();
      Rgb sum{}, beyond_mean{};
      LightDirection from{};
      double nearness = 0;  // sum of 1 / distance
      uint32_t escaped = 0, lost = 0;
      struck.clear();
      for (uint32_t k = 0; k < rays; ++k) {
        // Origins spread over the texel, as the form factor rays do: an element stands for its
        // whole footprint, and near a wall the footprint sees more of the wall than its centre.
        Vec3 origin = footprint_point(e, surface, i, cmj_sample(k, rays, origin_pattern)) + ng * e.offset[i];
        Vec3 dir = hemisphere_direction(e.normal[i], ng, cmj_sample(k, rays, direction_pattern));
        const Landing at = land(e, patches, surface, tracer, origin, dir, e.flags[i]);
        fates[block].add(at.fate);
        escaped += at.escaped;
        lost += at.fate != RayFate::TookLight && at.fate != RayFate::Escaped;
        if (!at.escaped) nearness += 1.0 / std::max(at.distance, 1e-6f);
        if (at.patch == UINT32_MAX) continue;
        if (near_field && at.distance < inputs.near_reach[at.patch]) {
          sum += e.reflectance[at.element] * direct[at.element];
          struck.push_back(at.element);
          if (directions)
            from.add(e.reflectance[at.element] * (direct[at.element] + inputs.patch_indirect[at.patch]), dir);
        } else {
          const Rgb value = far_exitance(e, inputs, patch_exitance, direct, at.element, at.patch);
          sum += value;
          beyond_mean += value - patch_exitance[at.patch];
          if (directions) from.add(value, dir);
        }
      }
      // Until the near texels' own light is solved, their patches' stands in for it.
      std::sort(struck.begin(), struck.end());
      for (auto a = struck.begin(); a != struck.end();) {
        const auto b = std::upper_bound(a, struck.end(), *a);
        landings[block].push_back({uint32_t(i), *a, uint32_t(b - a)});
        sum += e.reflectance[*a] * inputs.patch_indirect[patches.patch_of_element[*a]] * float(b - a);
        a = b;
      }
      // With cosine-distributed directions, irradiance is the mean exitance seen (E = pi * mean L).
      out.irradiance[i - range.begin] = sum / float(rays);
      if (directions) {  // over what the rays found, as the directions weigh it
        const Rgb per{sum.x > 0 ? 1 / sum.x : 0, sum.y > 0 ? 1 / sum.y : 0, sum.z > 0 ? 1 / sum.z : 0};
        out.mean_direction[i - range.begin] = from * per;
      }
      if (nearness > 0) out.harmonic_distance[i - range.begin] = float(double(rays) / nearness);
      out.open_view[i - range.begin] = float(escaped) / float(rays);
      out.lost_share[i - range.begin] = float(lost) / float(rays);
      out.far_beyond_mean[i - range.begin] = beyond_mean / float(rays);
    }
  });
  for (const auto& block : landings) out.landings.insert(out.landings.end(), block.begin(), block.end());
  for (const RayFates& f : fates) out.fates += f;
  return out;
}

GatheredLight finish_gather(const Elements& e, const Patches& patches, const PatchTransport& transport,
                            const GatherInputs& inputs, const std::vector<Rgb>& patch_exitance,
                            const std::vector<Rgb>& direct, const GatherOptions& options, GatherTrace whole,
                            GatherStats* stats) {
  const uint32_t rays = options.rays;
  const bool near_field = options.near_field;
  GatheredLight out;
  out.irradiance = std::move(whole.irradiance);
  out.harmonic_distance = std::move(whole.harmonic_distance);
  out.open_view = std::move(whole.open_view);
  out.lost_share = std::move(whole.lost_share);
  out.mean_direction = std::move(whole.mean_direction);
  if (rays > 0 && near_field) solve_near_indirect(e, patches, inputs.patch_indirect, whole.landings, rays, out.irradiance);
  const NearTally near = tally_near_field(e, patches, inputs, patch_exitance, direct, out.irradiance, whole.landings, rays);
  std::vector<Rgb> in_texels(patches.size());  // per patch: the mean change its texels already hold
  for (const auto& [pq, x] : near) {
    const float to_mean = float(1.0 / patches.area[pq.first]);
    in_texels[pq.first] += x.excess.rgb() * to_mean;
    in_texels[pq.first] += x.direct_beyond.rgb() * to_mean;
  }
  // Far rays took their struck texels' own direct light, which over each struck texel sums to what
  // it sends (nothing to balance), but which changes what their patches receive from the solve's.
  for (size_t i = 0; i < e.size(); ++i)
    if (e.valid(i) && patches.patch_of_element[i] != UINT32_MAX)
      in_texels[patches.patch_of_element[i]] +=
          whole.far_beyond_mean[i] * float(e.area[i] / patches.area[patches.patch_of_element[i]]);
  std::vector<Rgb> level_change(patches.size());
  for (size_t p = 0; p < patches.size(); ++p) level_change[p] = patches.reflectance[p] * in_texels[p];
  const std::vector<float> far_share = far_form_factors(patches, transport, near);
  std::vector<Rgb> correction = far_field_correction(patches, transport, near, far_share, level_change);
  const std::vector<Rgb> bounces = near_field_bounces(patches, transport, far_share, in_texels, correction);
  for (size_t p = 0; p < patches.size(); ++p) correction[p] += bounces[p];
  apply_patch_changes(e, patches, correction, out.irradiance);
  if (stats) stats->fates = whole.fates;
  return out;
}

}  // namespace radbake
