// Daylight from the command line: a sky and a sun placed by a site and a moment light
// scenes that have no lamp, in lux, and report.json says what the sky and the sun were.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "io/lightmaps/lightmap_images.h"
#include "support/commands.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

std::string fixture(const std::string& name) { return test::source_path("tests/fixtures/" + name); }

struct Baked {
  double mean = 0, lowest = 0, highest = 0;  // lux, over the page's texels (every one is the surface's: dilated)
  nlohmann::json report;
};

Baked bake_in_daylight(const std::string& scene, const std::string& case_name, const std::string& options) {
  const std::string out = test::fresh_folder("daylight_cli_" + case_name) + "/out";
  const test::Outcome r = test::radbake("bake " + fixture(scene + ".gltf") + " -o " + out + " --quiet " + options);
  EXPECT_EQ(r.status, 0) << r.err;
  Baked b;
  if (r.status != 0) return b;
  const LightmapPage page = read_lightmap_exr(out + "/" + scene + "_lightmap_0.exr");
  b.lowest = INFINITY;
  for (const Rgb& t : page.texels) {
    const double lux = sum(t) / 3;
    b.mean += lux / double(page.texels.size());
    b.lowest = std::min(b.lowest, lux);
    b.highest = std::max(b.highest, lux);
  }
  b.report = nlohmann::json::parse(test::slurp(out + "/report.json"));
  return b;
}

TEST(DaylightCli, AnOpenFloorUnderAnOvercastSkyGetsTheSkysIlluminance) {
  const Baked b = bake_in_daylight("open_floor", "overcast", "--sky cie-overcast --sky-illuminance 12000");
  // The floor sees the whole sky and nothing else: E = 12,000 lx. 1% bounds the sky rays' noise
  // per texel (256 stratified rays over a sky that varies 3:1 from zenith to horizon).
  EXPECT_NEAR(b.mean, 12000, 0.003 * 12000);
  EXPECT_GT(b.lowest, 0.99 * 12000);
  EXPECT_LT(b.highest, 1.01 * 12000);
  EXPECT_EQ(b.report["daylight"]["sky"], "cie-overcast");
  EXPECT_NEAR(double(b.report["daylight"]["zenith_luminance_cd_m2"]), 12000 / (7 * M_PI / 9), 0.1);
  EXPECT_EQ(b.report["options"]["sky"], "cie-overcast");
  // The floor alone is convex, but the sky shines from outside it: its rays are traced.
  bool sky_traced = false;
  for (const auto& d : b.report["plan"]) sky_traced |= d["effect"] == "shadows" && d["choice"] == "traced for the sky and the sun only";
  EXPECT_TRUE(sky_traced) << b.report["plan"].dump();
}

TEST(DaylightCli, ASunPlacedByASiteAndTimeAddsItsDirectNormalIlluminanceTimesCosZenith) {
  // NREL SPA's test site and moment; the sun's position comes back in report.json.
  const Baked b = bake_in_daylight("open_floor", "site",
                                   "--sky cie-clear --sky-illuminance 15000 --sun-illuminance 70000 "
                                   "--latitude 39.742476 --longitude -105.1786 --elevation 1830.14 --pressure 820 "
                                   "--temperature 11 --date 2003-10-17 --time 12:30:30 --utc-offset -7");
  const nlohmann::json& d = b.report["daylight"];
  // SPA: zenith 50.111622, azimuth 194.340241 degrees; ΔT differs by 2 s from SPA's (69 s, not 67).
  EXPECT_NEAR(double(d["sun_zenith_deg"]), 50.111622, 0.02);
  EXPECT_NEAR(double(d["sun_azimuth_deg_from_north_eastward"]), 194.340241, 0.02);
  const double expected = 15000 + 70000 * std::cos(50.111622 * M_PI / 180);
  EXPECT_NEAR(double(d["exterior_horizontal_illuminance_lx"]), expected, 0.001 * expected);
  // 1% bounds the clear sky's noise per texel (its circumsolar peak is a few rays' worth).
  EXPECT_NEAR(b.mean, expected, 0.005 * expected);
  EXPECT_GT(b.lowest, 0.99 * expected);
  EXPECT_LT(b.highest, 1.01 * expected);
}

TEST(DaylightCli, APerezSkyFromAnHourOfWeatherLightsTheFloorWithItsDiffuseAndDirectIlluminance) {
  // gendaylit's clear case (tests/daylight/perez_sky_test.cpp): 21 June noon at 40 N, 105 W (UTC-7),
  // 700 W/m2 direct normal, 120 W/m2 diffuse horizontal. gendaylit 6.1a: epsilon 6.6905, diffuse
  // 15,402 lx, direct normal 72,453 lx.
  const Baked b = bake_in_daylight("open_floor", "perez",
                                   "--sky perez --direct-normal 700 --diffuse-horizontal 120 --latitude 40 "
                                   "--longitude -105 --utc-offset -7 --date 2026-06-21 --time 12:00");
  const nlohmann::json& d = b.report["daylight"];
  // 1e-3 bounds epsilon's dependence on the sun's zenith angle: gendaylit places the sun by its own
  // year-less formula, we by SPA's for 2026 (0.02 degree apart here).
  EXPECT_NEAR(double(d["perez_clearness_epsilon"]), 6.6905, 1e-3);
  // 0.1% bounds the luminous efficacies against gendaylit's four printed digits and its sun.
  EXPECT_NEAR(double(d["sky_horizontal_illuminance_lx"]), 15402, 0.001 * 15402);
  EXPECT_NEAR(double(d["sun_direct_normal_illuminance_lx"]), 72453, 0.001 * 72453);
  const double expected = double(d["exterior_horizontal_illuminance_lx"]);
  // 1% bounds the sky rays' noise per texel under the Perez sky's circumsolar peak.
  EXPECT_NEAR(b.mean, expected, 0.005 * expected);
  EXPECT_GT(b.lowest, 0.99 * expected);
  EXPECT_LT(b.highest, 1.01 * expected);
}

TEST(DaylightCli, NorthDecidesWhichWallTheSunFalls) {
  // A wall facing +X, the sun in the east 30 degrees up, under a uniform sky. With north along -Z
  // (the default) the wall faces east and gets E_n sin 60 from the sun; turned so that north is
  // +X, it faces north and the sun grazes past it. The sky and the ground are the same both times.
  const std::string sun = "--sky uniform --sky-illuminance 10000 --sun-illuminance 50000 --sun-position 60,90 ";
  const Baked east = bake_in_daylight("east_wall", "facing_east", sun);
  const Baked north = bake_in_daylight("east_wall", "facing_north", sun + "--north 90");
  const double sunlit = 50000 * std::sin(M_PI / 3);
  // 0.5% bounds the sky and sun rays' noise in the difference of two page means.
  EXPECT_NEAR(east.mean - north.mean, sunlit, 0.005 * sunlit);
  // Facing north: half sky, half ground lit by sky and sun, (1 + rho) E_sky / 2 + rho E_sun,h / 2.
  const double shade = (1 + 0.2) * 10000 / 2 + 0.2 * 50000 * 0.5 / 2;
  EXPECT_NEAR(north.mean, shade, 0.01 * shade);
  EXPECT_EQ(north.report["options"]["north"], "1,0,0");
}

struct Refused {
  const char* name;
  std::string args;
  const char* says;
};

class DaylightCliRefuses : public ::testing::TestWithParam<Refused> {};

TEST_P(DaylightCliRefuses, WithOneLineAndWritesNothing) {
  const std::string parent = test::fresh_folder(std::string("daylight_cli_refused_") + GetParam().name);
  const test::Outcome r =
      test::radbake("bake " + fixture("open_floor.gltf") + " -o " + parent + "/out " + GetParam().args);
  test::expect_one_line_refusal(r, GetParam().says, parent + "/out");
}

INSTANTIATE_TEST_SUITE_P(
    Cases, DaylightCliRefuses,
    ::testing::Values(
        Refused{"no_light_at_all", "", "nothing"},
        Refused{"unknown_sky", "--sky sunny", "--sky must be none, uniform, cie-overcast, cie-clear, cie-1 .. cie-15 or perez, got 'sunny'"},
        Refused{"sky_type_16", "--sky cie-16", "--sky must be none"},
        Refused{"sunny_sky_without_sun", "--sky cie-12", "sky cie-12 has a sun"},
        Refused{"sun_without_position", "--sky cie-clear --sun-illuminance 1000", "needs the sun's position"},
        Refused{"site_half_given", "--sky cie-overcast --latitude 40 --date 2026-12-21",
                "missing --longitude --time"},
        Refused{"night", "--sky cie-clear --sun-illuminance 1000 --latitude 40 --longitude 0 --date 2026-12-21 --time 22:00",
                "the sun is below the horizon"},
        Refused{"two_suns", "--sky cie-clear --sun-illuminance 1000 --sun-position 30,180 --latitude 40 --longitude 0 "
                            "--date 2026-12-21 --time 12:00",
                "give one"},
        Refused{"bad_date", "--sky uniform --date 2026-13-01", "--date needs YYYY-MM-DD, got '2026-13-01'"},
        Refused{"bad_time", "--sky uniform --time 9h30", "--time needs HH:MM or HH:MM:SS"},
        Refused{"north_two_numbers", "--sky uniform --north 1,0", "--north needs 3 numbers"},
        Refused{"north_vertical", "--sky uniform --north 0,1,0", "north must not point straight up or down"},
        Refused{"ground_reflectance", "--sky uniform --ground-reflectance 1.5", "--ground-reflectance must be between 0 and 1"},
        Refused{"sun_below_ground_given", "--sky uniform --sun-illuminance 10 --sun-position 100,0", "below the horizon"},
        Refused{"latitude", "--sky uniform --latitude 91", "--latitude must be between -90 and 90"},
        Refused{"perez_without_weather", "--sky perez --latitude 40 --longitude 0 --date 2026-06-21 --time 12:00",
                "sky perez needs the hour's weather"},
        Refused{"perez_with_sun_illuminance", "--sky perez --sun-illuminance 1000 --direct-normal 700 "
                                              "--diffuse-horizontal 120 --latitude 40 --longitude 0 --date 2026-06-21 --time 12:00",
                "not --sun-illuminance"},
        Refused{"perez_without_site", "--sky perez --direct-normal 700 --diffuse-horizontal 120 --sun-position 30,180",
                "sky perez needs the hour's site and time"},
        Refused{"perez_more_than_the_sun_gives", "--sky perez --direct-normal 1400 --diffuse-horizontal 120 "
                                                  "--latitude 40 --longitude 0 --date 2026-06-21 --time 12:00",
                "sky perez: "}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace radbake
