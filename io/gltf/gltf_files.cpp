// The files-stay-inside rule: a URI is a path relative to the scene's folder (percent-decoded, as
// glTF's RFC 3986 URIs are), and only the files the document's buffers and images name, resolved
// there, can be opened. tinygltf reads through callbacks that know nothing else, so neither it
// nor the writer, which copies images from GltfSource::image_files, can reach another file.
#include <cstring>
#include <filesystem>
#include <fstream>

#include "base/errors.h"
#include "io/files/regular_file.h"
#include "io/gltf/gltf_source.h"

namespace radbake {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

// A decoded image holds 4 channels of 8 or 16 bits, twice: in tinygltf's model and in the Scene.
constexpr uint64_t kMaxImagePixels = uint64_t(1) << 26;  // 8192 x 8192
constexpr uint64_t kDecodedCopies = 2;

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// RFC 3986 percent-decoding; false for a broken escape or a NUL, which no file name holds.
bool percent_decode(const std::string& uri, std::string* out) {
  out->clear();
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] != '%') {
      *out += uri[i];
      continue;
    }
    if (i + 2 >= uri.size() || hex_value(uri[i + 1]) < 0 || hex_value(uri[i + 2]) < 0) return false;
    *out += char(hex_value(uri[i + 1]) * 16 + hex_value(uri[i + 2]));
    i += 2;
  }
  return out->find('\0') == std::string::npos;
}

// tinygltf's own decoding (it also reads '+' as a space), the key its file callbacks are called with.
std::string tinygltf_decoded(const std::string& uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '+') {
      out += ' ';
    } else if (uri[i] == '%' && i + 2 < uri.size()) {
      out += char(std::max(hex_value(uri[i + 1]), 0) * 16 + std::max(hex_value(uri[i + 2]), 0));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

bool has_scheme(const std::string& uri) {
  size_t colon = uri.find(':');
  if (colon == std::string::npos || colon == 0 || !std::isalpha(static_cast<unsigned char>(uri[0]))) return false;
  for (size_t i = 1; i < colon; ++i)
    if (!std::isalnum(static_cast<unsigned char>(uri[i])) && !std::strchr("+-.", uri[i])) return false;
  return true;
}

bool inside(const fs::path& path, const fs::path& folder) {
  auto p = path.begin();
  for (auto f = folder.begin(); f != folder.end(); ++f, ++p)
    if (p == path.end() || *p != *f) return false;
  return true;
}

class Resolver {
 public:
  Resolver(const std::string& file, const std::string& base_dir, bool allow_external)
      : file_(file), allow_external_(allow_external) {
    std::error_code ec;
    base_ = fs::canonical(base_dir.empty() ? "." : base_dir, ec);
    if (ec) throw InputError(file + ": its folder cannot be read: " + ec.message());
  }

  // The canonical file `uri` names, or empty when it does not exist (the caller decides whether
  // that is an error). Refuses what leads out of the scene's folder.
  std::string resolve(const std::string& uri, const std::string& pointer, FileAccess& access) {
    std::string decoded;
    if (has_scheme(uri))
      refuse(file_, pointer, "URI '" + clipped(uri) + "' is neither a relative file path nor a base64 data URI");
    if (!percent_decode(uri, &decoded)) refuse(file_, pointer, "URI '" + clipped(uri) + "' has a broken %-escape");
    const fs::path relative(decoded);
    const fs::path lexical = (base_ / relative).lexically_normal();
    if (!allow_external_ && (relative.is_absolute() || !inside(lexical, base_)))
      refuse(file_, pointer, "URI '" + clipped(uri) + "' names a file outside the scene's folder "
                             "(--allow-external-files reads it)");
    std::error_code ec;
    fs::path found = fs::canonical(lexical, ec);
    if (ec) return {};
    if (!fs::is_regular_file(found, ec))
      refuse(file_, pointer, "URI '" + clipped(uri) + "' is not a regular file (a FIFO, a device or a folder)");
    if (!allow_external_ && !inside(found, base_))
      refuse(file_, pointer, "URI '" + clipped(uri) + "' is a link to a file outside the scene's folder "
                             "(--allow-external-files reads it)");
    access.by_uri.emplace(tinygltf_decoded(uri), found.string());
    access.allowed.insert(found.string());
    return found.string();
  }

 private:
  std::string file_;
  bool allow_external_;
  fs::path base_;
};

bool is_data_uri(const std::string& uri) { return uri.rfind("data:", 0) == 0; }

// Bytes a base64 data URI decodes to, without decoding it; false when tinygltf cannot decode it.
bool data_uri_size(const std::string& uri, uint64_t* size) {
  static const char* kHeaders[] = {"data:application/octet-stream;base64,", "data:application/gltf-buffer;base64,",
                                   "data:image/png;base64,", "data:image/jpeg;base64,"};
  for (const char* header : kHeaders) {
    if (uri.rfind(header, 0) != 0) continue;
    uint64_t chars = uri.size() - std::strlen(header);
    uint64_t padding = 0;
    for (size_t i = uri.size(); i > std::strlen(header) && uri[i - 1] == '=' && padding < 2; --i) ++padding;
    *size = chars / 4 * 3 - padding;
    return true;
  }
  return false;
}

const std::string* file_of(const std::string& path, const FileAccess& access) {
  auto it = access.allowed.find(path);
  return it == access.allowed.end() ? nullptr : &*it;
}

// tinygltf asks for the URI it decoded (joined to an empty base folder); the answer is where
// the resolver found it. Anything else stays as asked and then does not exist.
std::string expand_path(const std::string& path, void* user) {
  const FileAccess& access = *static_cast<const FileAccess*>(user);
  auto it = access.by_uri.find(path);
  return it == access.by_uri.end() ? path : it->second;
}

bool file_exists(const std::string& path, void* user) { return file_of(path, *static_cast<const FileAccess*>(user)); }

bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  FileAccess& access = *static_cast<FileAccess*>(user);
  if (!file_of(path, access)) {
    if (err) *err = "not a file of this scene";
    return false;
  }
  try {
    *out = read_regular_bytes(path, "file", memory_limit(access.max_memory_bytes));
  } catch (const InputError& e) {
    access.error = access.file + ": " + e.what();
    return false;
  }
  return true;
}

bool write_whole_file(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err = "radbake does not write through tinygltf";
  return false;
}

uint32_t big_endian(const unsigned char* p, int n) {
  uint32_t v = 0;
  for (int i = 0; i < n; ++i) v = v << 8 | p[i];
  return v;
}

const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};  // a PNG's first bytes

// Width and height from a PNG's IHDR or a JPEG's start-of-frame, read before anything is decoded.
bool image_size(const unsigned char* bytes, size_t size, uint64_t* width, uint64_t* height) {
  if (size >= 24 && std::memcmp(bytes, kPng, 8) == 0 && std::memcmp(bytes + 12, "IHDR", 4) == 0) {
    *width = big_endian(bytes + 16, 4);
    *height = big_endian(bytes + 20, 4);
    return true;
  }
  if (size < 4 || bytes[0] != 0xff || bytes[1] != 0xd8) return false;
  for (size_t at = 2; at + 4 <= size;) {
    if (bytes[at] != 0xff) return false;
    const unsigned char marker = bytes[at + 1];
    if (marker == 0xff) {  // fill byte
      ++at;
      continue;
    }
    const size_t length = big_endian(bytes + at + 2, 2);
    const bool start_of_frame = marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 && marker != 0xcc;
    if (start_of_frame) {
      if (at + 9 > size) return false;
      *height = big_endian(bytes + at + 5, 2);
      *width = big_endian(bytes + at + 7, 2);
      return true;
    }
    at += 2 + length;
  }
  return false;
}

// Sizes the image from its header against the pixel cap and the memory budget, then lets
// tinygltf's stb_image decode it. Images radbake cannot size or decode are left undecoded: the
// loader warns, and textures using them are ignored.
bool load_image(tinygltf::Image* image, const int index, std::string*, std::string* warn, int req_width,
                int req_height, const unsigned char* bytes, int size, void* user) {
  FileAccess& access = *static_cast<FileAccess*>(user);
  if (index >= 0 && size_t(index) < access.image_types.size()) access.image_types[size_t(index)] = image_type(bytes, size_t(size));
  uint64_t width = 0, height = 0;
  if (!image_size(bytes, size_t(size), &width, &height)) return true;
  const std::string pointer = "/images/" + std::to_string(index);
  if (width * height > kMaxImagePixels) {
    access.error = access.file + ": " + pointer + ": image of " + std::to_string(width) + " x " + std::to_string(height) +
                   " pixels is larger than radbake reads (" + std::to_string(kMaxImagePixels) + " pixels)";
    return false;
  }
  const bool sixteen_bit = size >= 25 && bytes[0] == 0x89 && bytes[24] == 16;
  access.estimate->data_bytes += kDecodedCopies * width * height * 4 * (sixteen_bit ? 2 : 1);
  try {
    check_budget(*access.estimate, LoadOptions{false, UINT64_MAX, access.max_memory_bytes}, access.file);
  } catch (const InputError& e) {
    access.error = e.what();
    return false;
  }
  std::string decode_error;
  if (!tinygltf::LoadImageData(image, index, &decode_error, warn, req_width, req_height, bytes, size, nullptr)) {
    image->image.clear();
    image->width = image->height = 0;
  }
  return true;
}

}  // namespace

std::string image_type(const unsigned char* bytes, size_t size) {
  if (size >= 8 && std::memcmp(bytes, kPng, 8) == 0) return "image/png";
  if (size >= 3 && bytes[0] == 0xff && bytes[1] == 0xd8 && bytes[2] == 0xff) return "image/jpeg";
  if (size >= 12 && std::memcmp(bytes, "RIFF", 4) == 0 && std::memcmp(bytes + 8, "WEBP", 4) == 0) return "image/webp";
  return "";
}

FileAccess resolve_files(const json& doc, const std::string& file, const std::string& base_dir, bool allow_external) {
  FileAccess access;
  access.file = file;
  Resolver resolver(file, base_dir, allow_external);
  const json& buffers = doc.contains("buffers") ? doc["buffers"] : json::array();
  for (size_t b = 0; b < buffers.size(); ++b) {
    if (!buffers[b].contains("uri")) continue;
    const std::string uri = buffers[b]["uri"].get<std::string>();
    const std::string pointer = "/buffers/" + std::to_string(b) + "/uri";
    const uint64_t length = buffers[b]["byteLength"].get<uint64_t>();
    uint64_t size = 0;
    if (is_data_uri(uri)) {
      if (!data_uri_size(uri, &size)) refuse(file, pointer, "data URI is not base64 of a type glTF buffers use");
      if (size != length)
        refuse(file, pointer, "data URI holds " + std::to_string(size) + " bytes, byteLength says " + std::to_string(length));
      continue;
    }
    std::string found = resolver.resolve(uri, pointer, access);
    if (found.empty()) refuse(file, pointer, "file '" + clipped(uri) + "' not found beside the scene");
    std::error_code ec;
    size = fs::file_size(found, ec);
    if (ec || size != length)
      refuse(file, pointer, "file '" + clipped(uri) + "' holds " + std::to_string(size) + " bytes, byteLength says " +
                                std::to_string(length));
  }
  const json& images = doc.contains("images") ? doc["images"] : json::array();
  access.image_files.resize(images.size());
  access.image_types.resize(images.size());
  for (size_t i = 0; i < images.size(); ++i) {
    if (!images[i].contains("uri")) continue;
    const std::string uri = images[i]["uri"].get<std::string>();
    const std::string pointer = "/images/" + std::to_string(i) + "/uri";
    uint64_t size;
    if (is_data_uri(uri)) {
      if (!data_uri_size(uri, &size)) refuse(file, pointer, "data URI is not a base64 PNG or JPEG");
      continue;
    }
    access.image_files[i] = resolver.resolve(uri, pointer, access);
  }
  return access;
}

void restrict_file_access(tinygltf::TinyGLTF& loader, FileAccess& access) {
  loader.SetFsCallbacks({&file_exists, &expand_path, &read_whole_file, &write_whole_file, &access});
  loader.SetImageLoader(&load_image, &access);
}

}  // namespace radbake
