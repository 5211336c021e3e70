// The document checked in one pass before anything is read from it: the glTF 2.0 schema
// (https://registry.khronos.org/glTF/specs/2.0/glTF-2.0.html, section 5), the rules the Khronos
// glTF-Validator adds that can be read off the JSON alone, and the bounds on what radbake
// multiplies (light intensities, emission, texture transforms). What radbake reads must be valid
// or the file is refused; what it only carries along is dropped when invalid, so the writer, which
// copies the input's JSON, only ever writes valid glTF. What the document claims about sizes and
// its node tree is the second step's (gltf_claims.cpp).
#include "io/gltf/gltf_check.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "base/errors.h"
#include "base/scene.h"
#include "io/gltf/gltf_extensions.h"

namespace radbake {
namespace {

using json = nlohmann::ordered_json;  // keeps the input's member order when the file is rewritten

constexpr double kHalfPi = 1.5707963267948966;
constexpr double kMaxTextureTransform = 1e6;  // |offset|, |scale|, |rotation|: beyond, texel lookups lose all precision
constexpr double kLargestWhole = 9007199254740992.0;  // 2^53: JSON numbers are doubles

// A schema violation at a JSON pointer. Where it is caught decides what happens: inside something
// radbake only copies, that thing is dropped; otherwise it refuses the file.
struct Violation {
  std::string pointer, what;
};

[[noreturn]] void violate(const std::string& pointer, const std::string& what) { throw Violation{pointer, what}; }

// RFC 6901: "~" and "/" in a member name are escaped.
std::string child(const std::string& at, const std::string& key) {
  std::string escaped;
  for (char c : key) escaped += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
  return at + "/" + escaped;
}
std::string child(const std::string& at, size_t i) { return at + "/" + std::to_string(i); }

bool ends_with(const std::string& s, const char* tail) {
  const size_t n = std::strlen(tail);
  return s.size() >= n && s.compare(s.size() - n, n, tail) == 0;
}

// Where an extension object sits, as gltf_extensions.h's bits; known extensions belong to one kind of object.
enum class Owner : unsigned {
  Document = kOnDocument,
  Node = kOnNode,
  Material = kOnMaterial,
  TextureInfo = kOnTextureInfo,
  Other = 0
};

// Whether an extension sits on a kind of object its row in gltf_extensions.h does not allow (the
// validator's UNEXPECTED_EXTENSION_OBJECT); extensions without a row may sit anywhere.
bool misplaced(const std::string& name, Owner owner) {
  const GltfExtension* row = gltf_extension(name);
  return row && row->sits_on != 0 && !(row->sits_on & unsigned(owner));
}

// The extensions radbake reads (gltf_extensions.h): invalid, they refuse the file; unused but
// required, they are dropped from extensionsRequired (the validator's UNUSED_EXTENSION_REQUIRED).
bool radbake_reads(const std::string& name) {
  const GltfExtension* row = gltf_extension(name);
  return row && row->refused_when_invalid;
}

bool valid_attribute_name(const std::string& name) {
  if (name == "POSITION" || name == "NORMAL" || name == "TANGENT" || name[0] == '_') return true;
  for (const char* set : {"TEXCOORD_", "COLOR_", "JOINTS_", "WEIGHTS_"}) {
    const size_t n = std::strlen(set);
    if (name.compare(0, n, set) == 0 && name.size() > n && name.find_first_not_of("0123456789", n) == std::string::npos &&
        (name.size() == n + 1 || name[n] != '0'))
      return true;
  }
  return false;
}

size_t component_bytes(int64_t component_type) {
  switch (component_type) {
    case 5120: case 5121: return 1;
    case 5122: case 5123: return 2;
    default: return 4;
  }
}

size_t components_of(const std::string& type) {
  static const std::map<std::string, size_t> kCounts = {{"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4},
                                                         {"MAT2", 4},   {"MAT3", 9}, {"MAT4", 16}};
  auto it = kCounts.find(type);
  return it == kCounts.end() ? 0 : it->second;
}

class DocumentCheck {
 public:
  DocumentCheck(json& doc, std::vector<std::string>& warnings) : doc_(doc), warnings_(warnings) {}

  // True when something was dropped or declared, so the file must be rewritten.
  bool run() {
    if (!doc_.is_object()) violate("/", "the document must be a JSON object");
    asset();
    for (const char* key : {"buffers", "bufferViews", "accessors", "images", "samplers", "textures", "meshes",
                            "materials", "nodes", "scenes"})
      collection(key);
    for (const char* key : {"cameras", "skins", "animations"}) copied_collection(key);
    each("buffers", [&](json& b, const std::string& at) { buffer(b, at); });
    each("bufferViews", [&](json& v, const std::string& at) { buffer_view(v, at); });
    each("accessors", [&](json& a, const std::string& at) { accessor(a, at); });
    each("images", [&](json& i, const std::string& at) { image(i, at); });
    each("samplers", [&](json& s, const std::string& at) { sampler(s, at); });
    each("textures", [&](json& t, const std::string& at) { texture(t, at); });
    camera_renumbering_ = drop_invalid_elements("cameras", [&](json& c, const std::string& at) { camera(c, at); });
    skin_renumbering_ = drop_invalid_elements("skins", [&](json& s, const std::string& at) { skin(s, at); });
    lights();
    each("meshes", [&](json& m, const std::string& at) { mesh(m, at); });
    each("materials", [&](json& m, const std::string& at) { material(m, at); });
    each("nodes", [&](json& n, const std::string& at) { node(n, at); });
    skin_use();
    each("scenes", [&](json& s, const std::string& at) {
      index_list(s, "nodes", at, count("nodes"), false);
      common(s, at, Owner::Other);
    });
    drop_invalid_elements("animations", [&](json& a, const std::string& at) { animation(a, at); });
    index(doc_, "scene", "", count("scenes"), "/scenes");
    common(doc_, "", Owner::Document);
    declarations();
    return changed_;
  }

 private:
  // --- values ------------------------------------------------------------------------------------

  static bool whole(const json& v) {
    if (v.is_number_integer()) return true;
    return v.is_number_float() && std::isfinite(v.get<double>()) && std::floor(v.get<double>()) == v.get<double>();
  }

  static std::string shown(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
  }

  static json* find(json& o, const std::string& key) {
    auto it = o.find(key);
    return it == o.end() ? nullptr : &*it;
  }

  // o[keys[0]][keys[1]]..., or null where a member is missing.
  static const json* find_path(const json& o, std::initializer_list<const char*> keys) {
    const json* at = &o;
    for (const char* key : keys) {
      auto it = at->find(key);
      if (it == at->end()) return nullptr;
      at = &*it;
    }
    return at;
  }

  json* object(json& o, const std::string& key, const std::string& at, bool required = false) {
    json* v = find(o, key);
    if (!v && required) violate(at, key + " is missing");
    if (v && !v->is_object()) violate(child(at, key), "must be an object");
    return v;
  }

  json* array(json& o, const std::string& key, const std::string& at, bool required = false) {
    json* v = find(o, key);
    if (!v && required) violate(at, key + " is missing");
    if (v && (!v->is_array() || v->empty())) violate(child(at, key), "must be a non-empty array");
    return v;
  }

  int64_t integer(json& o, const std::string& key, const std::string& at, double lo, double hi, bool required = false,
                  int64_t fallback = -1) {
    json* v = find(o, key);
    if (!v) {
      if (required) violate(at, key + " is missing");
      return fallback;
    }
    if (!v->is_number() || !whole(*v)) violate(child(at, key), "must be a whole number");
    const double d = v->get<double>();
    if (d < lo || d > hi) violate(child(at, key), "is " + shown(d) + "; must be from " + shown(lo) + " to " + shown(hi));
    return int64_t(d);
  }

  int64_t index(json& o, const std::string& key, const std::string& at, size_t size, const char* into,
                bool required = false) {
    if (o.contains(key) && size == 0) violate(child(at, key), std::string("refers to ") + into + ", which has none");
    return integer(o, key, at, 0, double(size) - 1, required);
  }

  // A number in [lo, hi], or (lo, hi] when `above` (the schema's exclusiveMinimum).
  double number(json& o, const std::string& key, const std::string& at, double lo, double hi, double fallback,
                bool required = false, bool above = false) {
    json* v = find(o, key);
    if (!v) {
      if (required) violate(at, key + " is missing");
      return fallback;
    }
    if (!v->is_number()) violate(child(at, key), "must be a number");
    const double d = v->get<double>();
    if (!(above ? d > lo : d >= lo) || !(d <= hi))
      violate(child(at, key), "is " + shown(d) + "; must be " + (above ? "above " : "from ") + shown(lo) +
                                  (std::isinf(hi) ? std::string(above ? "" : " up") : " to " + shown(hi)));
    return d;
  }

  // An array of `n` numbers in [lo, hi] (any length from 1 when n is 0).
  std::vector<double> numbers(json& o, const std::string& key, const std::string& at, size_t n, double lo, double hi) {
    json* v = find(o, key);
    if (!v) return {};
    const std::string p = child(at, key);
    if (!v->is_array() || (n ? v->size() != n : v->empty()))
      violate(p, n ? "must be an array of " + std::to_string(n) + " numbers" : "must be a non-empty array of numbers");
    std::vector<double> out;
    for (size_t i = 0; i < v->size(); ++i) {
      const json& e = (*v)[i];
      if (!e.is_number() || !(e.get<double>() >= lo && e.get<double>() <= hi))
        violate(child(p, i), "must be a number from " + shown(lo) + " to " + shown(hi));
      out.push_back(e.get<double>());
    }
    return out;
  }

  std::string text(json& o, const std::string& key, const std::string& at, std::initializer_list<const char*> allowed = {},
                   bool required = false) {
    json* v = find(o, key);
    if (!v) {
      if (required) violate(at, key + " is missing");
      return "";
    }
    if (!v->is_string()) violate(child(at, key), "must be a string");
    const std::string s = v->get<std::string>();
    if (allowed.size() == 0) return s;
    std::string list;
    for (const char* a : allowed) {
      if (s == a) return s;
      list += (list.empty() ? "" : ", ") + std::string(a);
    }
    violate(child(at, key), "must be one of " + list);
  }

  void boolean(json& o, const std::string& key, const std::string& at) {
    if (o.contains(key) && !o[key].is_boolean()) violate(child(at, key), "must be true or false");
  }

  // A non-empty array of distinct indices below `size`.
  void index_list(json& o, const std::string& key, const std::string& at, size_t size, bool required) {
    json* v = array(o, key, at, required);
    if (!v) return;
    std::set<int64_t> seen;
    for (size_t i = 0; i < v->size(); ++i) {
      const std::string p = child(child(at, key), i);
      if (!(*v)[i].is_number() || !whole((*v)[i]) || (*v)[i].get<double>() < 0 || (*v)[i].get<double>() >= double(size))
        violate(p, "must be an index from 0 to " + std::to_string(size) + " - 1");
      if (!seen.insert((*v)[i].get<int64_t>()).second) violate(p, "is listed twice");
    }
  }

  // --- dropping ------------------------------------------------------------------------------------

  void drop(json& o, const std::string& key, const std::string& at, const Violation& why) {
    warnings_.push_back("dropped " + child(at, key) + " from the output (" + why.pointer + " " + why.what + ")");
    o.erase(key);
    changed_ = true;
  }

  // Runs `check`; a violation inside drops o[key].
  template <class Check>
  void droppable(json& o, const std::string& key, const std::string& at, Check check) {
    if (!o.contains(key)) return;
    try {
      check();
    } catch (const Violation& why) {
      drop(o, key, at, why);
    }
  }

  // --- collections ---------------------------------------------------------------------------------

  size_t count(const char* key) const { return doc_.contains(key) ? doc_[key].size() : 0; }

  // A top-level array of objects; an empty one is dropped (the validator's EMPTY_ENTITY; the writer
  // recreates the ones it fills).
  void collection(const char* key) {
    json* list = find(doc_, key);
    if (!list) return;
    if (!list->is_array()) violate(child("", key), "must be an array");
    if (list->empty()) return drop(doc_, key, "", {child("", key), "is empty"});
    for (size_t i = 0; i < list->size(); ++i)
      if (!(*list)[i].is_object()) violate(child(child("", key), i), "must be an object");
  }

  void copied_collection(const char* key) {
    json* list = find(doc_, key);
    if (list && (!list->is_array() || list->empty())) drop(doc_, key, "", {child("", key), "must be a non-empty array"});
  }

  template <class Check>
  void each(const char* key, Check check) {
    if (!doc_.contains(key)) return;
    for (size_t i = 0; i < doc_[key].size(); ++i) check(doc_[key][i], child(child("", key), i));
  }

  // For a collection radbake only copies: invalid elements are dropped. Returns old index -> new
  // index (-1: dropped) for the references to renumber.
  template <class Check>
  std::vector<int64_t> drop_invalid_elements(const char* key, Check check) {
    std::vector<int64_t> renumbered;
    json* list = find(doc_, key);
    if (!list) return renumbered;
    json kept = json::array();
    for (size_t i = 0; i < list->size(); ++i) {
      try {
        if (!(*list)[i].is_object()) violate(child(child("", key), i), "must be an object");
        check((*list)[i], child(child("", key), i));
        renumbered.push_back(int64_t(kept.size()));
        kept.push_back(std::move((*list)[i]));
      } catch (const Violation& why) {
        warnings_.push_back("dropped " + child(child("", key), i) + " from the output (" + why.pointer + " " + why.what + ")");
        renumbered.push_back(-1);
        changed_ = true;
      }
    }
    *list = std::move(kept);
    if (list->empty()) doc_.erase(key);
    return renumbered;
  }

  // A node's reference into a collection whose invalid elements were dropped.
  void renumber(json& node, const char* key, const std::string& at, const std::vector<int64_t>& renumbering,
                const char* into) {
    droppable(node, key, at, [&] {
      const int64_t i = index(node, key, at, renumbering.size(), into);
      if (renumbering[size_t(i)] < 0) violate(child(at, key), std::string("refers to one of the ") + into + " dropped");
      if (renumbering[size_t(i)] != i) {
        node[key] = renumbering[size_t(i)];
        changed_ = true;
      }
    });
  }

  // --- what every object may carry -------------------------------------------------------------

  void common(json& o, const std::string& at, Owner owner) {
    droppable(o, "name", at, [&] { text(o, "name", at); });
    extensions(o, at, owner);
    // "extras" may hold any JSON value (glTF 2.0 section 3.12): kept as it is.
  }

  void extensions(json& o, const std::string& at, Owner owner) {
    json* all = find(o, "extensions");
    if (!all) return;
    if (!all->is_object()) return drop(o, "extensions", at, {child(at, "extensions"), "must be an object"});
    const std::string p = child(at, "extensions");
    std::vector<std::string> names;
    for (auto it = all->begin(); it != all->end(); ++it) names.push_back(it.key());
    for (const std::string& name : names) {
      if (misplaced(name, owner)) {
        drop(*all, name, p, {child(p, name), "is not an extension of this kind of object"});
        continue;
      }
      try {
        if (!(*all)[name].is_object()) violate(child(p, name), "must be an object");
        extension(name, (*all)[name], child(p, name), owner);
        used_extensions_.insert(name);
      } catch (const Violation& why) {
        if (radbake_reads(name)) throw;
        drop(*all, name, p, why);
      }
    }
    if (all->empty()) o.erase("extensions");
  }

  // The extensions radbake reads, and the Khronos material extensions it looks into; others
  // (vendor extensions the validator does not know either) are copied as they are.
  void extension(const std::string& name, json& e, const std::string& at, Owner owner) {
    if (name == "KHR_lights_punctual") {
      // The document's lights are checked by lights(), before the nodes that refer to them.
      if (owner == Owner::Node) index(e, "light", at, light_count_, "/extensions/KHR_lights_punctual/lights", true);
    } else if (name == "KHR_texture_transform") {
      numbers(e, "offset", at, 2, -kMaxTextureTransform, kMaxTextureTransform);
      number(e, "rotation", at, -kMaxTextureTransform, kMaxTextureTransform, 0);
      numbers(e, "scale", at, 2, -kMaxTextureTransform, kMaxTextureTransform);
      integer(e, "texCoord", at, 0, 1 << 30);
    } else if (name == "KHR_materials_emissive_strength") {
      number(e, "emissiveStrength", at, 0, INFINITY, 1);
    } else if (name.compare(0, 14, "KHR_materials_") == 0) {
      // Their schemas share a shape: *Factor numbers (or colours), a few other numbers, and
      // *Texture texture references.
      std::vector<std::string> keys;
      for (auto it = e.begin(); it != e.end(); ++it) keys.push_back(it.key());
      for (const std::string& key : keys) {
        if (ends_with(key, "Texture")) texture_info(e, key, at);
        else if (const MaterialNumber* range = material_number(key)) material_value(e, key, at, *range);
      }
    }
  }

  // A number of a material extension, and its schema's range: factors in [0, 1] unless listed.
  // The loader reads some of them (transmission, ior), viewers all: out of range they are clamped,
  // of another type dropped (the extension's default applies), each with a warning.
  struct MaterialNumber {
    double lo, hi;
  };
  static const MaterialNumber* material_number(const std::string& key) {
    static const MaterialNumber kFactor = {0, 1};
    static const std::map<std::string, MaterialNumber> kOthers = {
        {"thicknessFactor", {0, INFINITY}},   {"specularColorFactor", {0, INFINITY}}, {"attenuationColor", {0, 1}},
        {"ior", {1, INFINITY}},               {"iridescenceIor", {1, INFINITY}},      {"dispersion", {0, INFINITY}},
        {"iridescenceThicknessMinimum", {0, INFINITY}}, {"iridescenceThicknessMaximum", {0, INFINITY}},
        {"anisotropyStrength", {0, 1}},       {"anisotropyRotation", {-INFINITY, INFINITY}}};
    auto it = kOthers.find(key);
    if (it != kOthers.end()) return &it->second;
    return ends_with(key, "Factor") ? &kFactor : nullptr;
  }

  void material_value(json& e, const std::string& key, const std::string& at, const MaterialNumber& range) {
    json& v = e[key];
    const bool numeric = v.is_number() || (v.is_array() && !v.empty() && std::all_of(v.begin(), v.end(), [](const json& c) {
                                              return c.is_number();
                                            }));
    if (!numeric) return drop(e, key, at, {child(at, key), v.is_array() ? "must be an array of numbers" : "must be a number"});
    // KHR_materials_ior also allows 0 (glTF's "no refraction"); below 1 is no refractive index.
    const bool ior_zero = key == "ior" && v == 0;
    json clamped = v.is_array() ? v : json::array({v});
    if (!ior_zero)
      for (json& c : clamped) c = std::clamp(c.get<double>(), range.lo, range.hi);
    if (!v.is_array()) clamped = json(clamped[0]);
    if (clamped == v) return;
    warnings_.push_back("clamped " + child(at, key) + " from " + v.dump() + " to " + clamped.dump() + " (its range is " +
                        shown(range.lo) + (std::isinf(range.hi) ? " up" : " to " + shown(range.hi)) +
                        (key == "ior" ? ", or 0)" : ")"));
    v = clamped;
    changed_ = true;
  }

  // --- the document ----------------------------------------------------------------------------

  void asset() {
    json* a = object(doc_, "asset", "", true);
    const std::string version = text(*a, "version", "/asset", {}, true);
    if (version.size() < 3 || version.compare(0, 2, "2.") != 0 ||
        version.find_first_not_of("0123456789", 2) != std::string::npos)
      violate("/asset/version", "is '" + version.substr(0, 20) + "'; radbake reads glTF 2.x");
    if (a->contains("minVersion") && text(*a, "minVersion", "/asset") != "2.0")
      violate("/asset/minVersion", "must be 2.0; radbake reads glTF 2.0");
    for (const char* key : {"generator", "copyright"}) droppable(*a, key, "/asset", [&] { text(*a, key, "/asset"); });
    common(*a, "/asset", Owner::Other);
    if (doc_.contains("extras") && !doc_["extras"].is_object() && a->contains("extras") && !(*a)["extras"].is_object())
      violate("/asset/extras", "must be an object when the top-level extras is not (radbake records its bake there)");
  }

  // A data URI as glTF's readers decode it: "data:MIME;base64," then RFC 4648's alphabet, with '='
  // only as its last one or two characters.
  void data_uri(const json& o, const std::string& at) {
    if (!o.contains("uri") || !o["uri"].is_string()) return;
    const std::string& uri = o["uri"].get_ref<const std::string&>();
    if (uri.rfind("data:", 0) != 0) return;
    const size_t comma = uri.find(',');
    if (comma == std::string::npos || comma < 12 || uri.compare(comma - 7, 7, ";base64") != 0)
      violate(child(at, "uri"), "is a data URI that is not base64 (radbake reads data:MIME;base64,...)");
    size_t padding = 0;
    for (size_t k = comma + 1; k < uri.size(); ++k) {
      const unsigned char c = static_cast<unsigned char>(uri[k]);
      const bool letter = std::isalnum(c) || c == '+' || c == '/';
      padding = c == '=' ? padding + 1 : padding;
      if ((letter && padding == 0) || (c == '=' && padding <= 2)) continue;
      violate(child(at, "uri"), "is a data URI whose base64 breaks at character " + std::to_string(k - comma) + " (" +
                                    (c >= 0x20 && c < 0x7f ? "'" + std::string(1, char(c)) + "'" : "byte " + std::to_string(c)) + ")");
    }
    if ((uri.size() - comma - 1) % 4 != 0)
      violate(child(at, "uri"), "is a data URI whose base64 length is not a multiple of 4 (cut short?)");
  }

  void buffer(json& b, const std::string& at) {
    text(b, "uri", at);
    data_uri(b, at);
    integer(b, "byteLength", at, 1, kLargestWhole, true);
    common(b, at, Owner::Other);
  }

  void buffer_view(json& v, const std::string& at) {
    index(v, "buffer", at, count("buffers"), "/buffers", true);
    integer(v, "byteOffset", at, 0, kLargestWhole);
    integer(v, "byteLength", at, 1, kLargestWhole, true);
    if (integer(v, "byteStride", at, 4, 252, false, 0) % 4) violate(child(at, "byteStride"), "must be a multiple of 4");
    if (v.contains("target") && integer(v, "target", at, 0, 1 << 16) != 34962 && v["target"] != 34963)
      violate(child(at, "target"), "must be 34962 or 34963");
    common(v, at, Owner::Other);
  }

  void accessor(json& a, const std::string& at) {
    const int64_t view = index(a, "bufferView", at, count("bufferViews"), "/bufferViews");
    const int64_t offset = integer(a, "byteOffset", at, 0, kLargestWhole, false, 0);
    const int64_t component_type = integer(a, "componentType", at, 5120, 5126, true);
    if (component_type == 5124) violate(child(at, "componentType"), "must be 5120, 5121, 5122, 5123, 5125 or 5126");
    boolean(a, "normalized", at);
    if (a.value("normalized", false) && component_type > 5123)
      violate(child(at, "normalized"), "applies to byte and short components only");
    integer(a, "count", at, 1, kLargestWhole, true);
    const size_t components = components_of(text(a, "type", at, {"SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4"}, true));
    numbers(a, "min", at, components, -INFINITY, INFINITY);
    numbers(a, "max", at, components, -INFINITY, INFINITY);
    if (a.contains("byteOffset") && view < 0) violate(child(at, "byteOffset"), "needs a bufferView");
    if (view >= 0) {
      // The validator's ACCESSOR_TOTAL_OFFSET_ALIGNMENT and ACCESSOR_SMALL_BYTESTRIDE.
      const json& v = doc_["bufferViews"][size_t(view)];
      const size_t size = component_bytes(component_type);
      if ((size_t(offset) + v.value("byteOffset", size_t(0))) % size)
        violate(at, "starts at a byte offset that is not a multiple of its component size (" + std::to_string(size) + ")");
      if (v.contains("byteStride") && v["byteStride"].get<size_t>() < size * components)
        violate(at, "elements of " + std::to_string(size * components) + " bytes do not fit bufferView " +
                        std::to_string(view) + "'s byteStride");
    }
    if (json* sparse = object(a, "sparse", at)) {
      const std::string s = child(at, "sparse");
      integer(*sparse, "count", s, 1, double(a["count"].get<double>()), true);
      json* indices = object(*sparse, "indices", s, true);
      index(*indices, "bufferView", child(s, "indices"), count("bufferViews"), "/bufferViews", true);
      integer(*indices, "byteOffset", child(s, "indices"), 0, kLargestWhole);
      const int64_t type = integer(*indices, "componentType", child(s, "indices"), 5121, 5125, true);
      if (type != 5121 && type != 5123 && type != 5125) violate(child(child(s, "indices"), "componentType"), "must be 5121, 5123 or 5125");
      json* values = object(*sparse, "values", s, true);
      index(*values, "bufferView", child(s, "values"), count("bufferViews"), "/bufferViews", true);
      integer(*values, "byteOffset", child(s, "values"), 0, kLargestWhole);
    }
    common(a, at, Owner::Other);
  }

  void image(json& i, const std::string& at) {
    text(i, "uri", at);
    data_uri(i, at);
    text(i, "mimeType", at, {"image/jpeg", "image/png"});
    const bool view = index(i, "bufferView", at, count("bufferViews"), "/bufferViews") >= 0;
    if (view == i.contains("uri")) violate(at, "needs exactly one of uri and bufferView");
    if (view && !i.contains("mimeType")) violate(at, "mimeType is missing (an image in a bufferView needs one)");
    common(i, at, Owner::Other);
  }

  void sampler(json& s, const std::string& at) {
    // Only the wrap modes are read; the filters are carried along.
    droppable(s, "magFilter", at, [&] { one_of(s, "magFilter", at, {9728, 9729}); });
    droppable(s, "minFilter", at, [&] { one_of(s, "minFilter", at, {9728, 9729, 9984, 9985, 9986, 9987}); });
    for (const char* wrap : {"wrapS", "wrapT"}) one_of(s, wrap, at, {33071, 33648, 10497});
    common(s, at, Owner::Other);
  }

  void one_of(json& o, const char* key, const std::string& at, std::initializer_list<int64_t> allowed) {
    if (!o.contains(key)) return;
    const int64_t v = integer(o, key, at, 0, 1 << 16);
    for (int64_t a : allowed)
      if (v == a) return;
    std::string list;
    for (int64_t a : allowed) list += (list.empty() ? "" : ", ") + std::to_string(a);
    violate(child(at, key), "must be one of " + list);
  }

  void texture(json& t, const std::string& at) {
    index(t, "sampler", at, count("samplers"), "/samplers");
    index(t, "source", at, count("images"), "/images");
    common(t, at, Owner::Other);
  }

  void camera(json& c, const std::string& at) {
    const std::string type = text(c, "type", at, {"perspective", "orthographic"}, true);
    json* p = object(c, type, at, true);
    const std::string pp = child(at, type);
    double znear;
    if (type == "perspective") {
      number(*p, "aspectRatio", pp, 0, INFINITY, 1, false, true);
      number(*p, "yfov", pp, 0, INFINITY, 0, true, true);
      znear = number(*p, "znear", pp, 0, INFINITY, 0, true, true);
    } else {
      for (const char* key : {"xmag", "ymag"})
        if (number(*p, key, pp, -INFINITY, INFINITY, 0, true) == 0) violate(child(pp, key), "must not be zero");
      number(*p, "zfar", pp, 0, INFINITY, 0, true, true);
      znear = number(*p, "znear", pp, 0, INFINITY, 0, true);
    }
    if (number(*p, "zfar", pp, 0, INFINITY, INFINITY, false, true) <= znear) violate(child(pp, "zfar"), "must be above znear");
    common(c, at, Owner::Other);
  }

  void skin(json& s, const std::string& at) {
    index(s, "inverseBindMatrices", at, count("accessors"), "/accessors");
    index(s, "skeleton", at, count("nodes"), "/nodes");
    index_list(s, "joints", at, count("nodes"), true);
    common(s, at, Owner::Other);
  }

  void animation(json& a, const std::string& at) {
    json* samplers = array(a, "samplers", at, true);
    for (size_t i = 0; i < samplers->size(); ++i) {
      json& s = (*samplers)[i];
      const std::string sp = child(child(at, "samplers"), i);
      if (!s.is_object()) violate(sp, "must be an object");
      index(s, "input", sp, count("accessors"), "/accessors", true);
      index(s, "output", sp, count("accessors"), "/accessors", true);
      text(s, "interpolation", sp, {"LINEAR", "STEP", "CUBICSPLINE"});
    }
    json* channels = array(a, "channels", at, true);
    for (size_t i = 0; i < channels->size(); ++i) {
      json& c = (*channels)[i];
      const std::string cp = child(child(at, "channels"), i);
      if (!c.is_object()) violate(cp, "must be an object");
      index(c, "sampler", cp, samplers->size(), "the animation's samplers", true);
      json* target = object(c, "target", cp, true);
      const int64_t node = index(*target, "node", child(cp, "target"), count("nodes"), "/nodes");
      if (text(*target, "path", child(cp, "target"), {"translation", "rotation", "scale", "weights"}, true) == "weights" &&
          node >= 0 && lost_targets(node))
        violate(child(cp, "target"), "animates the weights of a mesh whose empty morph targets were dropped");
    }
    common(a, at, Owner::Other);
  }

  void lights() {
    json* all = find(doc_, "extensions");
    json* punctual = all && all->is_object() ? find(*all, "KHR_lights_punctual") : nullptr;
    if (!punctual || !punctual->is_object()) return;
    const std::string at = "/extensions/KHR_lights_punctual";
    json* list = array(*punctual, "lights", at, true);
    for (size_t i = 0; i < list->size(); ++i) {
      json& light = (*list)[i];
      const std::string lp = child(child(at, "lights"), i);
      if (!light.is_object()) violate(lp, "must be an object");
      const std::string type = text(light, "type", lp, {"point", "spot", "directional"}, true);
      const std::vector<double> color = numbers(light, "color", lp, 3, 0, 1);
      const double intensity = number(light, "intensity", lp, 0, INFINITY, 1);
      const double brightest = color.empty() ? 1 : *std::max_element(color.begin(), color.end());
      if (intensity * brightest > kMaxLightIntensity)
        violate(child(lp, "intensity"), shown(intensity * brightest) + (type == "directional" ? " lx" : " cd") +
                                            " is above the " + shown(kMaxLightIntensity) + " radbake bakes");
      number(light, "range", lp, 0, INFINITY, 1, false, true);
      if (json* spot = object(light, "spot", lp, type == "spot")) {
        const std::string sp = child(lp, "spot");
        const double outer = number(*spot, "outerConeAngle", sp, 0, kHalfPi, kHalfPi / 2, false, true);
        if (number(*spot, "innerConeAngle", sp, 0, kHalfPi, 0) >= outer)
          violate(child(sp, "innerConeAngle"), "must be below outerConeAngle");
      }
      common(light, lp, Owner::Other);
    }
    light_count_ = list->size();
  }

  void mesh(json& m, const std::string& at) {
    json* primitives = array(m, "primitives", at, true);
    size_t targets = 0;
    for (size_t k = 0; k < primitives->size(); ++k) {
      json& prim = (*primitives)[k];
      const std::string pp = child(child(at, "primitives"), k);
      if (!prim.is_object()) violate(pp, "must be an object");
      json* attributes = object(prim, "attributes", pp, true);
      const std::string ap = child(pp, "attributes");
      std::vector<std::string> names;
      for (auto it = attributes->begin(); it != attributes->end(); ++it) names.push_back(it.key());
      for (const std::string& name : names) {
        if (!valid_attribute_name(name)) drop(*attributes, name, ap, {child(ap, name), "is not a glTF attribute name"});
        else index(*attributes, name, ap, count("accessors"), "/accessors");
      }
      // Skinning attributes come in pairs (JOINTS_n with WEIGHTS_n); radbake only carries them.
      for (const std::string& name : names)
        for (const auto& [mine, other] : {std::pair<std::string, std::string>{"JOINTS_", "WEIGHTS_"}, {"WEIGHTS_", "JOINTS_"}})
          if (name.compare(0, mine.size(), mine) == 0 && attributes->contains(name) &&
              !attributes->contains(other + name.substr(mine.size())))
            drop(*attributes, name, ap, {ap, other + name.substr(mine.size()) + " is missing"});
      if (attributes->empty()) violate(ap, "must name at least one attribute");
      if (!attributes->contains("POSITION")) violate(child(ap, "POSITION"), "missing");
      attribute_types(*attributes, ap);
      const int64_t indices = index(prim, "indices", pp, count("accessors"), "/accessors");
      // Unsigned byte, short and int are the odd component types.
      if (indices >= 0 && (accessor_type(indices) != "SCALAR" ||
                           doc_["accessors"][size_t(indices)]["componentType"].get<int64_t>() % 2 == 0))
        violate(child(pp, "indices"), "accessor " + std::to_string(indices) + " must be SCALAR unsigned byte, short or int");
      const int64_t material = index(prim, "material", pp, count("materials"), "/materials");
      integer(prim, "mode", pp, 0, 6);
      if (json* list = array(prim, "targets", pp)) {
        for (size_t t = 0; t < list->size(); ++t) {
          json& target = (*list)[t];
          const std::string tp = child(child(pp, "targets"), t);
          if (!target.is_object()) violate(tp, "must be an object");
          for (auto it = target.begin(); it != target.end(); ++it) index(target, it.key(), tp, count("accessors"), "/accessors");
        }
        targets = list->size();
      }
      // What texture coordinates every primitive using a material has (see texture_info).
      std::set<int64_t> sets;
      for (const std::string& name : names)
        if (name.compare(0, 9, "TEXCOORD_") == 0 && attributes->contains(name)) sets.insert(std::stoll(name.substr(9)));
      if (material < 0) continue;
      auto [it, first] = texcoords_of_material_.emplace(material, sets);
      if (!first)
        for (auto s = it->second.begin(); s != it->second.end();) s = sets.count(*s) ? std::next(s) : it->second.erase(s);
    }
    // After the primitives: dropping moves m's members, and `primitives` with them.
    dropped_targets_.push_back(drop_empty_targets(m, at));
    if (!dropped_targets_.back().empty()) targets = m["primitives"].back().value("targets", json::array()).size();
    morph_targets_.push_back(targets);
    droppable(m, "weights", at, [&] { weights(m, at, targets); });
    common(m, at, Owner::Other);
  }

  // Empty morph targets move nothing (the validator's EMPTY_ENTITY). Target t goes from every
  // primitive when it is empty in one, so the primitives keep equal counts, and its weight with it.
  // Returns the indices dropped.
  std::set<size_t> drop_empty_targets(json& m, const std::string& at) {
    std::set<size_t> empty;
    std::string example;
    json& primitives = m["primitives"];
    for (size_t k = 0; k < primitives.size(); ++k)
      for (size_t t = 0; t < primitives[k].value("targets", json::array()).size(); ++t)
        if (primitives[k]["targets"][t].empty() && empty.insert(t).second && example.empty())
          example = child(child(child(child(at, "primitives"), k), "targets"), t);
    if (empty.empty()) return empty;
    for (json& prim : primitives) {
      if (!prim.contains("targets")) continue;
      erase_elements(prim["targets"], empty);
      if (prim["targets"].empty()) prim.erase("targets");
    }
    if (m.contains("weights") && m["weights"].is_array()) erase_elements(m["weights"], empty);
    if (m.contains("weights") && m["weights"].empty()) m.erase("weights");
    warnings_.push_back("dropped " + std::to_string(empty.size()) + " empty morph targets of " + at +
                        " from the output, with their weights (" + example + " is empty)");
    changed_ = true;
    return empty;
  }

  static void erase_elements(json& list, const std::set<size_t>& indices) {
    json kept = json::array();
    for (size_t i = 0; i < list.size(); ++i)
      if (!indices.count(i)) kept.push_back(std::move(list[i]));
    list = std::move(kept);
  }

  // Whether node `n`'s mesh lost morph targets as empty (so its weights have fewer entries).
  bool lost_targets(int64_t n) const {
    const json& node = doc_["nodes"][size_t(n)];
    return node.contains("mesh") && !dropped_targets_[node["mesh"].get<size_t>()].empty();
  }

  const std::string& accessor_type(int64_t accessor) const {
    return doc_["accessors"][size_t(accessor)]["type"].get_ref<const std::string&>();
  }

  // The accessor types glTF requires of the attributes radbake reads (glTF 2.0 section 3.7.2.1).
  void attribute_types(const json& attributes, const std::string& at) const {
    static const std::pair<const char*, std::vector<std::string>> kTypes[] = {
        {"POSITION", {"VEC3"}}, {"NORMAL", {"VEC3"}}, {"TANGENT", {"VEC4"}}, {"TEXCOORD_", {"VEC2"}}, {"COLOR_", {"VEC3", "VEC4"}}};
    for (auto it = attributes.begin(); it != attributes.end(); ++it)
      for (const auto& [name, types] : kTypes) {
        if (it.key().rfind(name, 0) != 0) continue;
        const std::string& type = accessor_type(it.value().get<int64_t>());
        if (std::find(types.begin(), types.end(), type) == types.end())
          violate(child(at, it.key()), "is " + type + "; glTF requires " + types[0] + (types.size() > 1 ? " or " + types[1] : ""));
      }
  }

  void weights(json& o, const std::string& at, size_t targets) {
    numbers(o, "weights", at, 0, -INFINITY, INFINITY);
    if (o["weights"].size() != targets)
      violate(child(at, "weights"), "has " + std::to_string(o["weights"].size()) + " entries for " +
                                        std::to_string(targets) + " morph targets");
  }

  // A texture reference (glTF 2.0 textureInfo); `at` is its owner's pointer.
  void texture_info(json& owner, const std::string& key, const std::string& at, int64_t material = -1) {
    json* info = object(owner, key, at);
    if (!info) return;
    const std::string p = child(at, key);
    index(*info, "index", p, count("textures"), "/textures", true);
    int64_t set = integer(*info, "texCoord", p, 0, 1 << 30, false, 0);
    extensions(*info, p, Owner::TextureInfo);
    json* ext = find(*info, "extensions");
    if (ext && ext->contains("KHR_texture_transform")) set = (*ext)["KHR_texture_transform"].value("texCoord", set);
    // The validator's MESH_PRIMITIVE_TOO_FEW_TEXCOORDS: every primitive using the material has the set.
    auto sets = texcoords_of_material_.find(material);
    if (sets != texcoords_of_material_.end() && !sets->second.count(set))
      violate(p, "reads TEXCOORD_" + std::to_string(set) + ", which a primitive using the material does not have");
  }

  // KHR_materials_pbrSpecularGlossiness is archived: beside any other extension (MOZ_lightmap,
  // which every baked material gets) the validator warns MULTIPLE_EXTENSIONS, and current viewers
  // (three.js since r147, Blender's importer) show the metallic-roughness material instead. So the
  // extension is dropped; a material that gives no metallic-roughness fallback gets the one its
  // diffuse part makes (base colour = diffuse, metallic 0, roughness 1 - glossiness), which is
  // all a diffuse bake reads. A fallback the file gives is kept as it is: exporters put what they
  // mean there (assimp writes a glass's alpha only into it).
  void drop_specular_glossiness(json& m, const std::string& at) {
    json* all = find(m, "extensions");
    if (!all || !all->is_object() || !all->contains(kSpecularGlossiness)) return;
    json spec = (*all)[kSpecularGlossiness];
    all->erase(kSpecularGlossiness);
    if (all->empty()) m.erase("extensions");
    converted_specular_glossiness_ = true;
    changed_ = true;
    const std::string what = "dropped " + at + "/extensions/" + kSpecularGlossiness + " (archived)";
    if (m.contains("pbrMetallicRoughness")) {
      warnings_.push_back(what + "; its metallic-roughness material is the one current viewers show, kept");
      return;
    }
    json pbr = json::object();
    if (spec.is_object()) {
      if (spec.contains("diffuseFactor")) pbr["baseColorFactor"] = spec["diffuseFactor"];
      if (spec.contains("diffuseTexture")) pbr["baseColorTexture"] = spec["diffuseTexture"];
      const json glossiness = spec.value("glossinessFactor", json(1.0));
      pbr["roughnessFactor"] = glossiness.is_number() ? 1.0 - std::clamp(glossiness.get<double>(), 0.0, 1.0) : 0.0;
    }
    pbr["metallicFactor"] = 0.0;
    m["pbrMetallicRoughness"] = pbr;
    warnings_.push_back(what + "; it gave no metallic-roughness material, so its diffuse part became one: base colour = "
                        "diffuse, metallic 0, roughness 1 - glossiness");
  }

  void material(json& m, const std::string& at) {
    const int64_t self = std::stoll(at.substr(at.rfind('/') + 1));
    drop_specular_glossiness(m, at);
    if (json* pbr = object(m, "pbrMetallicRoughness", at)) {
      const std::string p = child(at, "pbrMetallicRoughness");
      numbers(*pbr, "baseColorFactor", p, 4, 0, 1);
      texture_info(*pbr, "baseColorTexture", p, self);
      number(*pbr, "metallicFactor", p, 0, 1, 1);
      droppable(*pbr, "roughnessFactor", p, [&] { number(*pbr, "roughnessFactor", p, 0, 1, 1); });
      texture_info(*pbr, "metallicRoughnessTexture", p, self);
      common(*pbr, p, Owner::Other);
    }
    // Normal and occlusion maps play no part in a diffuse bake: carried along when valid.
    droppable(m, "normalTexture", at, [&] {
      texture_info(m, "normalTexture", at, self);
      number(m["normalTexture"], "scale", child(at, "normalTexture"), -INFINITY, INFINITY, 1);
    });
    droppable(m, "occlusionTexture", at, [&] {
      texture_info(m, "occlusionTexture", at, self);
      number(m["occlusionTexture"], "strength", child(at, "occlusionTexture"), 0, 1, 1);
    });
    texture_info(m, "emissiveTexture", at, self);
    numbers(m, "emissiveFactor", at, 3, 0, 1);
    text(m, "alphaMode", at, {"OPAQUE", "MASK", "BLEND"});
    droppable(m, "alphaCutoff", at, [&] { number(m, "alphaCutoff", at, 0, INFINITY, 0.5); });
    boolean(m, "doubleSided", at);
    common(m, at, Owner::Material);
    const json* strength = find_path(m, {"extensions", "KHR_materials_emissive_strength"});
    if (!strength || !strength->contains("emissiveStrength")) return;
    double brightest = 0;
    if (m.contains("emissiveFactor"))
      for (const json& c : m["emissiveFactor"]) brightest = std::max(brightest, c.get<double>());
    const double luminance = brightest * (*strength)["emissiveStrength"].get<double>();
    if (luminance > kMaxLuminance)
      violate(at + "/extensions/KHR_materials_emissive_strength/emissiveStrength",
              "gives a luminance of " + shown(luminance) + " cd/m2, above the " + shown(kMaxLuminance) + " radbake bakes");
  }

  void node(json& n, const std::string& at) {
    renumber(n, "camera", at, camera_renumbering_, "/cameras");
    renumber(n, "skin", at, skin_renumbering_, "/skins");
    index_list(n, "children", at, count("nodes"), false);
    const int64_t mesh = index(n, "mesh", at, count("meshes"), "/meshes");
    if (n.contains("matrix")) {
      const std::vector<double> m = numbers(n, "matrix", at, 16, -INFINITY, INFINITY);
      if (m[3] != 0 || m[7] != 0 || m[11] != 0 || m[15] != 1)
        violate(child(at, "matrix"), "must be an affine transform (its last row 0, 0, 0, 1)");
      for (const char* trs : {"translation", "rotation", "scale"})
        if (n.contains(trs)) violate(at, std::string("has both matrix and ") + trs);
    }
    numbers(n, "translation", at, 3, -INFINITY, INFINITY);
    const std::vector<double> q = numbers(n, "rotation", at, 4, -1, 1);
    // The validator's NODE_ROTATION_NON_UNIT tolerance.
    if (!q.empty() && std::fabs(std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]) - 1) > 4e-6)
      violate(child(at, "rotation"), "must be a unit quaternion");
    numbers(n, "scale", at, 3, -INFINITY, INFINITY);
    if (mesh >= 0 && n.contains("weights") && n["weights"].is_array() &&
        n["weights"].size() == morph_targets_[size_t(mesh)] + dropped_targets_[size_t(mesh)].size()) {
      erase_elements(n["weights"], dropped_targets_[size_t(mesh)]);
      if (n["weights"].empty()) n.erase("weights");
    }
    droppable(n, "weights", at, [&] { weights(n, at, mesh >= 0 ? morph_targets_[size_t(mesh)] : 0); });
    common(n, at, Owner::Node);
  }

  // A mesh moves with a skin when every primitive has joints and every node showing it has a skin
  // (the validator's NODE_SKIN_WITH_NON_SKINNED_MESH and NODE_SKINNED_MESH_WITHOUT_SKIN). Where that
  // fails, the mesh's joints and weights go, then the skins of nodes whose mesh has none (radbake
  // bakes a skinned mesh where its node puts it, unposed, so nothing it baked moves with the skin).
  void skin_use() {
    if (!doc_.contains("nodes")) return;
    json& nodes = doc_["nodes"];
    auto skinning = [](const std::string& name) { return name.rfind("JOINTS_", 0) == 0 || name.rfind("WEIGHTS_", 0) == 0; };
    std::map<int64_t, Violation> unskinned;  // mesh -> why
    for (size_t n = 0; n < nodes.size(); ++n) {
      if (!nodes[n].contains("mesh")) continue;
      const int64_t mesh = nodes[n]["mesh"].get<int64_t>();
      size_t with_joints = 0, primitives = 0;
      for (const json& prim : doc_["meshes"][size_t(mesh)]["primitives"]) {
        ++primitives;
        with_joints += prim["attributes"].contains("JOINTS_0");
      }
      if (with_joints == 0) continue;
      if (with_joints < primitives) unskinned.emplace(mesh, Violation{child("/meshes", size_t(mesh)), "has primitives without JOINTS_0"});
      else if (!nodes[n].contains("skin")) unskinned.emplace(mesh, Violation{child("/nodes", n), "shows the mesh without a skin"});
    }
    for (const auto& [mesh, why] : unskinned) {
      const std::string at = child("/meshes", size_t(mesh));
      json& primitives = doc_["meshes"][size_t(mesh)]["primitives"];
      for (size_t k = 0; k < primitives.size(); ++k) {
        json& attributes = primitives[k]["attributes"];
        std::vector<std::string> names;
        for (auto it = attributes.begin(); it != attributes.end(); ++it)
          if (skinning(it.key())) names.push_back(it.key());
        for (const std::string& name : names)
          drop(attributes, name, child(child(child(at, "primitives"), k), "attributes"), why);
      }
    }
    for (size_t n = 0; n < nodes.size(); ++n) {
      if (!nodes[n].contains("skin") || !nodes[n].contains("mesh")) continue;
      const json& primitives = doc_["meshes"][nodes[n]["mesh"].get<size_t>()]["primitives"];
      if (std::none_of(primitives.begin(), primitives.end(), [](const json& p) { return p["attributes"].contains("JOINTS_0"); }))
        drop(nodes[n], "skin", child("/nodes", n), {child(child("/meshes", nodes[n]["mesh"].get<size_t>()), "primitives"),
                                                     "have no joints for the skin to move"});
    }
  }

  // extensionsUsed lists every extension the file uses, once; extensionsRequired only used ones.
  void declarations() {
    std::vector<std::string> used = declared("extensionsUsed");
    const bool converted_away = converted_specular_glossiness_ && !used_extensions_.count(kSpecularGlossiness);
    if (converted_away) used.erase(std::remove(used.begin(), used.end(), kSpecularGlossiness), used.end());
    for (const std::string& name : used_extensions_)
      if (std::find(used.begin(), used.end(), name) == used.end()) {
        warnings_.push_back("declared " + name + " in /extensionsUsed (the file uses it without declaring it)");
        used.push_back(name);
        changed_ = true;
      }
    std::vector<std::string> required = declared("extensionsRequired");
    if (converted_away) required.erase(std::remove(required.begin(), required.end(), kSpecularGlossiness), required.end());
    for (auto it = required.begin(); it != required.end();) {
      if (radbake_reads(*it) && !used_extensions_.count(*it)) {
        warnings_.push_back("dropped " + *it + " from /extensionsRequired (nothing in the file uses it)");
        it = required.erase(it);
        changed_ = true;
        continue;
      }
      if (std::find(used.begin(), used.end(), *it) == used.end()) {
        used.push_back(*it);
        changed_ = true;
      }
      ++it;
    }
    auto set = [&](const char* key, const std::vector<std::string>& list) {
      if (list.empty()) doc_.erase(key);
      else doc_[key] = list;
    };
    set("extensionsUsed", used);
    set("extensionsRequired", required);
  }

  // A declaration list's valid, distinct names; anything else in it dropped with a warning.
  std::vector<std::string> declared(const char* key) {
    std::vector<std::string> names;
    json* list = find(doc_, key);
    if (!list) return names;
    if (!list->is_array()) {
      drop(doc_, key, "", {child("", key), "must be an array of names"});
      return names;
    }
    for (size_t i = 0; i < list->size(); ++i) {
      const json& v = (*list)[i];
      if (v.is_string() && std::find(names.begin(), names.end(), v.get<std::string>()) == names.end()) {
        names.push_back(v.get<std::string>());
        continue;
      }
      warnings_.push_back("dropped " + child(child("", key), i) + " from the output (" +
                          (v.is_string() ? "listed twice" : "not a name") + ")");
      changed_ = true;
    }
    return names;
  }

  json& doc_;
  std::vector<std::string>& warnings_;
  bool changed_ = false;
  static constexpr const char* kSpecularGlossiness = "KHR_materials_pbrSpecularGlossiness";
  bool converted_specular_glossiness_ = false;
  std::set<std::string> used_extensions_;
  std::vector<int64_t> camera_renumbering_, skin_renumbering_;
  std::map<int64_t, std::set<int64_t>> texcoords_of_material_;
  std::vector<size_t> morph_targets_;  // per mesh
  std::vector<std::set<size_t>> dropped_targets_;  // per mesh: the empty morph targets dropped
  size_t light_count_ = 0;
};

}  // namespace

void refuse(const std::string& file, const std::string& pointer, const std::string& what) {
  throw InputError(clipped(file) + ": " + pointer + ": " + what);
}

bool check_document(json& doc, const std::string& file, std::vector<std::string>& warnings) {
  try {
    return DocumentCheck(doc, warnings).run();
  } catch (const Violation& v) {
    refuse(file, v.pointer.empty() ? "/" : v.pointer, v.what);
  }
}

}  // namespace radbake
