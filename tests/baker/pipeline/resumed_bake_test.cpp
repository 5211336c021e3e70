// Checkpoints (baker/sharing/stage_store.h): a bake resumed from any state it saved, within any stage,
// writes the same lightmaps bit for bit as the bake that was never stopped.
#include <gtest/gtest.h>

#include <map>

#include "baker/pipeline/bake.h"
#include "base/errors.h"
#include "support/scene_builders.h"

namespace radbake::test {
namespace {

// Keeps every save in order, as a folder would have held it at that moment.
class RecordingStore final : public StageStore {
 public:
  void save(const std::string& stage, const Bytes& state) override {
    held[stage] = state;
    history.emplace_back(stage, state);
  }
  std::optional<Bytes> load(const std::string& stage) const override {
    auto it = held.find(stage);
    if (it == held.end()) return std::nullopt;
    return it->second;
  }
  std::vector<std::string> stages(const std::string& prefix) const override {
    std::vector<std::string> out;
    for (const auto& [name, bytes] : held)
      if (name.rfind(prefix, 0) == 0) out.push_back(name);
    return out;
  }
  std::map<std::string, Bytes> held;
  std::vector<std::pair<std::string, Bytes>> history;
};

// A bright grey room with a block, solved to a tight tolerance: the shooting solve takes
// thousands of shots, so it saves several times within itself (every 1024 shots with
// solve_save_seconds 0).
struct Room {
  Scene scene = lit_room(0.85f, {1, 1, 1}, true);
  AtlasOptions atlas;
  BakeOptions options;
  Room() {
    atlas.max_page_size = 64;
    options.gather.rays = 32;
    options.form_factors.rays_per_patch = 256;
    options.solve.tolerance = 1e-7;
    options.sharing.solve_save_seconds = 0;
  }
};

TEST(ResumedBake, FromEveryStateSavedWithinEveryStageGivesTheSameLightmaps) {
  Room room;
  const Baked whole = bake_scene(room.scene, room.atlas, room.options);
  RecordingStore recording;
  room.options.sharing.store = &recording;
  const Baked saved = bake_scene(room.scene, room.atlas, room.options);
  ASSERT_TRUE(same_pages(whole.result.pages, saved.result.pages)) << "saving changed the bake";
  std::map<std::string, int> saves;
  for (const auto& [stage, bytes] : recording.history) ++saves[stage];
  // Each stage saved more than once (waves, or the solve every 1024 shots): there are states
  // within stages to resume from.
  for (const char* stage : {"direct light waves", "form factors waves", "radiosity", "final gather waves"}) {
    ASSERT_TRUE(saves.count(stage)) << stage;
    EXPECT_GE(saves[stage], 3) << stage;
  }
  // Stopped after each save in turn, at a stride so the test stays short: the store as it was.
  const size_t stride = std::max<size_t>(1, recording.history.size() / 12);
  for (size_t stop = 0; stop < recording.history.size(); stop += stride) {
    RecordingStore at_stop;
    for (size_t k = 0; k <= stop; ++k) at_stop.held[recording.history[k].first] = recording.history[k].second;
    BakeOptions resumed = room.options;
    resumed.sharing.store = &at_stop;
    resumed.sharing.resume = true;
    const Baked again = bake_scene(room.scene, room.atlas, resumed);
    EXPECT_TRUE(same_pages(whole.result.pages, again.result.pages))
        << "resumed after save " << stop << " (" << recording.history[stop].first << ")";
  }
}

TEST(ResumedBake, StopsAfterTheStageItIsToldAndGoesOnFromThere) {
  Room room;
  const Baked whole = bake_scene(room.scene, room.atlas, room.options);
  for (StopAfter stop : {StopAfter::DirectLight, StopAfter::FormFactors, StopAfter::Radiosity}) {
    RecordingStore store;
    BakeOptions first = room.options;
    first.sharing.store = &store;
    first.sharing.stop_after = stop;
    EXPECT_THROW(bake_scene(room.scene, room.atlas, first), StoppedEarly);
    EXPECT_EQ(store.held.count("final gather waves"), 0u) << "the gather ran past the stop";
    BakeOptions resumed = room.options;
    resumed.sharing.store = &store;
    resumed.sharing.resume = true;
    EXPECT_TRUE(same_pages(whole.result.pages, bake_scene(room.scene, room.atlas, resumed).result.pages));
  }
}

TEST(ResumedBake, SlicesOfTheGatherMergeIntoTheWholeBake) {
  Room room;
  const Baked whole = bake_scene(room.scene, room.atlas, room.options);
  for (GatherSlice::By by : {GatherSlice::By::Texels, GatherSlice::By::Pages}) {
    RecordingStore store;
    for (int k = 0; k < 3; ++k) {
      BakeOptions slice = room.options;
      slice.sharing.store = &store;
      slice.sharing.resume = true;  // the solve is the first slice's, shared
      slice.sharing.slice = {by, k, 3};
      EXPECT_THROW(bake_scene(room.scene, room.atlas, slice), StoppedEarly);
    }
    BakeOptions merge = room.options;
    merge.sharing.store = &store;
    merge.sharing.resume = true;
    merge.sharing.merge_slices = 3;
    EXPECT_TRUE(same_pages(whole.result.pages, bake_scene(room.scene, room.atlas, merge).result.pages));
    // Without one slice, the merge is refused rather than leaving texels dark.
    store.held.erase("final gather, slice 2 of 3 waves");
    EXPECT_THROW(bake_scene(room.scene, room.atlas, merge), InputError);
  }
}

}  // namespace
}  // namespace radbake::test
