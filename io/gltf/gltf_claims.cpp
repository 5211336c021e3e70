// The second step on a checked document (gltf_check.h): every size a later stage allocates from
// (accessor counts, buffer lengths, instanced triangles) held against what the file holds, the
// nodes held to disjoint trees, and what loading the file will cost. The first step has checked
// every type, range and index, so this one reads them as they are.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "io/gltf/gltf_check.h"

namespace radbake {
namespace {

using json = nlohmann::ordered_json;

size_t components_of(const std::string& type) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4" || type == "MAT2") return 4;
  if (type == "MAT3") return 9;
  return 16;  // MAT4
}

uint64_t bytes_of_component(uint64_t component_type) {
  switch (component_type) {
    case 5120: case 5121: return 1;
    case 5122: case 5123: return 2;
    default: return 4;
  }
}

// A whole number the first step has checked (it may be written 3.0), or `fallback` when absent.
uint64_t whole(const json& object, const char* key, uint64_t fallback = 0) {
  auto it = object.find(key);
  return it == object.end() ? fallback : uint64_t(it->get<double>());
}

const json& collection(const json& doc, const char* key) {
  static const json kNone = json::array();
  auto it = doc.find(key);
  return it == doc.end() ? kNone : *it;
}

class Claims {
 public:
  Claims(const json& doc, const std::string& file, size_t glb_bin_size)
      : doc_(doc), file_(file), glb_bin_size_(glb_bin_size) {}

  ResourceEstimate run() {
    buffers();
    buffer_views();
    accessors();
    meshes();
    node_trees();
    return estimate();
  }

 private:
  [[noreturn]] void fail(const std::string& pointer, const std::string& what) const { refuse(file_, pointer, what); }

  void buffers() {
    const json& buffers = collection(doc_, "buffers");
    for (size_t b = 0; b < buffers.size(); ++b) {
      const std::string at = "/buffers/" + std::to_string(b);
      const uint64_t length = whole(buffers[b], "byteLength");
      buffer_lengths_.push_back(length);
      data_bytes_ += double(length);
      if (buffers[b].contains("uri")) continue;
      if (glb_bin_size_ == SIZE_MAX || b > 0) fail(at, "has no uri (only a .glb's first buffer may omit it)");
      if (length > glb_bin_size_)
        fail(at + "/byteLength", std::to_string(length) + " is more than the .glb's BIN chunk holds (" +
                                     std::to_string(glb_bin_size_) + " bytes)");
    }
  }

  void buffer_views() {
    const json& views = collection(doc_, "bufferViews");
    for (size_t v = 0; v < views.size(); ++v) {
      const size_t buffer = size_t(whole(views[v], "buffer"));
      const uint64_t offset = whole(views[v], "byteOffset"), length = whole(views[v], "byteLength");
      if (offset + length > buffer_lengths_[buffer])
        fail("/bufferViews/" + std::to_string(v), "runs past the end of buffer " + std::to_string(buffer) +
                                                      " (byteOffset + byteLength = " + std::to_string(offset + length) +
                                                      ", its byteLength is " + std::to_string(buffer_lengths_[buffer]) + ")");
      view_lengths_.push_back(length);
      view_strides_.push_back(whole(views[v], "byteStride"));
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

  void accessors() {
    const json& accessors = collection(doc_, "accessors");
    for (size_t a = 0; a < accessors.size(); ++a) {
      const std::string at = "/accessors/" + std::to_string(a);
      const json& acc = accessors[a];
      const uint64_t count = whole(acc, "count");
      const uint64_t element_size =
          components_of(acc["type"].get<std::string>()) * bytes_of_component(whole(acc, "componentType"));
      if (acc.contains("bufferView")) {
        const uint64_t view = whole(acc, "bufferView");
        const uint64_t stride = view_strides_[view] ? view_strides_[view] : element_size;
        fits_view(at, view, whole(acc, "byteOffset"), stride, count, element_size);
      }
      if (acc.contains("sparse")) {
        const json& sparse = acc["sparse"];
        const std::string s = at + "/sparse";
        const uint64_t changed = whole(sparse, "count");
        const uint64_t index_size = bytes_of_component(whole(sparse["indices"], "componentType"));
        fits_view(s + "/indices", whole(sparse["indices"], "bufferView"), whole(sparse["indices"], "byteOffset"), index_size,
                  changed, index_size);
        fits_view(s + "/values", whole(sparse["values"], "bufferView"), whole(sparse["values"], "byteOffset"), element_size,
                  changed, element_size);
      }
      accessor_counts_.push_back(count);
    }
  }

  // An attribute or target accessor has as many elements as POSITION (glTF 2.0 3.7.2.1); the
  // writer copies each one per output vertex, so a short one would be read past its end.
  void same_count(const json& attributes, const std::string& pointer, uint64_t vertices) const {
    for (auto it = attributes.begin(); it != attributes.end(); ++it) {
      const size_t a = size_t(it->get<double>());
      if (accessor_counts_[a] != vertices)
        fail(pointer + "/" + it.key(), "accessor " + std::to_string(a) + " has " + std::to_string(accessor_counts_[a]) +
                                           " elements, POSITION has " + std::to_string(vertices));
    }
  }

  void meshes() {
    const json& meshes = collection(doc_, "meshes");
    for (size_t m = 0; m < meshes.size(); ++m) {
      MeshCost cost;
      const json& primitives = meshes[m]["primitives"];
      for (size_t p = 0; p < primitives.size(); ++p) {
        const std::string pp = "/meshes/" + std::to_string(m) + "/primitives/" + std::to_string(p);
        const json& prim = primitives[p];
        const json& attributes = prim["attributes"];
        const uint64_t vertices = accessor_counts_[whole(attributes, "POSITION")];
        same_count(attributes, pp + "/attributes", vertices);
        if (prim.contains("targets"))
          for (size_t t = 0; t < prim["targets"].size(); ++t)
            same_count(prim["targets"][t], pp + "/targets/" + std::to_string(t), vertices);
        const uint64_t mode = whole(prim, "mode", 4);
        const double drawn = prim.contains("indices") ? double(accessor_counts_[whole(prim, "indices")]) : double(vertices);
        cost.vertices += double(vertices);
        if (mode == 4) cost.triangles += std::floor(drawn / 3);
        else if (mode == 5 || mode == 6) cost.triangles += std::max(drawn - 2, 0.0);
      }
      mesh_costs_.push_back(cost);
    }
  }

  // One parent per node (glTF 2.0 section 3.5.3: the nodes form disjoint trees), which also rules
  // out cycles and the "instancing bomb": a DAG whose node i has two children, both node i + 1,
  // draws its mesh 2^depth times from a file of a few hundred bytes.
  void node_trees() {
    const json& nodes = collection(doc_, "nodes");
    parent_.assign(nodes.size(), -1);
    for (size_t n = 0; n < nodes.size(); ++n) {
      if (!nodes[n].contains("children")) continue;
      const json& children = nodes[n]["children"];
      for (size_t k = 0; k < children.size(); ++k) {
        const std::string c = "/nodes/" + std::to_string(n) + "/children/" + std::to_string(k);
        const size_t child = size_t(children[k].get<double>());
        if (child == n) fail(c, "is the node itself");
        if (parent_[child] >= 0)
          fail(c, "node " + std::to_string(child) + " is already a child of node " + std::to_string(parent_[child]) +
                      "; a glTF node has at most one parent");
        parent_[child] = int64_t(n);
      }
    }
    const json& scenes = collection(doc_, "scenes");
    for (size_t s = 0; s < scenes.size(); ++s) {
      if (!scenes[s].contains("nodes")) continue;
      const json& roots = scenes[s]["nodes"];
      for (size_t k = 0; k < roots.size(); ++k) {
        const size_t root = size_t(roots[k].get<double>());
        if (parent_[root] >= 0)
          fail("/scenes/" + std::to_string(s) + "/nodes/" + std::to_string(k),
               "node " + std::to_string(root) + " is a child of node " + std::to_string(parent_[root]) + ", not a root");
      }
    }
  }

  // Nodes are trees, so the instanced cost is each node's mesh once, summed over the nodes the
  // scene reaches: counted without expanding anything.
  ResourceEstimate estimate() const {
    const json& nodes = collection(doc_, "nodes");
    const json& scenes = collection(doc_, "scenes");
    std::vector<size_t> stack;
    if (!scenes.empty()) {
      const json& scene = scenes[size_t(whole(doc_, "scene", 0))];
      if (scene.contains("nodes"))
        for (const json& root : scene["nodes"]) stack.push_back(size_t(root.get<double>()));
    } else {
      for (size_t n = 0; n < nodes.size(); ++n)
        if (parent_[n] < 0) stack.push_back(n);
    }
    double triangles = 0, vertices = 0;
    while (!stack.empty()) {
      const json& node = nodes[stack.back()];
      stack.pop_back();
      if (node.contains("mesh")) {
        triangles += mesh_costs_[whole(node, "mesh")].triangles;
        vertices += mesh_costs_[whole(node, "mesh")].vertices;
      }
      if (node.contains("children"))
        for (const json& child : node["children"]) stack.push_back(size_t(child.get<double>()));
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
  std::vector<MeshCost> mesh_costs_;
  std::vector<int64_t> parent_;
  double data_bytes_ = 0;
};

}  // namespace

ResourceEstimate check_claims(const json& doc, const std::string& file, size_t glb_bin_size) {
  return Claims(doc, file, glb_bin_size).run();
}

}  // namespace radbake
