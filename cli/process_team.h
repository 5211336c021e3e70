// The team this process bakes in: under mpirun or srun (a build with RADBAKE_MPI), the MPI ranks;
// otherwise this process alone. The only place that knows MPI (docs/distributed.md).
#pragma once

#include <memory>

#include "baker/sharing/team.h"

namespace radbake {

class ProcessTeam {
 public:
  ProcessTeam(int& argc, char**& argv);  // joins MPI when a launcher started this process
  ~ProcessTeam();                        // leaves it
  Team& team() { return *team_; }
  // Ends every process of the team with `status` (after an error this one has reported).
  [[noreturn]] void abort(int status);

 private:
  std::unique_ptr<Team> team_;
  bool joined_mpi_ = false;
};

}  // namespace radbake
