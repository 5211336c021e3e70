#include "cli/diff_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "base/errors.h"
#include "io/analysis/annual_comparison.h"
#include "io/analysis/false_colour.h"
#include "io/lightmaps/bake_lightmaps.h"
#include "io/lightmaps/lightmap_images.h"

namespace radbake {
namespace {

namespace fs = std::filesystem;

// Beside the candidate's page name, so a folder of them reads like the bake it judges.
std::vector<std::string> write_difference_images(const LightmapDifference& d, const BakeLightmaps& candidate,
                                                 const std::string& folder) {
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) throw InputError("cannot create " + folder + ": " + ec.message());
  std::vector<std::string> paths;
  for (size_t p = 0; p < d.pages.size(); ++p) {
    const PageDifference& page = d.pages[p];
    paths.push_back((fs::path(folder) / (fs::path(candidate.files[p]).stem().string() + "_diff.png")).string());
    write_png(paths.back(), page.width, page.height, page.image);
  }
  return paths;
}

// A check's value or limit as printed: percent for fractions, else in the bake's unit.
std::string shown(const LimitCheck& c, double v, const std::string& unit) {
  char text[64];
  if (c.fraction) std::snprintf(text, sizeof text, "%.4g%%", 100 * v);
  else std::snprintf(text, sizeof text, "%.4g %s", v, unit.c_str());
  return text;
}

nlohmann::ordered_json stats_json(const DifferenceStats& s) {
  return {{"texels", s.texels},           {"reference_level", s.reference_level}, {"rmse_percent", 100 * s.rmse},
          {"max_error", s.max_error},     {"p50_percent", 100 * s.p50},          {"p95_percent", 100 * s.p95},
          {"p99_percent", 100 * s.p99}};
}

void print_json(const DiffCommand& cmd, const BakeLightmaps& a, const LightmapDifference& d,
                const std::vector<std::string>& images, const std::vector<LimitCheck>& checks, bool passed) {
  nlohmann::ordered_json pages = nlohmann::ordered_json::array();
  for (size_t p = 0; p < d.pages.size(); ++p) {
    nlohmann::ordered_json page = {{"page", p}, {"width", d.pages[p].width}, {"height", d.pages[p].height}};
    page.update(stats_json(d.pages[p].stats));
    if (!images.empty()) page["diff_image"] = images[p];
    pages.push_back(page);
  }
  nlohmann::ordered_json limits = nlohmann::ordered_json::array();
  for (const LimitCheck& c : checks)
    limits.push_back({{"name", c.name}, {"value", c.fraction ? 100 * c.value : c.value},
                      {"limit", c.fraction ? 100 * c.limit : c.limit}, {"unit", c.fraction ? "%" : a.unit},
                      {"exceeded", c.exceeded}});
  nlohmann::ordered_json j = {{"reference", cmd.reference},
                              {"candidate", cmd.candidate},
                              {"quantity", a.quantity},
                              {"unit", a.unit},
                              {"relative_floor_percent", 100 * cmd.difference.relative_floor},
                              {"image_scale_percent", 100 * cmd.difference.image_scale},
                              {"pages", pages},
                              {"all", stats_json(d.all)},
                              {"checks", limits},
                              {"passed", passed}};
  std::printf("%s\n", j.dump(1).c_str());
}

void print_row(const char* page, const std::string& size, const DifferenceStats& s, const std::string& unit) {
  std::printf("  %-5s %-11s %8zu %7.2f%% %10.4g %-5s %7.2f%% %7.2f%% %7.2f%%\n", page, size.c_str(), s.texels,
              100 * s.rmse, s.max_error, unit.c_str(), 100 * s.p50, 100 * s.p95, 100 * s.p99);
}

void print_text(const DiffCommand& cmd, const BakeLightmaps& a, const LightmapDifference& d,
                const std::vector<std::string>& images, const std::vector<LimitCheck>& checks) {
  std::printf("radbake diff: %s against %s (reference), %s in %s\n", cmd.candidate.c_str(), cmd.reference.c_str(),
              a.quantity.c_str(), a.unit.c_str());
  std::printf("  %-5s %-11s %8s %8s %16s %8s %8s %8s\n", "page", "size", "texels", "rmse", "max error", "p50", "p95",
              "p99");
  for (size_t p = 0; p < d.pages.size(); ++p)
    print_row(std::to_string(p).c_str(), std::to_string(d.pages[p].width) + "x" + std::to_string(d.pages[p].height),
              d.pages[p].stats, a.unit);
  if (d.pages.size() > 1) print_row("all", "", d.all, a.unit);
  std::printf("  reference level %.4g %s (mean of A); relative errors against at least %.4g %s (%g%% of it)\n",
              d.all.reference_level, a.unit.c_str(), cmd.difference.relative_floor * d.all.reference_level,
              a.unit.c_str(), 100 * cmd.difference.relative_floor);
  for (const std::string& image : images) std::printf("  wrote %s\n", image.c_str());
  if (!images.empty())
    std::printf("  (white: equal; red: B brighter, blue: B darker, full colour at %g%% of the texel; black: not "
                "compared)\n", 100 * cmd.difference.image_scale);
  for (const LimitCheck& c : checks)
    std::printf("  %-5s %s, limit %s: %s\n", c.name.c_str(), shown(c, c.value, a.unit).c_str(),
                shown(c, c.limit, a.unit).c_str(), c.exceeded ? "EXCEEDED" : "ok");
}

// Two years of daylight (radbake bake --weather folders): their metrics side by side and, with
// --diff-images, where daylight autonomy moved.
int run_annual_diff(const DiffCommand& cmd) {
  const DifferenceLimits& l = cmd.limits;
  if (l.rmse || l.p50 || l.p95 || l.p99 || l.max_error)
    throw InputError("--max-rmse, --max-p50/p95/p99 and --max-error compare lightmaps; " + cmd.reference + " and " +
                     cmd.candidate + " are years of daylight");
  const AnnualFolder a = read_annual_folder(cmd.reference), b = read_annual_folder(cmd.candidate);
  const std::vector<double> change = daylight_autonomy_change(a, b);
  // Full colour at the largest change, rounded up as the legends' scales are (at least 1 point).
  double largest = 0;
  for (double c : change) largest = std::max(largest, std::fabs(c));
  const double full_colour = nice_number_at_or_above(std::max(1.0, largest));
  std::vector<std::string> images;
  if (!cmd.image_folder.empty()) {
    std::filesystem::create_directories(cmd.image_folder);
    images.push_back(cmd.image_folder + "/daylight_autonomy_change.png");
    write_daylight_autonomy_change_map(images.back(), a, change, full_colour);
  }
  std::map<std::string, double> theirs(b.metrics.begin(), b.metrics.end());
  if (cmd.json) {
    nlohmann::ordered_json metrics = nlohmann::ordered_json::array();
    for (const auto& [name, value] : a.metrics)
      if (theirs.count(name)) metrics.push_back({{"metric", name}, {"a", value}, {"b", theirs[name]}, {"b_minus_a", theirs[name] - value}});
    nlohmann::ordered_json j = {{"reference", cmd.reference}, {"candidate", cmd.candidate}, {"metrics", metrics},
                                {"sensors", change.size()}, {"images", images}, {"full_colour_points", full_colour}};
    std::printf("%s\n", j.dump(1).c_str());
    return 0;
  }
  std::printf("radbake diff: a year of daylight, %s (B) against %s (A)\n", cmd.candidate.c_str(), cmd.reference.c_str());
  std::printf("  %-40s %10s %10s %10s\n", "metric", "A", "B", "B - A");
  for (const auto& [name, value] : a.metrics)
    if (theirs.count(name)) std::printf("  %-40s %10.3f %10.3f %+10.3f\n", name.c_str(), value, theirs[name], theirs[name] - value);
  double most = 0, least = 0;
  for (double c : change) most = std::max(most, c), least = std::min(least, c);
  std::printf("  daylight autonomy per sensor: %zu sensors, from %+.1f to %+.1f points\n", change.size(), least, most);
  for (const std::string& image : images)
    std::printf("  wrote %s (white: unchanged; red: B more, blue: B less, full colour at %g points)\n", image.c_str(), full_colour);
  return 0;
}

}  // namespace

int run_diff(const DiffCommand& cmd) {
  const bool a_annual = is_annual_folder(cmd.reference), b_annual = is_annual_folder(cmd.candidate);
  if (a_annual && b_annual) return run_annual_diff(cmd);
  if (a_annual || b_annual)
    throw InputError("one of " + cmd.reference + " and " + cmd.candidate + " is a year of daylight and the other a bake");
  const BakeLightmaps a = read_bake_lightmaps(cmd.reference), b = read_bake_lightmaps(cmd.candidate);
  if (a.quantity != b.quantity || a.unit != b.unit)
    throw InputError(cmd.reference + " holds " + a.quantity + " (" + a.unit + ") but " + cmd.candidate + " holds " +
                     b.quantity + " (" + b.unit + ")");
  const LightmapDifference d = compare_lightmaps(a.pages, b.pages, cmd.difference);
  const std::vector<std::string> images =
      cmd.image_folder.empty() ? std::vector<std::string>{} : write_difference_images(d, b, cmd.image_folder);
  const std::vector<LimitCheck> checks = check_limits(d.all, cmd.limits);
  bool passed = true;
  for (const LimitCheck& c : checks) passed = passed && !c.exceeded;
  if (cmd.json) print_json(cmd, a, d, images, checks, passed);
  else print_text(cmd, a, d, images, checks);
  for (const LimitCheck& c : checks)
    if (c.exceeded)
      std::fprintf(stderr, "radbake: diff: %s %s exceeds --max-%s %s\n", c.name.c_str(),
                   shown(c, c.value, a.unit).c_str(), c.name.c_str(), shown(c, c.limit, a.unit).c_str());
  return passed ? 0 : 1;
}

}  // namespace radbake
