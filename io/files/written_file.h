// What radbake says when an output cannot be written: one line naming the file and the reason in
// radbake's words (the disk is full, read-only, or the folder is not the user's), never a
// library's ("Failed OpenEXR write: ... File output failed."). The libraries do not say why; the
// free space on the file's disk and errno do.
#pragma once

#include <fstream>
#include <string>

namespace radbake {

// Throws OutputError for `path`, whose writing just failed.
[[noreturn]] void refuse_unwritten(const std::string& path);

// Flushes and closes `out`, then throws OutputError when any write to it failed (a stream's last
// buffer reaches the disk only here, so a full disk is often first noticed here).
void close_written(std::ofstream& out, const std::string& path);

}  // namespace radbake
