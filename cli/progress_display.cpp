#include "cli/progress_display.h"

#include <unistd.h>

#include <cstdio>

namespace radbake {

ProgressDisplay::ProgressDisplay(bool enabled) : enabled_(enabled), tty_(isatty(STDERR_FILENO) != 0) {}

ProgressDisplay::~ProgressDisplay() { finish(); }

void ProgressDisplay::update(const std::string& stage, double fraction) {
  if (!enabled_) return;
  int tenth = int(fraction * 10);
  if (tty_) {
    const int width = 30;
    int filled = int(fraction * width);
    std::fprintf(stderr, "\r[%-*.*s] %3d%% %-24s", width, filled, "##############################", int(fraction * 100),
                 stage.c_str());
    std::fflush(stderr);
    bar_open_ = true;
    return;
  }
  if (stage == stage_ && tenth == last_tenth_) return;
  stage_ = stage;
  last_tenth_ = tenth;
  std::fprintf(stderr, "radbake: %s %d%%\n", stage.c_str(), tenth * 10);
}

void ProgressDisplay::finish() {
  if (bar_open_) std::fprintf(stderr, "\n");
  bar_open_ = false;
}

}  // namespace radbake
