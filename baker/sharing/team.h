// The processes that bake one scene together (MPI ranks; docs/distributed.md). Every process
// loads the scene and builds its own ray tracer; the stages that loop over rows or texels share
// their chunks out (shared_stage.h) and exchange results as bytes through this seam, so baker/
// knows nothing of MPI and a process alone runs the same code as a team of one.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace radbake {

using Bytes = std::vector<uint8_t>;

// What one stage cost the team, for the report and the bench's scaling model.
struct StageTraffic {
  std::string stage;
  uint64_t bytes = 0;     // payload bytes that left the process that made them
  uint32_t exchanges = 0; // collective operations
  // Shared stages (shared_stage.h): seconds the processes spent computing chunks, summed, and of
  // the busiest process, wave by wave: (busiest / (sum / size)) - 1 is the imbalance.
  double compute_seconds = 0, busiest_seconds = 0;
};

class Team {
 public:
  virtual ~Team() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  bool first() const { return rank() == 0; }

  // Each process's bytes, in rank order, to every process.
  std::vector<Bytes> all_gather(const std::string& stage, const Bytes& mine);
  // Each process's bytes, in rank order, to the first; the others get an empty list.
  std::vector<Bytes> gather_to_first(const std::string& stage, const Bytes& mine);
  // The first process's bytes to every process.
  void broadcast_from_first(const std::string& stage, Bytes& bytes);

  const std::vector<StageTraffic>& traffic() const { return traffic_; }
  StageTraffic& traffic_of(const std::string& stage);

 protected:
  virtual std::vector<Bytes> do_all_gather(const Bytes& mine) = 0;
  virtual std::vector<Bytes> do_gather_to_first(const Bytes& mine) = 0;
  virtual void do_broadcast_from_first(Bytes& bytes) = 0;

 private:
  void count(const std::string& stage, uint64_t bytes);
  std::vector<StageTraffic> traffic_;
};

// A process baking alone.
class SoloTeam final : public Team {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }

 protected:
  std::vector<Bytes> do_all_gather(const Bytes& mine) override { return {mine}; }
  std::vector<Bytes> do_gather_to_first(const Bytes& mine) override { return {mine}; }
  void do_broadcast_from_first(Bytes&) override {}
};

}  // namespace radbake
