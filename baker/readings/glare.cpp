#include "baker/readings/glare.h"

#include <algorithm>
#include <cmath>

namespace radbake {

namespace {

constexpr double kDegree = M_PI / 180;
constexpr double kSearchAngle = 0.2;  // radians: evalglare's default search radius for joining glare pixels

// Guth's position index for angles in degrees: sigma from the line of sight, tau from the vertical
// in the plane across it.
double guth(double sigma, double tau) {
  return std::exp((35.2 - 0.31889 * tau - 1.22 * std::exp(-2 * tau / 9)) * 1e-3 * sigma +
                  (21 + 0.26667 * tau - 0.002963 * tau * tau) * 1e-5 * sigma * sigma);
}

}  // namespace

bool fisheye_pixel(const FisheyeImage& image, int x, int y, Vec3* direction, double* solid_angle) {
  const double radius = 0.5 * image.size;
  const double u = (x + 0.5 - radius) / radius, v = (radius - y - 0.5) / radius, r = std::sqrt(u * u + v * v);
  if (r > 1) return false;
  const double theta = r * M_PI / 2;
  const Vec3 right = normalize(cross(image.view, image.up));
  const Vec3 across = r > 0 ? right * float(u / r) + image.up * float(v / r) : Vec3{};
  *direction = normalize(image.view * float(std::cos(theta)) + across * float(std::sin(theta)));
  // Equidistant: d(omega) = sin(theta) d(theta) d(phi), and r d(r) d(phi) is the pixel's area.
  const double step = M_PI / 2 / radius;
  *solid_angle = step * step * (theta > 0 ? std::sin(theta) / theta : 1.0);
  return true;
}

double position_index(Vec3 d, Vec3 view, Vec3 up) {
  const Vec3 right = normalize(cross(view, up));
  const double x = dot(d, right), y = dot(d, up), z = dot(d, view);
  if (z <= 0) return 16;
  if (y < 0) {  // below the line of sight: Iwata, as evalglare takes it
    const double sigma = std::atan(std::sqrt(x * x + 1.15 * 1.15 * y * y) / z) / kDegree;
    return std::min(16.0, guth(sigma, 90));
  }
  const double sigma = std::acos(std::clamp(z, -1.0, 1.0)) / kDegree;
  const double across = std::sqrt(x * x + y * y);
  const double tau = across > 0 ? std::acos(std::clamp(y / across, -1.0, 1.0)) / kDegree : 0;
  return std::min(16.0, guth(sigma, tau));
}

double daylight_glare_probability(double ev, const std::vector<GlareSource>& sources) {
  if (!(ev > 0)) return 0;
  double sum = 0;
  for (const GlareSource& s : sources)
    sum += s.luminance * s.luminance * s.solid_angle / (std::pow(ev, 1.87) * s.position_index * s.position_index);
  return std::min(1.0, 5.87e-5 * ev + 9.18e-2 * std::log10(1 + sum) + 0.16);
}

Glare evaluate_glare(const FisheyeImage& image) {
  Glare g;
  const int n = image.size;
  std::vector<Vec3> direction(size_t(n) * size_t(n));
  std::vector<double> omega(size_t(n) * size_t(n), 0);
  double total_omega = 0, luminous = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const size_t k = size_t(y) * size_t(n) + size_t(x);
      if (!fisheye_pixel(image, x, y, &direction[k], &omega[k])) continue;
      const double l = image.luminance[k];
      g.vertical_illuminance += l * omega[k] * std::max(0.0f, dot(direction[k], image.view));
      luminous += l * omega[k];
      total_omega += omega[k];
    }
  g.mean_luminance = total_omega > 0 ? luminous / total_omega : 0;
  g.threshold = 5 * g.mean_luminance;
  // Sources, as evalglare gathers them: each pixel over the threshold joins the source whose
  // centre lies within the search angle of it, or starts one; then sources whose centres lie
  // within that angle of each other merge.
  struct Gathering {
    double omega = 0, luminous = 0;
    Vec3 weighted{};
    Vec3 centre() const { return normalize(weighted); }
  };
  std::vector<Gathering> found;
  const float near = float(std::cos(kSearchAngle));
  for (size_t k = 0; k < omega.size(); ++k) {
    if (!(omega[k] > 0) || !(image.luminance[k] > g.threshold)) continue;
    Gathering* into = nullptr;
    float best = near;
    for (Gathering& s : found) {
      const float c = dot(s.centre(), direction[k]);
      if (c >= best) best = c, into = &s;
    }
    if (!into) into = &found.emplace_back();
    into->omega += omega[k], into->luminous += image.luminance[k] * omega[k], into->weighted += direction[k] * float(omega[k]);
  }
  for (bool merged = true; merged;) {
    merged = false;
    for (size_t i = 0; i < found.size() && !merged; ++i)
      for (size_t j = i + 1; j < found.size() && !merged; ++j)
        if (dot(found[i].centre(), found[j].centre()) >= near) {
          found[i].omega += found[j].omega, found[i].luminous += found[j].luminous, found[i].weighted += found[j].weighted;
          found.erase(found.begin() + ptrdiff_t(j));
          merged = true;
        }
  }
  for (const Gathering& s : found)
    g.sources.push_back({s.luminous / s.omega, s.omega, position_index(s.centre(), image.view, image.up), s.centre()});
  g.dgp = daylight_glare_probability(g.vertical_illuminance, g.sources);
  return g;
}

}  // namespace radbake
