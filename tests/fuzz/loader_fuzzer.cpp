// libFuzzer target on the loader (./dev fuzz): each input is written as a file and read by
// load_gltf, which must accept it or throw InputError (exit 2 in the CLI). Anything else is a
// finding: a crash or sanitizer report, an exception of another type (exit 1), a hang, or an
// allocation past libFuzzer's limit. Built twice, as gltf_fuzzer and glb_fuzzer, which differ in
// the file name they write (RADBAKE_FUZZ_EXTENSION) and in the seeds ./dev fuzz gives them.
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "base/errors.h"
#include "io/gltf/gltf_loader.h"

namespace {

namespace fs = std::filesystem;

// A folder of this process's own holding the corpus's external buffers, so seeds that name
// cornell_box.bin and the like load as far as they do in the test.
fs::path scratch_folder() {
  char pattern[] = "/tmp/radbake_fuzz_XXXXXX";
  const fs::path folder = mkdtemp(pattern);
  for (const auto& entry : fs::directory_iterator(RADBAKE_FUZZ_CORPUS))
    if (entry.path().extension() == ".bin") fs::copy_file(entry.path(), folder / entry.path().filename());
  return folder;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const fs::path input = scratch_folder() / ("input" RADBAKE_FUZZ_EXTENSION);
  std::ofstream(input, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), std::streamsize(size));
  try {
    radbake::load_gltf(input.string());
  } catch (const radbake::InputError&) {
    // Refused with a message: what hostile input should get.
  }
  return 0;
}
