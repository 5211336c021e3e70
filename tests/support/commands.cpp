#include "support/commands.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace radbake::test {

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

Outcome run(const std::string& command) {
  // Named for the process, so tests that ctest runs side by side do not share the files.
  const std::string stem = ::testing::TempDir() + "/cli_" + std::to_string(getpid());
  const std::string out = stem + "_out.txt", err = stem + "_err.txt";
  int raw = std::system((command + " > " + out + " 2> " + err + " < /dev/null").c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
}

Outcome radbake(const std::string& args) { return run(std::string(RADBAKE_BINARY) + " " + args); }

}  // namespace radbake::test
