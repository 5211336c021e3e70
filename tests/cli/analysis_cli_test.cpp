// The analysis files from the command line: sensors from a CSV and on a work plane,
// their readings as CSV and heat maps, daylight factors, false-colour pages, and the statistics in
// report.json.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/closed_forms.h"
#include "support/commands.h"
#include "support/images.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

namespace fs = std::filesystem;

std::string fixture(const std::string& name) { return test::source_path("tests/fixtures/" + name); }

std::vector<std::vector<double>> csv_rows(const std::string& path) {
  std::stringstream in(test::slurp(path));
  std::string line;
  std::getline(in, line);  // the header
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

int png_width(const std::string& path) {
  int width = -1;
  test::read_png_rgb(path, &width);
  return width;
}

TEST(AnalysisCli, AWorkPlaneUnderAnOvercastSkyGivesLuxDaylightFactorsAndTheirImages) {
  const std::string out = test::fresh_folder("analysis_cli_work_plane") + "/out";
  const test::Outcome r = test::radbake("bake " + fixture("open_floor.gltf") + " -o " + out +
                                        " --sky cie-overcast --sky-illuminance 8000 --work-plane --work-plane-outdoors"
                                        " --work-plane-spacing 1 --daylight-factor --false-colour log");
  ASSERT_EQ(r.status, 0) << r.err;
  // The open 4 m floor (measured as asked, though open to the sky): a 4 x 4 grid, each point facing the whole sky and nothing else (the floor
  // is below it): 8,000 lx, a daylight factor of 100%.
  const std::vector<std::vector<double>> rows = csv_rows(out + "/sensors.csv");
  ASSERT_EQ(rows.size(), 16u);
  for (const std::vector<double>& row : rows) {
    ASSERT_EQ(row.size(), 10u);  // position, normal, lux, daylight factor, their standard errors
    EXPECT_NEAR(row[1], 0.8, 1e-4);  // over the floor at y = 0
    // 0.1% bounds the sky rays' noise at a point (16,384 stratified rays over a 3:1 sky), and what
    // each point states of it.
    EXPECT_NEAR(row[6], 8000, 8);
    EXPECT_NEAR(row[7], 100 * row[6] / 8000, 1e-3);
    EXPECT_GT(row[8], 0);
    EXPECT_LT(row[8], 8);
    EXPECT_NEAR(row[9], 100 * row[8] / 8000, 1e-4);
  }
  const nlohmann::json report = nlohmann::json::parse(test::slurp(out + "/report.json"));
  EXPECT_EQ(report["work_plane"]["points"], 16);
  EXPECT_NEAR(double(report["work_plane"]["mean_lx"]), 8000, 8);
  EXPECT_GT(double(report["work_plane"]["uniformity_min_over_mean"]), 0.99);
  EXPECT_NEAR(double(report["work_plane"]["daylight_factor_percent"]["mean"]), 100, 0.1);
  ASSERT_EQ(report["surfaces"].size(), 1u);
  EXPECT_NEAR(double(report["surfaces"][0]["area_m2"]), 16, 1e-3);
  EXPECT_NEAR(double(report["surfaces"][0]["mean_lx"]), 8000, 8);
  // The images, each with its legend beside the data.
  for (const char* image : {"work_plane.png", "work_plane_daylight_factor.png", "open_floor_false_colour_0.png",
                            "open_floor_daylight_factor_0.png"})
    EXPECT_TRUE(fs::exists(out + "/" + image)) << image;
  EXPECT_GT(png_width(out + "/open_floor_false_colour_0.png"), int(report["atlas"]["pages"][0]["width"]));
  EXPECT_NE(r.err.find("radbake: work plane: 16 points, min"), std::string::npos) << r.err;
  for (const char* listed : {"sensors.csv", "work_plane.png"})
    EXPECT_NE(std::find(report["files"].begin(), report["files"].end(), listed), report["files"].end()) << listed;
}

// A daylight factor is the overcast sky's light alone: the Cornell box's lamp (an emitting
// surface) is left out, and said so. Light adds up, so the work plane under the sky and the lamp
// reads what the daylight-factor run (sky alone) and a lamp-only run read together.
TEST(AnalysisCli, TheDaylightFactorLeavesTheScenesOwnLightsOut) {
  const std::string folder = test::fresh_folder("analysis_cli_daylight_factor_lights");
  auto mean_lux = [&](const std::string& name, const std::string& args, std::string* err = nullptr) {
    const test::Outcome r = test::radbake("bake " + test::source_path("samples/cornell_box/cornell_box.gltf") + " -o " +
                                          folder + "/" + name + " --work-plane --work-plane-height 0.2"
                                          " --work-plane-spacing 0.1 --gather-rays 8 " + args);
    EXPECT_EQ(r.status, 0) << r.err;
    if (err) *err = r.err;
    return double(nlohmann::json::parse(test::slurp(folder + "/" + name + "/report.json"))["work_plane"]["mean_lx"]);
  };
  std::string said;
  const double sky = mean_lux("sky", "--sky cie-overcast --daylight-factor", &said);
  EXPECT_NE(said.find("--daylight-factor: the scene's 0 lights and 1 emitting material are left out"), std::string::npos) << said;
  const double lamp = mean_lux("lamp", ""), both = mean_lux("both", "--sky cie-overcast");
  // Measured 1,134 + 1,237 lx; 3% bounds the three bakes' gather noise at 8 rays per texel.
  EXPECT_NEAR(sky + lamp, both, 0.03 * both);
  EXPECT_GT(lamp, 0.5 * sky);  // the lamp is no small part: leaving it in would show
}

// A byte-order mark, comments and one header before the first point are skipped (a
// comment before the header was refused).
TEST(AnalysisCli, SensorsFromACsvFileFaceTheWayTheyAreTold) {
  const std::string csv = test::write_text_file("analysis_sensors.csv",
                                                "\xEF\xBB\xBF# measured points, spreadsheet export\n"
                                                "x,y,z,nx,ny,nz\n"
                                                "# over the middle, facing up\n"
                                                "2,1,2\n"
                                                "\n"
                                                "2,1,2,0,-2,0\n");
  const std::string out = test::fresh_folder("analysis_cli_csv") + "/out";
  const test::Outcome r = test::radbake("bake " + fixture("open_floor.gltf") + " -o " + out + " --quiet --sensors " +
                                        csv + " --sky uniform --sky-illuminance 10000 --ground-reflectance 0");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<std::vector<double>> rows = csv_rows(out + "/sensors.csv");
  ASSERT_EQ(rows.size(), 2u);
  // Up: the uniform sky's 10,000 lx exactly (nothing in the way; float rounding).
  EXPECT_NEAR(rows[0][6], 10000, 0.1);
  EXPECT_NEAR(rows[1][4], -1, 1e-6);  // the normal is made unit length
  // Down at the floor (reflectance 0.5, lit by the sky's 10,000 lx: 5,000 lm/m2): its exitance
  // times the form factor of the 4 m square from 1 m over its middle (Howell B-3: 0.831). The sky
  // below the horizon is the ground's, of reflectance 0. 2% bounds the 1,024 rays' noise.
  const double floor = 5000 * test::point_to_rectangle(2, 2, 0, 4, 0, 4, 1);
  EXPECT_NEAR(rows[1][6], floor, 0.02 * floor);
}

struct Refused {
  const char* name;
  std::string args;
  std::string csv;  // written to a file named by --sensors when not empty
  const char* says;
};

class AnalysisCliRefuses : public ::testing::TestWithParam<Refused> {};

TEST_P(AnalysisCliRefuses, WithOneLineAndWritesNothing) {
  const std::string parent = test::fresh_folder(std::string("analysis_cli_refused_") + GetParam().name);
  std::string args = GetParam().args;
  if (!GetParam().csv.empty())
    args += " --sensors " + test::write_text_file(std::string("refused_") + GetParam().name + ".csv", GetParam().csv);
  const test::Outcome r = test::radbake("bake " + fixture("open_floor.gltf") + " -o " + parent + "/out " + args);
  test::expect_one_line_refusal(r, GetParam().says, parent + "/out");
}

INSTANTIATE_TEST_SUITE_P(
    Cases, AnalysisCliRefuses,
    ::testing::Values(
        Refused{"daylight_factor_under_a_clear_sky", "--sky cie-clear --sun-illuminance 0 --sun-position 30,180 --daylight-factor", "",
                "a daylight factor needs an overcast sky without a sun"},
        Refused{"daylight_factor_with_a_sun", "--sky cie-overcast --sun-illuminance 1000 --sun-position 30,180 --daylight-factor", "",
                "with a sun"},
        Refused{"daylight_factor_without_a_sky", "--sky none --daylight-factor", "", "a daylight factor needs an overcast sky"},
        Refused{"daylight_factor_of_radiosity", "--sky uniform --daylight-factor --store radiosity", "",
                "--daylight-factor needs --store irradiance"},
        Refused{"csv_with_two_numbers", "--sky uniform", "x,y,z\n1,2\n", "line 2: a sensor is x,y,z or x,y,z,nx,ny,nz"},
        Refused{"csv_with_a_word", "--sky uniform", "1,2,3\n1,two,3\n", "line 2: a sensor is"},
        Refused{"csv_with_two_headers", "--sky uniform", "x,y,z\nX,Y,Z\n1,2,3\n", "line 2: a sensor is"},
        Refused{"csv_with_nan", "--sky uniform", "1,2,nan\n", "line 1: a sensor is"},
        Refused{"csv_with_a_zero_normal", "--sky uniform", "1,2,3,0,0,0\n", "line 1: the sensor's normal is zero"},
        Refused{"csv_empty", "--sky uniform", "# nothing\n", "holds no sensor"},
        Refused{"csv_missing", "--sky uniform --sensors /nonexistent/sensors.csv", "", "sensor file '/nonexistent/sensors.csv' cannot be opened"},
        Refused{"work_plane_too_fine", "--quiet --sky uniform --work-plane --work-plane-spacing 0.001", "",
                "raise --work-plane-spacing"},
        Refused{"work_plane_over_nothing", "--quiet --sky uniform --work-plane --work-plane-over desk", "",
                "no surface is named like the work plane's floors"},
        Refused{"false_colour_unknown", "--sky uniform --false-colour rainbow", "", "--false-colour must be linear or log"},
        Refused{"work_plane_height_negative", "--sky uniform --work-plane --work-plane-height -1", "",
                "--work-plane-height must be between 0 and 1000"}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace radbake

namespace radbake {
namespace {

// The classroom sample as the README bakes it: readings per work plane point.
std::vector<std::vector<double>> classroom_readings(const std::string& case_name, const std::string& sky) {
  const std::string out = test::fresh_folder("analysis_cli_classroom_" + case_name) + "/out";
  const test::Outcome r = test::radbake("bake " + test::source_path("samples/classroom/classroom.gltf") + " -o " + out +
                                        " --quiet --work-plane --work-plane-over floor " + sky);
  EXPECT_EQ(r.status, 0) << r.err;
  return r.status == 0 ? csv_rows(out + "/sensors.csv") : std::vector<std::vector<double>>{};
}

// At the defaults, the classroom's daylight factors against the path tracer's: whole
// paths from each point, 2^20 of them, sharing nothing with the sensors' sampling
// (tests/fixtures/classroom_daylight_reference.csv, ./dev daylight-reference; 0.4% noise per point).
// The bounds: RMS within 2% and every point within 6%. And the noise each reading states must
// be honest: a point's error against the reference over both standard errors would scatter as a
// standard normal deviate if they were all there is. They leave out the bake's own texel noise and
// bias (shared by every batch of a point's rays), so the scatter is wider: measured RMS 1.64 (the
// sensors' own rays, three quarters aimed into the windows, are quiet: 0.24% per point). Above 2, the stated
// noise would hide three quarters of the error's variance.
TEST(ClassroomSample, DaylightFactorsAtTheDefaultsMatchThePathTracerWithinTheirStatedNoise) {
  const auto rows = classroom_readings("against_reference", "--sky cie-overcast --daylight-factor");
  std::stringstream in(test::slurp(fixture("classroom_daylight_reference.csv")));
  std::vector<std::vector<double>> reference;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#' || line[0] == 'x') continue;
    std::vector<double> row;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    reference.push_back(row);
  }
  ASSERT_EQ(rows.size(), 252u);
  ASSERT_EQ(reference.size(), rows.size());
  double squares = 0, worst = 0;
  double squared_deviates = 0;
  for (size_t k = 0; k < rows.size(); ++k) {
    ASSERT_EQ(rows[k].size(), 10u);  // position, normal, lux, daylight factor, their standard errors
    ASSERT_NEAR(rows[k][0], reference[k][0], 1e-4);
    ASSERT_NEAR(rows[k][2], reference[k][2], 1e-4);
    const double ours = rows[k][7], theirs = reference[k][7];
    const double relative = ours / theirs - 1;
    squares += relative * relative;
    worst = std::max(worst, std::fabs(relative));
    const double noise = std::hypot(rows[k][9], reference[k][9]);
    EXPECT_GT(rows[k][9], 0) << "a reading states its noise";
    squared_deviates += (ours - theirs) * (ours - theirs) / (noise * noise);
  }
  const double rms = std::sqrt(squares / double(rows.size()));
  RecordProperty("daylight_factor_rms_percent", std::to_string(100 * rms));
  RecordProperty("daylight_factor_worst_percent", std::to_string(100 * worst));
  const double rms_deviate = std::sqrt(squared_deviates / double(rows.size()));
  RecordProperty("rms_error_over_stated_noise", std::to_string(rms_deviate));
  EXPECT_LT(rms, 0.02);
  EXPECT_LT(worst, 0.06);
  EXPECT_LT(rms_deviate, 2.0);
}

TEST(ClassroomSample, TheDaylightFactorFallsFromTheWindowsToTheBack) {
  const auto rows = classroom_readings("overcast", "--sky cie-overcast --daylight-factor");
  ASSERT_EQ(rows.size(), 252u);  // 18 x 14 points at 0.5 m over 9 x 7 m
  double front = 0, back = 0;
  for (const std::vector<double>& row : rows) {
    // Every bit of light came through the glazing (transmittance 0.7) from a sky of 100%.
    EXPECT_GT(row[7], 0);
    EXPECT_LT(row[7], 70);
    if (row[2] > 6.5) front += row[7] / 18;  // the row by the south windows (z = 6.75)
    if (row[2] < 0.5) back += row[7] / 18;   // the row by the north wall (z = 0.25)
  }
  RecordProperty("front_row_daylight_factor_percent", std::to_string(front));
  RecordProperty("back_row_daylight_factor_percent", std::to_string(back));
  EXPECT_GT(front, 4 * back);
  EXPECT_GT(back, 0.3);  // the interreflected light still reaches the back
}

TEST(ClassroomSample, TheDecemberSunReachesTheWorkPlaneInPatches) {
  const auto rows = classroom_readings("december", "--sky cie-clear --sky-illuminance 5000 --sun-illuminance 22000 "
                                                   "--latitude 51.5 --longitude -0.13 --utc-offset 0 --date 2026-12-21 --time 10:00");
  ASSERT_EQ(rows.size(), 252u);
  // The sun alone through the glazing on a horizontal plane: 0.7 x 22,000 lx x cos(79.25 degrees)
  // = 2,870 lx. Sunlit points have at least that; the others far less (sky and walls only).
  const double sun_on_the_plane = 0.7 * 22000 * std::cos(79.248 * M_PI / 180);
  size_t sunlit = 0, shaded = 0;
  for (const std::vector<double>& row : rows) {
    sunlit += row[6] > sun_on_the_plane;
    shaded += row[6] < 0.5 * sun_on_the_plane;
  }
  RecordProperty("sunlit_points", std::to_string(sunlit));
  EXPECT_GT(sunlit, 50u);
  EXPECT_GT(shaded, 50u);
}

}  // namespace
}  // namespace radbake

namespace radbake {
namespace {

TEST(GlareCli, AViewWritesItsFisheyeAndReportsItsDgp) {
  const std::string out = test::fresh_folder("glare_cli") + "/out";
  // The classroom at 10:00 on 21 December in London: from mid-room, the sun low in the south
  // windows, and the back wall behind.
  const test::Outcome r = test::radbake(
      "bake " + test::source_path("samples/classroom/classroom.gltf") + " -o " + out +
      " --quiet --sky perez --latitude 51.5 --longitude -0.12 --date 2026-12-21 --time 10:00 --direct-normal 450"
      " --diffuse-horizontal 60 --view 4.5,1.2,3.5:0,0,1 --view 4.5,1.2,3.5:0,0,-1 --view-size 256");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(test::slurp(out + "/report.json"));
  ASSERT_EQ(report["views"].size(), 2u);
  const nlohmann::json& south = report["views"][0];
  const nlohmann::json& north = report["views"][1];
  // Facing the low sun: intolerable glare (Wienold: DGP over 0.45); facing the back wall: under
  // 0.35, imperceptible.
  EXPECT_GT(south["dgp"].get<double>(), 0.45) << south.dump();
  EXPECT_LT(north["dgp"].get<double>(), 0.35) << north.dump();
  EXPECT_GT(south["vertical_illuminance_lux"].get<double>(), 5 * north["vertical_illuminance_lux"].get<double>());
  EXPECT_GT(south["glare_sources"].size(), 0u);
  for (const char* file : {"/view_0.exr", "/view_0.png", "/view_1.exr", "/view_1.png", "/view_0_perspective.exr",
                           "/view_0_perspective.png"})
    EXPECT_FALSE(test::slurp(out + file).empty()) << file;
  test::expect_one_line_refusal(test::radbake("bake " + test::source_path("samples/classroom/classroom.gltf") + " -o " +
                                              out + "2 --view 1,2,3"),
                                "option --view must be X,Y,Z:DX,DY,DZ", out + "2");
}

}  // namespace
}  // namespace radbake
