// Options that were once accepted and then ran for ever with nothing said. Each stage
// that scales with an option is now estimated before a ray is cast and refused past --max-rays
// (default 10^10, about an hour on 2 cores) in one line naming the option; sensors far outside the
// scene are counted in a warning. Every refusal here comes before the bake starts, so each command
// runs under `timeout 120` and a stage that ran instead fails the test (status 124).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/commands.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

const std::string kCornell = "samples/cornell_box/cornell_box.gltf";

test::Outcome bake(const std::string& out, const std::string& options) {
  return test::run("timeout 120 " + std::string(RADBAKE_BINARY) + " bake " + test::source_path(kCornell) + " -o " + out +
                   " --quiet " + options);
}

// `count` sensors in a row from (x, y, z), 1 cm apart, facing up.
std::string sensor_file(const std::string& path, size_t count, double x, double y, double z) {
  std::ofstream out(path);
  out << "x,y,z,nx,ny,nz\n";
  char row[128];
  for (size_t k = 0; k < count; ++k) {
    std::snprintf(row, sizeof row, "%.3f,%.3f,%.3f,0,1,0\n", x + 0.01 * double(k % 1000), y, z + 0.01 * double(k / 1000));
    out << row;
  }
  return path;
}

struct Reproducer {
  std::string name, options, says;
};

class RayBudget : public ::testing::TestWithParam<Reproducer> {};

TEST_P(RayBudget, RefusesWhatWouldRunForEverBeforeARayIsCast) {
  const std::string folder = test::fresh_folder("ray_budget_" + GetParam().name);
  std::string options = GetParam().options;
  const size_t at = options.find("SENSORS");
  if (at != std::string::npos) options.replace(at, 7, sensor_file(folder + "/sensors.csv", 100000, 0.1, 0.5, 0.1));
  const test::Outcome r = bake(folder + "/out", options);
  ASSERT_NE(r.status, 124) << "the stage ran";
  test::expect_one_line_refusal(r, GetParam().says, folder + "/out");
  EXPECT_NE(r.err.find("raise --max-rays"), std::string::npos) << r.err;
}

INSTANTIATE_TEST_SUITE_P(
    Options, RayBudget,
    ::testing::Values(
        // Estimated 7.2e10: 1,374 patches x 3 x 4096^2 pixels.
        Reproducer{"hemicube_4096", "--form-factors hemicube --hemicube-resolution 4096",
                   "the form factors would cast about 7.15e+10 rays (--hemicube-resolution), more than --max-rays 1e+10"},
        // 65,536 probes (the grid's cap) x 1,000,512 rays.
        Reproducer{"probe_rays", "--probes 0.01 --probe-rays 1000000",
                   "the light probes would cast about 6.56e+10 rays (--probes and --probe-rays)"},
        // 65,536 probes x 4,608 rays: 3e8, 2 minutes measured: within the default, refused below it.
        Reproducer{"probe_spacing", "--probes 0.001 --max-rays 1e8",
                   "the light probes would cast about 3.02e+08 rays (--probes and --probe-rays), more than --max-rays 1e+08"},
        // 100,000 sensors x (4,096 + 16,384) rays under a sky.
        Reproducer{"sensors", "--sky uniform --sensors SENSORS --max-rays 1e9",
                   "the 100000 sensors would cast about 2.05e+09 rays (--sensors, --sensor-rays and --sensor-sky-rays)"},
        Reproducer{"samples", "--method pathtrace --samples 16000000",
                   "the path tracing would cast about 2.91e+12 rays (--samples)"}),
    [](const auto& info) { return info.param.name; });

// The defaults stay well inside the budget: the Cornell box bakes as before.
TEST(RayBudget, TheDefaultsBakeUnrefused) {
  const std::string folder = test::fresh_folder("ray_budget_defaults");
  const test::Outcome r = bake(folder + "/out", "--max-page-size 256");
  EXPECT_EQ(r.status, 0) << r.err;
}

// A thousand sensors a kilometre from the Cornell box: baked, and said, with their count.
TEST(RayBudget, SensorsFarOutsideTheSceneAreCountedInAWarning) {
  const std::string folder = test::fresh_folder("ray_budget_outside");
  const std::string sensors = sensor_file(folder + "/far.csv", 1000, 1000.0, 0.5, 0.0);
  std::ofstream(sensors, std::ios::app) << "0.2,0.5,0.2,0,1,0\n";  // and one inside
  const test::Outcome r = test::run("timeout 120 " + std::string(RADBAKE_BINARY) + " bake " + test::source_path(kCornell) +
                                    " -o " + folder + "/out --max-page-size 64 --sensors " + sensors);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("radbake: warning: 1000 of the 1001 sensors lie outside the scene's bounds"), std::string::npos)
      << r.err;
  const nlohmann::json report = nlohmann::json::parse(test::slurp(folder + "/out/report.json"));
  bool reported = false;
  for (const auto& w : report["warnings"]) reported |= w.get<std::string>().find("1000 of the 1001 sensors") != std::string::npos;
  EXPECT_TRUE(reported);
}

// A weather file whose every hour carries the same bright midsummer noon: the year's hours stage
// (each daylit hour's sun rays at each sensor) is estimated and refused past --max-rays.
TEST(RayBudget, AYearOfCopiesOfOneHourIsEstimatedByItsDaylitHours) {
  const std::string folder = test::fresh_folder("ray_budget_year");
  std::ifstream in(test::source_path("samples/weather/london_synthetic.epw"));
  std::ofstream out(folder + "/noon.epw");
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 8 + 8760u);
  // The data fields of 21 June, 12:00 (hour 4092 of the year), under every hour's date and time.
  const std::string noon = lines[8 + 24 * 171 + 11];
  size_t fifth = 0;
  for (int k = 0; k < 5; ++k) fifth = noon.find(',', fifth) + 1;
  for (size_t k = 0; k < lines.size(); ++k) {
    if (k < 8) {
      out << lines[k] << "\n";
      continue;
    }
    size_t cut = 0;
    for (int f = 0; f < 5; ++f) cut = lines[k].find(',', cut) + 1;
    out << lines[k].substr(0, cut) << noon.substr(fifth) << "\n";
  }
  out.close();
  const std::string sensors = sensor_file(folder + "/sensors.csv", 1000, 0.1, 0.5, 0.1);
  const test::Outcome r = test::run("timeout 120 " + std::string(RADBAKE_BINARY) + " bake " +
                                    test::source_path("samples/classroom/classroom.gltf") + " -o " + folder +
                                    "/out --quiet --weather " + folder + "/noon.epw --sensors " + sensors +
                                    " --max-rays 5e7");
  ASSERT_NE(r.status, 124) << "the year ran";
  // 1,000 sensors' own rays (2e7) fit; their hours do not.
  test::expect_one_line_refusal(r, "daylit hours at 1000 sensors would cast about", folder + "/out");
  EXPECT_NE(r.err.find("(--weather and --sensors)"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace radbake
