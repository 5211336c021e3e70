#include "support/closed_forms.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace radbake::test {

double corner_point_to_rectangle(double a, double b, double c) {
  double A = a / c, B = b / c;
  return (A / std::sqrt(1 + A * A) * std::atan(B / std::sqrt(1 + A * A)) +
          B / std::sqrt(1 + B * B) * std::atan(A / std::sqrt(1 + B * B))) /
         (2 * M_PI);
}

double point_to_rectangle(double px, double pz, double x0, double x1, double z0, double z1, double h) {
  // The corner form factor is odd in each side, so the four signed spans add up right whether the
  // point lies under the rectangle or beside it (inclusion-exclusion).
  double f = 0;
  for (double w : {x1 - px, px - x0})
    for (double d : {z1 - pz, pz - z0}) f += corner_point_to_rectangle(w, d, h);
  return f;
}

double point_to_polygon(Vec3 x, Vec3 n, const std::vector<Vec3>& corners) {
  double sum = 0;
  const size_t count = corners.size();
  for (size_t i = 0; i < count; ++i) {
    const Vec3 p = corners[i], q = corners[(i + 1) % count];
    double a[3] = {double(p.x) - x.x, double(p.y) - x.y, double(p.z) - x.z};
    double b[3] = {double(q.x) - x.x, double(q.y) - x.y, double(q.z) - x.z};
    const double la = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    const double lb = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    for (int k = 0; k < 3; ++k) a[k] /= la, b[k] /= lb;
    const double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    const double sine = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    if (sine == 0) continue;  // an edge seen end-on subtends no angle
    const double angle = std::atan2(sine, a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
    sum += angle * (n.x * c[0] + n.y * c[1] + n.z * c[2]) / sine;
  }
  return std::fabs(sum) / (2 * M_PI);
}

double centred_rectangle_solid_angle(double a, double b, double d) {
  return 4 * std::asin(a * b / std::sqrt((a * a + d * d) * (b * b + d * d)));
}

double point_light_lux(double candela, Vec3 light, Vec3 x, Vec3 n) {
  double dx = double(light.x) - x.x, dy = double(light.y) - x.y, dz = double(light.z) - x.z;
  double d2 = dx * dx + dy * dy + dz * dz;
  double cosine = (dx * n.x + dy * n.y + dz * n.z) / std::sqrt(d2);
  return cosine > 0 ? candela * cosine / d2 : 0.0;
}

namespace {

// ISO 15469:2004 Table 1, the standard general skies 1 to 15: gradation a, b; indicatrix c, d, e.
struct SkyParameters {
  double a, b, c, d, e;
};
constexpr SkyParameters kStandardSkies[15] = {
    {4.0, -0.70, 0, -1.0, 0.00},   {4.0, -0.70, 2, -1.5, 0.15},   {1.1, -0.80, 0, -1.0, 0.00},
    {1.1, -0.80, 2, -1.5, 0.15},   {0.0, -1.00, 0, -1.0, 0.00},   {0.0, -1.00, 2, -1.5, 0.15},
    {0.0, -1.00, 5, -2.5, 0.30},   {0.0, -1.00, 10, -3.0, 0.45},  {-1.0, -0.55, 2, -1.5, 0.15},
    {-1.0, -0.55, 5, -2.5, 0.30},  {-1.0, -0.55, 10, -3.0, 0.45}, {-1.0, -0.32, 10, -3.0, 0.45},
    {-1.0, -0.32, 16, -3.0, 0.30}, {-1.0, -0.15, 16, -3.0, 0.30}, {-1.0, -0.15, 24, -2.8, 0.15},
};

// phi(Z) = 1 + a exp(b / cos Z), 1 at the horizon (its limit).
double gradation(const SkyParameters& p, double cos_zenith) {
  return cos_zenith > 0 ? 1 + p.a * std::exp(p.b / cos_zenith) : 1.0;
}

// f(chi) = 1 + c (exp(d chi) - exp(d pi / 2)) + e cos^2 chi, chi the angle from the sun.
double indicatrix(const SkyParameters& p, double chi) {
  return 1 + p.c * (std::exp(p.d * chi) - std::exp(p.d * M_PI / 2)) + p.e * std::cos(chi) * std::cos(chi);
}

Vec3d operator+(Vec3d a, Vec3d b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3d operator-(Vec3d a, Vec3d b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3d operator*(Vec3d a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(Vec3d a, Vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double length(Vec3d a) { return std::sqrt(dot(a, a)); }
Vec3d cross(Vec3d a, Vec3d b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

// Gauss-Legendre, 4 points on [0, 1].
constexpr double kNode[4] = {0.5 - 0.5 * 0.8611363115940526, 0.5 - 0.5 * 0.3399810435848563,
                             0.5 + 0.5 * 0.3399810435848563, 0.5 + 0.5 * 0.8611363115940526};
constexpr double kWeight[4] = {0.5 * 0.3478548451374538, 0.5 * 0.6521451548625461, 0.5 * 0.6521451548625461,
                               0.5 * 0.3478548451374538};

struct Opening {
  Vec3d x, n, normal;  // the point, its normal, the opening's unit normal
  const SeenLuminance& luminance;

  double cell(Vec3d corner, Vec3d u, Vec3d v, double area, int depth) const {
    const double diagonal = std::max(length(u + v), length(u - v));
    const double distance = length(corner + u * 0.5 + v * 0.5 - x) - 0.5 * diagonal;
    if (depth < 16 && diagonal > 0.25 * std::max(distance, 0.0)) {
      double sum = 0;
      for (double s : {0.0, 0.5})
        for (double t : {0.0, 0.5}) sum += cell(corner + u * s + v * t, u * 0.5, v * 0.5, area / 4, depth + 1);
      return sum;
    }
    double sum = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        const Vec3d q = corner + u * kNode[i] + v * kNode[j], r = q - x;
        const double r2 = dot(r, r);
        const Vec3d d = r * (1 / std::sqrt(r2));
        const double cos_x = dot(n, d);
        if (cos_x <= 0) continue;
        sum += kWeight[i] * kWeight[j] * luminance(q, d) * cos_x * std::fabs(dot(normal, d)) / r2;
      }
    return sum * area;
  }
};

}  // namespace

double cie171_sky_luminance(int type, double zenith, double azimuth, double sun_zenith, double sun_azimuth) {
  if (type < 1 || type > 16) throw std::invalid_argument("CIE 171 sky type 1..16, got " + std::to_string(type));
  if (zenith > M_PI / 2) return 0;
  if (type == 16) return (1 + 2 * std::cos(zenith)) / 3;
  const SkyParameters& p = kStandardSkies[type - 1];
  const double cos_chi = std::cos(sun_zenith) * std::cos(zenith) +
                         std::sin(sun_zenith) * std::sin(zenith) * std::cos(azimuth - sun_azimuth);
  const double chi = std::acos(std::clamp(cos_chi, -1.0, 1.0));
  return indicatrix(p, chi) * gradation(p, std::cos(zenith)) / (indicatrix(p, sun_zenith) * gradation(p, 1));
}

double cie171_sky_horizontal_illuminance(int type, double sun_zenith, double sun_azimuth) {
  // E_hz / L_z = integral of L cos Z d(omega) = integral over mu = cos Z in [0, 1] and azimuth of L mu.
  constexpr int kRings = 400, kSectors = 800;
  double sum = 0;
  for (int i = 0; i < kRings; ++i) {
    const double mu = (i + 0.5) / kRings, zenith = std::acos(mu);
    double ring = 0;
    for (int j = 0; j < kSectors; ++j)
      ring += cie171_sky_luminance(type, zenith, (j + 0.5) * 2 * M_PI / kSectors, sun_zenith, sun_azimuth);
    sum += ring * mu;
  }
  return sum / kRings * (2 * M_PI / kSectors);
}

double clear_glass_transmittance(double c) {
  const double t = -0.028378 + c * (3.156075 + c * (-3.058376 + c * (-1.428919 + c * (4.014235 + c * -1.775827))));
  return std::max(0.0, t);  // the fit dips to -0.028 within half a degree of grazing
}

double thin_pane_transmittance(double c, double n) {
  if (!(c > 0)) return 0;
  const double s = std::sqrt(1 - c * c) / n, t = std::sqrt(1 - s * s);  // the refracted ray's sine and cosine
  const double r_s = std::pow((c - n * t) / (c + n * t), 2), r_p = std::pow((t - n * c) / (t + n * c), 2);
  return 0.5 * ((1 - r_s) / (1 + r_s) + (1 - r_p) / (1 + r_p));
}

double illuminance_through_opening(Vec3d x, Vec3d n, Vec3d corner, Vec3d u, Vec3d v, const SeenLuminance& luminance) {
  const Vec3d normal = cross(u, v);
  const double area = length(normal);
  const Opening opening{x, n, normal * (1 / area), luminance};
  return opening.cell(corner, u, v, area, 0);
}

}  // namespace radbake::test
