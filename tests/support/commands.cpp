#include "support/commands.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
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

void expect_one_line_refusal(const Outcome& r, const std::string& says, const std::string& unwritten) {
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err.rfind("radbake: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(unwritten)) << unwritten;
}

std::string make_fifo(const std::string& path) {
  EXPECT_EQ(mkfifo(path.c_str(), 0600), 0) << path;
  return path;
}

}  // namespace radbake::test
