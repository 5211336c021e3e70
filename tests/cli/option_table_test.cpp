// The option tables (cli/command_line.cpp) are the only place an option is spelled: every option
// --help lists is a row, parses, sets what it says and is echoed in report.json with the value in
// effect; and --help lists every row.
#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

#include "cli/command_line.h"
#include "support/commands.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

std::vector<std::string> words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

template <class Target>
std::set<std::string> names(const OptionTable<Target>& table) {
  std::set<std::string> out;
  for (const auto& group : table)
    for (const auto& o : group.options) out.insert(o.name);
  return out;
}

// The options `radbake --help` lists, as the binary prints them.
std::set<std::string> listed_in_help() {
  const test::Outcome help = test::radbake("--help");
  EXPECT_EQ(help.status, 0);
  std::set<std::string> out;
  std::istringstream lines(help.out);
  const std::regex option(R"(^  (?:-[a-z], )?(--[a-z0-9-]+))");
  std::smatch m;
  for (std::string line; std::getline(lines, line);)
    if (std::regex_search(line, m, option)) out.insert(m[1]);
  return out;
}

TEST(OptionTable, HelpListsEveryRowOfEveryCommandAndNothingElse) {
  std::set<std::string> rows = {"--help", "--version"};
  for (const std::set<std::string>& n : {names(bake_options()), names(uv_options()), names(diff_options()), names(view_options())})
    rows.insert(n.begin(), n.end());
  EXPECT_EQ(listed_in_help(), rows);
  EXPECT_GT(rows.size(), 100u);
}

// A value for each bake option other than its default, with what it needs beside it. A new option
// without an entry here fails BakeOptionsTest.EveryOptionHasAnExample.
std::string scene() { return test::source_path("samples/cornell_box/cornell_box.gltf"); }
std::string site() { return " --latitude 51.5 --longitude -0.1 --date 2026-12-21 --time 10:00"; }
const std::map<std::string, std::string>& bake_examples() {
  static const std::string out = " -o unused_out";
  static const std::map<std::string, std::string> examples = {
      {"--allow-external-files", out + " --allow-external-files"}, {"--max-memory", out + " --max-memory 2G"},
      {"--max-triangles", out + " --max-triangles 1000"}, {"--density", out + " --density 40"},
      {"--texels", out + " --texels 20000"}, {"--max-page-size", out + " --max-page-size 256"},
      {"--any-page-size", out + " --any-page-size"}, {"--padding", out + " --padding 3"},
      {"--fit-page", out + " --fit-page"}, {"--no-rotate", out + " --no-rotate"},
      {"--lightmap-uvs", out + " --lightmap-uvs generate"}, {"--chart-angle", out + " --chart-angle 30"},
      {"--output", " --output other_out"}, {"--quality", out + " --quality draft"},
      {"--method", out + " --method pathtrace"}, {"--samples", out + " --samples 64"},
      {"--tolerance", out + " --tolerance 0.01"}, {"--solver", out + " --solver jacobi"},
      {"--threads", out + " --threads 1"}, {"--seed", out + " --seed 7"}, {"--gather-rays", out + " --gather-rays 32"}, {"--max-rays", out + " --max-rays 1e12"},
      {"--no-near-field", out + " --no-near-field"}, {"--gather-filter", out + " --gather-filter 1"},
      {"--gather-filter-validity", out + " --gather-filter-validity 2"},
      {"--form-factors", out + " --form-factors hemicube"}, {"--patch-rays", out + " --patch-rays 512"},
      {"--hemicube-resolution", out + " --hemicube-resolution 32"}, {"--subdivide", out + " --subdivide 0.2"},
      {"--subdivide-rounds", out + " --subdivide-rounds 2"}, {"--preview-every", out + " --preview-every 10"},
      {"--area-light-rays", out + " --area-light-rays 16"}, {"--light-rays", out + " --light-rays 2"},
      {"--patch-size", out + " --patch-size 8"}, {"--emission-scale", out + " --emission-scale 683"},
      {"--glazing-transmittance", out + " --glazing-transmittance 0.8"},
      {"--glazing-model", out + " --glazing-model cie171"}, {"--no-ambient", out + " --no-ambient"},
      {"--direct-only", out + " --direct-only"}, {"--simulate-everything", out + " --simulate-everything"},
      {"--debug-dumps", out + " --debug-dumps"}, {"--quiet", out + " --quiet"},
      {"--store", out + " --store radiosity"}, {"--png-scale", out + " --png-scale 100"},
      {"--display", out + " --display vertex"}, {"--display-detail", out + " --display-detail 2"},
      {"--vertex-refine", out + " --vertex-refine 1000"}, {"--exposure", out + " --exposure 0.01"},
      {"--key", out + " --key 0.3"}, {"--color-0", out + " --color-0 light"},
      {"--directional", out + " --directional sh"}, {"--probes", out + " --probes 0.5"},
      {"--probe-rays", out + " --probe-rays 256"}, {"--sky", out + " --sky cie-overcast"},
      {"--sky-illuminance", out + " --sky-illuminance 5000"}, {"--sun-illuminance", out + " --sun-illuminance 20000"},
      {"--direct-normal", out + " --direct-normal 600"}, {"--diffuse-horizontal", out + " --diffuse-horizontal 100"},
      {"--dew-point", out + " --dew-point 5"}, {"--latitude", out + site()},
      {"--longitude", out + site()}, {"--date", out + site()}, {"--time", out + site()},
      {"--utc-offset", out + site() + " --utc-offset 1"}, {"--elevation", out + site() + " --elevation 300"},
      {"--pressure", out + site() + " --pressure 950"}, {"--temperature", out + site() + " --temperature 5"},
      {"--sun-position", out + " --sun-position 30,180"}, {"--north", out + " --north 90"},
      {"--ground-reflectance", out + " --ground-reflectance 0.3"}, {"--sky-rays", out + " --sky-rays 64"},
      {"--sun-rays", out + " --sun-rays 8"}, {"--work-plane", out + " --work-plane"},
      {"--work-plane-height", out + " --work-plane-height 0.5"}, {"--work-plane-spacing", out + " --work-plane-spacing 1"},
      {"--work-plane-over", out + " --work-plane-over floor"}, {"--work-plane-outdoors", out + " --work-plane --work-plane-outdoors"}, {"--sensors", out + " --sensors points.csv"},
      {"--sensor-rays", out + " --sensor-rays 64"}, {"--sensor-sky-rays", out + " --sensor-sky-rays 64"},
      {"--daylight-factor", out + " --daylight-factor"},
      {"--false-colour", out + " --false-colour log"}, {"--false-colour-max", out + " --false-colour-max 500"},
      {"--view", out + " --view 1,1,1:0,0,1"}, {"--view-size", out + " --view-size 64"},
      {"--weather", out + " --weather year.epw --work-plane"}, {"--occupied", out + " --occupied 9-17"},
      {"--da-threshold", out + " --da-threshold 500"}, {"--sky-subdivision", out + " --sky-subdivision 2"},
      {"--checkpoint", out + " --checkpoint ckpt"}, {"--resume", out + " --checkpoint ckpt --resume"},
      {"--checkpoint-every", out + " --checkpoint-every 5"}, {"--stop-after", " --checkpoint ckpt --stop-after radiosity"},
      {"--pages", " --checkpoint ckpt --pages 1/2"}, {"--texel-range", " --checkpoint ckpt --texel-range 1/2"},
  };
  return examples;
}

std::map<std::string, std::string> echo_of(const std::string& args) {
  std::vector<std::string> argv = {"bake", scene()};
  for (const std::string& w : words(args)) argv.push_back(w);
  const CommandLine cl = parse_command_line(argv);
  EXPECT_EQ(cl.bake.effective.size(), names(bake_options()).size()) << "every row is echoed";
  return {cl.bake.effective.begin(), cl.bake.effective.end()};
}

TEST(OptionTable, EveryBakeOptionHasAnExample) {
  std::set<std::string> with_example;
  for (const auto& [name, args] : bake_examples()) with_example.insert(name);
  EXPECT_EQ(with_example, names(bake_options()));
}

// Each option, given a value other than its default, parses and is echoed under its own name with
// a value other than the default's: the row sets the command and the echo reads it back.
TEST(OptionTable, EveryBakeOptionParsesAndIsEchoedWithTheValueInEffect) {
  const std::map<std::string, std::string> defaults = echo_of(" -o unused_out");
  for (const auto& [name, args] : bake_examples()) {
    SCOPED_TRACE(name + ":" + args);
    std::map<std::string, std::string> given;
    ASSERT_NO_THROW(given = echo_of(args));
    const std::string key = name.substr(2);
    ASSERT_TRUE(given.count(key));
    EXPECT_NE(given[key], defaults.at(key));
  }
  // Units as the help says: a percentage is a fraction inside, the presets' values in effect.
  EXPECT_EQ(echo_of(" -o x --quality draft")["gather-rays"], "32");
  EXPECT_EQ(echo_of(" -o x --quality draft --gather-rays 99")["gather-rays"], "99");  // given beats the preset
  EXPECT_EQ(echo_of(" -o x --gather-rays 99 --quality draft")["gather-rays"], "99");  // wherever it stands
}

TEST(OptionTable, UvDiffAndViewOptionsParse) {
  const std::string s = scene();
  for (const std::string& args : {"uv " + s + " --stats --json --evaluate-texcoord 0 --density 40 --max-memory 1G"}) {
    CommandLine cl;
    ASSERT_NO_THROW(cl = parse_command_line(words(args))) << args;
    EXPECT_TRUE(cl.uv.json);
    EXPECT_EQ(cl.uv.evaluate_texcoord, 0);
    EXPECT_FLOAT_EQ(cl.uv.atlas.texel_density, 40);
  }
  const CommandLine diff = parse_command_line(words(
      "diff a b --json --max-rmse 3 --max-p50 1 --max-p95 2 --max-p99 4 --max-error 5 --relative-floor 20 "
      "--diff-images d --image-scale 5"));
  EXPECT_TRUE(diff.diff.json);
  EXPECT_DOUBLE_EQ(*diff.diff.limits.rmse, 0.03);  // percent given, fraction held
  EXPECT_DOUBLE_EQ(*diff.diff.limits.p99, 0.04);
  EXPECT_DOUBLE_EQ(*diff.diff.limits.max_error, 5);
  EXPECT_DOUBLE_EQ(diff.diff.difference.relative_floor, 0.2);
  EXPECT_EQ(diff.diff.image_folder, "d");
  const CommandLine view = parse_command_line(words("view a --port 8123 --no-open"));
  EXPECT_EQ(view.view.port, 8123);
  EXPECT_FALSE(view.view.open);
}

TEST(OptionTable, AFlagGivenAValueIsRefusedNamingIt) {
  std::string message = "(parsed)";
  try {
    parse_command_line({"bake", scene(), "-o", "x", "--quiet=yes"});
  } catch (const UsageError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("option --quiet takes no value, got 'yes'"), std::string::npos) << message;
}

// What report.json lists is what the table echoes, for a real bake.
TEST(OptionTable, ReportJsonListsEveryOptionAsTheTableEchoesIt) {
  const std::string folder = test::fresh_folder("option_table_report");
  const std::string args = " -o " + folder + "/out --max-page-size 64 --quality draft --no-ambient --seed 3 --sky uniform";
  ASSERT_EQ(test::radbake("bake " + scene() + args + " --quiet").status, 0);
  const nlohmann::json report = nlohmann::json::parse(test::slurp(folder + "/out/report.json"));
  std::map<std::string, std::string> listed;
  for (const auto& [key, value] : report["options"].items()) listed[key] = value.get<std::string>();
  EXPECT_EQ(listed, echo_of(args + " --quiet"));
  EXPECT_EQ(listed["no-ambient"], "yes");
  EXPECT_EQ(listed["sky"], "uniform");
}

}  // namespace
}  // namespace radbake
