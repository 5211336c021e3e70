// A bake writes into a hidden staging folder next to OUTDIR and renames it into place only when
// everything is written, so a failed or cancelled bake leaves no half-written OUTDIR behind.
//
// While it does, it holds an fcntl lock on a file beside OUTDIR (.NAME.radbake-lock): a second
// bake into the same OUTDIR is refused, naming the process that holds it, instead of racing it to
// the rename. Holding the lock also proves that any other staging folder of OUTDIR was left by a
// bake that died (a crash, SIGKILL, a power cut): the kernel let its lock go, so it is removed.
#pragma once

#include <mutex>
#include <string>
#include <vector>

namespace radbake {

class StagedFolder {
 public:
  // Throws InputError when another bake is writing `target`, or when `target` exists and is
  // neither empty nor an earlier radbake output, or holds files that output did not list in its
  // report.json ("files"): a user's files in OUTDIR are never deleted.
  explicit StagedFolder(const std::string& target);
  ~StagedFolder();  // removes the staging folder unless committed, then lets the lock go
  StagedFolder(const StagedFolder&) = delete;
  StagedFolder& operator=(const StagedFolder&) = delete;

  const std::string& path() const { return staging_; }
  // `file` (a path in the staging folder) as the user will find it once committed: under the
  // target as they named it. Any other path is returned as it is.
  std::string as_committed(const std::string& file) const;
  // Every file in the staging folder, '/'-separated and relative to it: what report.json lists
  // as radbake's, so the next bake can tell a user's files from its own.
  std::vector<std::string> files() const;
  void commit();  // replaces `target` with the staging folder
  bool committed() const { return committed_; }

  // For a thread that must end the process while the owner cannot unwind (see cli/interrupts.h):
  // removes the staging folder and the lock as the destructor would, even while the owner is still
  // writing into it. Returns false, doing nothing, once commit() has put the output in place.
  bool abandon() noexcept;

 private:
  // The lock file and its descriptor; the file is removed before the lock is let go.
  struct Lock {
    std::string path;
    int fd = -1;
    ~Lock();
  };

  std::string given_, target_, staging_;  // the target as the user named it, and as an absolute path
  Lock lock_;
  std::mutex mutex_;  // commit() against abandon()
  bool committed_ = false;
};

}  // namespace radbake
