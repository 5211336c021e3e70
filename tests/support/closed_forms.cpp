#include "support/closed_forms.h"

#include <cmath>

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

}  // namespace radbake::test
