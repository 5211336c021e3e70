// A stage whose work is a list of independent chunks (rows of form factors, ranges of texels),
// shared out among the processes of a team and balanced by measured cost: the chunks go in eight
// interleaved waves; the first is dealt out by count and measures each chunk's rays, and every
// later wave is cut into contiguous runs of equal estimated rays, a chunk's estimate being what
// its sibling in the first wave cost. A chunk's result depends only on its index, never on who
// computed it, so any number of processes gives the same bytes. After each wave the first
// process can save what is done (a stage store), and a resumed stage starts from there.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "baker/sharing/stage_store.h"
#include "baker/sharing/team.h"
#include "baker/surface/ray_tracer.h"
#include "base/progress.h"

namespace radbake {

struct SharedStage {
  std::string name;                // progress, traffic and the store's key ("<name> waves")
  size_t chunks = 0;
  std::optional<std::vector<size_t>> only;  // the chunks to compute (a slice of the bake); none: all
  bool results_to_all = false;     // every process needs every result; else only the first does
  std::function<Bytes(size_t chunk)> compute;                    // on this process, threads inside
  std::function<void(size_t chunk, const Bytes& result)> take;   // keeps a chunk's result
};

// Runs the stage across `team`. With `store`, the first process saves the finished waves after
// each one, and with `resume` first takes back what a stopped run saved.
void run_shared_stage(const SharedStage& stage, Team& team, StageStore* store, bool resume, const RayTracer& tracer,
                      Progress& progress);

// Takes back the results a run of `stage` saved (in a store, under "<name> waves"): calls
// stage.take for each and returns the chunks taken.
std::vector<size_t> take_saved_stage(const SharedStage& stage, const Bytes& saved);

// Chunk boundaries over `count` items: about `target` items each, at least `least`, a multiple of
// `align`, never crossing a boundary in `breaks` (sorted item indices, e.g. where pages start).
std::vector<size_t> chunk_starts(size_t count, size_t target, size_t least, size_t align,
                                 const std::vector<size_t>& breaks);

}  // namespace radbake
