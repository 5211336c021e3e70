#include "io/output_folder.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "baker/errors.h"

namespace radbake {
namespace fs = std::filesystem;
namespace {

// Only a folder radbake wrote (it holds report.json naming radbake) or an empty one is replaced:
// `-o ~` must never delete someone's home.
bool replaceable(const fs::path& target) {
  std::error_code ec;
  if (!fs::exists(target, ec)) return true;
  if (!fs::is_directory(target, ec)) return false;
  if (fs::is_empty(target, ec)) return true;
  std::ifstream report(target / "report.json");
  std::string head(256, '\0');
  report.read(head.data(), std::streamsize(head.size()));
  return head.find("\"generator\": \"radbake\"") != std::string::npos;
}

}  // namespace

StagedFolder::StagedFolder(const std::string& target) : target_(target) {
  fs::path t = fs::absolute(fs::path(target).lexically_normal());
  if (!t.has_filename()) t = t.parent_path();
  if (!replaceable(t))
    throw InputError("output folder " + target + " exists and is not a radbake output; choose another or remove it");
  std::error_code ec;
  fs::create_directories(t.parent_path(), ec);
  if (ec) throw InputError("cannot create " + t.parent_path().string() + ": " + ec.message());
  fs::path staging = t.parent_path() / ("." + t.filename().string() + ".radbake-" + std::to_string(getpid()));
  fs::remove_all(staging, ec);
  fs::create_directory(staging, ec);
  if (ec) throw InputError("cannot create " + staging.string() + ": " + ec.message());
  target_ = t.string();
  staging_ = staging.string();
}

StagedFolder::~StagedFolder() {
  if (committed_) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
}

void StagedFolder::commit() {
  fs::path old = fs::path(staging_).string() + "-old";
  std::error_code ec;
  bool had_old = fs::exists(target_, ec);
  if (had_old) fs::rename(target_, old);
  fs::rename(staging_, target_);
  committed_ = true;
  if (had_old) fs::remove_all(old, ec);
}

}  // namespace radbake
