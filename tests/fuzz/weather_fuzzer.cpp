// libFuzzer target on the readers of text files an annual bake and radbake diff read (./dev fuzz):
// each input is read as an EPW weather file by read_epw (io/analysis/epw_reader.h), as a sensor
// CSV by read_sensor_csv (io/analysis/analysis_outputs.h), and as a year folder's
// annual_sensors.csv beside a valid report.json by read_annual_folder
// (io/analysis/annual_comparison.h). Each must accept the input or throw InputError (exit 2 in the
// CLI). Anything else is a finding: a crash or sanitizer report, an exception of another type
// (exit 1), a hang, or an allocation past libFuzzer's limit.
//
// Seeds (tests/fuzz/corpus/weather.*): the head of a sample EPW (a whole year is 1 MB, too big to
// mutate), a few rows of odd but valid hours, and sensor files of both shapes with a header,
// comments, a byte-order mark and CRLF line ends, and an annual_sensors.csv as a year writes it.
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "base/errors.h"
#include "io/analysis/analysis_outputs.h"
#include "io/analysis/annual_comparison.h"
#include "io/analysis/epw_reader.h"

namespace {

namespace fs = std::filesystem;

// A year folder's report, as write_annual's has it (the parts read_annual_folder reads).
const char* const kReport = R"({"series": {"file": "annual_illuminance.f32"},
 "metrics": {"sDA_percent": 50.5, "ASE_percent": 3.2, "mean_daylight_autonomy_percent": 61.0,
             "mean_udi_useful_percent": 70.25},
 "views": [{"mean_dgp": 0.31, "share_dgp_045_or_more": 0.02}]})";

// A folder of this process's own, removed when it exits.
struct Scratch {
  fs::path folder;
  Scratch() {
    char pattern[] = "/tmp/radbake_fuzz_XXXXXX";
    folder = mkdtemp(pattern);
    fs::create_directories(folder / "year");
    std::ofstream(folder / "year" / "report.json") << kReport;
  }
  ~Scratch() {
    std::error_code ignored;
    fs::remove_all(folder, ignored);
  }
};

const fs::path& scratch_folder() {
  static const Scratch scratch;
  return scratch.folder;
}

void write(const fs::path& path, const uint8_t* data, size_t size) {
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), std::streamsize(size));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const fs::path& folder = scratch_folder();
  const fs::path epw = folder / "input.epw", csv = folder / "input.csv", year = folder / "year";
  write(epw, data, size);
  write(csv, data, size);
  write(year / "annual_sensors.csv", data, size);
  try {
    radbake::read_epw(epw.string());
  } catch (const radbake::InputError&) {
    // Refused with a message: what hostile input should get.
  }
  try {
    radbake::read_sensor_csv(csv.string());
  } catch (const radbake::InputError&) {
  }
  try {
    radbake::read_annual_folder(year.string());
  } catch (const radbake::InputError&) {
  }
  return 0;
}
