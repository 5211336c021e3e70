// Small vector types shared by every stage. Plain aggregates so stages can pass arrays of them
// without conversions; colours use the same type (one channel per component, linear RGB).
#pragma once

#include <algorithm>
#include <cmath>

namespace radbake {

struct Vec2 {
  float x = 0, y = 0;
};

struct Vec3 {
  float x = 0, y = 0, z = 0;

  float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  float& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
};

// Linear RGB. For reflectance a unitless fraction; for light a photometric quantity whose unit
// the field name states (lux, lm/m2, candela).
using Rgb = Vec3;

inline Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 operator*(Vec2 a, float s) { return {a.x * s, a.y * s}; }
inline float cross2(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
inline Vec3 operator*(Vec3 a, float s) { return {a.x * s, a.y * s, a.z * s}; }
inline Vec3 operator*(float s, Vec3 a) { return a * s; }
inline Vec3 operator/(Vec3 a, float s) { return {a.x / s, a.y / s, a.z / s}; }
// Component-wise product: reflectance times irradiance, texture times factor.
inline Vec3 operator*(Vec3 a, Vec3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
inline Vec3& operator+=(Vec3& a, Vec3 b) { return a = a + b; }
inline Vec3& operator-=(Vec3& a, Vec3 b) { return a = a - b; }
inline Vec3& operator*=(Vec3& a, float s) { return a = a * s; }

inline float dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline float length(Vec3 a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalize(Vec3 a) {
  float len = length(a);
  return len > 0 ? a / len : Vec3{0, 0, 0};
}
inline float max_component(Vec3 a) { return std::max(a.x, std::max(a.y, a.z)); }
inline float sum(Vec3 a) { return a.x + a.y + a.z; }
// What a light meter reads of linear RGB light: the CIE 1931 Y (photopic) weights of its
// primaries, sRGB's (ITU-R BT.709, D65 white; IEC 61966-2-1), so white (1, 1, 1) weighs 1. Lux,
// cd/m2 and daylight factors are this; the lightmap pages and the energy balance stay RGB.
inline double photopic(Rgb c) { return 0.2126 * double(c.x) + 0.7152 * double(c.y) + 0.0722 * double(c.z); }
inline bool is_finite(Vec3 a) {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

// Two unit vectors perpendicular to n and to each other (Duff et al. 2017, branchless ONB).
inline void orthonormal_basis(Vec3 n, Vec3& t, Vec3& b) {
  float sign = std::copysign(1.0f, n.z);
  float a = -1.0f / (sign + n.z);
  float c = n.x * n.y * a;
  t = {1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x};
  b = {c, sign + n.y * n.y * a, -n.y};
}

// Column-major 4x4 affine transform, as glTF stores node matrices.
struct Mat4 {
  double m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

  Mat4 operator*(const Mat4& o) const {
    Mat4 r;
    for (int col = 0; col < 4; ++col)
      for (int row = 0; row < 4; ++row) {
        double s = 0;
        for (int k = 0; k < 4; ++k) s += m[k * 4 + row] * o.m[col * 4 + k];
        r.m[col * 4 + row] = s;
      }
    return r;
  }
  Vec3 transform_point(Vec3 p) const {
    return {float(m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12]),
            float(m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13]),
            float(m[2] * p.x + m[6] * p.y + m[10] * p.z + m[14])};
  }
  Vec3 transform_direction(Vec3 d) const {
    return {float(m[0] * d.x + m[4] * d.y + m[8] * d.z), float(m[1] * d.x + m[5] * d.y + m[9] * d.z),
            float(m[2] * d.x + m[6] * d.y + m[10] * d.z)};
  }
  // Normals transform by the inverse transpose of the upper 3x3, which is its cofactor matrix over
  // the determinant: the cofactors times the determinant's sign give it up to a positive scale (a
  // mirrored node's normals keep pointing out of its surface). Cofactor cRC is of row R, column C.
  Vec3 transform_normal(Vec3 n) const {
    double a = m[0], b = m[4], c = m[8], d = m[1], e = m[5], f = m[9], g = m[2], h = m[6], i = m[10];
    double det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
    double s = det < 0 ? -1.0 : 1.0;
    double c00 = e * i - f * h, c01 = -(d * i - f * g), c02 = d * h - e * g;
    double c10 = -(b * i - c * h), c11 = a * i - c * g, c12 = -(a * h - b * g);
    double c20 = b * f - c * e, c21 = -(a * f - c * d), c22 = a * e - b * d;
    return {float(s * (c00 * n.x + c01 * n.y + c02 * n.z)),
            float(s * (c10 * n.x + c11 * n.y + c12 * n.z)),
            float(s * (c20 * n.x + c21 * n.y + c22 * n.z))};
  }
  double determinant3() const {
    double a = m[0], b = m[4], c = m[8], d = m[1], e = m[5], f = m[9], g = m[2], h = m[6], i = m[10];
    return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
  }
};

// Barycentrics (b1, b2), the weights of corners 1 and 2, of a point in the plane of a triangle;
// the centroid for a degenerate one.
inline Vec2 barycentric(const Vec3* corners, Vec3 p) {
  const Vec3 e1 = corners[1] - corners[0], e2 = corners[2] - corners[0], d = p - corners[0];
  const float d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2), d1 = dot(d, e1), d2 = dot(d, e2);
  const float det = d11 * d22 - d12 * d12;
  if (!(det > 0)) return {1.0f / 3, 1.0f / 3};
  return {(d22 * d1 - d12 * d2) / det, (d11 * d2 - d12 * d1) / det};
}

}  // namespace radbake
