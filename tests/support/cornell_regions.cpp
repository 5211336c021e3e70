#include "support/cornell_regions.h"

#include <cmath>
#include <functional>

namespace radbake::test {
namespace {

struct Box {
  Vec3 lo, hi;
};

bool inside(Vec3 p, const Box& box) {
  constexpr float kMargin = 0.002f;  // metres: texel sample points sit a hair inside the faces
  return p.x >= box.lo.x - kMargin && p.x <= box.hi.x + kMargin && p.y >= box.lo.y - kMargin &&
         p.y <= box.hi.y + kMargin && p.z >= box.lo.z - kMargin && p.z <= box.hi.z + kMargin;
}

const Box kShortBlock{{0.082f, 0.0f, 0.065f}, {0.29f, 0.165f, 0.272f}};
const Box kTallBlock{{0.265f, 0.0f, 0.247f}, {0.472f, 0.33f, 0.456f}};

// Within `depth` metres of the short block's front face, on the camera's side, along its width.
bool before_short_block(Vec3 p, float depth) {
  const float ax = 0.1317f, az = 0.0655f, bx = 0.2883f, bz = 0.1135f;  // the face's foot, (x, z)
  const float dx = bx - ax, dz = bz - az, length = std::hypot(dx, dz);
  const float along = ((p.x - ax) * dx + (p.z - az) * dz) / (length * length);
  const float out = ((p.x - ax) * dz - (p.z - az) * dx) / length;
  return along >= 0 && along <= 1 && out > 0 && out < depth;
}

struct Region {
  const char* name;
  std::function<bool(Vec3 p, Vec3 n)> contains;
};

const std::vector<Region>& regions() {
  static const std::vector<Region> all = {
      {"short block's front face, bottom 2 cm",
       [](Vec3 p, Vec3 n) { return inside(p, kShortBlock) && n.z < -0.7f && p.y < 0.02f; }},
      {"tall block's face to the red wall, bottom 2 cm",
       [](Vec3 p, Vec3 n) { return inside(p, kTallBlock) && n.x > 0.7f && p.y < 0.02f; }},
      {"floor within 5 cm in front of the short block",
       [](Vec3 p, Vec3 n) { return n.y > 0.9f && p.y < 0.001f && before_short_block(p, 0.05f); }},
      {"red wall, bottom 2 cm", [](Vec3 p, Vec3 n) { return p.x > 0.549f && n.x < -0.9f && p.y < 0.02f; }},
  };
  return all;
}

}  // namespace

std::vector<RegionBias> cornell_region_biases(const Elements& e, const std::vector<Rgb>& irradiance,
                                              const std::vector<Rgb>& reference,
                                              const std::vector<float>& reference_noise) {
  std::vector<RegionBias> out;
  for (const Region& region : regions()) {
    RegionBias r{region.name};
    double ours = 0, theirs = 0, variance = 0;
    for (size_t i = 0; i < e.size(); ++i) {
      if (!e.valid(i) || !region.contains(e.position[i], e.normal[i])) continue;
      ours += sum(irradiance[i]) / 3.0;
      theirs += sum(reference[i]) / 3.0;
      if (!reference_noise.empty()) variance += double(reference_noise[i]) * reference_noise[i];
      ++r.texels;
    }
    r.bias = theirs > 0 ? ours / theirs - 1 : NAN;
    r.noise = theirs > 0 ? std::sqrt(variance) / theirs : NAN;
    out.push_back(r);
  }
  return out;
}

std::vector<uint8_t> cornell_region_texels(const Elements& e) {
  std::vector<uint8_t> in(e.size(), 0);
  for (size_t i = 0; i < e.size(); ++i)
    for (const Region& region : regions()) in[i] |= e.valid(i) && region.contains(e.position[i], e.normal[i]);
  return in;
}

}  // namespace radbake::test
