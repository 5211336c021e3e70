// Form factors between patches by Embree ray casting: from each patch, cosine-distributed rays
// from points spread over its area; the share landing on patch q is the form factor F(p -> q).
// Every ray lands somewhere or leaves the scene, so each row sums to one exactly: what the
// furnace test and the energy balance rely on.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "baker/surface/elements.h"
#include "baker/surface/hit_element.h"
#include "baker/surface/ray_tracer.h"
#include "baker/transport/patches.h"
#include "base/progress.h"

namespace radbake {

struct PatchTransport {
  // Row p in compressed form: targets[row_start[p] .. row_start[p + 1]) with their form factors.
  // Balanced: A_p F_pq = A_q F_qp, to within each row's scale to what its rays measured.
  std::vector<uint64_t> row_start;
  std::vector<uint32_t> target;
  std::vector<float> form_factor;
  std::vector<float> escaped;  // per patch: share of its light that left the scene
  std::vector<float> lost;     // per patch: share that struck back faces or buried texels
  std::vector<uint32_t> rays;  // per patch
  RayFates fates;              // where every patch's rays (or hemicube pixels) ended
};

// Groups of patches that exchange light, directly or through one another (connected through the
// rows): rooms closed off from each other are separate enclosures. Every patch is in exactly one.
struct Enclosures {
  std::vector<uint32_t> of_patch;  // enclosure of each patch, numbered from 0 by lowest patch
  size_t count = 0;
};

Enclosures find_enclosures(const PatchTransport& transport);

// The rows read the other way, for gathering: for each receiver q, the sources p with F_pq
// weighted by A_p / A_q (what q receives per unit of p's exitance).
struct IncomingRows {
  std::vector<uint64_t> start;
  std::vector<uint32_t> source;
  std::vector<float> weight;
};

IncomingRows incoming_rows(const Patches& patches, const PatchTransport& transport);

// Rows F(p -> q) as measured, before reciprocity: what adaptive subdivision keeps between rounds.
using MeasuredRow = std::vector<std::pair<uint32_t, float>>;  // (target patch, F) by target

struct MeasuredRows {
  std::vector<MeasuredRow> rows;  // per patch
  std::vector<float> escaped, lost;
  std::vector<uint32_t> rays;
  std::vector<RayFates> fates;  // per patch, of the rays its row was measured with

  void resize(size_t patches) {
    rows.resize(patches);
    escaped.resize(patches);
    lost.resize(patches);
    rays.resize(patches);
    fates.resize(patches);
  }
};

// One thread's tally of what a patch's rays (or hemicube pixels) leave on each target patch,
// taken out as the patch's row, sorted by target.
class RowTally {
 public:
  void add(uint32_t target, double share, size_t patch_count) {
    if (share_.size() != patch_count) share_.assign(patch_count, 0);
    if (share_[target] == 0) touched_.push_back(target);
    share_[target] += share;
  }
  // Each target's tally divided by `divisor` into `row`; the tally starts again from nothing.
  void take(std::vector<std::pair<uint32_t, float>>& row, float divisor) {
    std::sort(touched_.begin(), touched_.end());
    row.clear();
    row.reserve(touched_.size());
    for (uint32_t q : touched_) {
      row.emplace_back(q, float(share_[q]) / divisor);
      share_[q] = 0;
    }
    touched_.clear();
  }

 private:
  std::vector<double> share_;
  std::vector<uint32_t> touched_;
};

// Measures the rows of the patches in `which` into `into` (sized for all patches). Every patch
// casts at least `rays_per_patch` rays; as many again are shared out in proportion to `power` (lm
// leaving each patch on the first bounce, over all patches), up to 16 times the base, so the
// patches that carry the light are measured most finely.
void measure_ray_cast_rows(const Elements& elements, const Patches& patches, const Surface& surface,
                           const RayTracer& tracer, uint32_t rays_per_patch, const std::vector<double>& power,
                           const std::vector<uint32_t>& which, uint64_t seed, Progress& progress, MeasuredRows& into);

// All rows by ray casting, balanced.
PatchTransport trace_patch_transport(const Elements& elements, const Patches& patches, const Surface& surface,
                                     const RayTracer& tracer, uint32_t rays_per_patch,
                                     const std::vector<double>& power, uint64_t seed, Progress& progress);

// Measured rows made reciprocal (A_p F_pq = A_q F_qp) with every row still summing to what it
// measured landing, and compressed. Takes the rows by value: a caller done with them moves them in
// and the balance frees them early.
PatchTransport balanced_transport(const Patches& patches, MeasuredRows measured);

// 0, 1, ..., n - 1: every patch.
std::vector<uint32_t> all_patches(size_t n);

// Where a ray from `origin` in `direction` lands: the element and patch it struck (UINT32_MAX for
// none: it left the scene, or struck a back face, a buried texel or the far side of a thin gap's
// mouth) and how far away (infinite if it left). `seen_from`: the origin's element's flags (only
// kUnderCover counts); a ray that leaves a thin gap is lost, not escaped.
struct Landing {
  uint32_t element = UINT32_MAX, patch = UINT32_MAX;
  float distance = 0;  // metres
  bool escaped = false;
  RayFate fate = RayFate::Escaped;
};
Landing land(const Elements& elements, const Patches& patches, const Surface& surface, const RayTracer& tracer,
             Vec3 origin, Vec3 direction, uint8_t seen_from);

// Where a ray from `origin` in `direction` lands, as `land` has it: the patch it struck, or
// UINT32_MAX with `escaped` telling whether it left the scene (else it was lost); its fate tallied.
uint32_t patch_hit(const Elements& elements, const Patches& patches, const Surface& surface,
                   const RayTracer& tracer, Vec3 origin, Vec3 direction, uint8_t seen_from, bool& escaped,
                   RayFates& fates);

}  // namespace radbake
