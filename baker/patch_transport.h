// Form factors between patches by Embree ray casting: from each patch, cosine-distributed rays
// from points spread over its area; the share landing on patch q is the form factor F(p -> q).
// Every ray lands somewhere or leaves the scene, so each row sums to one exactly: what the
// furnace test and the energy balance rely on.
//
// A double-sided patch has two faces that both send out its light (glTF doubleSided: the back
// shows the front's texels), so rows are measured per face: patch p's front is face p, its back
// face `patches + p`. Light landing on a double-sided back is absorbed there: the texels hold the
// light arriving at the front.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "baker/elements.h"
#include "baker/patches.h"
#include "baker/progress.h"
#include "baker/ray_tracer.h"

namespace radbake {

struct PatchTransport {
  // Row p in compressed form: targets[row_start[p] .. row_start[p + 1]) with their form factors,
  // the share of the light leaving one face of p that lands on the front of the target, from both
  // faces of a double-sided p (so its row may sum to 2). Balanced: A_p F_pq from one face of p
  // to one face of q equals A_q F_qp back.
  std::vector<uint64_t> row_start;
  std::vector<uint32_t> target;
  std::vector<float> form_factor;
  // Per patch, in the same shares, summed over its faces:
  std::vector<float> escaped;  // left the scene
  std::vector<float> lost;     // struck back faces (single- or double-sided) or buried texels
  std::vector<uint32_t> rays;  // per face
};

// The back face of a double-sided patch, as measured rows number faces.
inline uint32_t back_face(uint32_t patch, size_t patch_count) { return uint32_t(patch_count + patch); }

// Groups of patches that exchange light, directly or through one another (connected through the
// rows): rooms closed off from each other are separate enclosures. Every patch is in exactly one.
struct Enclosures {
  std::vector<uint32_t> of_patch;  // enclosure of each patch, numbered from 0 by lowest patch
  size_t count = 0;
};

Enclosures find_enclosures(const PatchTransport& transport);

// Rows F(f -> g) between faces as measured, before reciprocity: what adaptive subdivision keeps
// between rounds. Indexed by face: fronts 0 .. patches - 1, backs after them (empty for the
// single-sided).
struct MeasuredRows {
  std::vector<std::vector<std::pair<uint32_t, float>>> rows;  // per face, by target face
  std::vector<float> escaped, lost;  // per face; lost: single-sided back faces and buried texels
  std::vector<uint32_t> rays;

  void resize(size_t patches) {
    rows.resize(2 * patches);
    escaped.resize(2 * patches);
    lost.resize(2 * patches);
    rays.resize(2 * patches);
  }
};

// One thread's tally of what a face's rays (or hemicube pixels) leave on each target face, taken
// out as the face's row, sorted by target.
class RowTally {
 public:
  void add(uint32_t target, double share, size_t face_count) {
    if (share_.size() != face_count) share_.assign(face_count, 0);
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

// Measures the rows of the patches in `which` (both faces of the double-sided) into `into`
// (sized for all patches). Every face casts at least `rays_per_patch` rays; as many again are
// shared out in proportion to `power` (lm leaving each patch on the first bounce, over all
// patches), up to 16 times the base, so the patches that carry the light are measured most finely.
void measure_ray_cast_rows(const Elements& elements, const Patches& patches, const Surface& surface,
                           const RayTracer& tracer, uint32_t rays_per_patch, const std::vector<double>& power,
                           const std::vector<uint32_t>& which, uint64_t seed, Progress& progress, MeasuredRows& into);

// All rows by ray casting, balanced.
PatchTransport trace_patch_transport(const Elements& elements, const Patches& patches, const Surface& surface,
                                     const RayTracer& tracer, uint32_t rays_per_patch,
                                     const std::vector<double>& power, uint64_t seed, Progress& progress);

// Measured rows made reciprocal face to face (A_f F_fg = A_g F_gf) with every row still summing
// to what it measured landing, and gathered per patch: both faces' light landing on fronts.
PatchTransport balanced_transport(const Patches& patches, const MeasuredRows& measured);

// 0, 1, ..., n - 1: every patch.
std::vector<uint32_t> all_patches(size_t n);

// The faces of the patches in `which`: each patch's front, then the backs of the double-sided.
std::vector<uint32_t> faces_of(const Patches& patches, const std::vector<uint32_t>& which);

// Where a ray from `origin` in `direction` lands: the patch whose face it struck (`back`: the back
// of a double-sided one, which shows the same light), or UINT32_MAX with `escaped` telling
// whether it left the scene (else it struck a single-sided back face or a buried texel).
uint32_t patch_hit(const Elements& elements, const Patches& patches, const Surface& surface,
                   const RayTracer& tracer, Vec3 origin, Vec3 direction, bool& escaped, bool& back);

// The face a hit stands for, as measured rows number them.
inline uint32_t face_hit(uint32_t patch, bool back, size_t patch_count) {
  return back ? back_face(patch, patch_count) : patch;
}

}  // namespace radbake
