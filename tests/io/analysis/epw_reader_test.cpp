// EnergyPlus weather (io/analysis/epw_reader.h) and the year of skies made from it (daylight/annual_skies.h):
// the sample files read as written, and broken files refused naming line and field.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "base/errors.h"
#include "daylight/annual_skies.h"
#include "io/analysis/epw_reader.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

std::string london() { return test::source_path("samples/weather/london_synthetic.epw"); }

std::string text_of(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

void expect_refused(const std::string& text, const std::string& words) {
  const std::string path = test::write_text_file("broken.epw", text);
  try {
    read_epw(path);
    ADD_FAILURE() << "accepted: " << words;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line";
  }
}

TEST(EpwReader, TheSampleYearReadsAsWritten) {
  const Weather w = read_epw(london());
  EXPECT_EQ(w.place, "London, GBR");
  EXPECT_DOUBLE_EQ(w.latitude, 51.51);
  EXPECT_DOUBLE_EQ(w.longitude, -0.13);
  EXPECT_DOUBLE_EQ(w.utc_offset, 0);
  ASSERT_EQ(w.hours.size(), 8760u);
  // 3 July, the hour ending at noon, as samples/weather/make_weather.py wrote it.
  const WeatherHour& h = w.hours[(31 + 28 + 31 + 30 + 31 + 30 + 2) * 24 + 11];
  EXPECT_EQ(h.month, 7);
  EXPECT_EQ(h.day, 3);
  EXPECT_EQ(h.hour, 12);
  EXPECT_DOUBLE_EQ(h.direct_normal, 166);
  EXPECT_DOUBLE_EQ(h.diffuse_horizontal, 391);
  EXPECT_DOUBLE_EQ(h.dew_point, 12);
}

TEST(EpwReader, BrokenFilesAreOneLineNamingLineAndField) {
  const std::string good = text_of(london());
  expect_refused("HELLO\n" + good.substr(good.find('\n') + 1), "starts with its LOCATION line");
  // The first data row (line 9) with its direct normal irradiance missing.
  std::string missing = good;
  const size_t row = [&] { size_t at = 0; for (int k = 0; k < 8; ++k) at = missing.find('\n', at) + 1; return at; }();
  std::string first = missing.substr(row, missing.find('\n', row) - row);
  std::vector<std::string> f;
  std::stringstream in(first);
  for (std::string x; std::getline(in, x, ',');) f.push_back(x);
  f[14] = "9999";
  std::string broken_row;
  for (size_t k = 0; k < f.size(); ++k) broken_row += (k ? "," : "") + f[k];
  expect_refused(missing.replace(row, first.size(), broken_row), "line 9: direct normal irradiance 9999 is outside");
  std::string word = good;
  word.replace(row, first.size(), "2025,1,1,one,60");
  expect_refused(word, "line 9: hour is not a number: 'one'");
  expect_refused(good.substr(0, good.find("2025,2,1,1,")), "has 744 hours of weather; a year has 8760");
}

TEST(AnnualSkies, DaylitHoursGetASkyAndNightsNone) {
  Weather w = read_epw(london());
  w.hours.resize(31 * 24);  // January: the year's skies take a while, and `radbake bake --weather` runs them all
  const AnnualSkies skies = annual_skies(w, DaylightOptions{});
  ASSERT_EQ(skies.hours.size(), 31u * 24);
  // A London January has 7.8 to 9.0 hours of the sun above the horizon a day (the hour counts when
  // its middle is), so about 240 to 280.
  EXPECT_GT(skies.daylit, 240u);
  EXPECT_LT(skies.daylit, 290u);
  size_t enabled = 0;
  for (const SkyLight& s : skies.hours) enabled += s.enabled;
  EXPECT_EQ(enabled, skies.daylit);
  EXPECT_FALSE(skies.hours[0].enabled);       // midnight, 1 January
  EXPECT_TRUE(skies.hours[14 * 24 + 11].enabled);  // noon, 15 January
  EXPECT_FALSE(skies.hours[14 * 24 + 20].enabled); // 8 pm
  EXPECT_LT(skies.substituted, skies.daylit / 20);  // the Perez fit holds for nearly every hour
}

}  // namespace
}  // namespace radbake
