#include "baker/final_gather.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <map>

#include "baker/interreflection.h"
#include "baker/sampling.h"

namespace radbake {

namespace {

// What each texel reflects: its own reflectance times its own direct light plus its patch's
// indirect. Over a patch these average to about the patch's exitance, but a ray landing close by
// sees the texel, not the average: the bright strip of ceiling over a lamp, the dark floor at a
// block's foot.
std::vector<Rgb> texel_exitance(const Elements& e, const Patches& patches, const PatchTransport& transport,
                                const std::vector<Rgb>& patch_exitance, const std::vector<Rgb>& direct) {
  const std::vector<Rgb> indirect = gathered_irradiance(patches, transport, patch_exitance);
  std::vector<Rgb> exitance(e.size());
  for (size_t j = 0; j < e.size(); ++j)
    if (patches.patch_of_element[j] != UINT32_MAX)
      exitance[j] = e.reflectance[j] * (direct[j] + indirect[patches.patch_of_element[j]]);
  return exitance;
}

// How far each patch reaches across its surface, metres: a ray landing nearer than this sees the
// patch's texels unevenly, and its mean exitance is the wrong answer there.
std::vector<float> patch_widths(const Elements& e, const Patches& patches, const Surface& surface) {
  std::vector<float> width(patches.size());
  for (size_t p = 0; p < patches.size(); ++p)
    width[p] = float(patches.side[p]) * surface.texel_size(e.triangle[patches.members[patches.first_member[p]]]);
  return width;
}

// What the near field took from one patch q into the texels of patch p: lm of texel exitance
// beyond q's mean (excess) and the share of p's hemisphere it came through, A_p-weighted (m^2).
struct NearExchange {
  double share = 0;
  double excess[3] = {};
};
using NearTally = std::map<std::pair<uint32_t, uint32_t>, NearExchange>;  // by (p, q)

// The near field moves light, it must not make any: what receivers near a patch took beyond its
// mean is what its far receivers get less of. Their share of the patch's light, F_pq less what
// the near field carried, is known from the form factors; each far receiving patch p gives up
// sum over q of f_pq c_q, with c_q chosen so that q's far receivers give up its excess exactly.
std::vector<Rgb> far_field_correction(const Patches& patches, const PatchTransport& transport, const NearTally& near) {
  const size_t n = patches.size();
  std::vector<std::array<double, 3>> excess(n, {0, 0, 0});
  for (const auto& [pq, x] : near)
    for (int c = 0; c < 3; ++c) excess[pq.second][size_t(c)] += x.excess[c];
  auto far_share = [&](size_t p, uint64_t k) {
    auto it = near.find({uint32_t(p), transport.target[k]});
    const double near_share = it == near.end() ? 0.0 : it->second.share / patches.area[p];
    return std::max(0.0, double(transport.form_factor[k]) - near_share);
  };
  // sum over p of A_p f_pq, and of A_p F_pq: a patch that only near receivers see (every F_pq
  // taken up by the near field) has its excess shared by all its receivers instead.
  std::vector<double> far_area(n, 0), seen_area(n, 0);
  for (size_t p = 0; p < n; ++p)
    for (uint64_t k = transport.row_start[p]; k < transport.row_start[p + 1]; ++k) {
      far_area[transport.target[k]] += patches.area[p] * far_share(p, k);
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
      const double f = only_near[q] ? transport.form_factor[k] / seen_area[q] : far_share(p, k) / far_area[q];
      for (int c = 0; c < 3; ++c) sum[c] += f * excess[q][size_t(c)];
    }
    correction[p] = Rgb{float(-sum[0]), float(-sum[1]), float(-sum[2])};
  }
  return correction;
}

// The near field changes what patches receive (the far correction included: per patch p, its
// texels' mean change), and so what they reflect, which the solve did not know. The change is
// solved as radiosity of its own over the same form factors, dB_p = rho_p (dE_p + sum_q F_pq dB_q)
// (Gauss-Seidel; it converges as the solve did, rho F < 1), and what it sends is gathered back
// per patch: without it the extra light a lamp's near texels take from the ceiling over it would
// still be reflected into the room as well.
std::vector<Rgb> near_field_bounces(const Patches& patches, const PatchTransport& transport,
                                    const std::vector<Rgb>& received) {
  const size_t n = patches.size();
  std::vector<Rgb> reflected(n);
  float largest = 0;
  for (size_t p = 0; p < n; ++p) {
    reflected[p] = patches.reflectance[p] * received[p];
    largest = std::max({largest, std::fabs(reflected[p].x), std::fabs(reflected[p].y), std::fabs(reflected[p].z)});
  }
  if (!(largest > 0)) return std::vector<Rgb>(n);
  for (int sweep = 0; sweep < 500; ++sweep) {
    float change = 0;
    for (size_t p = 0; p < n; ++p) {
      Rgb incoming = received[p];
      for (uint64_t k = transport.row_start[p]; k < transport.row_start[p + 1]; ++k)
        incoming += reflected[transport.target[k]] * transport.form_factor[k];
      const Rgb b = patches.reflectance[p] * incoming, d = b - reflected[p];
      change = std::max({change, std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
      reflected[p] = b;
    }
    if (change <= 1e-5f * largest) break;
  }
  return gathered_irradiance(patches, transport, reflected);
}

}  // namespace

GatheredLight gather_indirect(const Elements& e, const Patches& patches, const Surface& surface,
                              const RayTracer& tracer, const PatchTransport& transport,
                              const std::vector<Rgb>& patch_exitance, const std::vector<Rgb>& direct, uint32_t rays,
                              bool near_field, uint64_t seed, Progress& progress, GatherStats* stats) {
  GatheredLight out;
  out.irradiance.resize(e.size());
  out.harmonic_distance.assign(e.size(), INFINITY);
  const std::vector<Rgb> near_exitance = texel_exitance(e, patches, transport, patch_exitance, direct);
  const std::vector<float> width = patch_widths(e, patches, surface);
  // Fixed blocks of elements, each with its own tally, merged in block order: the same sums
  // whatever the threads.
  constexpr size_t kBlock = 256;
  std::vector<NearTally> tallies((e.size() + kBlock - 1) / kBlock);
  std::atomic<uint64_t> lost{0}, cast{0};
  progress.begin("final gather", e.size());
  tbb::parallel_for(size_t(0), tallies.size(), [&](size_t block) {
    uint64_t my_lost = 0, my_cast = 0;
    NearTally& tally = tallies[block];
    const size_t begin = block * kBlock, end = std::min(e.size(), begin + kBlock);
    for (size_t i = begin; i < end; ++i) {
      if (!e.valid(i) || rays == 0 || patches.patch_of_element[i] == UINT32_MAX) continue;
      const Vec3 ng = surface.normal[e.triangle[i]];
      const double share = double(e.area[i]) / rays;
      Rng rng(seed, Stream::Gather, i);
      const uint32_t origin_pattern = rng.next_u32(), direction_pattern = rng.next_u32();
      Rgb sum{};
      double nearness = 0;  // sum of 1 / distance
      for (uint32_t k = 0; k < rays; ++k) {
        // Origins spread over the texel, as the form factor rays do: an element stands for its
        // whole footprint, and near a wall the footprint sees more of the wall than its centre.
        Vec3 origin = footprint_point(e, surface, i, cmj_sample(k, rays, origin_pattern)) + ng * e.offset[i];
        Vec3 dir = hemisphere_direction(e.normal[i], ng, cmj_sample(k, rays, direction_pattern));
        const Landing at = land(e, patches, surface, tracer, origin, dir);
        if (!at.escaped) nearness += 1.0 / std::max(at.distance, 1e-6f);
        if (at.patch == UINT32_MAX) {
          my_lost += !at.escaped;
          continue;
        }
        if (!near_field || at.distance >= width[at.patch]) {
          sum += patch_exitance[at.patch];
          continue;
        }
        const Rgb x = near_exitance[at.element], beyond = x - patch_exitance[at.patch];
        sum += x;
        NearExchange& exchange = tally[{patches.patch_of_element[i], at.patch}];
        exchange.share += share;
        exchange.excess[0] += share * beyond.x;
        exchange.excess[1] += share * beyond.y;
        exchange.excess[2] += share * beyond.z;
      }
      // With cosine-distributed directions, irradiance is the mean exitance seen (E = pi * mean L).
      out.irradiance[i] = sum / float(rays);
      if (nearness > 0) out.harmonic_distance[i] = float(double(rays) / nearness);
      my_cast += rays;
    }
    lost += my_lost;
    cast += my_cast;
    progress.advance(end - begin);
  });
  progress.end();
  NearTally near;
  for (const NearTally& tally : tallies)
    for (const auto& [pq, x] : tally) {
      NearExchange& into = near[pq];
      into.share += x.share;
      for (int c = 0; c < 3; ++c) into.excess[c] += x.excess[c];
    }
  std::vector<Rgb> correction = far_field_correction(patches, transport, near);
  std::vector<Rgb> received = correction;  // per patch: the mean change of its texels' irradiance
  for (const auto& [pq, x] : near) {
    const float to_mean = float(1.0 / patches.area[pq.first]);
    received[pq.first] += Rgb{float(x.excess[0]), float(x.excess[1]), float(x.excess[2])} * to_mean;
  }
  const std::vector<Rgb> bounces = near_field_bounces(patches, transport, received);
  for (size_t p = 0; p < patches.size(); ++p) correction[p] += bounces[p];
  for (size_t i = 0; i < e.size(); ++i)
    if (e.valid(i) && patches.patch_of_element[i] != UINT32_MAX) {
      const Rgb v = out.irradiance[i] + correction[patches.patch_of_element[i]];
      out.irradiance[i] = Rgb{std::max(v.x, 0.0f), std::max(v.y, 0.0f), std::max(v.z, 0.0f)};
    }
  if (stats) stats->back_face_fraction = cast ? double(lost) / double(cast) : 0.0;
  return out;
}

}  // namespace radbake
