// Running the radbake binary as a script or pipeline would, for the command-line tests.
#pragma once

#include <string>

namespace radbake::test {

struct Outcome {
  int status;  // exit status; -1 when the command did not exit (a crash)
  std::string out, err;
};

// Through the shell, stdin from /dev/null, stdout and stderr captured.
Outcome run(const std::string& command);

// The radbake under test with `args`.
Outcome radbake(const std::string& args);

std::string slurp(const std::string& path);

// A refused command: exit status 2, one `radbake: error:` line that holds `says`, and nothing
// written at `unwritten` (the output folder it was given).
void expect_one_line_refusal(const Outcome& r, const std::string& says, const std::string& unwritten);

// A FIFO made at `path` (which it returns), as a hostile user would leave one: no writer, so
// opening it to read blocks for ever unless it is opened without blocking.
std::string make_fifo(const std::string& path);

}  // namespace radbake::test
