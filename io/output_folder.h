// A bake writes into a hidden staging folder next to OUTDIR and renames it into place only when
// everything is written, so a failed or cancelled bake leaves no half-written OUTDIR behind.
#pragma once

#include <string>

namespace radbake {

class StagedFolder {
 public:
  // Throws InputError when `target` exists and is neither empty nor an earlier radbake output.
  explicit StagedFolder(const std::string& target);
  ~StagedFolder();  // removes the staging folder unless committed
  StagedFolder(const StagedFolder&) = delete;
  StagedFolder& operator=(const StagedFolder&) = delete;

  const std::string& path() const { return staging_; }
  void commit();  // replaces `target` with the staging folder

 private:
  std::string target_, staging_;
  bool committed_ = false;
};

}  // namespace radbake
