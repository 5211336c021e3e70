// libFuzzer target on the checkpoint reader (./dev fuzz): each input is read by CheckpointFolder
// (io/run/checkpoint_folder.h) twice, as --resume and radbake merge read a folder:
//   - as a stage file: written under the name its header claims (or direct_light_waves.stage when
//     it claims none that can be a file's), then listed by stages() (merge's slice count) and read
//     back by load() for every stage listed and for the names a bake asks for;
//   - as the manifest, checkpoint.json, opened by the first process's constructor.
// Each must accept the input or throw InputError (exit 2 in the CLI). Anything else is a finding:
// a crash or sanitizer report, an exception of another type (exit 1), a hang, or an allocation
// past libFuzzer's limit.
//
// Seeds (tests/fuzz/corpus/checkpoint.*): the files of real checkpoints of the Cornell box,
//   radbake bake samples/cornell_box/cornell_box.gltf --max-page-size 16 --quality draft \
//     --checkpoint A --stop-after radiosity             # checkpoint.json and three stages
//   cp -r A B
//   radbake bake (the same) --checkpoint A --resume --texel-range 1/2   # and 2/2: the slices
//   radbake bake (the same) --checkpoint B --resume -o OUT              # the whole final gather
// copied as checkpoint.manifest.json and checkpoint.<stage file>. The manifest's fingerprint is the
// one the constructor is given, so the seed manifest is accepted.
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/errors.h"
#include "io/run/checkpoint_folder.h"

namespace {

namespace fs = std::filesystem;

// The header of a stage file, as checkpoint_folder.cpp writes it (40 bytes).
constexpr size_t kHeaderBytes = 40;
constexpr size_t kNameSizeAt = 12, kFingerprintAt = 16;

// What a bake asks a checkpoint for (baker/pipeline, baker/transport): loaded even when the input
// is another stage, so the missing-stage path runs too.
const char* const kStages[] = {"direct light waves", "form factors waves", "radiosity", "final gather waves",
                               "final gather, slice 1 of 2 waves"};

struct Scratch {
  fs::path root, stages, manifest;  // one folder per role, in a folder of this process's own
  uint64_t fingerprint = 0;         // the seed manifest's, so it is accepted
  ~Scratch() {
    std::error_code ignored;
    if (!root.empty()) fs::remove_all(root, ignored);
  }
};

// The seed manifest's fingerprint (16 hex digits), 0 when the corpus has none.
uint64_t seed_fingerprint() {
  try {
    std::ifstream in(fs::path(RADBAKE_FUZZ_CORPUS) / "checkpoint.manifest.json");
    const nlohmann::json m = nlohmann::json::parse(in);
    return std::stoull(m.at("fingerprint").get<std::string>(), nullptr, 16);
  } catch (const std::exception&) {
    return 0;
  }
}

const Scratch& scratch() {
  static const Scratch s = [] {
    char pattern[] = "/tmp/radbake_fuzz_XXXXXX";
    const fs::path folder = mkdtemp(pattern);
    fs::create_directories(folder / "stages");
    fs::create_directories(folder / "manifest");
    return Scratch{folder, folder / "stages", folder / "manifest", seed_fingerprint()};
  }();
  return s;
}

// The file CheckpointFolder keeps `stage` in (file_of: every byte not a letter or digit is '_').
std::string file_name_of(const std::string& stage) {
  std::string name;
  for (char c : stage) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name + ".stage";
}

void write(const fs::path& path, const uint8_t* data, size_t size) {
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), std::streamsize(size));
}

void read_as_stage(const uint8_t* data, size_t size) {
  const Scratch& s = scratch();
  for (const auto& entry : fs::directory_iterator(s.stages)) fs::remove(entry.path());
  // The stage the header names, when it is there whole and short enough to be a file's name.
  std::optional<std::string> claimed;
  uint64_t fingerprint = s.fingerprint;
  if (size >= kHeaderBytes) {
    uint32_t name_size = 0;
    std::memcpy(&name_size, data + kNameSizeAt, sizeof name_size);
    std::memcpy(&fingerprint, data + kFingerprintAt, sizeof fingerprint);
    if (name_size <= 200 && name_size <= size - kHeaderBytes)
      claimed = std::string(reinterpret_cast<const char*>(data + kHeaderBytes), name_size);
  }
  write(s.stages / file_name_of(claimed ? *claimed : kStages[0]), data, size);
  // The folder of the bake whose fingerprint the input carries, and of another bake.
  for (const uint64_t folder_fingerprint : {fingerprint, ~fingerprint}) {
    // Not the owner: the manifest is the other half's business.
    const radbake::CheckpointFolder folder(s.stages.string(), folder_fingerprint, "fuzz.gltf", false);
    try {
      std::vector<std::string> names = folder.stages("");
      folder.stages("final gather, slice ");
      if (claimed) names.push_back(*claimed);
      for (const char* stage : kStages) names.push_back(stage);
      std::sort(names.begin(), names.end());
      names.erase(std::unique(names.begin(), names.end()), names.end());
      for (const std::string& name : names) {
        try {
          folder.load(name);
        } catch (const radbake::InputError&) {
        }
      }
    } catch (const radbake::InputError&) {
      // Refused with a message: what hostile input should get.
    }
  }
}

void read_as_manifest(const uint8_t* data, size_t size) {
  const Scratch& s = scratch();
  write(s.manifest / "checkpoint.json", data, size);
  try {
    radbake::CheckpointFolder folder(s.manifest.string(), s.fingerprint, "fuzz.gltf");
  } catch (const radbake::InputError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  read_as_stage(data, size);
  read_as_manifest(data, size);
  return 0;
}
