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

double point_light_lux(double candela, Vec3 light, Vec3 x, Vec3 n) {
  double dx = double(light.x) - x.x, dy = double(light.y) - x.y, dz = double(light.z) - x.z;
  double d2 = dx * dx + dy * dy + dz * dz;
  double cosine = (dx * n.x + dy * n.y + dz * n.z) / std::sqrt(d2);
  return cosine > 0 ? candela * cosine / d2 : 0.0;
}

}  // namespace radbake::test
