// --checkpoint DIR: a bake's stages saved in a folder (baker/sharing/stage_store.h), one file per stage.
// Every file is headed by the bake's fingerprint (the scene's bytes, the options, radbake's
// version) and a checksum of what follows, and is written to a temporary and renamed, so a node
// preempted mid-write leaves the last whole file. A file of another bake, or a damaged one, is
// refused with one error line; nothing is read from a file before its size and checksum are known.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "baker/sharing/stage_store.h"
#include "io/gltf/gltf_loader.h"

namespace radbake {

// What a checkpoint must agree with: the loaded scene (JSON, buffers, decoded images) and the
// options that change what the stages compute (name, value).
uint64_t bake_fingerprint(const LoadedScene& scene, const std::vector<std::pair<std::string, std::string>>& options);

class CheckpointFolder final : public StageStore {
 public:
  // Creates the folder when missing. Throws InputError when it already holds stages of another
  // bake, or when it cannot be written. Not `owner`: a process of a team that leaves the folder
  // to the first (it neither checks nor makes it).
  CheckpointFolder(std::string folder, uint64_t fingerprint, std::string scene, bool owner = true);

  void save(const std::string& stage, const Bytes& state) override;
  std::optional<Bytes> load(const std::string& stage) const override;
  std::vector<std::string> stages(const std::string& prefix) const override;
  const std::string& folder() const { return folder_; }

 private:
  std::string file_of(const std::string& stage) const;
  std::string folder_;
  uint64_t fingerprint_;
};

}  // namespace radbake
