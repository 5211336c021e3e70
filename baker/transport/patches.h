// Patches group neighbouring elements of one chart into square blocks of texels: they are the
// sources of the interreflection solve, while elements keep texel resolution as receivers.
#pragma once

#include <cstdint>
#include <vector>

#include "baker/surface/elements.h"
#include "base/math.h"

namespace radbake {

struct Patches {
  std::vector<uint32_t> first_member;  // members of patch p: members[first_member[p] .. first_member[p + 1])
  std::vector<uint32_t> members;       // element indices
  std::vector<float> area;             // m^2
  std::vector<Rgb> reflectance;        // area-weighted mean of the members
  std::vector<Rgb> emission;           // area-weighted mean exitance, lm/m2
  std::vector<float> opacity;          // area-weighted mean of the members' (Elements::opacity); empty: all 1
  std::vector<uint16_t> side;          // texels per side of the block each patch was cut from
  std::vector<uint32_t> patch_of_element;  // UINT32_MAX for buried elements
  int block_size = 1;                  // texels per side of the coarsest blocks

  size_t size() const { return area.size(); }
};

struct PatchOptions {
  int block_size = 0;       // texels per patch side; 0 picks the smallest power of two that keeps
  size_t max_patches = 0;   // the patch count at or under this; 0: one patch per 32 elements,
                            // between 64 and 4096, so form factor rays cost about what the gather does
};

// Square blocks of `block_size` texels (a power of two; a given size is rounded down to one).
Patches build_patches(const Elements& elements, const Surface& surface, const PatchOptions& options);

// The same elements with every patch marked in `split` (and larger than a texel) cut into the
// quarters of its block; the others keep their blocks. Patch numbers change.
Patches split_patches(const Elements& elements, const Surface& surface, const Patches& patches,
                      const std::vector<uint8_t>& split);

}  // namespace radbake
