// Deterministic sampling. Every random number is a hash of (seed, what it is for, which element,
// which sample), never a shared generator's state, so results do not depend on how the work is
// split across threads.
#pragma once

#include <cmath>
#include <cstdint>

#include "base/math.h"

namespace radbake {

constexpr float kPi = 3.14159265358979323846f;

inline uint64_t mix64(uint64_t x) {  // splitmix64 finaliser
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ull;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebull;
  x ^= x >> 31;
  return x;
}

// What a random stream is used for; part of the hash so that streams never correlate.
enum class Stream : uint64_t {
  DirectLight = 1,
  AreaLight,
  PatchRays,
  Gather,
  Probe,
  Footprint,
  Hemicube,
  Cover,
  PathTrace,
  Sky,
  SensorSky,
  SensorGather,
  View,
  LightProbe,
  FreePath,
};

// A counter-based generator for one (seed, stream, key) triple.
class Rng {
 public:
  Rng(uint64_t seed, Stream stream, uint64_t key)
      : state_(mix64(seed * 0x9e3779b97f4a7c15ull ^ mix64(uint64_t(stream) << 56 ^ key))) {}
  uint32_t next_u32() {
    state_ += 0x9e3779b97f4a7c15ull;
    return uint32_t(mix64(state_) >> 32);
  }
  // Uniform in [0, 1).
  float uniform() { return float(next_u32() >> 8) * (1.0f / 16777216.0f); }

 private:
  uint64_t state_;
};

// Correlated multi-jittered sample s of n in the unit square (Kensler 2013): stratified in 2D and
// in each axis for any n, so a few dozen rays already integrate smooth functions well.
inline uint32_t cmj_permute(uint32_t i, uint32_t l, uint32_t p) {
  uint32_t w = l - 1;
  w |= w >> 1;
  w |= w >> 2;
  w |= w >> 4;
  w |= w >> 8;
  w |= w >> 16;
  do {
    i ^= p;
    i *= 0xe170893d;
    i ^= p >> 16;
    i ^= (i & w) >> 4;
    i ^= p >> 8;
    i *= 0x0929eb3f;
    i ^= p >> 23;
    i ^= (i & w) >> 1;
    i *= 1 | p >> 27;
    i *= 0x6935fa69;
    i ^= (i & w) >> 11;
    i *= 0x74dcb303;
    i ^= (i & w) >> 2;
    i *= 0x9e501cc3;
    i ^= (i & w) >> 2;
    i *= 0xc860a3df;
    i &= w;
    i ^= i >> 5;
  } while (i >= l);
  return (i + p) % l;
}

inline float cmj_randfloat(uint32_t i, uint32_t p) {
  i ^= p;
  i ^= i >> 17;
  i ^= i >> 10;
  i *= 0xb36534e5;
  i ^= i >> 12;
  i ^= i >> 21;
  i *= 0x93fc4795;
  i ^= 0xdf6e307f;
  i ^= i >> 17;
  i *= 1 | p >> 18;
  return float(i) * (1.0f / 4294967808.0f);
}

inline Vec2 cmj_sample(uint32_t s, uint32_t n, uint32_t pattern) {
  uint32_t m = uint32_t(std::sqrt(float(n)));
  while (m * m > n) --m;
  while ((m + 1) * (m + 1) <= n) ++m;
  uint32_t cols = m, rows = (n + m - 1) / m, cells = cols * rows;
  // Samples take distinct cells of the cols x rows grid in a shuffled order. When n does not fill
  // the grid, which cells stay empty is random, so every sample is still uniform over the square
  // (taking the first n in order would leave the last row thin and bias azimuths). The shuffle
  // also keeps two patterns' strata independent, so a ray's origin and direction do not correlate.
  s = cmj_permute(s, cells, pattern * 0x51633e2d);
  uint32_t sx = cmj_permute(s % cols, cols, pattern * 0xa511e9b3);
  uint32_t sy = cmj_permute(s / cols, rows, pattern * 0x63d83595);
  float jx = cmj_randfloat(s, pattern * 0xa399d265);
  float jy = cmj_randfloat(s, pattern * 0x711ad6a5);
  Vec2 r{(float(s % cols) + (float(sy) + jx) / float(rows)) / float(cols),
         (float(s / cols) + (float(sx) + jy) / float(cols)) / float(rows)};
  r.x = std::min(r.x, 0.99999994f);
  r.y = std::min(r.y, 0.99999994f);
  return r;
}

// Cosine-weighted direction about unit normal n; pdf = cos(theta) / pi.
inline Vec3 cosine_direction(Vec3 n, Vec2 u) {
  Vec3 t, b;
  orthonormal_basis(n, t, b);
  float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
  float z = std::sqrt(std::max(0.0f, 1.0f - u.x));
  return t * (r * std::cos(phi)) + b * (r * std::sin(phi)) + n * z;
}

// Uniform point on a triangle from a unit-square sample, as barycentrics (b1, b2).
inline Vec2 uniform_triangle(Vec2 u) {
  float su = std::sqrt(u.x);
  return {1.0f - su, u.y * su};
}

}  // namespace radbake

namespace radbake {

// A direction about the shading normal that dips under the geometric surface is mirrored back
// above it, so interpolated normals cannot send rays into the surface they start from.
inline Vec3 above_surface(Vec3 d, Vec3 geometric_normal) {
  float below = dot(d, geometric_normal);
  if (below <= 0) d = normalize(d - geometric_normal * (2 * below - 1e-4f));
  return d;
}

// A cosine-weighted direction about the shading normal that stays above the geometric surface.
inline Vec3 hemisphere_direction(Vec3 shading_normal, Vec3 geometric_normal, Vec2 u) {
  return above_surface(cosine_direction(shading_normal, u), geometric_normal);
}

}  // namespace radbake
