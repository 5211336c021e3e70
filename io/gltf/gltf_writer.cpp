#include "io/gltf/gltf_writer.h"

#include <algorithm>
#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <set>
#include <nlohmann/json.hpp>
#include <tuple>

#include "baker/finish/prelit_pages.h"
#include "base/errors.h"
#include "io/files/written_file.h"
#include "io/files/regular_file.h"
#include "io/gltf/gltf_binary.h"
#include "io/gltf/gltf_prune.h"
#include "io/gltf/gltf_source.h"
#include "io/gltf/image_repair.h"
#include "io/gltf/vertex_repair.h"
#include "io/lightmaps/light_probe_outputs.h"

namespace radbake {
namespace {

using json = nlohmann::ordered_json;
namespace fs = std::filesystem;

// The most an image file may hold to be copied (the scene's own file may hold no more).
constexpr uint64_t kMostImageFileBytes = 0xffffffffu;

void write_bytes(const fs::path& path, const uint8_t* data, size_t size) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  close_written(out, path.string());
}

bool is_data_uri(const std::string& uri) { return uri.rfind("data:", 0) == 0; }

// Every texCoord a material's textures read, including KHR_texture_transform overrides.
void collect_tex_coords(const json& node, std::vector<int>& sets) {
  if (node.is_object()) {
    for (auto it = node.begin(); it != node.end(); ++it) {
      if (it.key() == "MOZ_lightmap") continue;  // an earlier bake's lightmap, which this bake replaces
      if (it.key() == "texCoord" && it.value().is_number_integer()) sets.push_back(it.value().get<int>());
      collect_tex_coords(it.value(), sets);
    }
  } else if (node.is_array()) {
    for (const json& v : node) collect_tex_coords(v, sets);
  }
}

class Writer {
 public:
  Writer(const GltfSource& src, const Scene& scene, const Atlas& atlas, const std::vector<std::vector<Rgb>>& values,
         const LightmapFiles& lightmaps, const fs::path& folder, const std::string& name, const EngineFileOptions& options)
      : src_(src), scene_(scene), atlas_(atlas), values_(values), lightmaps_(lightmaps), folder_(folder), name_(name),
        options_(options), doc_(json::parse(src.json_text)) {}

  GltfOutput run() {
    // COLOR_0 must stay within [0, 1]; its scale is the PNG's unless a vertex is brighter.
    color_scale_ = lightmaps_.png_scale;
    for (const auto& mesh : values_)
      for (Rgb c : mesh) color_scale_ = std::max(color_scale_, max_component(c));
    for (const char* key : {"accessors", "bufferViews", "buffers", "meshes", "materials", "images", "textures", "samplers"})
      if (!doc_.contains(key)) doc_[key] = json::array();
    // Both drop what they cannot repair, so before the copies below.
    repairs_.emplace(src_.model, doc_, out_.warnings);
    const std::vector<uint8_t> written_images = repair_images(doc_, src_, out_.warnings);
    original_meshes_ = doc_["meshes"];
    original_materials_ = doc_["materials"];
    relocate_buffers();
    correct_bounds();
    copy_images(written_images);
    remove_objects(doc_, "images", written_images);
    const int lightmap_buffer = int(doc_["buffers"].size());
    BinaryWriter bin(doc_, lightmap_buffer);
    add_lightmap_textures();
    has_back_.assign(scene_.instances.size(), 0);
    for (const MeshInstance& inst : scene_.instances)
      if (inst.back_of >= 0) has_back_[size_t(inst.back_of)] = 1;
    for (size_t i = 0; i < scene_.instances.size(); ++i) rewrite_primitive(i, bin);
    write_repaired_attributes(bin);
    std::string bin_name = name_ + "_lightmap.bin";
    doc_["buffers"].push_back({{"uri", bin_name}, {"byteLength", bin.data().size()}});
    write_bytes(folder_ / bin_name, bin.data().data(), bin.data().size());
    out_.written_files.push_back(bin_name);
    add_extension_used("MOZ_lightmap");
    mark_baked_lights();
    prune_unused_objects(doc_, out_.warnings);
    remove_unreferenced_files();
    describe_bake();  // after pruning, which renumbers the page textures
    out_.gltf_file = name_ + ".gltf";
    std::ofstream file(folder_ / out_.gltf_file);
    file << doc_.dump(2) << "\n";
    close_written(file, (folder_ / out_.gltf_file).string());
    out_.written_files.push_back(out_.gltf_file);
    return out_;
  }

 private:
  // Input buffers are written beside the output (the .glb's BIN chunk as a file of its own), so
  // the folder stands alone.
  void relocate_buffers() {
    json& buffers = doc_["buffers"];
    for (size_t b = 0; b < buffers.size(); ++b) {
      json& buffer = buffers[b];
      std::string uri = buffer.value("uri", "");
      if (is_data_uri(uri)) continue;
      const std::vector<uint8_t>* data = &src_.model.buffers[b].data;
      if (uri.empty() && src_.binary && b == 0) data = &src_.glb_bin;
      std::string file = name_ + "_buffer" + std::to_string(b) + ".bin";
      size_t length = buffer.value("byteLength", size_t(0));
      std::vector<uint8_t> bytes(data->begin(), data->begin() + long(std::min(length, data->size())));
      bytes.resize(length, 0);
      make_buffer_view_pngs_plain(b, bytes);
      write_bytes(folder_ / file, bytes.data(), bytes.size());
      buffer["uri"] = file;
      out_.written_files.push_back(file);
    }
  }

  // PNG images in buffer `b` shrink in place (make_png_plain): their view's byteLength is what is
  // left, and the freed bytes are zeros no view covers.
  void make_buffer_view_pngs_plain(size_t b, std::vector<uint8_t>& bytes) {
    const json& images = doc_["images"];
    for (size_t i = 0; i < images.size(); ++i) {
      if (!images[i].contains("bufferView") || src_.image_types[i] != "image/png") continue;
      json& view = doc_["bufferViews"][images[i]["bufferView"].get<size_t>()];
      if (view["buffer"].get<size_t>() != b) continue;
      const size_t offset = view.value("byteOffset", size_t(0)), length = view["byteLength"].get<size_t>();
      if (offset + length > bytes.size()) continue;
      std::string png(bytes.begin() + long(offset), bytes.begin() + long(offset + length));
      const std::string warning = make_png_plain(png, "/images/" + std::to_string(i));
      if (warning.empty()) continue;
      std::fill(std::copy(png.begin(), png.end(), bytes.begin() + long(offset)), bytes.begin() + long(offset + length), 0);
      view["byteLength"] = png.size();
      out_.warnings.push_back(warning);
    }
  }

  // POSITION accessors must have bounds (glTF 2.0 section 3.7.2.1), and bounds must match the
  // data (the validator's ACCESSOR_MIN_MISMATCH); the input's are copied, so they are checked here.
  bool needs_bounds(size_t accessor) const {
    const json& a = doc_["accessors"][accessor];
    return a.contains("min") || a.contains("max") || position_accessors_.count(accessor);
  }

  void correct_bounds() {
    for (const json& mesh : original_meshes_)
      for (const json& prim : mesh["primitives"]) {
        if (prim["attributes"].contains("POSITION")) position_accessors_.insert(prim["attributes"]["POSITION"].get<size_t>());
        for (const json& target : prim.value("targets", json::array()))
          if (target.contains("POSITION")) position_accessors_.insert(target["POSITION"].get<size_t>());
      }
    for (size_t i = 0; i < src_.model.accessors.size(); ++i) {
      json& a = doc_["accessors"][i];
      if (!needs_bounds(i) || a["count"].get<size_t>() == 0 || repairs_->replaces(int(i))) continue;
      size_t element_size;
      std::vector<uint8_t> bytes;
      try {
        bytes = accessor_bytes(src_.model, int(i), &element_size);
      } catch (const InputError&) {
        continue;  // an accessor no primitive reads may point anywhere; nothing to measure
      }
      json measured = json::object();
      add_bounds(measured, bytes, a["count"].get<size_t>(), a["componentType"].get<int>());
      if (a.contains("min") && a.contains("max") && same_bounds(a, measured)) continue;
      if (a.contains("min") || a.contains("max"))
        out_.warnings.push_back("/accessors/" + std::to_string(i) + ": min and max did not match the data; written as measured");
      a["min"] = measured["min"];
      a["max"] = measured["max"];
    }
  }

  // Compared as the validator does, in the precision of the components.
  static bool same_bounds(const json& declared, const json& measured) {
    const bool floats = declared["componentType"] == TINYGLTF_COMPONENT_TYPE_FLOAT;
    auto as_float = [](double v) {  // beyond float's range the cast is undefined; the validator reads infinity
      return std::fabs(v) > FLT_MAX ? std::copysign(INFINITY, v) : double(float(v));
    };
    for (const char* key : {"min", "max"})
      for (size_t c = 0; c < measured[key].size(); ++c) {
        const double d = declared[key][c].get<double>(), m = measured[key][c].get<double>();
        if (floats ? as_float(d) != as_float(m) : d != m) return false;
      }
    return true;
  }

  // Only the files the loader resolved (inside the scene's folder, unless external files were
  // allowed), and only images the engine file may carry (`written`, from repair_images).
  void copy_images(const std::vector<uint8_t>& written) {
    json& images = doc_["images"];
    for (size_t i = 0; i < images.size(); ++i) {
      std::string uri = images[i].value("uri", "");
      if (uri.empty() || is_data_uri(uri) || !written[i]) continue;
      const fs::path from = src_.image_files[i];
      // Named for what the bytes are (a PNG named .webp is repaired as a PNG).
      const std::string& type = src_.image_types[i];
      std::string file = name_ + "_image" + std::to_string(i) + (type == "image/jpeg" ? ".jpg" : "." + type.substr(6));
      std::string bytes;
      try {
        if (from.empty()) throw InputError("its file was not found");
        // Read again as it was first read: a regular file, bounded (the loader decoded it whole).
        bytes = read_regular_file(from.string(), "image", kMostImageFileBytes);
      } catch (const InputError& e) {
        out_.warnings.push_back("image '" + clipped(uri) + "' could not be copied: " + e.what());
        continue;
      }
      if (type == "image/png") {
        const std::string warning = make_png_plain(bytes, "/images/" + std::to_string(i));
        if (!warning.empty()) out_.warnings.push_back(warning);
      }
      write_bytes(folder_ / file, reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
      images[i]["uri"] = file;
      out_.written_files.push_back(file);
    }
  }

  // No mipmaps: a chart's neighbours are a few texels away, and mip levels average them in (see
  // docs/mip_bleeding.md).
  void add_lightmap_textures() {
    doc_["samplers"].push_back({{"magFilter", 9729}, {"minFilter", 9729}, {"wrapS", 33071}, {"wrapT", 33071}});
    const int sampler = int(doc_["samplers"].size() - 1);
    for (size_t page = 0; page < lightmaps_.files.size(); ++page) {
      doc_["images"].push_back({{"uri", lightmaps_.texture(page)}, {"mimeType", "image/png"}});
      doc_["textures"].push_back({{"sampler", sampler}, {"source", doc_["images"].size() - 1}});
      page_texture_.push_back(int(doc_["textures"].size() - 1));
    }
  }

  int mesh_for_node(int node, int mesh) {
    auto [it, first] = mesh_of_node_.emplace(node, mesh);
    if (!first) return it->second;
    if (!meshes_taken_.insert(mesh).second) {
      json copy = original_meshes_[size_t(mesh)];
      copy["name"] = copy.value("name", "mesh " + std::to_string(mesh)) + " (node " + std::to_string(node) + ")";
      doc_["meshes"].push_back(copy);
      it->second = int(doc_["meshes"].size() - 1);
    }
    doc_["nodes"][size_t(node)]["mesh"] = it->second;
    return it->second;
  }

  // `single_sided`: a double-sided material whose backs have texels of their own, shown by a
  // primitive of their own; culling keeps each face to its own texels.
  int lightmap_material(int material, int page, int tex_coord, bool single_sided) {
    auto key = std::make_tuple(material, page, tex_coord, single_sided);
    auto found = material_clones_.find(key);
    if (found != material_clones_.end()) return found->second;
    json m = material >= 0 ? original_materials_[size_t(material)] : json::object();
    if (material < 0) m["name"] = "radbake default material";
    if (single_sided) {
      m.erase("doubleSided");
      m["name"] = m.value("name", "material " + std::to_string(material)) + " (one face)";
    }
    m["extensions"]["MOZ_lightmap"] = {
        {"index", page_texture_[size_t(page)]}, {"texCoord", tex_coord}, {"intensity", lightmaps_.png_scale}};
    doc_["materials"].push_back(m);
    return material_clones_[key] = int(doc_["materials"].size() - 1);
  }

  // Components [first, first + count) of every element negated: a back face's normals (all three)
  // and its tangents' handedness (the fourth), floats or normalized signed integers.
  static void negate(std::vector<uint8_t>& bytes, size_t element_size, int component_type, size_t first, size_t count) {
    const size_t cs = component_size(component_type);
    for (size_t at = 0; at + element_size <= bytes.size(); at += element_size)
      for (size_t c = first; c < first + count && (c + 1) * cs <= element_size; ++c) {
        uint8_t* p = &bytes[at + c * cs];
        if (component_type == TINYGLTF_COMPONENT_TYPE_FLOAT) {
          float v;
          std::memcpy(&v, p, 4);
          v = -v;
          std::memcpy(p, &v, 4);
        } else if (component_type == TINYGLTF_COMPONENT_TYPE_SHORT) {
          int16_t v;
          std::memcpy(&v, p, 2);
          v = int16_t(-std::max<int>(v, -32767));
          std::memcpy(p, &v, 2);
        } else if (component_type == TINYGLTF_COMPONENT_TYPE_BYTE) {
          *p = uint8_t(int8_t(-std::max<int>(int8_t(*p), -127)));
        }
      }
  }

  // An input accessor's packed elements, as the input has them or, where its data is not valid
  // glTF for `use`, repaired (as floats).
  struct Elements {
    std::vector<uint8_t> bytes;
    size_t size = 0;  // of one element, bytes
    int component_type = 0;
    bool normalized = false;
  };
  Elements source_elements(int accessor, VertexUse use) const {
    if (const RepairedAccessor* fixed = repairs_->find(accessor, use))
      return {as_bytes(fixed->values), 4 * fixed->components, kFloat, false};
    const json& a = doc_["accessors"][size_t(accessor)];
    Elements e;
    e.bytes = accessor_bytes(src_.model, accessor, &e.size);
    e.component_type = a["componentType"].get<int>();
    e.normalized = a.value("normalized", false);
    return e;
  }

  int remapped(int accessor_index, const std::vector<uint32_t>& source_vertex, BinaryWriter& bin,
               const std::string& semantic, bool morph_target, bool back) {
    const Elements in = source_elements(accessor_index, vertex_use(semantic, morph_target));
    std::vector<uint8_t> out(source_vertex.size() * in.size);
    for (size_t v = 0; v < source_vertex.size(); ++v)
      std::memcpy(&out[v * in.size], &in.bytes[size_t(source_vertex[v]) * in.size], in.size);
    if (back && semantic == "NORMAL") negate(out, in.size, in.component_type, 0, 3);
    if (back && semantic == "TANGENT") negate(out, in.size, in.component_type, 3, 1);
    const json& a = doc_["accessors"][size_t(accessor_index)];
    return bin.add(out, source_vertex.size(), a["type"].get<std::string>().c_str(), in.component_type, in.normalized,
                   kArrayBuffer, needs_bounds(size_t(accessor_index)));
  }

  // Attributes that still read the input's accessors (kept lightmap UVs, primitives radbake does
  // not bake) read a repaired copy where the input's data is not valid glTF (io/gltf/vertex_repair.h).
  void write_repaired_attributes(BinaryWriter& bin) {
    auto repair = [&](json& index, const std::string& semantic, bool morph_target) {
      const int accessor = index.get<int>();
      if (size_t(accessor) >= src_.model.accessors.size()) return;  // written by this bake
      const VertexUse use = vertex_use(semantic, morph_target);
      const RepairedAccessor* fixed = repairs_->find(accessor, use);
      if (!fixed) return;
      auto [it, first] = repaired_accessors_.emplace(std::make_pair(accessor, use), -1);
      if (first)
        it->second = bin.add(as_bytes(fixed->values), fixed->values.size() / fixed->components,
                             doc_["accessors"][size_t(accessor)]["type"].get<std::string>().c_str(), kFloat, false,
                             kArrayBuffer, needs_bounds(size_t(accessor)));
      index = it->second;
    };
    for (json& mesh : doc_["meshes"])
      for (json& prim : mesh["primitives"]) {
        for (auto it = prim["attributes"].begin(); it != prim["attributes"].end(); ++it) repair(it.value(), it.key(), false);
        if (prim.contains("targets"))
          for (json& target : prim["targets"])
            for (auto it = target.begin(); it != target.end(); ++it) repair(it.value(), it.key(), true);
      }
  }

  void rewrite_primitive(size_t i, BinaryWriter& bin) {
    const MeshInstance& inst = scene_.instances[i];
    const AtlasMesh& lm = atlas_.meshes[i];
    const int mesh = mesh_for_node(inst.node, inst.mesh);
    const bool back = inst.back_of >= 0;
    size_t back_at = 0;
    json& primitives = doc_["meshes"][size_t(mesh)]["primitives"];
    if (back) {
      // A primitive of its own beside its front's: the front's source attributes, its own indices
      // (reversed winding), lightmap UVs into its own charts, flipped normals.
      json copy = original_meshes_[size_t(inst.mesh)]["primitives"][size_t(inst.primitive)];
      if (!copy["extras"].is_object()) copy["extras"] = json::object();
      copy["extras"]["radbake"] = {{"back_faces_of_primitive", inst.primitive}};
      // Baking radbake's output again: the earlier back primitive (which the loader left out) is
      // replaced rather than shown beside the new one.
      back_at = primitives.size();
      auto back_of = [](const json& p) {
        const json& extras = p.contains("extras") ? p["extras"] : json();
        const json& record = extras.is_object() && extras.contains("radbake") ? extras["radbake"] : json();
        return record.is_object() && record.contains("back_faces_of_primitive") && record["back_faces_of_primitive"].is_number_integer()
                   ? record["back_faces_of_primitive"].get<int64_t>()
                   : int64_t(-1);
      };
      for (size_t k = 0; k < primitives.size(); ++k)
        if (back_of(primitives[k]) == inst.primitive) back_at = k;
      if (back_at == primitives.size()) primitives.push_back(copy);
      else primitives[back_at] = copy;
    }
    json& prim = primitives[back ? back_at : size_t(inst.primitive)];
    // A working copy: inserting keys into an ordered_json object moves its members, so no
    // reference into `prim` may be held while it grows.
    json attributes = prim["attributes"];
    const int mode = prim.value("mode", 4);
    const size_t vertex_count = lm.source_vertex.size();

    std::vector<int> used_sets;
    if (prim.contains("material")) collect_tex_coords(original_materials_[prim["material"].get<size_t>()], used_sets);
    int lightmap_set = 1;
    if (!lm.kept_input_uvs) {
      // Remap every attribute through the atlas's vertex split.
      for (auto it = attributes.begin(); it != attributes.end(); ++it)
        it.value() = remapped(it.value().get<int>(), lm.source_vertex, bin, it.key(), false, back);
      if (prim.contains("targets"))
        for (json& target : prim["targets"])
          for (auto it = target.begin(); it != target.end(); ++it)
            it.value() = remapped(it.value().get<int>(), lm.source_vertex, bin, it.key(), true, back);
      bool set1_in_use = attributes.contains("TEXCOORD_1") && std::count(used_sets.begin(), used_sets.end(), 1);
      if (set1_in_use) {
        while (attributes.contains("TEXCOORD_" + std::to_string(lightmap_set))) ++lightmap_set;
        out_.warnings.push_back(inst.name + ": its material reads TEXCOORD_1, so lightmap UVs go to TEXCOORD_" +
                                std::to_string(lightmap_set));
      }
      std::vector<float> uv;
      for (Vec2 p : lm.uvs) uv.insert(uv.end(), {p.x, p.y});
      int uv_accessor = bin.add(as_bytes(uv), vertex_count, "VEC2", TINYGLTF_COMPONENT_TYPE_FLOAT, false, kArrayBuffer, true);
      attributes["TEXCOORD_" + std::to_string(lightmap_set)] = uv_accessor;
      // Attribute sets must be numbered from 0 without gaps.
      if (!attributes.contains("TEXCOORD_0")) attributes["TEXCOORD_0"] = uv_accessor;
    }
    if (!lm.kept_input_uvs || mode != 4) {
      const auto [indices, type] = index_bytes(lm.triangles, vertex_count);
      prim["indices"] = bin.add(indices, lm.triangles.size(), "SCALAR", type, false, kElementArrayBuffer, false);
      prim["mode"] = 4;
    }
    std::vector<float> light, colors;
    for (Rgb c : values_[i]) light.insert(light.end(), {c.x, c.y, c.z});
    // An earlier bake's light (re-baking our own output) is replaced, not kept beside the new.
    attributes["_BAKED_LIGHT"] = bin.add(as_bytes(light), vertex_count, "VEC3", TINYGLTF_COMPONENT_TYPE_FLOAT, false,
                                         kArrayBuffer, false);
    if (inst.color_0_was_light) {
      // An earlier radbake output whose COLOR_0 held light: the file's own colours are in _SOURCE_COLOR_0.
      attributes.erase("COLOR_0");
      if (attributes.contains("_SOURCE_COLOR_0")) {
        json source_colors = attributes["_SOURCE_COLOR_0"];
        attributes.erase("_SOURCE_COLOR_0");
        attributes["COLOR_0"] = source_colors;
      }
    }
    if (options_.color_0 != Color0::Source) {
      if (attributes.contains("COLOR_0")) {
        json source_colors = attributes["COLOR_0"];
        attributes["_SOURCE_COLOR_0"] = source_colors;
        out_.warnings.push_back(inst.name + ": its COLOR_0 moved to _SOURCE_COLOR_0 to make room for the baked values");
      }
      for (Rgb c : values_[i]) {
        const Rgb shown = options_.color_0 == Color0::Light ? c / color_scale_ : prelit_vertex(c) * options_.display_exposure;
        for (int k = 0; k < 3; ++k) colors.push_back(std::clamp(shown[k], 0.0f, 1.0f));
      }
      attributes["COLOR_0"] = bin.add(as_bytes(colors), vertex_count, "VEC3", TINYGLTF_COMPONENT_TYPE_FLOAT, false,
                                      kArrayBuffer, false);
    }
    prim["attributes"] = attributes;
    prim["material"] = lightmap_material(prim.contains("material") ? prim["material"].get<int>() : -1, lm.page,
                                         lightmap_set, back || has_back_[i]);
  }

  void add_extension_used(const std::string& ext) {
    if (!doc_.contains("extensionsUsed")) doc_["extensionsUsed"] = json::array();
    json& used = doc_["extensionsUsed"];
    if (std::find(used.begin(), used.end(), ext) == used.end()) used.push_back(ext);
  }

  // Input buffers and images are copied before the bake's own replace some of them (an earlier
  // bake's pages, accessors of remapped attributes); the copies nothing refers to any more go.
  void remove_unreferenced_files() {
    std::set<std::string> referenced;
    for (const char* kind : {"buffers", "images"})
      if (doc_.contains(kind))
        for (const json& object : doc_[kind]) referenced.insert(object.value("uri", ""));
    std::vector<std::string> kept;
    for (const std::string& file : out_.written_files) {
      if (referenced.count(file)) kept.push_back(file);
      else fs::remove(folder_ / file);
    }
    out_.written_files = kept;
  }

  int texture_of_png(const std::string& png) const {
    for (size_t t = 0; t < doc_["textures"].size(); ++t) {
      const json& texture = doc_["textures"][t];
      if (texture.contains("source") && doc_["images"][texture["source"].get<size_t>()].value("uri", "") == png) return int(t);
    }
    return -1;
  }

  // Engines light the scene with its punctual lights; the ones radbake baked are in the lightmap
  // already, so an engine (or the three.js plugin) that adds them again lights the scene twice.
  void mark_baked_lights() {
    json* lights = nullptr;
    if (doc_.contains("extensions") && doc_["extensions"].contains("KHR_lights_punctual"))
      lights = &doc_["extensions"]["KHR_lights_punctual"]["lights"];
    if (!lights || !lights->is_array()) return;
    for (const Light& light : scene_.lights) {
      if (light.source_index < 0 || size_t(light.source_index) >= lights->size()) continue;
      json& extras = (*lights)[size_t(light.source_index)]["extras"];
      if (extras.is_null()) extras = json::object();
      if (extras.is_object()) extras["radbake"] = {{"baked", true}};
    }
  }

  void describe_bake() {
    // Per page: its texture's file first, then its other files, then the texture's index.
    json pages = json::array();
    for (size_t p = 0; p < lightmaps_.files.size(); ++p) {
      json page = {{texture_encoding().key, lightmaps_.texture(p)}};
      for (size_t k = 0; k < page_encodings().size(); ++k)
        if (&page_encodings()[k] != &texture_encoding()) page[page_encodings()[k].key] = lightmaps_.files[p][k];
      page["texture"] = texture_of_png(lightmaps_.texture(p));
      pages.push_back(page);
    }
    const char* color_0 = options_.color_0 == Color0::Source ? "the input's own COLOR_0 (a base colour multiplier)"
                          : options_.color_0 == Color0::Light ? "linear RGB per vertex; quantity = COLOR_0 * color_0_intensity"
                                                              : "pre-lit display colour of a white surface: clip(quantity / pi * display_exposure), linear";
    json info = {
        {"generator", "radbake"},
        {"quantity", lightmaps_.quantity},
        {"unit", lightmaps_.unit},
        {"pages", pages},
    };
    for (const PageEncoding& encoding : page_encodings()) info[encoding.key] = encoding.light_read_back;
    info["png_intensity"] = lightmaps_.png_scale;
    info["baked_light"] = "_BAKED_LIGHT: linear RGB per vertex, the quantity in its unit";
    info["color_0"] = color_0;
    info["color_0_holds"] = options_.color_0 == Color0::Source ? "source" : options_.color_0 == Color0::Light ? "light" : "prelit";
    if (options_.color_0 == Color0::Light) info["color_0_intensity"] = color_scale_;
    if (options_.display_exposure > 0) {
      info["display_exposure"] = options_.display_exposure;
      info["display"] = "linear display value = luminance (cd/m2) * display_exposure; a Lambertian surface of "
                        "reflectance r under E lux has luminance r * E / pi";
    }
    if (!options_.display_file.empty()) info["display_file"] = options_.display_file;
    if (!options_.directional.mode.empty()) info["directional"] = directional_info();
    if (options_.probes) {
      info["probes"] = light_probes_json(*options_.probes);
      info["probes"]["file"] = options_.probes_file;
    }
    json& extras = doc_["extras"];
    if (extras.is_null()) extras = json::object();
    if (extras.is_object()) extras["radbake"] = info;
    else doc_["asset"]["extras"]["radbake"] = info;
  }

  // --directional: the pages, how the PNGs decode and how the coefficients make light.
  json directional_info() const {
    const DirectionalFiles& d = options_.directional;
    json sets = json::array();
    for (const DirectionalSet& set : d.sets) {
      json entry = {{"coefficient", set.coefficient}};
      for (size_t k = 0; k < page_encodings().size(); ++k) {
        json files = json::array();
        for (const std::vector<std::string>& page : set.files) files.push_back(page[k]);
        entry[page_encodings()[k].key] = files;
      }
      entry["png_scale"] = set.scale;
      entry["png_offset"] = set.offset;
      sets.push_back(entry);
    }
    json info = {{"mode", d.mode}, {"pages", sets}};
    for (const PageEncoding& encoding : page_encodings()) info[encoding.key] = encoding.coefficients_read_back;
    info["space"] = "world space of the glTF (+Y up), the texel of a page is the lightmap's (TEXCOORD_1)";
    if (d.mode == "sh")
      info["irradiance"] = "lux for a surface of unit normal n: max(0, c0 + c1x n.x + c1y n.y + c1z n.z) per channel; "
                           "at the surface's own normal the lightmap's irradiance; L1 spherical harmonics of the "
                           "irradiance, c0 = 0.282095 E00, (c1x, c1y, c1z) = 0.488603 (E11, E1-1, E10)";
    else
      info["irradiance"] = "Unity's directional lightmaps: the lightmap's irradiance E times (n . dir + 0.5) / "
                           "max(1e-4, |dir|), dir the stored luminance-weighted mean direction of the arriving "
                           "light (its length is how directional the light is)";
    return info;
  }

  const GltfSource& src_;
  const Scene& scene_;
  const Atlas& atlas_;
  const std::vector<std::vector<Rgb>>& values_;
  const LightmapFiles& lightmaps_;
  fs::path folder_;
  std::string name_;
  EngineFileOptions options_;
  json doc_, original_meshes_, original_materials_;
  std::map<int, int> mesh_of_node_;
  std::set<int> meshes_taken_;
  std::set<size_t> position_accessors_;
  std::map<std::tuple<int, int, int, bool>, int> material_clones_;
  std::optional<VertexRepairs> repairs_;
  std::map<std::pair<int, VertexUse>, int> repaired_accessors_;  // (input accessor, use) -> its repaired copy
  std::vector<uint8_t> has_back_;  // per instance: some of its triangles have back-face twins
  std::vector<int> page_texture_;
  float color_scale_ = 1;
  GltfOutput out_;
};

}  // namespace

GltfOutput write_gltf(const GltfSource& source, const Scene& scene, const Atlas& atlas,
                      const std::vector<std::vector<Rgb>>& vertex_values, const LightmapFiles& lightmaps,
                      const std::string& folder, const std::string& name, const EngineFileOptions& options) {
  return Writer(source, scene, atlas, vertex_values, lightmaps, folder, name, options).run();
}

}  // namespace radbake
