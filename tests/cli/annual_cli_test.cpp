// A year of daylight from the command line: `radbake bake --weather` on the classroom
// writes the hourly series, each sensor's metrics and a report that agree with each other.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/commands.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

const std::string kClassroom = "samples/classroom/classroom.gltf", kLondon = "samples/weather/london_synthetic.epw";

TEST(AnnualCli, AYearAtThreeSensorsWritesTheSeriesTheMetricsAndTheReport) {
  const std::string folder = test::fresh_folder("annual_cli");
  // On the middle window's axis: 1 m from the glass, mid-room, 1 m from the back wall.
  const std::string sensors = test::write_text_file("annual_sensors_in.csv", "4.5,0.8,6.0\n4.5,0.8,3.5\n4.5,0.8,1.0\n");
  const test::Outcome r = test::radbake("bake " + test::source_path(kClassroom) + " -o " + folder + "/out --weather " +
                                        test::source_path(kLondon) + " --sensors " + sensors +
                                        " --view 4.5,1.2,3.5:0,0,1 --quiet --texels 8000 --sky-rays 64 --sun-rays 8"
                                        " --sensor-rays 256");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("sDA300/50%"), std::string::npos) << r.out;

  const std::string series = test::slurp(folder + "/out/annual_illuminance.f32");
  ASSERT_EQ(series.size(), 8760u * 3 * sizeof(float));
  auto lux = [&](size_t hour, size_t sensor) {
    float v;
    std::memcpy(&v, series.data() + (hour * 3 + sensor) * sizeof(float), sizeof v);
    return v;
  };
  for (size_t s = 0; s < 3; ++s) EXPECT_EQ(lux(0, s), 0.0f) << "midnight, 1 January";
  const size_t noon_july_3 = (31 + 28 + 31 + 30 + 31 + 30 + 2) * 24 + 11;
  EXPECT_GT(lux(noon_july_3, 2), 50.0f);
  EXPECT_GT(lux(noon_july_3, 0), lux(noon_july_3, 1));  // nearer the window, more light
  EXPECT_GT(lux(noon_july_3, 1), lux(noon_july_3, 2));

  // Each sensor's metrics, and the report's spatial ones made from them.
  std::istringstream csv(test::slurp(folder + "/out/annual_sensors.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line.rfind("x,y,z,nx,ny,nz,daylight_autonomy_percent,", 0), 0u) << line;
  size_t rows = 0, autonomous = 0, sunny = 0;
  std::vector<double> da;
  while (std::getline(csv, line)) {
    std::vector<double> f;
    std::stringstream fields(line);
    for (std::string x; std::getline(fields, x, ',');) f.push_back(std::stod(x));
    ASSERT_EQ(f.size(), 13u) << line;
    ++rows;
    da.push_back(f[6]);
    autonomous += f[6] >= 50;
    sunny += f[12] > 250;
    EXPECT_NEAR(f[7] + f[8] + f[9] + f[10], 100, 0.05) << "the UDI bins cover every hour; 0.05 bounds the printed rounding";
  }
  ASSERT_EQ(rows, 3u);
  EXPECT_GT(da[0], da[2]) << "daylight autonomy falls away from the window";
  const nlohmann::json report = nlohmann::json::parse(test::slurp(folder + "/out/report.json"));
  EXPECT_EQ(report["weather"]["hours"], 8760);
  EXPECT_EQ(report["series"]["sensors"], 3);
  EXPECT_EQ(report["metrics"]["occupied_hours"], 3650);
  EXPECT_NEAR(report["metrics"]["sDA_percent"].get<double>(), 100.0 * double(autonomous) / 3, 1e-9);
  EXPECT_NEAR(report["metrics"]["ASE_percent"].get<double>(), 100.0 * double(sunny) / 3, 1e-9);

  // Every texel's year, as lightmap pages.
  for (const char* file : {"/out/classroom_daylight_autonomy_0.png", "/out/classroom_udi_0.png", "/out/classroom_mean_lux_0.exr"})
    EXPECT_FALSE(test::slurp(folder + file).empty()) << file;

  // The eye mid-room facing the south windows: its hourly DGP, and how often it glares.
  EXPECT_EQ(test::slurp(folder + "/out/annual_dgp.f32").size(), 8760u * sizeof(float));
  ASSERT_EQ(report["views"].size(), 1u);
  const nlohmann::json& eye = report["views"][0];
  EXPECT_GT(eye["occupied_daylit_hours"].get<double>(), 3000);
  EXPECT_GT(eye["mean_dgp"].get<double>(), 0.16);  // the formula's floor
  EXPECT_GT(eye["share_dgp_045_or_more"].get<double>(), 0.0) << "a low sun in the south windows some mornings";
  EXPECT_LE(eye["share_dgp_045_or_more"].get<double>(), eye["share_dgp_035_or_more"].get<double>());
  EXPECT_LE(eye["share_dgp_035_or_more"].get<double>(), 1.0);

  // The design variant without the overhang, at the same sensors, compared metric by metric.
  const test::Outcome variant = test::radbake(
      "bake " + test::source_path("samples/classroom/classroom_no_overhang.gltf") + " -o " + folder + "/variant --weather " +
      test::source_path(kLondon) + " --sensors " + sensors + " --view 4.5,1.2,3.5:0,0,1 --quiet --texels 8000"
      " --sky-rays 64 --sun-rays 8 --sensor-rays 256");
  ASSERT_EQ(variant.status, 0) << variant.err;
  const test::Outcome diff = test::radbake("diff " + folder + "/out " + folder + "/variant --json --diff-images " + folder + "/maps");
  ASSERT_EQ(diff.status, 0) << diff.err;
  const nlohmann::json d = nlohmann::json::parse(diff.out);
  std::map<std::string, nlohmann::json> by_name;
  for (const nlohmann::json& m : d["metrics"]) by_name[m["metric"]] = m;
  for (const char* metric : {"sDA_percent", "ASE_percent", "mean_daylight_autonomy_percent", "mean_udi_useful_percent",
                             "view_0_mean_dgp", "view_0_share_dgp_045_or_more"})
    ASSERT_TRUE(by_name.count(metric)) << metric << " " << diff.out;
  const nlohmann::json& ase = by_name["ASE_percent"];
  EXPECT_NEAR(ase["a"].get<double>(), report["metrics"]["ASE_percent"].get<double>(), 1e-9);
  EXPECT_NEAR(ase["b_minus_a"].get<double>(), ase["b"].get<double>() - ase["a"].get<double>(), 1e-9);
  // Without the overhang more sun and sky reach the room: autonomy and glare cannot fall.
  EXPECT_GE(by_name["mean_daylight_autonomy_percent"]["b_minus_a"].get<double>(), 0.0);
  EXPECT_GE(by_name["view_0_mean_dgp"]["b_minus_a"].get<double>(), 0.0);
  EXPECT_FALSE(test::slurp(folder + "/maps/daylight_autonomy_change.png").empty());
}

TEST(AnnualCli, WhatAYearCannotBeRunWithIsOneLine) {
  const std::string folder = test::fresh_folder("annual_cli_refusals"), out = folder + "/out";
  const std::string scene = test::source_path(kClassroom), weather = " --weather " + test::source_path(kLondon);
  test::expect_one_line_refusal(test::radbake("bake " + scene + " -o " + out + weather),
                                "--weather needs --sensors, --work-plane or --view", out);
  test::expect_one_line_refusal(test::radbake("bake " + scene + " -o " + out + weather + " --work-plane --sky cie-overcast"),
                                "leave out --sky", out);
  test::expect_one_line_refusal(test::radbake("bake " + scene + " -o " + out + weather + " --work-plane --latitude 40"),
                                "--weather gives the site", out);
  test::expect_one_line_refusal(test::radbake("bake " + scene + " -o " + out + weather + " --work-plane --occupied 18-8"),
                                "--occupied must end after it starts", out);
  test::expect_one_line_refusal(test::radbake("bake " + scene + " -o " + out + " --work-plane --weather " + folder + "/none.epw"),
                                "weather file '" + folder + "/none.epw' cannot be opened", out);
}

TEST(AnnualCli, DiffRefusesYearsItCannotCompareWithOneLine) {
  // Hand-written year folders: one without its sensors' file, two measured at different sensors,
  // and a year against a plain bake folder.
  const std::string root = test::fresh_folder("annual_diff_refusals");
  auto year = [&](const std::string& name, const std::string& csv) {
    std::filesystem::create_directories(root + "/" + name);
    std::ofstream(root + "/" + name + "/report.json") << R"({"series": {}, "metrics": {"sDA_percent": 50}})";
    if (!csv.empty()) std::ofstream(root + "/" + name + "/annual_sensors.csv") << "x,y,z,nx,ny,nz,da\n" << csv;
    return root + "/" + name;
  };
  const std::string bare = year("bare", ""), one = year("one", "1,0.8,1,0,1,0,50\n"),
                    two = year("two", "1,0.8,1,0,1,0,50\n2,0.8,1,0,1,0,60\n");
  std::filesystem::create_directories(root + "/bake");
  std::ofstream(root + "/bake/report.json") << R"({"lightmaps": {}})";
  const struct {
    std::string a, b, says;
  } cases[] = {{one, bare, "annual_sensors.csv' cannot be opened"},
               {one, two, "were measured at different sensors (1 and 2)"},
               {one, root + "/bake", "is a year of daylight and the other a bake"}};
  for (const auto& c : cases)
    test::expect_one_line_refusal(test::radbake("diff " + c.a + " " + c.b + " --diff-images " + root + "/maps"), c.says,
                                  root + "/maps");
}

}  // namespace
}  // namespace radbake
