#include "baker/direct/sky_portals.h"

#include <algorithm>
#include <cmath>

#include "baker/surface/sampling.h"

namespace radbake {

SkyPortals::SkyPortals(const Surface& surface, const MaterialSampler& materials) {
  double total = 0;
  for (uint32_t t = 0; t < surface.triangle_count(); ++t) {
    // A double-sided pane's back-face twin lies in its plane: its front stands for both.
    if (surface.back_face[t] || !(surface.area[t] > 0) || !materials.glazing(t)) continue;
    if (area_.size() == kMostTriangles) {
      *this = SkyPortals();
      return;
    }
    for (int k = 0; k < 3; ++k) corner_.push_back(surface.corners[3 * t + k]);
    const Vec3* c = &surface.corners[3 * t];
    centre_.push_back((c[0] + c[1] + c[2]) / 3.0f);
    reach_.push_back(std::max({length(c[0] - centre_.back()), length(c[1] - centre_.back()), length(c[2] - centre_.back())}));
    normal_.push_back(surface.normal[t]);
    area_.push_back(surface.area[t]);
    total += surface.area[t];
    cumulative_.push_back(total);
  }
  for (double& c : cumulative_) c /= total;
}

bool SkyPortals::any_in_front(Vec3 point, Vec3 normal) const {
  for (size_t t = 0; t < centre_.size(); ++t)
    if (dot(centre_[t] - point, normal) + reach_[t] > 1e-4f * reach_[t]) return true;
  return false;
}

Vec3 SkyPortals::aim(Vec3 from, Vec2 u) const {
  // The first coordinate picks the triangle and, rescaled within its share, the point on it, so
  // the rays stay stratified over the glazing.
  const size_t t = size_t(std::lower_bound(cumulative_.begin(), cumulative_.end(), double(u.x)) - cumulative_.begin());
  const size_t k = std::min(t, area_.size() - 1);
  const double low = k ? cumulative_[k - 1] : 0.0, width = cumulative_[k] - low;
  const float within = width > 0 ? float(std::clamp((double(u.x) - low) / width, 0.0, 1.0)) : 0.5f;
  const Vec2 b = uniform_triangle({within, u.y});
  const Vec3 p = corner_[3 * k] * (1 - b.x - b.y) + corner_[3 * k + 1] * b.x + corner_[3 * k + 2] * b.y;
  return normalize(p - from);
}

double SkyPortals::density(Vec3 from, Vec3 d) const {
  double total = 0;
  for (size_t t = 0; t < area_.size(); ++t) {
    // Moller and Trumbore's ray-triangle test, in double: where along d the ray meets t's plane
    // inside it.
    const Vec3 a = corner_[3 * t], e1 = corner_[3 * t + 1] - a, e2 = corner_[3 * t + 2] - a;
    const Vec3 p = cross(d, e2);
    const double det = dot(e1, p);
    if (std::fabs(det) < 1e-20) continue;
    const Vec3 s = from - a;
    const double u = dot(s, p) / det;
    if (u < 0 || u > 1) continue;
    const Vec3 q = cross(s, e1);
    const double v = dot(d, q) / det;
    if (v < 0 || u + v > 1) continue;
    const double distance = dot(e2, q) / det;
    const double facing = std::fabs(double(dot(d, normal_[t])));
    if (!(distance > 0) || !(facing > 1e-9)) continue;
    const double share = cumulative_[t] - (t ? cumulative_[t - 1] : 0.0);
    total += share / area_[t] * distance * distance / facing;
  }
  return total;
}

}  // namespace radbake
