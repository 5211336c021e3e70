#include "cli/process_team.h"

#include <climits>
#include <cstdlib>

#include "base/errors.h"

#ifdef RADBAKE_WITH_MPI
#include <mpi.h>
#endif

namespace radbake {
namespace {

#ifdef RADBAKE_WITH_MPI
// Started by mpirun/mpiexec (Open MPI, MPICH) or Slurm's srun: a plain run never touches MPI.
bool launched_by_mpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "PMI_RANK", "MPI_LOCALNRANKS"})
    if (std::getenv(name)) return true;
  return false;
}

int count_of(uint64_t size) {
  if (size > uint64_t(INT_MAX)) throw std::runtime_error("a message between processes over 2 GB: use more processes");
  return int(size);
}

// Ranks of MPI_COMM_WORLD; every exchange first shares the sizes, then the bytes.
class MpiTeam final : public Team {
 public:
  MpiTeam() {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  int rank() const override { return rank_; }
  int size() const override { return size_; }

 protected:
  std::vector<Bytes> do_all_gather(const Bytes& mine) override {
    std::vector<int> counts(static_cast<size_t>(size_)), offsets(static_cast<size_t>(size_));
    const int my_count = count_of(mine.size());
    MPI_Allgather(&my_count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    Bytes all(layout(counts, offsets));
    MPI_Allgatherv(mine.data(), my_count, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE, MPI_COMM_WORLD);
    return split(all, counts, offsets);
  }
  std::vector<Bytes> do_gather_to_first(const Bytes& mine) override {
    std::vector<int> counts(static_cast<size_t>(size_)), offsets(static_cast<size_t>(size_));
    const int my_count = count_of(mine.size());
    MPI_Gather(&my_count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    Bytes all(rank_ == 0 ? layout(counts, offsets) : 0);
    MPI_Gatherv(mine.data(), my_count, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE, 0, MPI_COMM_WORLD);
    return rank_ == 0 ? split(all, counts, offsets) : std::vector<Bytes>{};
  }
  void do_broadcast_from_first(Bytes& bytes) override {
    uint64_t size = bytes.size();
    MPI_Bcast(&size, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    bytes.resize(size);
    for (uint64_t at = 0; at < size; at += uint64_t(INT_MAX))
      MPI_Bcast(bytes.data() + at, int(std::min<uint64_t>(INT_MAX, size - at)), MPI_BYTE, 0, MPI_COMM_WORLD);
  }

 private:
  static size_t layout(const std::vector<int>& counts, std::vector<int>& offsets) {
    uint64_t total = 0;
    for (size_t r = 0; r < counts.size(); ++r) {
      offsets[r] = count_of(total);
      total += uint64_t(counts[r]);
    }
    count_of(total);
    return size_t(total);
  }
  static std::vector<Bytes> split(const Bytes& all, const std::vector<int>& counts, const std::vector<int>& offsets) {
    std::vector<Bytes> out(counts.size());
    for (size_t r = 0; r < counts.size(); ++r)
      out[r].assign(all.begin() + offsets[r], all.begin() + offsets[r] + counts[r]);
    return out;
  }
  int rank_ = 0, size_ = 1;
};
#endif

}  // namespace

ProcessTeam::ProcessTeam([[maybe_unused]] int& argc, [[maybe_unused]] char**& argv) {
#ifdef RADBAKE_WITH_MPI
  if (launched_by_mpi()) {
    int provided = 0;
    // Only the main thread calls MPI; TBB's workers never do.
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    joined_mpi_ = true;
    team_ = std::make_unique<MpiTeam>();
    return;
  }
#endif
  team_ = std::make_unique<SoloTeam>();
}

ProcessTeam::~ProcessTeam() {
#ifdef RADBAKE_WITH_MPI
  if (joined_mpi_) MPI_Finalize();
#endif
}

void ProcessTeam::abort(int status) {
#ifdef RADBAKE_WITH_MPI
  if (joined_mpi_ && team_->size() > 1) MPI_Abort(MPI_COMM_WORLD, status);
#endif
  std::exit(status);
}

}  // namespace radbake
