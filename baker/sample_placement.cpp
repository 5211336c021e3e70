#include <tbb/parallel_for.h>

#include <cmath>

#include "baker/elements.h"
#include "baker/ray_tracer.h"
#include "baker/sampling.h"

namespace radbake {
namespace {

constexpr int kTangentProbes = 8;
constexpr int kBurialProbes = 16;
constexpr int kFootprintCells = 4;  // per side: the grid of Elements::visible_cells
// Bakery's rule of thumb: a sample that sees back faces in half its hemisphere is inside geometry.
constexpr float kBuriedBackfaceFraction = 0.5f;

}  // namespace

void place_samples(Elements& e, const Surface& surface, const RayTracer& tracer, uint64_t seed, Progress& progress) {
  const size_t n = e.size();
  progress.begin("sample placement", n);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 512), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i) {
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
            Vec3 from = e.position[i] + ng * eps, to = p + ng * eps;
            Vec3 d = to - from;
            float dist = length(d);
            if (dist <= eps || !tracer.occluded(from, d / dist, 0.0f, dist)) {
              ++visible;
              e.visible_cells[i] |= uint16_t(1u << (sy * k + sx));
            }
          }
        if (on_surface > 0) e.area[i] *= float(visible) / float(on_surface);
        if (visible == 0) e.flags[i] |= kBuried;  // all of it is behind the wall
      }

      Rng rng(seed, Stream::Probe, i);
      uint32_t pattern = rng.next_u32();
      int back = 0;
      Vec3 from = e.position[i] + ng * eps;
      for (int k = 0; k < kBurialProbes; ++k) {
        Vec3 dir = cosine_direction(ng, cmj_sample(uint32_t(k), kBurialProbes, pattern));
        Hit hit = tracer.intersect(from, dir, 0.0f, INFINITY);
        back += !hit.missed() && !hit.front;
      }
      if (back >= kBuriedBackfaceFraction * kBurialProbes) e.flags[i] |= kBuried;
    }
    progress.advance(r.size());
  });

  // Joins to the right and lower neighbours, once every sample has its final place. Only texels
  // near geometry can have a wall between them and a neighbour; the rest join without a ray.
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
        if (j < 0 || !e.valid(size_t(j)) || surface.chart[e.triangle[size_t(j)]] != surface.chart[e.triangle[i]]) continue;
        bool joined = true;
        if ((e.flags[i] | e.flags[size_t(j)]) & kNearGeometry) {
          Vec3 from = e.position[i] + surface.normal[e.triangle[i]] * e.offset[i];
          Vec3 to = e.position[size_t(j)] + surface.normal[e.triangle[size_t(j)]] * e.offset[size_t(j)];
          Vec3 d = to - from;
          float dist = length(d);
          joined = !(dist > 0) || !tracer.occluded(from, d / dist, 0.0f, dist);
        }
        if (joined) e.flags[i] |= bits[k];
      }
    }
  });
  progress.end();
}

}  // namespace radbake
