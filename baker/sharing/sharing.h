// How one bake is shared and kept (docs/distributed.md): the team of processes baking it, the
// store its stages are saved in, and whether to take back what a stopped run saved.
#pragma once

#include "baker/sharing/stage_store.h"
#include "baker/sharing/team.h"

namespace radbake {

// Where a run stops with its checkpoint saved (--stop-after), for pipelines that share a solve.
enum class StopAfter { Nothing, DirectLight, FormFactors, Radiosity };

// The part of the final gather a run does (--pages K/N, --texel-range K/N); radbake merge joins the
// parts. index counts from 0.
struct GatherSlice {
  enum class By { Everything, Pages, Texels } by = By::Everything;
  int index = 0, count = 1;
};

struct Sharing {
  Team* team = nullptr;         // null: this process alone
  StageStore* store = nullptr;  // null: nothing is saved
  bool resume = false;          // take back what the store holds
  double solve_save_seconds = 60;  // within the radiosity solve, save at most this often; 0: every 1024 shots or sweep
  StopAfter stop_after = StopAfter::Nothing;
  GatherSlice slice;
  int merge_slices = 0;         // > 0: the gather comes from this many slices in the store, none is computed
};

}  // namespace radbake
