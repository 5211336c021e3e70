// The document checked before anything is built from it. Every complaint names the JSON pointer
// of the object at fault, and every size a later stage allocates from (accessor counts, buffer
// lengths, instanced triangles) is checked against what the file holds or against the budget
// first, so a file can only make radbake allocate what it really contains.
#include <algorithm>
#include <cmath>

#include "baker/errors.h"
#include "io/gltf_source.h"

namespace radbake {
namespace {

using json = nlohmann::json;

constexpr double kMaxTextureTransform = 1e6; // |offset|, |scale|, |rotation|
constexpr uint64_t kLargestWhole = uint64_t(1) << 53;  // JSON numbers are doubles

constexpr int kComponentTypes[] = {5120, 5121, 5122, 5123, 5125, 5126};
const char* const kCollections[] = {"accessors", "animations", "buffers", "bufferViews", "cameras", "images",
                                    "materials", "meshes",     "nodes",   "samplers",    "scenes",  "skins",
                                    "textures"};

size_t elements_of_type(const std::string& type) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4" || type == "MAT2") return 4;
  if (type == "MAT3") return 9;
  if (type == "MAT4") return 16;
  return 0;
}

size_t bytes_of_component(int component_type) {
  switch (component_type) {
    case 5120: case 5121: return 1;
    case 5122: case 5123: return 2;
    default: return 4;
  }
}

class DocumentCheck {
 public:
  DocumentCheck(const json& doc, const std::string& file, size_t glb_bin_size)
      : doc_(doc), file_(file), glb_bin_size_(glb_bin_size) {}

  ResourceEstimate run() {
    if (!doc_.is_object()) fail("", "the document is not a JSON object");
    if (!doc_.contains("asset") || !doc_["asset"].is_object()) fail("/asset", "missing (every glTF file has one)");
    for (const char* key : kCollections) collection(key);
    for (const char* key : {"extensionsUsed", "extensionsRequired"}) strings(doc_, key, std::string("/") + key);
    if (doc_.contains("extras") && !doc_["extras"].is_object() && doc_["asset"].contains("extras") &&
        !doc_["asset"]["extras"].is_object())
      fail("/asset/extras", "must be an object when the top-level extras is not (radbake records its bake there)");
    check_buffers();
    check_buffer_views();
    check_accessors();
    check_images_and_textures();
    check_materials();
    check_meshes();
    check_lights();
    check_nodes();
    return estimate();
  }

 private:
  [[noreturn]] void fail(const std::string& pointer, const std::string& what) const {
    refuse(file_, pointer.empty() ? "/" : pointer, what);
  }

  const json& collection(const char* key) const {
    static const json kNone = json::array();
    if (!doc_.contains(key)) return kNone;
    const json& list = doc_[key];
    const std::string pointer = std::string("/") + key;
    if (!list.is_array()) fail(pointer, "must be an array");
    for (size_t i = 0; i < list.size(); ++i) {
      const std::string at = pointer + "/" + std::to_string(i);
      if (!list[i].is_object()) fail(at, "must be an object");
      text(list[i], "name", at);
      if (list[i].contains("extensions") && !list[i]["extensions"].is_object()) fail(at + "/extensions", "must be an object");
    }
    return list;
  }

  size_t count_of(const char* key) const { return collection(key).size(); }

  void text(const json& object, const char* key, const std::string& pointer) const {
    if (object.contains(key) && !object[key].is_string()) fail(pointer + "/" + key, "must be a string");
  }

  void strings(const json& object, const char* key, const std::string& pointer) const {
    if (!object.contains(key)) return;
    if (!object[key].is_array()) fail(pointer, "must be an array of strings");
    for (size_t i = 0; i < object[key].size(); ++i)
      if (!object[key][i].is_string()) fail(pointer + "/" + std::to_string(i), "must be a string");
  }

  void boolean(const json& object, const char* key, const std::string& pointer) const {
    if (object.contains(key) && !object[key].is_boolean()) fail(pointer + "/" + key, "must be true or false");
  }

  const json* object_member(const json& object, const char* key, const std::string& pointer) const {
    if (!object.contains(key)) return nullptr;
    if (!object[key].is_object()) fail(pointer + "/" + key, "must be an object");
    return &object[key];
  }

  // A whole number in [lo, hi]; `fallback` when absent and not required.
  uint64_t whole(const json& object, const char* key, const std::string& pointer, uint64_t lo, uint64_t hi,
                 bool required, uint64_t fallback = 0) const {
    const std::string at = pointer + "/" + key;
    if (!object.contains(key)) {
      if (required) fail(at, "missing");
      return fallback;
    }
    const json& v = object[key];
    const double d = v.is_number() ? v.get<double>() : NAN;
    if (!(d == std::floor(d)) || d < double(lo) || d > double(hi))
      fail(at, "must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi));
    return v.is_number_float() ? uint64_t(d) : v.get<uint64_t>();
  }

  // An index into doc[collection]; -1 when absent and not required.
  int64_t index(const json& object, const char* key, const std::string& pointer, const char* into,
                bool required = false) const {
    const std::string at = pointer + "/" + key;
    if (!object.contains(key)) {
      if (required) fail(at, "missing");
      return -1;
    }
    const size_t n = count_of(into);
    const json& v = object[key];
    const double d = v.is_number() ? v.get<double>() : NAN;
    if (!(d == std::floor(d)) || d < 0 || d >= double(n))
      fail(at, n == 0 ? std::string("refers to /") + into + ", which is empty"
                      : std::string("must be an index into /") + into + " (0 to " + std::to_string(n - 1) + ")");
    return int64_t(d);
  }

  double number(const json& object, const char* key, const std::string& pointer, double lo, double hi,
                double fallback) const {
    if (!object.contains(key)) return fallback;
    const json& v = object[key];
    const double d = v.is_number() ? v.get<double>() : NAN;
    if (!(d >= lo && d <= hi && std::isfinite(d))) fail(pointer + "/" + key, "must be " + range_text(lo, hi));
    return d;
  }

  // An array of exactly `n` numbers in [lo, hi]; empty when absent.
  std::vector<double> numbers(const json& object, const char* key, const std::string& pointer, size_t n, double lo,
                              double hi) const {
    if (!object.contains(key)) return {};
    const std::string at = pointer + "/" + key;
    const json& v = object[key];
    if (!v.is_array() || v.size() != n) fail(at, "must be an array of " + std::to_string(n) + " numbers");
    std::vector<double> out;
    for (size_t i = 0; i < n; ++i) out.push_back(number(v, i, at, lo, hi));
    return out;
  }

  double number(const json& array, size_t i, const std::string& pointer, double lo, double hi) const {
    const double d = array[i].is_number() ? array[i].get<double>() : NAN;
    if (!(d >= lo && d <= hi && std::isfinite(d))) fail(pointer + "/" + std::to_string(i), "must be " + range_text(lo, hi));
    return d;
  }

  static std::string range_text(double lo, double hi) {
    if (std::isinf(lo) && std::isinf(hi)) return "a finite number";
    if (std::isinf(hi)) return "a finite number of at least " + shown(lo);
    return "a number from " + shown(lo) + " to " + shown(hi);
  }

  static std::string shown(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
  }

  void check_buffers() {
    const json& buffers = collection("buffers");
    for (size_t b = 0; b < buffers.size(); ++b) {
      const std::string at = "/buffers/" + std::to_string(b);
      text(buffers[b], "uri", at);
      const uint64_t length = whole(buffers[b], "byteLength", at, 1, kLargestWhole, true);
      buffer_lengths_.push_back(length);
      data_bytes_ += double(length);
      if (buffers[b].contains("uri")) continue;
      if (glb_bin_size_ == SIZE_MAX || b > 0) fail(at, "has no uri (only a .glb's first buffer may omit it)");
      if (length > glb_bin_size_)
        fail(at + "/byteLength", std::to_string(length) + " is more than the .glb's BIN chunk holds (" +
                                     std::to_string(glb_bin_size_) + " bytes)");
    }
  }

  void check_buffer_views() {
    const json& views = collection("bufferViews");
    for (size_t v = 0; v < views.size(); ++v) {
      const std::string at = "/bufferViews/" + std::to_string(v);
      const int64_t buffer = index(views[v], "buffer", at, "buffers", true);
      const uint64_t offset = whole(views[v], "byteOffset", at, 0, kLargestWhole, false);
      const uint64_t length = whole(views[v], "byteLength", at, 1, kLargestWhole, true);
      if (offset + length > buffer_lengths_[size_t(buffer)])
        fail(at, "runs past the end of buffer " + std::to_string(buffer) + " (byteOffset + byteLength = " +
                     std::to_string(offset + length) + ", its byteLength is " +
                     std::to_string(buffer_lengths_[size_t(buffer)]) + ")");
      const uint64_t stride = whole(views[v], "byteStride", at, 4, 252, false);
      if (stride % 4) fail(at + "/byteStride", "must be a multiple of 4");
      view_lengths_.push_back(length);
      view_strides_.push_back(stride);
    }
  }

  // `count` elements of `element_size` bytes at `offset`, `stride` apart, inside bufferView `view`.
  void fits_view(const std::string& pointer, uint64_t view, uint64_t offset, uint64_t stride, uint64_t count,
                 uint64_t element_size) const {
    const uint64_t end = offset + (count - 1) * stride + element_size;  // below 2^62: every term is capped
    if (end > view_lengths_[view])
      fail(pointer, std::to_string(count) + " elements need " + std::to_string(end) + " bytes of bufferView " +
                        std::to_string(view) + ", which has " + std::to_string(view_lengths_[view]));
  }

  void check_accessors() {
    const json& accessors = collection("accessors");
    for (size_t a = 0; a < accessors.size(); ++a) {
      const std::string at = "/accessors/" + std::to_string(a);
      const json& acc = accessors[a];
      const int component_type = int(whole(acc, "componentType", at, 0, 1u << 16, true));
      if (std::find(std::begin(kComponentTypes), std::end(kComponentTypes), component_type) == std::end(kComponentTypes))
        fail(at + "/componentType", "must be 5120, 5121, 5122, 5123, 5125 or 5126");
      text(acc, "type", at);
      const size_t components = acc.contains("type") ? elements_of_type(acc["type"].get<std::string>()) : 0;
      if (components == 0) fail(at + "/type", "must be SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3 or MAT4");
      const uint64_t count = whole(acc, "count", at, 1, kLargestWhole, true);
      const uint64_t offset = whole(acc, "byteOffset", at, 0, kLargestWhole, false);
      boolean(acc, "normalized", at);
      const uint64_t element_size = components * bytes_of_component(component_type);
      const int64_t view = index(acc, "bufferView", at, "bufferViews");
      if (view >= 0) {
        const uint64_t stride = view_strides_[size_t(view)] ? view_strides_[size_t(view)] : element_size;
        if (stride < element_size)
          fail(at, "elements of " + std::to_string(element_size) + " bytes do not fit the byteStride " +
                       std::to_string(stride) + " of bufferView " + std::to_string(view));
        fits_view(at, uint64_t(view), offset, stride, count, element_size);
      }
      if (const json* sparse = object_member(acc, "sparse", at)) check_sparse(*sparse, at + "/sparse", count, element_size);
      accessor_counts_.push_back(count);
      accessor_types_.push_back(acc["type"].get<std::string>());
      accessor_component_types_.push_back(component_type);
    }
  }

  void check_sparse(const json& sparse, const std::string& at, uint64_t accessor_count, uint64_t element_size) {
    const uint64_t count = whole(sparse, "count", at, 1, accessor_count, true);
    const json* indices = object_member(sparse, "indices", at);
    const json* values = object_member(sparse, "values", at);
    if (!indices || !values) fail(at, "needs indices and values");
    const int component_type = int(whole(*indices, "componentType", at + "/indices", 0, 1u << 16, true));
    if (component_type != 5121 && component_type != 5123 && component_type != 5125)
      fail(at + "/indices/componentType", "must be 5121, 5123 or 5125");
    const uint64_t index_size = bytes_of_component(component_type);
    fits_view(at + "/indices", uint64_t(index(*indices, "bufferView", at + "/indices", "bufferViews", true)),
              whole(*indices, "byteOffset", at + "/indices", 0, kLargestWhole, false), index_size, count, index_size);
    fits_view(at + "/values", uint64_t(index(*values, "bufferView", at + "/values", "bufferViews", true)),
              whole(*values, "byteOffset", at + "/values", 0, kLargestWhole, false), element_size, count, element_size);
  }

  void check_images_and_textures() {
    const json& images = collection("images");
    for (size_t i = 0; i < images.size(); ++i) {
      const std::string at = "/images/" + std::to_string(i);
      text(images[i], "uri", at);
      text(images[i], "mimeType", at);
      const bool has_view = index(images[i], "bufferView", at, "bufferViews") >= 0;
      if (has_view == images[i].contains("uri")) fail(at, "needs exactly one of uri and bufferView");
    }
    const json& textures = collection("textures");
    for (size_t t = 0; t < textures.size(); ++t) {
      const std::string at = "/textures/" + std::to_string(t);
      index(textures[t], "source", at, "images");
      index(textures[t], "sampler", at, "samplers");
    }
  }

  void texture_info(const json& owner, const char* key, const std::string& pointer) const {
    const json* info = object_member(owner, key, pointer);
    if (!info) return;
    const std::string at = pointer + "/" + key;
    index(*info, "index", at, "textures", true);
    whole(*info, "texCoord", at, 0, 1u << 30, false);
    const json* extensions = object_member(*info, "extensions", at);
    const json* transform = extensions ? object_member(*extensions, "KHR_texture_transform", at + "/extensions") : nullptr;
    if (!transform) return;
    const std::string t = at + "/extensions/KHR_texture_transform";
    numbers(*transform, "offset", t, 2, -kMaxTextureTransform, kMaxTextureTransform);
    numbers(*transform, "scale", t, 2, -kMaxTextureTransform, kMaxTextureTransform);
    number(*transform, "rotation", t, -kMaxTextureTransform, kMaxTextureTransform, 0);
    whole(*transform, "texCoord", t, 0, 1u << 30, false);
  }

  void check_materials() const {
    const json& materials = collection("materials");
    for (size_t m = 0; m < materials.size(); ++m) {
      const std::string at = "/materials/" + std::to_string(m);
      const json& mat = materials[m];
      if (const json* pbr = object_member(mat, "pbrMetallicRoughness", at)) {
        const std::string p = at + "/pbrMetallicRoughness";
        numbers(*pbr, "baseColorFactor", p, 4, 0, 1);
        number(*pbr, "metallicFactor", p, 0, 1, 1);
        number(*pbr, "roughnessFactor", p, 0, 1, 1);
        texture_info(*pbr, "baseColorTexture", p);
        texture_info(*pbr, "metallicRoughnessTexture", p);
      }
      for (const char* key : {"normalTexture", "occlusionTexture", "emissiveTexture"}) texture_info(mat, key, at);
      std::vector<double> emissive = numbers(mat, "emissiveFactor", at, 3, 0, 1);
      text(mat, "alphaMode", at);
      boolean(mat, "doubleSided", at);
      const json* extensions = object_member(mat, "extensions", at);
      const json* strength =
          extensions ? object_member(*extensions, "KHR_materials_emissive_strength", at + "/extensions") : nullptr;
      if (!strength) continue;
      const std::string s = at + "/extensions/KHR_materials_emissive_strength";
      const double value = number(*strength, "emissiveStrength", s, 0, INFINITY, 1);
      const double brightest = emissive.empty() ? 0 : *std::max_element(emissive.begin(), emissive.end());
      if (brightest * value > kMaxLuminance)
        fail(s + "/emissiveStrength", "gives a luminance of " + shown(brightest * value) + " cd/m2, above the " +
                                          shown(kMaxLuminance) + " radbake bakes");
    }
  }

  // An attribute or target accessor has as many elements as POSITION (glTF 2.0 3.7.2.1); the
  // writer copies each one per output vertex, so a short one would be read past its end.
  void same_count(const json& attributes, const std::string& pointer, uint64_t vertices) const {
    if (!attributes.is_object()) fail(pointer, "must be an object");
    for (auto it = attributes.begin(); it != attributes.end(); ++it) {
      const std::string at = pointer + "/" + it.key();
      const int64_t a = index(attributes, it.key().c_str(), pointer, "accessors", true);
      if (accessor_counts_[size_t(a)] != vertices)
        fail(at, "accessor " + std::to_string(a) + " has " + std::to_string(accessor_counts_[size_t(a)]) +
                     " elements, POSITION has " + std::to_string(vertices));
    }
  }

  void attribute_type(const json& attributes, const std::string& pointer, const std::string& name,
                      const std::vector<std::string>& types) const {
    for (auto it = attributes.begin(); it != attributes.end(); ++it) {
      if (it.key().rfind(name, 0) != 0) continue;
      const std::string& type = accessor_types_[it.value().get<size_t>()];
      if (std::find(types.begin(), types.end(), type) == types.end())
        fail(pointer + "/" + it.key(), "is " + type + "; glTF requires " + types[0] + (types.size() > 1 ? " or " + types[1] : ""));
    }
  }

  void check_meshes() {
    const json& meshes = collection("meshes");
    for (size_t m = 0; m < meshes.size(); ++m) {
      const std::string at = "/meshes/" + std::to_string(m);
      if (!meshes[m].contains("primitives") || !meshes[m]["primitives"].is_array() || meshes[m]["primitives"].empty())
        fail(at + "/primitives", "must be a non-empty array");
      MeshCost cost;
      const json& primitives = meshes[m]["primitives"];
      for (size_t p = 0; p < primitives.size(); ++p) {
        const std::string pp = at + "/primitives/" + std::to_string(p);
        const json& prim = primitives[p];
        if (!prim.is_object()) fail(pp, "must be an object");
        const json* attributes = object_member(prim, "attributes", pp);
        if (!attributes) fail(pp + "/attributes", "missing");
        const int mode = int(whole(prim, "mode", pp, 0, 6, false, 4));
        const int64_t indices = index(prim, "indices", pp, "accessors");
        index(prim, "material", pp, "materials");
        // Unsigned byte, short and int are the odd component types.
        if (indices >= 0 && (accessor_types_[size_t(indices)] != "SCALAR" || accessor_component_types_[size_t(indices)] % 2 == 0))
          fail(pp + "/indices", "accessor " + std::to_string(indices) + " must be SCALAR unsigned byte, short or int");
        if (!attributes->contains("POSITION")) {
          if (!attributes->empty()) fail(pp + "/attributes/POSITION", "missing");
          continue;
        }
        const uint64_t vertices = accessor_counts_[size_t(index(*attributes, "POSITION", pp + "/attributes", "accessors"))];
        same_count(*attributes, pp + "/attributes", vertices);
        attribute_type(*attributes, pp + "/attributes", "POSITION", {"VEC3"});
        attribute_type(*attributes, pp + "/attributes", "NORMAL", {"VEC3"});
        attribute_type(*attributes, pp + "/attributes", "TANGENT", {"VEC4"});
        attribute_type(*attributes, pp + "/attributes", "TEXCOORD_", {"VEC2"});
        attribute_type(*attributes, pp + "/attributes", "COLOR_", {"VEC3", "VEC4"});
        if (prim.contains("targets")) {
          if (!prim["targets"].is_array()) fail(pp + "/targets", "must be an array");
          for (size_t t = 0; t < prim["targets"].size(); ++t)
            same_count(prim["targets"][t], pp + "/targets/" + std::to_string(t), vertices);
        }
        const double drawn = indices >= 0 ? double(accessor_counts_[size_t(indices)]) : double(vertices);
        cost.vertices += double(vertices);
        if (mode == 4) cost.triangles += std::floor(drawn / 3);
        else if (mode == 5 || mode == 6) cost.triangles += std::max(drawn - 2, 0.0);
      }
      mesh_costs_.push_back(cost);
    }
  }

  void check_lights() {
    const json* extensions = object_member(doc_, "extensions", "");
    const json* punctual = extensions ? object_member(*extensions, "KHR_lights_punctual", "/extensions") : nullptr;
    if (!punctual || !punctual->contains("lights")) return;
    const std::string pointer = "/extensions/KHR_lights_punctual/lights";
    const json& lights = (*punctual)["lights"];
    if (!lights.is_array()) fail(pointer, "must be an array");
    light_count_ = lights.size();
    for (size_t l = 0; l < lights.size(); ++l) {
      const std::string at = pointer + "/" + std::to_string(l);
      const json& light = lights[l];
      if (!light.is_object()) fail(at, "must be an object");
      text(light, "name", at);
      const std::string type = light.contains("type") && light["type"].is_string() ? light["type"].get<std::string>() : "";
      if (type != "point" && type != "spot" && type != "directional") fail(at + "/type", "must be point, spot or directional");
      std::vector<double> color = numbers(light, "color", at, 3, 0, 1);
      const double intensity = number(light, "intensity", at, 0, INFINITY, 1);
      const double brightest = color.empty() ? 1 : *std::max_element(color.begin(), color.end());
      if (intensity * brightest > kMaxLightIntensity)
        fail(at + "/intensity", shown(intensity * brightest) + (type == "directional" ? " lx" : " cd") +
                                    " is above the " + shown(kMaxLightIntensity) + " radbake bakes");
      number(light, "range", at, 0, INFINITY, 0);
      if (const json* spot = object_member(light, "spot", at)) {
        const double outer = number(*spot, "outerConeAngle", at + "/spot", 0, M_PI / 2, M_PI / 4);
        number(*spot, "innerConeAngle", at + "/spot", 0, outer, 0);
      }
    }
  }

  // One parent per node (glTF 2.0 section 3.5.3: the nodes form disjoint trees), which also rules
  // out cycles and the "instancing bomb": a DAG whose node i has two children, both node i + 1,
  // draws its mesh 2^depth times from a file of a few hundred bytes.
  void check_nodes() {
    const json& nodes = collection("nodes");
    parent_.assign(nodes.size(), -1);
    for (size_t n = 0; n < nodes.size(); ++n) {
      const std::string at = "/nodes/" + std::to_string(n);
      const json& node = nodes[n];
      index(node, "mesh", at, "meshes");
      index(node, "skin", at, "skins");
      index(node, "camera", at, "cameras");
      numbers(node, "matrix", at, 16, -INFINITY, INFINITY);
      numbers(node, "translation", at, 3, -INFINITY, INFINITY);
      numbers(node, "rotation", at, 4, -1, 1);
      numbers(node, "scale", at, 3, -INFINITY, INFINITY);
      const json* extensions = object_member(node, "extensions", at);
      const json* light = extensions ? object_member(*extensions, "KHR_lights_punctual", at + "/extensions") : nullptr;
      if (light) {
        const std::string l = at + "/extensions/KHR_lights_punctual/light";
        const double d = light->contains("light") && (*light)["light"].is_number() ? (*light)["light"].get<double>() : NAN;
        if (!(d == std::floor(d) && d >= 0 && d < double(light_count_)))
          fail(l, "must be an index into /extensions/KHR_lights_punctual/lights");
      }
      if (!node.contains("children")) continue;
      if (!node["children"].is_array()) fail(at + "/children", "must be an array");
      for (size_t k = 0; k < node["children"].size(); ++k) {
        const std::string c = at + "/children/" + std::to_string(k);
        const double d = node["children"][k].is_number() ? node["children"][k].get<double>() : NAN;
        if (!(d == std::floor(d) && d >= 0 && d < double(nodes.size()))) fail(c, "must be an index into /nodes");
        const size_t child = size_t(d);
        if (child == n) fail(c, "is the node itself");
        if (parent_[child] >= 0)
          fail(c, "node " + std::to_string(child) + " is already a child of node " + std::to_string(parent_[child]) +
                      "; a glTF node has at most one parent");
        parent_[child] = int64_t(n);
      }
    }
    const json& scenes = collection("scenes");
    for (size_t s = 0; s < scenes.size(); ++s) {
      const std::string at = "/scenes/" + std::to_string(s) + "/nodes";
      if (!scenes[s].contains("nodes")) continue;
      if (!scenes[s]["nodes"].is_array()) fail(at, "must be an array");
      std::vector<char> listed(nodes.size(), 0);
      for (size_t k = 0; k < scenes[s]["nodes"].size(); ++k) {
        const json& v = scenes[s]["nodes"][k];
        const double d = v.is_number() ? v.get<double>() : NAN;
        const std::string r = at + "/" + std::to_string(k);
        if (!(d == std::floor(d) && d >= 0 && d < double(nodes.size()))) fail(r, "must be an index into /nodes");
        if (parent_[size_t(d)] >= 0)
          fail(r, "node " + std::to_string(size_t(d)) + " is a child of node " + std::to_string(parent_[size_t(d)]) +
                      ", not a root");
        if (listed[size_t(d)]++) fail(r, "node " + std::to_string(size_t(d)) + " is listed twice");
      }
    }
    index(doc_, "scene", "", "scenes");
  }

  // Nodes are trees, so the instanced cost is each node's mesh once, summed over the nodes the
  // scene reaches: counted without expanding anything.
  ResourceEstimate estimate() const {
    const json& nodes = collection("nodes");
    const json& scenes = collection("scenes");
    std::vector<size_t> stack;
    if (!scenes.empty()) {
      const size_t s = size_t(std::max<int64_t>(index(doc_, "scene", "", "scenes"), 0));
      if (scenes[s].contains("nodes"))
        for (const json& root : scenes[s]["nodes"]) stack.push_back(root.get<size_t>());
    } else {
      for (size_t n = 0; n < nodes.size(); ++n)
        if (parent_[n] < 0) stack.push_back(n);
    }
    double triangles = 0, vertices = 0;
    while (!stack.empty()) {
      const json& node = nodes[stack.back()];
      stack.pop_back();
      if (node.contains("mesh")) {
        triangles += mesh_costs_[node["mesh"].get<size_t>()].triangles;
        vertices += mesh_costs_[node["mesh"].get<size_t>()].vertices;
      }
      if (node.contains("children"))
        for (const json& child : node["children"]) stack.push_back(child.get<size_t>());
    }
    auto clamp = [](double v) { return v >= 1.8e19 ? UINT64_MAX : uint64_t(v); };
    ResourceEstimate e;
    e.triangles = clamp(triangles);
    e.vertices = clamp(vertices);
    e.data_bytes = clamp(data_bytes_);
    return e;
  }

  struct MeshCost {
    double triangles = 0, vertices = 0;
  };

  const json& doc_;
  std::string file_;
  size_t glb_bin_size_;
  std::vector<uint64_t> buffer_lengths_, view_lengths_, view_strides_, accessor_counts_;
  std::vector<std::string> accessor_types_;
  std::vector<int> accessor_component_types_;
  std::vector<MeshCost> mesh_costs_;
  std::vector<int64_t> parent_;
  size_t light_count_ = 0;
  double data_bytes_ = 0;
};

}  // namespace

ResourceEstimate check_document(const json& doc, const std::string& file, size_t glb_bin_size) {
  return DocumentCheck(doc, file, glb_bin_size).run();
}

}  // namespace radbake
