#include "io/gltf/gltf_prune.h"

#include <algorithm>
#include <functional>
#include <map>
#include <set>

#include "io/gltf/gltf_extensions.h"

namespace radbake {
namespace {

using json = nlohmann::ordered_json;

// A reference to an object of kind `kind` held at doc[...]; visited so it can be read or rewritten.
using Visitor = std::function<void(const std::string& kind, json& index)>;

void each_texture_info(json& node, const Visitor& visit) {
  if (node.is_object()) {
    for (auto it = node.begin(); it != node.end(); ++it) {
      const std::string& key = it.key();
      const bool texture_key = key == "MOZ_lightmap" ||
                               (key.size() >= 7 && std::equal(key.end() - 7, key.end(), "Texture")) ||
                               (key.size() >= 7 && std::equal(key.end() - 7, key.end(), "texture"));
      if (texture_key && it.value().is_object() && it.value().contains("index") && it.value()["index"].is_number_integer())
        visit("textures", it.value()["index"]);
      else
        each_texture_info(it.value(), visit);
    }
  } else if (node.is_array()) {
    for (json& v : node) each_texture_info(v, visit);
  }
}

void visit_int(json& parent, const char* key, const std::string& kind, const Visitor& visit) {
  if (parent.is_object() && parent.contains(key) && parent[key].is_number_integer()) visit(kind, parent[key]);
}

// The members of parent[key] when it is an array; nothing otherwise.
json& array_of(json& parent, const char* key) {
  thread_local json none;
  none = json::array();
  return parent.is_object() && parent.contains(key) && parent[key].is_array() ? parent[key] : none;
}

// Every reference from an object that is not itself pruned (scenes, nodes, meshes, skins,
// animations), and from the prunable kinds to each other.
void each_reference(json& doc, const Visitor& visit) {
  for (json& mesh : array_of(doc, "meshes"))
    for (json& prim : array_of(mesh, "primitives")) {
      if (prim.contains("attributes") && prim["attributes"].is_object())
        for (auto it = prim["attributes"].begin(); it != prim["attributes"].end(); ++it)
          if (it.value().is_number_integer()) visit("accessors", it.value());
      for (json& target : array_of(prim, "targets"))
        if (target.is_object())
          for (auto it = target.begin(); it != target.end(); ++it)
            if (it.value().is_number_integer()) visit("accessors", it.value());
      visit_int(prim, "indices", "accessors", visit);
      visit_int(prim, "material", "materials", visit);
      if (prim.contains("extensions") && prim["extensions"].contains("KHR_materials_variants"))
        for (json& mapping : array_of(prim["extensions"]["KHR_materials_variants"], "mappings"))
          visit_int(mapping, "material", "materials", visit);
    }
  for (json& node : array_of(doc, "nodes"))
    if (node.contains("extensions") && node["extensions"].contains("EXT_mesh_gpu_instancing")) {
      json& attributes = node["extensions"]["EXT_mesh_gpu_instancing"]["attributes"];
      if (attributes.is_object())
        for (auto it = attributes.begin(); it != attributes.end(); ++it)
          if (it.value().is_number_integer()) visit("accessors", it.value());
    }
  for (json& skin : array_of(doc, "skins")) visit_int(skin, "inverseBindMatrices", "accessors", visit);
  for (json& animation : array_of(doc, "animations"))
    for (json& sampler : array_of(animation, "samplers")) {
      visit_int(sampler, "input", "accessors", visit);
      visit_int(sampler, "output", "accessors", visit);
    }
  for (json& material : array_of(doc, "materials")) each_texture_info(material, visit);
  for (json& texture : array_of(doc, "textures")) {
    visit_int(texture, "source", "images", visit);
    visit_int(texture, "sampler", "samplers", visit);
    if (texture.contains("extensions") && texture["extensions"].is_object())
      for (auto it = texture["extensions"].begin(); it != texture["extensions"].end(); ++it)
        visit_int(it.value(), "source", "images", visit);
  }
  for (json& image : array_of(doc, "images")) visit_int(image, "bufferView", "bufferViews", visit);
  for (json& accessor : array_of(doc, "accessors")) {
    visit_int(accessor, "bufferView", "bufferViews", visit);
    if (accessor.contains("sparse") && accessor["sparse"].is_object()) {
      visit_int(accessor["sparse"]["indices"], "bufferView", "bufferViews", visit);
      visit_int(accessor["sparse"]["values"], "bufferView", "bufferViews", visit);
    }
  }
  for (json& view : array_of(doc, "bufferViews")) visit_int(view, "buffer", "buffers", visit);
}

// Kinds in the order references run: an object of a later kind is referenced only by earlier ones.
const char* const kPrunable[] = {"materials", "textures", "samplers", "images", "accessors", "bufferViews", "buffers"};

std::vector<std::string> unknown_extensions(const json& doc) {
  std::set<std::string> used;
  std::function<void(const json&)> walk = [&](const json& node) {
    if (node.is_object()) {
      for (auto it = node.begin(); it != node.end(); ++it) {
        if (it.key() == "extensions" && it.value().is_object())
          for (auto e = it.value().begin(); e != it.value().end(); ++e) used.insert(e.key());
        if (it.key() != "extras") walk(it.value());
      }
    } else if (node.is_array()) {
      for (const json& v : node) walk(v);
    }
  };
  walk(doc);
  std::vector<std::string> unknown;
  for (const std::string& e : used)
    if (const GltfExtension* row = gltf_extension(e); !row || !row->references_known) unknown.push_back(e);
  return unknown;
}

}  // namespace

void prune_unused_objects(json& doc, std::vector<std::string>& warnings) {
  const std::vector<std::string> unknown = unknown_extensions(doc);
  if (!unknown.empty()) {
    warnings.push_back("objects nothing references were kept: the extension " + unknown.front() +
                       " may refer to them in ways radbake does not know");
    return;
  }
  // Kind by kind, in reference order: once the referrers of a kind are final, its unused objects go.
  for (const char* kind : kPrunable) {
    if (!doc.contains(kind) || !doc[kind].is_array() || doc[kind].empty()) continue;
    json& objects = doc[kind];
    std::vector<uint8_t> used(objects.size(), 0);
    each_reference(doc, [&](const std::string& k, json& index) {
      if (k == kind && index.get<int64_t>() >= 0 && size_t(index.get<int64_t>()) < used.size()) used[size_t(index.get<int64_t>())] = 1;
    });
    remove_objects(doc, kind, used);
  }
}

void remove_objects(json& doc, const char* kind, const std::vector<uint8_t>& keep) {
  if (std::all_of(keep.begin(), keep.end(), [](uint8_t k) { return k; })) return;
  json& objects = doc[kind];
  std::vector<int64_t> renumbered(objects.size(), -1);
  json kept = json::array();
  for (size_t i = 0; i < objects.size(); ++i)
    if (keep[i]) {
      renumbered[i] = int64_t(kept.size());
      kept.push_back(std::move(objects[i]));
    }
  each_reference(doc, [&](const std::string& k, json& index) {
    if (k == kind && index.get<int64_t>() >= 0 && size_t(index.get<int64_t>()) < renumbered.size())
      index = renumbered[size_t(index.get<int64_t>())];
  });
  if (kept.empty()) doc.erase(kind);
  else objects = std::move(kept);
}

}  // namespace radbake
