#include "baker/transport/hemicube_transport.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "baker/surface/sampling.h"

namespace radbake {
namespace {

struct HemicubePixel {
  Vec3 direction;  // in the hemicube's frame (z along the normal), not normalised
  float delta_form_factor;
};

// The unit hemicube's pixels: top face z = 1 over [-1, 1]^2, and four half faces of height 1.
// Delta form factors: dA / (pi (x^2 + y^2 + 1)^2) on top, z dA / (pi (u^2 + z^2 + 1)^2) on a
// side. They sum to 1 only as the resolution grows; they are scaled to sum to exactly 1, so that a
// row, like a ray-cast one, accounts for all the light leaving the patch.
std::vector<HemicubePixel> hemicube_pixels(int resolution) {
  std::vector<HemicubePixel> pixels;
  const float step = 2.0f / float(resolution);
  const float area = step * step;
  for (int j = 0; j < resolution; ++j)
    for (int i = 0; i < resolution; ++i) {
      float x = -1 + (float(i) + 0.5f) * step, y = -1 + (float(j) + 0.5f) * step;
      float r = x * x + y * y + 1;
      pixels.push_back({{x, y, 1}, area / (kPi * r * r)});
    }
  const Vec3 outward[4] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  for (Vec3 side : outward) {
    Vec3 across{side.y, side.x, 0};  // along the face, perpendicular to z
    for (int j = 0; j < resolution / 2; ++j)
      for (int i = 0; i < resolution; ++i) {
        float u = -1 + (float(i) + 0.5f) * step, z = (float(j) + 0.5f) * step;
        float r = u * u + z * z + 1;
        pixels.push_back({side + across * u + Vec3{0, 0, z}, z * area / (kPi * r * r)});
      }
  }
  double total = 0;
  for (const HemicubePixel& p : pixels) total += p.delta_form_factor;
  for (HemicubePixel& p : pixels) p.delta_form_factor = float(p.delta_form_factor / total);
  return pixels;
}

struct Viewpoint {
  Vec3 origin, normal, geometric_normal;
};

// Where a patch's hemicube stands: the area-weighted centroid of a flat patch (lifted like its
// elements' ray origins); on a curved patch, whose centroid may lie off the surface, the sample
// point of the member element nearest to it.
Viewpoint viewpoint(const Elements& elements, const Patches& patches, const Surface& surface, size_t p) {
  Vec3 centroid{};
  double area = 0;
  for (uint32_t k = patches.first_member[p]; k < patches.first_member[p + 1]; ++k) {
    uint32_t i = patches.members[k];
    centroid += elements.position[i] * elements.area[i];
    area += elements.area[i];
  }
  centroid = centroid / float(area);
  uint32_t nearest = patches.members[patches.first_member[p]];
  float nearest_distance = INFINITY, offset = 0;
  bool flat = true;
  const Vec3 ng = surface.normal[elements.triangle[nearest]];
  for (uint32_t k = patches.first_member[p]; k < patches.first_member[p + 1]; ++k) {
    uint32_t i = patches.members[k];
    float d = length(elements.position[i] - centroid);
    if (d < nearest_distance) nearest_distance = d, nearest = i;
    offset = std::max(offset, elements.offset[i]);
    flat = flat && dot(surface.normal[elements.triangle[i]], ng) > 0.9999f &&
           std::fabs(dot(elements.position[i] - centroid, ng)) <= elements.offset[i];
  }
  const Vec3 n = surface.normal[elements.triangle[nearest]];
  if (flat) return {centroid + n * offset, elements.normal[nearest], n};
  return {elements.position[nearest] + n * elements.offset[nearest], elements.normal[nearest], n};
}

}  // namespace

void measure_hemicube_rows(const Elements& elements, const Patches& patches, const Surface& surface,
                           const RayTracer& tracer, int resolution, const std::vector<uint32_t>& which, uint64_t seed,
                           Progress& progress, MeasuredRows& out) {
  const std::vector<HemicubePixel> pixels = hemicube_pixels(resolution);
  const size_t patch_count = patches.size();

  tbb::enumerable_thread_specific<RowTally> tallies;
  progress.begin("form factors", which.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, which.size(), 4), [&](const tbb::blocked_range<size_t>& r) {
    RowTally& tally = tallies.local();
    for (size_t w = r.begin(); w < r.end(); ++w) {
      const uint32_t p = which[w];
      const Viewpoint view = viewpoint(elements, patches, surface, p);
      const Vec3 ng = view.geometric_normal, n = view.normal, origin = view.origin;
      // A patch never holds texels both under a cover and in the open (place_samples).
      const uint8_t side = elements.flags[patches.members[patches.first_member[p]]] & kUnderCover;
      Vec3 t, b;
      orthonormal_basis(n, t, b);
      Rng rng(seed, Stream::Hemicube, p);
      const float turn = 2 * kPi * rng.uniform();
      const Vec3 tx = t * std::cos(turn) + b * std::sin(turn), ty = cross(n, tx);
      double escaped = 0, lost = 0;
      RayFates fates;
      for (const HemicubePixel& pixel : pixels) {
        Vec3 dir = above_surface(normalize(tx * pixel.direction.x + ty * pixel.direction.y + n * pixel.direction.z), ng);
        bool left;
        uint32_t q = patch_hit(elements, patches, surface, tracer, origin, dir, side, left, fates);
        if (q == UINT32_MAX) {
          (left ? escaped : lost) += pixel.delta_form_factor;
          continue;
        }
        tally.add(q, pixel.delta_form_factor, patch_count);
      }
      tally.take(out.rows[p], 1.0f);
      out.escaped[p] = float(escaped);
      out.lost[p] = float(lost);
      out.rays[p] = uint32_t(pixels.size());
      out.fates[p] = fates;
    }
    progress.advance(r.size());
  });
  progress.end();
}

PatchTransport hemicube_patch_transport(const Elements& elements, const Patches& patches, const Surface& surface,
                                        const RayTracer& tracer, int resolution, uint64_t seed, Progress& progress) {
  MeasuredRows rows;
  rows.resize(patches.size());
  measure_hemicube_rows(elements, patches, surface, tracer, resolution, all_patches(patches.size()), seed, progress,
                        rows);
  return balanced_transport(patches, std::move(rows));
}

}  // namespace radbake
