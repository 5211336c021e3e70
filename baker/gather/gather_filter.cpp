#include "baker/gather/gather_filter.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace radbake {

std::vector<Rgb> filter_gathered(const Elements& e, const Surface& surface, const std::vector<Rgb>& indirect,
                                 const std::vector<float>& harmonic_distance, const std::vector<uint8_t>& use,
                                 const GatherFilterOptions& options) {
  if (options.radius <= 0) return indirect;
  std::vector<Rgb> filtered = indirect;
  const int r = options.radius;
  const float sigma = 0.5f * float(r), inverse_two_sigma2 = 1.0f / (2 * sigma * sigma);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, e.size(), 256), [&](const tbb::blocked_range<size_t>& range) {
    for (size_t i = range.begin(); i < range.end(); ++i) {
      if (!use[i]) continue;
      const int64_t width = surface.pages[e.page[i]].width;
      const std::vector<int32_t>& grid = e.element_at[e.page[i]];
      const int64_t height = int64_t(grid.size()) / width, x = e.texel[i] % width, y = e.texel[i] / width;
      const float texel = surface.texel_size(e.triangle[i]);
      const Vec3 n = e.normal[i], p = e.position[i];
      // Weighted least squares of a plane over page offsets: light falling off across the
      // kernel is followed, not averaged, so a texel whose kernel is one-sided (at a wall's foot,
      // a chart's edge) is not pulled toward the far side's level.
      double m[3][3] = {}, rhs[3][3] = {};  // normal equations; rhs per colour channel
      Rgb sum{};
      double weights = 0;
      for (int64_t dy = -r; dy <= r; ++dy) {
        if (y + dy < 0 || y + dy >= height) continue;
        for (int64_t dx = -r; dx <= r; ++dx) {
          if (x + dx < 0 || x + dx >= width) continue;
          const int32_t k = grid[size_t((y + dy) * width + x + dx)];
          if (k < 0 || !use[size_t(k)]) continue;
          const Vec3 offset = e.position[size_t(k)] - p;
          const float page_distance = std::sqrt(float(dx * dx + dy * dy)), distance = length(offset);
          // Same surface: facing the same way, in the same plane, as far away as on the page (a
          // neighbour on the page from another chart is elsewhere in the world).
          if (dot(e.normal[size_t(k)], n) < 0.95f || std::fabs(dot(offset, n)) > 0.25f * texel ||
              distance > (page_distance + 1.5f) * texel)
            continue;
          const float valid = options.validity * std::min(harmonic_distance[i], harmonic_distance[size_t(k)]);
          if (distance > valid && k != int32_t(i)) continue;
          const double w = std::exp(-float(dx * dx + dy * dy) * inverse_two_sigma2);
          sum += indirect[size_t(k)] * float(w);
          weights += w;
          const double basis[3] = {1.0, double(dx), double(dy)};
          const Rgb& v = indirect[size_t(k)];
          for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < 3; ++b) m[a][b] += w * basis[a] * basis[b];
            rhs[0][a] += w * basis[a] * v.x;
            rhs[1][a] += w * basis[a] * v.y;
            rhs[2][a] += w * basis[a] * v.z;
          }
        }
      }
      if (!(weights > 0)) continue;
      filtered[i] = sum / float(weights);
      // The plane's value at the texel, (M^-1 rhs)[0] by Cramer's rule, where the offsets span
      // both page directions well enough; else the plain weighted mean.
      const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
      if (!(det > 1e-3 * weights * weights * weights)) continue;
      float at[3];
      for (int c = 0; c < 3; ++c) {
        const double* r = rhs[c];
        at[c] = float((r[0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (r[1] * m[2][2] - m[1][2] * r[2]) +
                       m[0][2] * (r[1] * m[2][1] - m[1][1] * r[2])) / det);
      }
      if (at[0] >= 0 && at[1] >= 0 && at[2] >= 0) filtered[i] = Rgb{at[0], at[1], at[2]};
    }
  });
  return filtered;
}

}  // namespace radbake
