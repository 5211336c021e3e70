// Where the rays that carry light between surfaces ended: left the scene, struck a back face, took
// the light of the element they struck, or struck a front face and took nothing, by the reason
// element_for_hit gave. A front-face hit that takes nothing loses what the path tracer would find
// there, at every bounce: the report counts them so that such losses show before a room reads dark.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace radbake {

enum class RayFate : uint8_t {
  TookLight,      // struck a front face whose element (with a patch) stands for the hit
  Escaped,        // left the scene
  BackFace,       // struck the back of a single-sided surface
  NoElement,      // struck a front face where no texel lies (outside every chart's texels)
  BuriedElement,  // struck a front face whose texel's element is buried or has no patch
  OtherSide,      // struck a front face whose texel's sample, and its neighbours', lie across a wall
  SealedGap,      // entered or left a gap thinner than a sixteenth of a texel through its mouth
  // struck a front face, with no element standing for it, at a point inside geometry: one that sees
  // back faces in half its hemisphere, the test that buries texels (the inside of stacked or
  // interpenetrating parts, which a path there would find dark as well)
  InsideGeometry,
};
constexpr size_t kRayFateCount = 8;

// The name report.json gives each fate, in RayFate's order.
constexpr std::array<const char*, kRayFateCount> kRayFateNames = {
    "took_light", "escaped", "back_face", "no_element", "buried_element", "other_side", "sealed_gap",
    "inside_geometry"};

struct RayFates {
  std::array<uint64_t, kRayFateCount> count{};

  void add(RayFate fate) { ++count[size_t(fate)]; }
  RayFates& operator+=(const RayFates& o) {
    for (size_t k = 0; k < kRayFateCount; ++k) count[k] += o.count[k];
    return *this;
  }
  uint64_t operator[](RayFate fate) const { return count[size_t(fate)]; }
  uint64_t total() const {
    uint64_t sum = 0;
    for (uint64_t c : count) sum += c;
    return sum;
  }
  // Front faces struck that gave no light: the rays lost to the scene's own detail, and to its
  // closed spaces (SealedGap, InsideGeometry).
  uint64_t front_face_took_none() const { return total() - (*this)[RayFate::TookLight] - (*this)[RayFate::Escaped] -
                                                 (*this)[RayFate::BackFace]; }
  double share(RayFate fate) const { return total() ? double((*this)[fate]) / double(total()) : 0.0; }
};

}  // namespace radbake
