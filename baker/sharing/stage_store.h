// Where a bake keeps what its stages computed, so a preempted bake resumes where it stopped
// (--checkpoint, --resume; docs/distributed.md). baker/ hands over and takes back bytes by stage
// name; io/checkpoint_folder keeps them in files that carry the bake's fingerprint and a checksum.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "baker/sharing/team.h"

namespace radbake {

class StageStore {
 public:
  virtual ~StageStore() = default;
  virtual void save(const std::string& stage, const Bytes& state) = 0;
  // What was saved under `stage`, or nothing; throws InputError when it is there but corrupt.
  virtual std::optional<Bytes> load(const std::string& stage) const = 0;
  // Stages saved whose names begin with `prefix`.
  virtual std::vector<std::string> stages(const std::string& prefix) const = 0;
};

}  // namespace radbake
