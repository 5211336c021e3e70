#include "io/lightmaps/bake_lightmaps.h"

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>

#include "base/errors.h"
#include "io/files/regular_file.h"
#include "io/lightmaps/lightmap_images.h"

namespace radbake {
namespace {

namespace fs = std::filesystem;

// The pages a folder holds, by index; the names of write_lightmaps().
std::map<size_t, fs::path> find_pages(const fs::path& folder) {
  static const std::regex page_name(R"((.+)_lightmap_(\d{1,6})\.exr)");
  std::map<size_t, fs::path> pages;
  std::set<std::string> names;
  std::error_code ec;
  fs::directory_iterator entries(folder, ec);
  if (ec) throw InputError("cannot read " + folder.string() + ": " + ec.message());
  for (const auto& entry : entries) {
    std::smatch m;
    const std::string file = entry.path().filename().string();
    if (!std::regex_match(file, m, page_name)) continue;
    names.insert(m[1]);
    pages[std::stoul(m[2])] = entry.path();
  }
  if (pages.empty()) throw InputError(folder.string() + " holds no lightmap pages (NAME_lightmap_N.exr)");
  if (names.size() > 1)
    throw InputError(folder.string() + " holds the lightmap pages of more than one bake (" + *names.begin() + ", " +
                     *std::next(names.begin()) + ")");
  for (size_t n = 0; n < pages.size(); ++n)
    if (!pages.count(n))
      throw InputError(folder.string() + " has no page " + std::to_string(n) + " (" + *names.begin() + "_lightmap_" +
                       std::to_string(n) + ".exr) but has page " + std::to_string(pages.rbegin()->first));
  return pages;
}

void read_quantity(const fs::path& report_path, BakeLightmaps& out) {
  nlohmann::json report =
      nlohmann::json::parse(read_regular_file(report_path.string(), "report", kMostReportBytes), nullptr, false);
  if (report.is_discarded() || !report.contains("lightmaps") || !report["lightmaps"].contains("unit") ||
      !report["lightmaps"]["unit"].is_string() || !report["lightmaps"].value("quantity", nlohmann::json()).is_string())
    throw InputError(report_path.string() + " is not a radbake report (no lightmaps.quantity and .unit)");
  out.quantity = report["lightmaps"]["quantity"];
  out.unit = report["lightmaps"]["unit"];
}

}  // namespace

BakeLightmaps read_bake_lightmaps(const std::string& path) {
  const fs::path p(path);
  std::error_code ec;
  if (!fs::exists(p, ec)) throw InputError(path + " does not exist");
  BakeLightmaps out;
  const bool is_folder = fs::is_directory(p, ec);
  const fs::path folder = is_folder ? p : p.parent_path();
  if (is_folder)
    for (const auto& [index, file] : find_pages(p)) out.files.push_back(file.string());
  else
    out.files.push_back(path);
  for (const std::string& file : out.files) out.pages.push_back(read_lightmap_exr(file));
  if (fs::is_regular_file(folder / "report.json", ec)) read_quantity(folder / "report.json", out);
  return out;
}

}  // namespace radbake
