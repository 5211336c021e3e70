// Progress on stderr: a redrawn bar on a terminal, one plain line per tenth of a stage otherwise.
#pragma once

#include <string>

namespace radbake {

class ProgressDisplay {
 public:
  explicit ProgressDisplay(bool enabled);
  ~ProgressDisplay();
  void update(const std::string& stage, double fraction);
  void finish();  // ends the bar's line

 private:
  bool enabled_, tty_;
  std::string stage_;
  int last_tenth_ = -1;
  bool bar_open_ = false;
};

}  // namespace radbake
