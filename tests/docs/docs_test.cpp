// The README and docs/ cannot drift from the code: every command they show runs as written, the
// README's map of the house names every folder, and every include points down that map.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "support/commands.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

namespace fs = std::filesystem;

// The pages a newcomer reads: the README, then docs/ and docs/bench/.
std::vector<std::string> pages() {
  std::vector<std::string> out = {"README.md"};
  std::vector<std::string> docs;
  for (const char* folder : {"docs", "docs/bench"})
    for (const auto& e : fs::directory_iterator(test::source_path(folder)))
      if (e.path().extension() == ".md") docs.push_back(fs::relative(e.path(), test::source_path("")).string());
  std::sort(docs.begin(), docs.end());
  out.insert(out.end(), docs.begin(), docs.end());
  return out;
}

// Lines that start (after indentation) with ./build/radbake, continuation lines joined.
std::vector<std::string> commands_in(const std::string& page) {
  std::stringstream text(test::slurp(test::source_path(page)));
  std::vector<std::string> out;
  for (std::string line; std::getline(text, line);) {
    line.erase(0, line.find_first_not_of(' '));
    if (line.rfind("./build/radbake ", 0) != 0) continue;
    for (std::string more; line.size() > 1 && line.back() == '\\' && std::getline(text, more);)
      line = line.substr(0, line.find_last_not_of(" \\") + 1) + " " + more.substr(more.find_first_not_of(' '));
    out.push_back(line);
  }
  return out;
}

// Each distinct command of the README and docs/, in the order they appear (a page's later command
// may read what an earlier one wrote), with out/ moved to a temporary folder.
TEST(Docs, EveryCommandInTheReadmeAndDocsRunsAsWritten) {
  const std::string parent = test::fresh_folder("docs_commands");
  std::set<std::string> ran;
  for (const std::string& page : pages())
    for (const std::string& line : commands_in(page)) {
      if (!ran.insert(line).second) continue;
      std::string args = line.substr(std::string("./build/radbake ").size());
      for (size_t at; (at = args.find(" out/")) != std::string::npos;) args.replace(at, 5, " " + parent + "/");
      for (const std::string folder : {" samples/", " tests/"})
        for (size_t at; (at = args.find(folder)) != std::string::npos;)
          args.replace(at, folder.size(), " " + test::source_path(folder.substr(1)));
      const bool bakes = args.rfind("bake ", 0) == 0 || args.rfind("merge ", 0) == 0;
      const test::Outcome r = test::radbake(args + (bakes ? " --quiet" : ""));
      EXPECT_EQ(r.status, 0) << page << ": " << line << "\n" << r.err;
    }
  EXPECT_GE(ran.size(), 20u);
  // And the two set-up commands are the ones ./dev offers.
  const std::string dev = test::slurp(test::source_path("dev"));
  for (const char* command : {"  sample)", "  test)", "  bench)", "  asan)"}) EXPECT_NE(dev.find(command), std::string::npos);
}

// `./dev help` prints the "#:" lines of ./dev, one per command: every command ./dev runs is there,
// and nothing that it does not run.
TEST(Docs, DevHelpListsEveryCommandOnceAndNothingElse) {
  std::stringstream text(test::slurp(test::source_path("dev")));
  std::multiset<std::string> listed;
  std::set<std::string> handled;
  const std::regex help_line("^#: ([a-z-]+) .*"), case_label("^  ([a-z-]+)\\)$");
  std::smatch m;
  for (std::string line; std::getline(text, line);) {
    if (std::regex_match(line, m, help_line)) listed.insert(m[1]);
    if (std::regex_match(line, m, case_label)) handled.insert(m[1]);
  }
  EXPECT_GE(handled.size(), 15u);
  EXPECT_EQ(std::set<std::string>(listed.begin(), listed.end()), handled);
  EXPECT_EQ(listed.size(), handled.size()) << "a command listed twice";
}

// The README's map: its folders, bottom first.
std::vector<std::string> map_of_the_house() {
  std::stringstream text(test::slurp(test::source_path("README.md")));
  std::vector<std::string> folders;
  bool in_map = false;
  for (std::string line; std::getline(text, line);) {
    if (line == "<!-- folders -->") {
      std::getline(text, line);  // the opening fence
      in_map = true;
      continue;
    }
    if (!in_map) continue;
    if (line.rfind("```", 0) == 0) break;
    folders.push_back(line.substr(0, line.find(' ')));
  }
  return folders;
}

// The map entry a path lies in (the longest that holds it), or -1.
int entry_of(const std::vector<std::string>& map, const std::string& path) {
  int best = -1;
  for (size_t k = 0; k < map.size(); ++k)
    if (path.rfind(map[k], 0) == 0 && (best < 0 || map[k].size() > map[size_t(best)].size())) best = int(k);
  return best;
}

// Every file of the house, relative to the source folder; what the build, npm and a run leave
// (build*/, out/, node_modules/) and hidden files are not the house.
std::vector<std::string> files_of_the_house() {
  std::vector<std::string> out;
  const fs::path root = fs::path(test::source_path("")).lexically_normal();
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
    const fs::path relative = fs::relative(it->path(), root);
    const std::string name = it->path().filename().string();
    const bool top = relative.parent_path().empty();
    if (it->is_directory() && (name == "node_modules" || name == "__pycache__" ||
                               (top && (name[0] == '.' || name == "out" || name.rfind("build", 0) == 0)))) {
      it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file()) out.push_back(relative.string());
  }
  return out;
}

TEST(Docs, TheReadmesMapNamesEveryFolderAndOnlyFoldersThatAre) {
  const std::vector<std::string> map = map_of_the_house();
  ASSERT_GE(map.size(), 15u);
  for (const std::string& folder : map) {
    EXPECT_EQ(folder.back(), '/') << folder;
    EXPECT_TRUE(fs::is_directory(test::source_path(folder))) << folder << " is on the map but not in the tree";
  }
  std::set<std::string> unmapped;
  for (const std::string& file : files_of_the_house()) {
    const bool top_level = file.find('/') == std::string::npos;
    const bool folder_build_file = fs::path(file).filename() == "CMakeLists.txt";  // baker/ and io/ hold only theirs
    if (!top_level && !folder_build_file && entry_of(map, file) < 0) unmapped.insert(fs::path(file).parent_path().string());
  }
  EXPECT_TRUE(unmapped.empty()) << "folders the README's map leaves out: " << *unmapped.begin();
}

// Arrows point down only: a file includes its own folder's headers and those of folders below it.
TEST(Docs, EveryIncludePointsDownTheMap) {
  const std::vector<std::string> map = map_of_the_house();
  const std::regex include(R"re(^#include "([^"]+)")re");
  size_t checked = 0;
  for (const std::string& file : files_of_the_house()) {
    const std::string ext = fs::path(file).extension().string();
    if (ext != ".cpp" && ext != ".h" && ext != ".in") continue;
    const int from = entry_of(map, file);
    if (from < 0 || map[size_t(from)] == "tests/" || map[size_t(from)] == "bench/") continue;
    std::stringstream text(test::slurp(test::source_path(file)));
    std::smatch m;
    for (std::string line; std::getline(text, line);) {
      if (!std::regex_search(line, m, include)) continue;
      const int to = entry_of(map, m[1]);
      ASSERT_GE(to, 0) << file << " includes " << m[1] << ", which lies on no folder of the map";
      EXPECT_LE(to, from) << file << " includes " << m[1] << " from a folder above its own";
      ++checked;
    }
  }
  EXPECT_GT(checked, 300u);
}

// Code, tests, build files and scripts say what was measured or what broke, not which issue asked:
// an issue's number means nothing to a reader of the repository. docs/ may tell the history.
TEST(Docs, NoSourceCitesAnIssueByNumber) {
  const std::regex issue_number("[Ii]ssues? ?#?[0-9]+|Issue[0-9]+");
  size_t checked = 0;
  for (const std::string& file : files_of_the_house()) {
    const std::string ext = fs::path(file).extension().string();
    static const std::set<std::string> source = {".cpp", ".h", ".in", ".py", ".mjs", ".js", ".html", ".cmake", ".txt", ""};
    if (file.rfind("docs/", 0) == 0 || !source.count(ext)) continue;
    std::stringstream text(test::slurp(test::source_path(file)));
    size_t line_number = 0;
    for (std::string line; std::getline(text, line);) {
      ++line_number;
      EXPECT_FALSE(std::regex_search(line, issue_number)) << file << ":" << line_number << ": " << line;
    }
    ++checked;
  }
  EXPECT_GT(checked, 300u);
}

}  // namespace
}  // namespace radbake
