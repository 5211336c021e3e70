#include "baker/final_gather.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include "baker/patch_transport.h"
#include "baker/sampling.h"

namespace radbake {

GatheredLight gather_indirect(const Elements& e, const Patches& patches, const Surface& surface,
                                 const RayTracer& tracer, const std::vector<Rgb>& patch_exitance, uint32_t rays,
                                 uint64_t seed, Progress& progress, GatherStats* stats) {
  GatheredLight out;
  out.irradiance.resize(e.size());
  out.harmonic_distance.assign(e.size(), INFINITY);
  std::atomic<uint64_t> lost{0}, cast{0};
  progress.begin("final gather", e.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, e.size(), 64), [&](const tbb::blocked_range<size_t>& r) {
    uint64_t my_lost = 0, my_cast = 0;
    for (size_t i = r.begin(); i < r.end(); ++i) {
      if (!e.valid(i) || rays == 0) continue;
      const Vec3 ng = surface.normal[e.triangle[i]];
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
        if (at.patch != UINT32_MAX) sum += patch_exitance[at.patch];
        else my_lost += !at.escaped;
      }
      // With cosine-distributed directions, irradiance is the mean exitance seen (E = pi * mean L).
      out.irradiance[i] = sum / float(rays);
      if (nearness > 0) out.harmonic_distance[i] = float(double(rays) / nearness);
      my_cast += rays;
    }
    lost += my_lost;
    cast += my_cast;
    progress.advance(r.size());
  });
  progress.end();
  if (stats) stats->back_face_fraction = cast ? double(lost) / double(cast) : 0.0;
  return out;
}

}  // namespace radbake
