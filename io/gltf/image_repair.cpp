#include "io/gltf/image_repair.h"

#include <algorithm>
#include <set>

#include "io/gltf/base64.h"

namespace radbake {
namespace {

using json = nlohmann::ordered_json;

const char* const kWebp = "EXT_texture_webp";

bool named_by_webp(const tinygltf::Model& model, size_t image) {
  return std::any_of(model.textures.begin(), model.textures.end(), [&](const tinygltf::Texture& t) {
    auto it = t.extensions.find(kWebp);
    return it != t.extensions.end() && it->second.Has("source") && it->second.Get("source").IsNumber() &&
           it->second.Get("source").GetNumberAsDouble() == double(image);
  });
}

// The image a texture extension's `source` names, or -1 when it names none of the `count`.
int64_t extension_source(const json& extension, size_t count) {
  if (!extension.is_object() || !extension.contains("source") || !extension["source"].is_number_integer()) return -1;
  const int64_t s = extension["source"].get<int64_t>();
  return s >= 0 && size_t(s) < count ? s : -1;
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// Removes every texture reference (textureInfo) under `node` to a texture in `blank`.
void drop_texture_references(json& node, const std::set<int64_t>& blank) {
  if (node.is_array()) {
    for (json& v : node) drop_texture_references(v, blank);
    return;
  }
  if (!node.is_object()) return;
  std::vector<std::string> gone;
  for (auto it = node.begin(); it != node.end(); ++it) {
    const bool reference = (ends_with(it.key(), "Texture") || it.key() == "MOZ_lightmap") && it.value().is_object() &&
                           it.value().contains("index") && it.value()["index"].is_number_integer();
    if (reference && blank.count(it.value()["index"].get<int64_t>())) gone.push_back(it.key());
    else drop_texture_references(it.value(), blank);
  }
  for (const std::string& key : gone) node.erase(key);
}

std::string format_name(const std::string& type) {
  return type == "image/png" ? "PNG" : type == "image/jpeg" ? "JPEG" : type == "image/webp" ? "WebP" : "of no known format";
}

}  // namespace

std::string unwritable_image(const GltfSource& source, size_t i) {
  const tinygltf::Image& image = source.model.images[i];
  const std::string& type = i < source.image_types.size() ? source.image_types[i] : std::string();
  if (type == "image/png" || type == "image/jpeg")
    return image.image.empty() ? "a " + format_name(type) + " that does not decode" : "";
  if (type == "image/webp") return named_by_webp(source.model, i) ? "" : "WebP, which glTF allows only through EXT_texture_webp";
  if (!image.uri.empty() && (i >= source.image_files.size() || source.image_files[i].empty()))
    return "its file was not found";
  return "neither PNG nor JPEG, glTF's image formats";
}

namespace {

// mimeType, and a data URI's media type, as the bytes of the image say (IMAGE_MIME_TYPE_INVALID).
void declare_types(json& images, const GltfSource& source, const std::vector<uint8_t>& keep,
                   std::vector<std::string>& warnings) {
  for (size_t i = 0; i < images.size(); ++i) {
    if (!keep[i]) continue;
    json& image = images[i];
    const std::string at = "/images/" + std::to_string(i), &type = source.image_types[i];
    if (image.contains("mimeType") && image["mimeType"] != type) {
      warnings.push_back(at + "/mimeType: " + image["mimeType"].get<std::string>() + ", but the bytes are " +
                         format_name(type) + "; written as " + type);
      image["mimeType"] = type;
    }
    const std::string uri = image.value("uri", "");
    const size_t comma = uri.find(',');
    if (uri.rfind("data:", 0) != 0 || comma == std::string::npos || uri.rfind("data:" + type + ";", 0) == 0) continue;
    const size_t end = std::min(uri.find(';'), comma);
    const std::string declared = uri.substr(5, end - 5);
    warnings.push_back(at + "/uri: a data URI of " + (declared.empty() ? "no media type" : declared) +
                       ", but the bytes are " + format_name(type) + "; written as " + type);
    image["uri"] = "data:" + type + uri.substr(end);
  }
}

// Texture `t`'s extensions naming an image not written, or EXT_texture_webp naming one that is no
// WebP, dropped (their names added to `dropped`); its source removed where that image is not
// written or is WebP (TEXTURE_INVALID_IMAGE_MIME_TYPE). Returns whether the texture has an image left.
bool repair_texture(json& texture, size_t t, const GltfSource& source, const std::vector<uint8_t>& keep,
                    std::set<std::string>& dropped, std::vector<std::string>& warnings) {
  const std::string at = "/textures/" + std::to_string(t);
  auto type = [&](int64_t i) { return source.image_types[size_t(i)]; };
  if (texture.contains("extensions") && texture["extensions"].is_object()) {
    json& extensions = texture["extensions"];
    std::vector<std::string> names;
    for (auto it = extensions.begin(); it != extensions.end(); ++it)
      if (it.value().is_object() && it.value().contains("source")) names.push_back(it.key());
    int64_t fallback = -1;  // set after the loop: a new member moves an ordered_json object's others
    for (const std::string& name : names) {
      const int64_t s = extension_source(extensions[name], keep.size());
      const std::string image = "/images/" + std::to_string(s);
      std::string why;
      if (s < 0) why = "names no image";
      else if (!keep[size_t(s)]) why = image + " is not written";
      else if (name == kWebp && type(s) != "image/webp") why = image + " is " + format_name(type(s)) + ", not WebP";
      if (why.empty()) continue;
      if (name == kWebp && s >= 0 && keep[size_t(s)] && !texture.contains("source")) {
        fallback = s;
        why += "; " + image + " is the texture's source instead";
      }
      warnings.push_back("dropped " + at + "/extensions/" + name + " from the output (" + why + ")");
      extensions.erase(name);
      dropped.insert(name);
    }
    if (extensions.empty()) texture.erase("extensions");
    if (fallback >= 0) texture["source"] = fallback;
  }
  if (texture.contains("source")) {
    const int64_t s = texture["source"].get<int64_t>();
    // An image not written has had its warning from the loader, which says its textures go.
    if (keep[size_t(s)] && type(s) == "image/webp")
      warnings.push_back("dropped " + at + "/source from the output (/images/" + std::to_string(s) +
                         " is WebP, which a texture names only through EXT_texture_webp)");
    if (!keep[size_t(s)] || type(s) == "image/webp") texture.erase("source");
  }
  bool has_image = texture.contains("source");
  if (texture.contains("extensions"))
    for (const json& e : texture["extensions"]) has_image |= extension_source(e, keep.size()) >= 0;
  return has_image;
}

// Extensions in `names` that no texture uses any more, taken out of the declarations.
void undeclare(json& doc, const std::set<std::string>& names) {
  for (const std::string& name : names) {
    const json& textures = doc["textures"];
    if (std::any_of(textures.begin(), textures.end(),
                    [&](const json& t) { return t.contains("extensions") && t["extensions"].contains(name); }))
      continue;
    for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
      if (!doc.contains(key)) continue;
      json& list = doc[key];
      list.erase(std::remove(list.begin(), list.end(), json(name)), list.end());
      if (list.empty()) doc.erase(key);
    }
  }
}

uint32_t big_endian(const std::string& b, size_t at) {
  return uint32_t(uint8_t(b[at])) << 24 | uint32_t(uint8_t(b[at + 1])) << 16 | uint32_t(uint8_t(b[at + 2])) << 8 |
         uint32_t(uint8_t(b[at + 3]));
}

// Whether the validator accepts the chunk `type` with `data` (its PNG reader's rules): cHRM only
// with sRGB's primaries and white, gAMA only 1/2.2 or 1, pHYs only square pixels.
bool plain_chunk(const std::string& type, const std::string& bytes, size_t data, uint32_t length) {
  if (type == "iCCP" || type == "acTL" || type == "fcTL" || type == "fdAT") return false;
  if (type == "cHRM") {
    static const uint32_t kSrgb[8] = {31270, 32900, 64000, 33000, 30000, 60000, 15000, 6000};
    if (length != 32) return false;
    for (size_t k = 0; k < 8; ++k)
      if (big_endian(bytes, data + 4 * k) != kSrgb[k]) return false;
  }
  if (type == "gAMA") return length == 4 && (big_endian(bytes, data) == 45455 || big_endian(bytes, data) == 100000);
  if (type == "pHYs") return length == 9 && big_endian(bytes, data) == big_endian(bytes, data + 4);
  return true;
}

}  // namespace

std::string make_png_plain(std::string& bytes, const std::string& pointer) {
  static const char kSignature[] = "\x89PNG\r\n\x1a\n";
  if (bytes.size() < 8 || bytes.compare(0, 8, kSignature, 8) != 0) return "";
  std::string kept = bytes.substr(0, 8);
  std::vector<std::string> dropped;
  for (size_t at = 8; at + 12 <= bytes.size();) {
    const uint32_t length = big_endian(bytes, at);
    if (length > bytes.size() - at - 12) return "";  // cut short: left as it is, the validator judges it
    const std::string type = bytes.substr(at + 4, 4);
    if (plain_chunk(type, bytes, at + 8, length)) kept.append(bytes, at, 12 + size_t(length));
    else if (std::find(dropped.begin(), dropped.end(), type) == dropped.end()) dropped.push_back(type);
    at += 12 + size_t(length);
  }
  if (dropped.empty()) return "";
  bytes = std::move(kept);
  std::string names;
  for (const std::string& d : dropped) names += (names.empty() ? "" : ", ") + d;
  return pointer + ": took its PNG's " + names + (dropped.size() == 1 ? " chunk" : " chunks") + " out (a colour space other than sRGB, non-square pixels or " +
         "animation, which glTF viewers ignore and the validator flags as IMAGE_FEATURES_UNSUPPORTED)";
}

std::vector<uint8_t> repair_images(json& doc, const GltfSource& source, std::vector<std::string>& warnings) {
  if (!doc.contains("images")) return {};
  std::vector<uint8_t> keep(doc["images"].size());
  for (size_t i = 0; i < keep.size(); ++i) keep[i] = unwritable_image(source, i).empty();
  declare_types(doc["images"], source, keep, warnings);
  for (size_t i = 0; i < keep.size(); ++i) {
    json& image = doc["images"][i];
    const std::string uri = image.value("uri", ""), header = "data:image/png;base64,";
    if (!keep[i] || uri.rfind(header, 0) != 0) continue;
    std::string png = from_base64(uri.substr(header.size()));
    const std::string warning = make_png_plain(png, "/images/" + std::to_string(i));
    if (warning.empty()) continue;
    image["uri"] = header + to_base64(png);
    warnings.push_back(warning);
  }
  if (!doc.contains("textures")) return keep;
  std::set<int64_t> blank;  // textures left with no image
  std::set<std::string> dropped;
  for (size_t t = 0; t < doc["textures"].size(); ++t)
    if (!repair_texture(doc["textures"][t], t, source, keep, dropped, warnings)) blank.insert(int64_t(t));
  if (!blank.empty() && doc.contains("materials")) drop_texture_references(doc["materials"], blank);
  undeclare(doc, dropped);
  return keep;
}

}  // namespace radbake
