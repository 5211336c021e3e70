#include "io/run/checkpoint_folder.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>

#include "baker/sharing/byte_stream.h"
#include "base/errors.h"
#include "base/version.h"
#include "io/files/regular_file.h"
#include "io/files/written_file.h"

namespace radbake {
namespace {

constexpr char kMagic[8] = {'r', 'a', 'd', 'b', 'a', 'k', 'e', 'C'};
// 2: form factor rows and gather chunks keep where their rays ended (ray_fates.h).
// 3: gather chunks keep each texel's lost share and what its far rays took beyond patch means.
// 4: ray fates count front faces struck inside geometry.
constexpr uint32_t kVersion = 4;
const char* kManifest = "checkpoint.json";
constexpr uint64_t kMostManifestBytes = 1 << 20;  // it holds a fingerprint, a scene's name and a version

// FNV-1a, 64 bits: a checksum against damage and a fingerprint of inputs, not a defence against
// someone forging a file (a checkpoint is the user's own).
struct Fnv {
  uint64_t h = 1469598103934665603ull;
  void add(const void* data, size_t n) {
    const auto* p = static_cast<const uint8_t*>(data);
    for (size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ull;
  }
  void add(const std::string& s) {
    add(s.data(), s.size());
    add("\0", 1);
  }
};

std::string hex(uint64_t v) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(v));
  return text;
}

struct Header {
  char magic[8];
  uint32_t version;
  uint32_t name_size;
  uint64_t fingerprint;
  uint64_t payload_size;
  uint64_t checksum;
};

// A checkpoint file written whole, or no file: a failed write leaves no partial file behind.
void write_or_remove(const std::string& path, const std::function<void(std::ofstream&)>& write) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  write(out);
  try {
    close_written(out, path);
  } catch (const OutputError&) {
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
    throw;
  }
}

}  // namespace

uint64_t bake_fingerprint(const LoadedScene& loaded, const std::vector<std::pair<std::string, std::string>>& options) {
  Fnv f;
  f.add(std::string("radbake ") + kRadbakeVersion + " checkpoint");
  for (const std::string_view part : scene_contents(loaded)) f.add(part.data(), part.size());
  for (const auto& [name, value] : options) {
    f.add(name);
    f.add(value);
  }
  return f.h;
}

CheckpointFolder::CheckpointFolder(std::string folder, uint64_t fingerprint, std::string scene, bool owner)
    : folder_(std::move(folder)), fingerprint_(fingerprint) {
  namespace fs = std::filesystem;
  if (!owner) return;
  std::error_code error;
  fs::create_directories(folder_, error);
  if (!fs::is_directory(folder_)) throw InputError("checkpoint " + clipped(folder_) + ": cannot make the folder");
  const fs::path manifest = fs::path(folder_) / kManifest;
  std::error_code exists_error;
  if (fs::exists(fs::symlink_status(manifest, exists_error))) {
    nlohmann::json m;
    try {
      m = nlohmann::json::parse(read_regular_file(manifest.string(), "checkpoint manifest", kMostManifestBytes));
    } catch (const nlohmann::json::exception&) {
      throw InputError("checkpoint " + clipped(folder_) + ": " + kManifest + " is damaged");
    }
    // Members of another type (a fuzzed {"fingerprint": 5}) read as absent, never as json's type_error.
    const auto member = [&](const char* key) {
      return m.is_object() && m.contains(key) && m[key].is_string() ? m[key].get<std::string>() : std::string("?");
    };
    if (member("fingerprint") != hex(fingerprint))
      throw InputError("checkpoint " + clipped(folder_) + " was saved by a bake of another scene or other options (" +
                       clipped(member("scene")) + "): use another folder");
    return;
  }
  nlohmann::json m = {{"fingerprint", hex(fingerprint)}, {"scene", scene}, {"format", kVersion}};
  const fs::path temporary = fs::path(folder_) / (std::string(kManifest) + ".partial");
  write_or_remove(temporary.string(), [&](std::ofstream& out) { out << m.dump(2) << "\n"; });
  fs::rename(temporary, manifest, error);
  if (error) throw OutputError("checkpoint " + clipped(folder_) + ": cannot write " + kManifest + ": " + error.message());
}

std::string CheckpointFolder::file_of(const std::string& stage) const {
  std::string name;
  for (char c : stage) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return (std::filesystem::path(folder_) / (name + ".stage")).string();
}

void CheckpointFolder::save(const std::string& stage, const Bytes& state) {
  Fnv sum;
  sum.add(state.data(), state.size());
  Header h{};
  std::memcpy(h.magic, kMagic, sizeof kMagic);
  h.version = kVersion;
  h.name_size = uint32_t(stage.size());
  h.fingerprint = fingerprint_;
  h.payload_size = state.size();
  h.checksum = sum.h;
  const std::string file = file_of(stage), temporary = file + ".partial." + std::to_string(::getpid());
  write_or_remove(temporary, [&](std::ofstream& out) {
    out.write(reinterpret_cast<const char*>(&h), sizeof h);
    out.write(stage.data(), std::streamsize(stage.size()));
    out.write(reinterpret_cast<const char*>(state.data()), std::streamsize(state.size()));
  });
  std::error_code error;
  std::filesystem::rename(temporary, file, error);
  if (error) throw OutputError("checkpoint " + clipped(file) + ": cannot write: " + error.message());
}

std::optional<Bytes> CheckpointFolder::load(const std::string& stage) const {
  const std::string file = file_of(stage);
  std::error_code error;
  if (!std::filesystem::exists(std::filesystem::symlink_status(file, error))) return std::nullopt;
  RegularFile in(file, "checkpoint");
  const uint64_t size = in.size();
  auto damaged = [&](const std::string& why) { return InputError("checkpoint " + clipped(file) + " is damaged: " + why); };
  Header h{};
  if (size < sizeof h || !in.read(&h, sizeof h)) throw damaged("it is shorter than its header");
  if (std::memcmp(h.magic, kMagic, sizeof kMagic) != 0 || h.version != kVersion)
    throw damaged("it is not a radbake checkpoint file of this version");
  if (h.fingerprint != fingerprint_)
    throw InputError("checkpoint " + clipped(file) + " was saved by a bake of another scene or other options");
  // Each size against the bytes that remain, never their sum: a payload size near 2^64 wraps it.
  const uintmax_t body = size - sizeof h;
  if (h.name_size > body || h.payload_size != body - h.name_size) throw damaged("its size is not what its header says");
  std::string name(h.name_size, '\0');
  Bytes payload(h.payload_size);
  if (!in.read(name.data(), name.size()) || !in.read(payload.data(), payload.size()) || name != stage)
    throw damaged("it holds another stage");
  Fnv sum;
  sum.add(payload.data(), payload.size());
  if (sum.h != h.checksum) throw damaged("its checksum does not match");
  return payload;
}

std::vector<std::string> CheckpointFolder::stages(const std::string& prefix) const {
  std::vector<std::string> out;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder_, error)) {
    if (entry.path().extension() != ".stage") continue;
    // What is no regular file is no stage here; load() refuses it by name.
    std::optional<RegularFile> in;
    try {
      in.emplace(entry.path().string(), "checkpoint");
    } catch (const InputError&) {
      continue;
    }
    Header h{};
    if (!in->read(&h, sizeof h) || h.name_size > 4096) continue;
    std::string name(h.name_size, '\0');
    if (in->read(name.data(), name.size()) && name.rfind(prefix, 0) == 0) out.push_back(name);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace radbake
