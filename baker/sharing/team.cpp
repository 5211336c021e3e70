#include "baker/sharing/team.h"

namespace radbake {

StageTraffic& Team::traffic_of(const std::string& stage) {
  for (StageTraffic& t : traffic_)
    if (t.stage == stage) return t;
  traffic_.push_back({stage});
  return traffic_.back();
}

void Team::count(const std::string& stage, uint64_t bytes) {
  StageTraffic& t = traffic_of(stage);
  t.bytes += bytes;
  ++t.exchanges;
}

// The whole team's traffic as the first process sees it (it writes the report): every process's
// bytes to each of the others (all-gather), the others' bytes to the first (gather), the first's
// to each of the others (broadcast). Alone, nothing.
std::vector<Bytes> Team::all_gather(const std::string& stage, const Bytes& mine) {
  std::vector<Bytes> all = do_all_gather(mine);
  uint64_t total = 0;
  for (const Bytes& b : all) total += b.size();
  count(stage, total * uint64_t(size() - 1));
  return all;
}

std::vector<Bytes> Team::gather_to_first(const std::string& stage, const Bytes& mine) {
  std::vector<Bytes> all = do_gather_to_first(mine);
  uint64_t total = 0;
  for (size_t r = 1; r < all.size(); ++r) total += all[r].size();
  count(stage, total);
  return all;
}

void Team::broadcast_from_first(const std::string& stage, Bytes& bytes) {
  do_broadcast_from_first(bytes);
  count(stage, uint64_t(bytes.size()) * uint64_t(size() - 1));
}

}  // namespace radbake
