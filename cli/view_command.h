// `radbake view OUTDIR [OUTDIR_B]`: a page on 127.0.0.1 that shows bakes in three.js (served from
// web/, three.js pinned by web/package-lock.json), and the files of the folders named: nothing
// else, from nowhere else.
#pragma once

#include <string>
#include <vector>

namespace radbake {

struct ViewCommand {
  std::vector<std::string> folders;  // one or two radbake output folders: A, and B to compare
  int port = 0;                      // 0: a free one
  bool open = true;                  // open the page in the browser (xdg-open)
};

// Serves until interrupted; returns the exit status. Throws InputError for a folder that is not a
// radbake output, UsageError-like InputError for a port that cannot be bound.
int run_view(const ViewCommand& command);

}  // namespace radbake
