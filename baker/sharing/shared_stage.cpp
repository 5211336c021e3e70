#include "baker/sharing/shared_stage.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <map>
#include <optional>

#include "baker/sharing/byte_stream.h"
#include "base/errors.h"
#include "base/progress.h"

namespace radbake {
namespace {

constexpr size_t kWaves = 8;

struct ChunkCost {
  uint64_t chunk = 0;
  uint64_t rays = 0;
  double seconds = 0;
};

// Which process computes each of `todo` (positions into the wanted list): the first wave by
// count, round robin; later waves in contiguous runs of equal estimated rays.
std::vector<int> assign(const std::vector<size_t>& todo, const std::vector<double>& estimate, int processes) {
  std::vector<int> owner(todo.size());
  const bool measured = std::all_of(todo.begin(), todo.end(), [&](size_t k) { return estimate[k] >= 0; });
  if (!measured) {
    for (size_t j = 0; j < todo.size(); ++j) owner[j] = int(j % size_t(processes));
    return owner;
  }
  double total = 0;
  for (size_t k : todo) total += std::max(1.0, estimate[k]);
  double before = 0;
  for (size_t j = 0; j < todo.size(); ++j) {
    const double cost = std::max(1.0, estimate[todo[j]]);
    owner[j] = std::min(processes - 1, int((before + cost / 2) / total * processes));
    before += cost;
  }
  return owner;
}

// Calls f(chunk, measured rays, result) for each chunk in bytes saved by run_shared_stage.
template <typename F>
void for_each_saved(const SharedStage& stage, const Bytes& saved, const F& f) {
  ByteReader in(saved);
  const uint64_t count = in.get<uint64_t>();
  if (in.get<uint64_t>() != stage.chunks) throw InputError("the checkpoint's " + stage.name + " has other chunks");
  for (uint64_t n = 0; n < count; ++n) {
    const uint64_t chunk = in.get<uint64_t>(), measured = in.get<uint64_t>();
    if (chunk >= stage.chunks) throw TruncatedBytes();
    f(chunk, measured, in.get_bytes());
  }
}

// What a run of a stage knows of its wanted chunks as it goes: which are done and what each cost,
// and on the first process with a store, the results kept for the next save.
class Ledger {
 public:
  Ledger(const SharedStage& stage, StageStore* store, bool first) : stage_(stage), store_(first ? store : nullptr) {
    if (stage.only) wanted = *stage.only;
    else
      for (size_t c = 0; c < stage.chunks; ++c) wanted.push_back(c);
    for (size_t k = 0; k < wanted.size(); ++k) position_[wanted[k]] = k;
    rays.assign(wanted.size(), -1);
    done.assign(wanted.size(), 0);
    if (store_) kept_.resize(wanted.size());
  }

  // A chunk is done: `measured` rays, its result given to the stage when `take`.
  void record(uint64_t chunk, uint64_t measured, Bytes result, bool take) {
    auto it = position_.find(size_t(chunk));
    if (it == position_.end() || done[it->second]) throw InputError("the " + stage_.name + " results name a chunk twice");
    done[it->second] = 1;
    ++done_count;
    rays[it->second] = double(measured);
    if (take) stage_.take(size_t(chunk), result);
    if (store_) kept_[it->second] = std::move(result);
  }

  // The first process with a store saves what is done (a slice with no chunks too: its empty part
  // tells a merge it ran).
  void save(const std::string& key) {
    if (!store_) return;
    ByteWriter out;
    out.put(uint64_t(done_count));
    out.put(uint64_t(stage_.chunks));
    for (size_t k = 0; k < wanted.size(); ++k)
      if (done[k]) {
        out.put(uint64_t(wanted[k]));
        out.put(uint64_t(rays[k]));
        out.put_bytes(kept_[k]);
      }
    store_->save(key, out.bytes());
    saved_once = true;
  }

  std::vector<size_t> wanted;
  std::vector<double> rays;    // per position in `wanted`: measured rays, -1 until measured
  std::vector<uint8_t> done;   // per position in `wanted`
  size_t done_count = 0;
  bool saved_once = false;

 private:
  const SharedStage& stage_;
  StageStore* store_;
  std::map<size_t, size_t> position_;  // chunk -> position in `wanted`
  std::vector<Bytes> kept_;
};

// Takes back what a stopped run saved: the first reads it; the others get it too, without the
// results when only the first needs those (they still learn which chunks are done and what they
// cost).
void resume_saved(const SharedStage& stage, Team& team, StageStore& store, const std::string& key, Ledger& ledger,
                  Progress& progress) {
  Bytes saved, sent;
  if (team.first())
    if (std::optional<Bytes> s = store.load(key)) saved = std::move(*s);
  if (team.first() && !saved.empty()) {
    ByteWriter out;
    out.put(uint64_t(0));
    out.put(uint64_t(stage.chunks));
    uint64_t count = 0;
    for_each_saved(stage, saved, [&](uint64_t chunk, uint64_t measured, const Bytes& result) {
      out.put(chunk);
      out.put(measured);
      out.put_bytes(stage.results_to_all ? result : Bytes{});
      ++count;
    });
    std::memcpy(out.bytes().data(), &count, sizeof count);
    sent = std::move(out.bytes());
  }
  team.broadcast_from_first(stage.name, sent);
  if (sent.empty()) return;
  for_each_saved(stage, team.first() ? saved : sent, [&](uint64_t chunk, uint64_t measured, Bytes result) {
    ledger.record(chunk, measured, std::move(result), stage.results_to_all || team.first());
  });
  progress.advance(ledger.done_count);
}

// One wave: this process computes its share of the wave's chunks not yet done, then the costs go
// to everyone (they plan the next waves) and the results where they are needed. False when the
// wave had nothing left to do.
bool run_wave(const SharedStage& stage, Team& team, const RayTracer& tracer, size_t wave, Ledger& ledger,
              StageTraffic& traffic, Progress& progress) {
  std::vector<size_t> todo;  // positions in `wanted`
  for (size_t k = wave; k < ledger.wanted.size(); k += kWaves)
    if (!ledger.done[k]) todo.push_back(k);
  if (todo.empty()) return false;
  // A chunk's estimate: what its sibling in the first wave (the same run of eight) cost.
  std::vector<double> estimate(ledger.wanted.size(), -1);
  for (size_t k : todo) estimate[k] = ledger.rays[k - k % kWaves];
  const std::vector<int> owner = assign(todo, estimate, team.size());

  ByteWriter costs, results;
  size_t mine = 0;
  for (size_t j = 0; j < todo.size(); ++j) {
    if (owner[j] != team.rank()) continue;
    const size_t chunk = ledger.wanted[todo[j]];
    const uint64_t rays_before = tracer.rays_cast();
    const auto start = std::chrono::steady_clock::now();
    Bytes result = stage.compute(chunk);
    const double seconds = seconds_since(start);
    ++mine;
    costs.put(ChunkCost{chunk, tracer.rays_cast() - rays_before, seconds});
    results.put(uint64_t(chunk));
    results.put_bytes(result);
    progress.advance(1);
  }
  const std::vector<Bytes> all_costs = team.all_gather(stage.name, costs.bytes());
  const std::vector<Bytes> all_results = stage.results_to_all ? team.all_gather(stage.name, results.bytes())
                                                              : team.gather_to_first(stage.name, results.bytes());
  double wave_sum = 0, wave_busiest = 0;
  std::map<uint64_t, ChunkCost> cost_of;
  for (const Bytes& b : all_costs) {
    ByteReader in(b);
    double process_seconds = 0;
    while (!in.done()) {
      const ChunkCost c = in.get<ChunkCost>();
      cost_of[c.chunk] = c;
      process_seconds += c.seconds;
    }
    wave_sum += process_seconds;
    wave_busiest = std::max(wave_busiest, process_seconds);
  }
  traffic.compute_seconds += wave_sum;
  traffic.busiest_seconds += wave_busiest;
  const size_t before = ledger.done_count;
  if (all_results.empty()) {  // not the first, and the results go to the first only
    for (const auto& [chunk, c] : cost_of) ledger.record(chunk, c.rays, {}, false);
  } else {
    for (const Bytes& from : all_results) {
      ByteReader in(from);
      while (!in.done()) {
        const uint64_t chunk = in.get<uint64_t>();
        Bytes result = in.get_bytes();
        ledger.record(chunk, cost_of.at(chunk).rays, std::move(result), true);
      }
    }
  }
  progress.advance(ledger.done_count - before - mine);
  return true;
}

}  // namespace

std::vector<size_t> take_saved_stage(const SharedStage& stage, const Bytes& saved) {
  std::vector<size_t> taken;
  for_each_saved(stage, saved, [&](uint64_t chunk, uint64_t, const Bytes& result) {
    stage.take(size_t(chunk), result);
    taken.push_back(size_t(chunk));
  });
  return taken;
}

std::vector<size_t> chunk_starts(size_t count, size_t target, size_t least, size_t align,
                                 const std::vector<size_t>& breaks) {
  const size_t size = std::max(align, (std::max(target, least) + align - 1) / align * align);
  std::vector<size_t> starts;
  size_t next_break = 0;
  for (size_t at = 0; at < count;) {
    starts.push_back(at);
    while (next_break < breaks.size() && breaks[next_break] <= at) ++next_break;
    const size_t limit = next_break < breaks.size() ? breaks[next_break] : count;
    at = std::min(at + size, limit);
  }
  starts.push_back(count);
  return starts;
}

void run_shared_stage(const SharedStage& stage, Team& team, StageStore* store, bool resume, const RayTracer& tracer,
                      Progress& progress) {
  const std::string key = stage.name + " waves";
  Ledger ledger(stage, store, team.first());
  progress.begin(stage.name, ledger.wanted.size());
  if (resume && store) resume_saved(stage, team, *store, key, ledger, progress);
  StageTraffic& traffic = team.traffic_of(stage.name);
  for (size_t wave = 0; wave < kWaves; ++wave)
    if (run_wave(stage, team, tracer, wave, ledger, traffic, progress)) ledger.save(key);
  if (!ledger.saved_once) ledger.save(key);
  progress.end();
}

}  // namespace radbake
