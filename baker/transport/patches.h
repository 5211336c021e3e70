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
  size_t max_patches = 0;   // the patch count at or under this; 0: patch_budget's
  // The budget when max_patches is 0: one patch per `elements_per_patch` elements, between 64 and
  // `patch_cap`. The cap is what keeps memory linear in texels: a patch holds a row of form factors
  // (about 8 bytes for each of a thousand or more targets), so patches of a fixed number of texels
  // make the rows grow with the texels (4-texel patches took 3 KB per texel); past the cap patches
  // grow in texels instead and keep their size in metres, while the final gather stays at texel
  // resolution (as Enlighten sizes its clusters in metres, apart from the output texels).
  size_t elements_per_patch = 32;
  size_t patch_cap = 4096;
  // The scene's mean free path (mean_free_path), metres; 0: unknown. Where the budget's automatic
  // blocks are wider than it, the widest blocks within it are taken if they are at most twice the
  // budget: a patch spreads its light evenly, and one as wide as a room spreads one side's light
  // over the other.
  double mean_free_path_m = 0;
};

// The most patches `options` allow for `elements` elements.
size_t patch_budget(const PatchOptions& options, size_t elements);

// Square blocks of `block_size` texels (a power of two; a given size is rounded down to one); with
// none given, the smallest power of two within the budget (or, where that is wider than the mean
// free path, the widest within it if at most twice the budget).
Patches build_patches(const Elements& elements, const Surface& surface, const PatchOptions& options);

// The same elements with every patch marked in `split` (and larger than a texel) cut into the
// quarters of its block; the others keep their blocks. Patch numbers change.
Patches split_patches(const Elements& elements, const Surface& surface, const Patches& patches,
                      const std::vector<uint8_t>& split);

}  // namespace radbake
