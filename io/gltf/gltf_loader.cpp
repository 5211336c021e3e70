#include "io/gltf/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "base/errors.h"
#include "io/files/regular_file.h"
#include "io/gltf/gltf_check.h"
#include "io/gltf/gltf_extensions.h"
#include "io/gltf/gltf_source.h"
#include "io/gltf/image_repair.h"
#include "io/gltf/vertex_repair.h"

namespace radbake {
namespace {

// tinygltf turns extras and extensions into its Value recursively, and the writer's JSON
// serializer recurses too: deeper documents are refused before any parser sees them. glTF itself
// nests about ten levels.
constexpr size_t kMaxJsonDepth = 128;
// World coordinates in metres. Float positions beyond this resolve no better than a metre, and
// Embree refuses bounds near 1.8e19; ten thousand kilometres holds a planet.
constexpr double kMaxCoordinate = 1e7;

std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  return clipped(text, 300);
}

// Counted without recursion, so the count itself cannot overflow the stack.
void check_nesting(const std::string& text, const std::string& file) {
  size_t depth = 0;
  bool in_string = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '{' || c == '[') {
      if (++depth > kMaxJsonDepth)
        throw InputError(file + ": JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels (at byte " +
                         std::to_string(i) + ")");
    } else if ((c == '}' || c == ']') && depth > 0) {
      --depth;
    }
  }
}

uint32_t read_u32(const std::vector<uint8_t>& b, size_t at) {
  uint32_t v;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}

// The JSON and BIN chunks of a .glb (glTF 2.0 section 4.4), kept so the writer can copy them
// untouched. The JSON chunk comes first; chunks of other types are skipped.
void split_glb(const std::vector<uint8_t>& bytes, const std::string& file, GltfSource& src) {
  auto bad = [&](const std::string& what) { throw InputError(file + ": not a valid .glb: " + what); };
  if (bytes.size() < 20) bad("shorter than its header");
  if (read_u32(bytes, 4) != 2) bad("version " + std::to_string(read_u32(bytes, 4)) + ", not 2");
  if (read_u32(bytes, 8) > bytes.size()) bad("its header claims more bytes than the file has");
  const size_t total = read_u32(bytes, 8);
  for (size_t at = 12; at + 8 <= total;) {
    const uint32_t length = read_u32(bytes, at), type = read_u32(bytes, at + 4);
    if (length > total - at - 8) bad("chunk at byte " + std::to_string(at) + " runs past the end of the file");
    if (length % 4) bad("chunk at byte " + std::to_string(at) + " is " + std::to_string(length) + " bytes long, not a multiple of 4");
    if (at == 12 && type != 0x4E4F534Au) bad("the first chunk is not JSON");
    if (type == 0x4E4F534Au && at == 12) src.json_text.assign(bytes.begin() + long(at + 8), bytes.begin() + long(at + 8 + length));
    if (type == 0x004E4942u && at > 12 && src.glb_bin.empty())
      src.glb_bin.assign(bytes.begin() + long(at + 8), bytes.begin() + long(at + 8 + length));
    at += 8 + ((size_t(length) + 3) & ~size_t(3));
  }
  if (src.json_text.empty()) bad("no JSON chunk");
}

void append_u32(std::vector<uint8_t>& b, uint32_t v) {
  uint8_t raw[4];
  std::memcpy(raw, &v, 4);
  b.insert(b.end(), raw, raw + 4);
}

// A .glb of a JSON chunk (padded with spaces) and, when there is one, a BIN chunk (glTF 2.0 4.4).
std::vector<uint8_t> glb_bytes(std::string json_text, const std::vector<uint8_t>& bin) {
  json_text.append((4 - json_text.size() % 4) % 4, ' ');
  const size_t bin_padded = (bin.size() + 3) & ~size_t(3);
  std::vector<uint8_t> out = {'g', 'l', 'T', 'F'};
  append_u32(out, 2);
  append_u32(out, uint32_t(12 + 8 + json_text.size() + (bin.empty() ? 0 : 8 + bin_padded)));
  append_u32(out, uint32_t(json_text.size()));
  append_u32(out, 0x4E4F534Au);
  out.insert(out.end(), json_text.begin(), json_text.end());
  if (bin.empty()) return out;
  append_u32(out, uint32_t(bin_padded));
  append_u32(out, 0x004E4942u);
  out.insert(out.end(), bin.begin(), bin.end());
  out.resize(out.size() + bin_padded - bin.size(), 0);
  return out;
}

Mat4 local_transform(const tinygltf::Node& node) {
  Mat4 m;
  if (node.matrix.size() == 16) {
    for (int i = 0; i < 16; ++i) m.m[i] = node.matrix[size_t(i)];
    return m;
  }
  double tx = 0, ty = 0, tz = 0, qx = 0, qy = 0, qz = 0, qw = 1, sx = 1, sy = 1, sz = 1;
  if (node.translation.size() == 3) tx = node.translation[0], ty = node.translation[1], tz = node.translation[2];
  if (node.rotation.size() == 4) qx = node.rotation[0], qy = node.rotation[1], qz = node.rotation[2], qw = node.rotation[3];
  if (node.scale.size() == 3) sx = node.scale[0], sy = node.scale[1], sz = node.scale[2];
  double r[9] = {1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy + qz * qw),     2 * (qx * qz - qy * qw),
                 2 * (qx * qy - qz * qw),     1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz + qx * qw),
                 2 * (qx * qz + qy * qw),     2 * (qy * qz - qx * qw),     1 - 2 * (qx * qx + qy * qy)};
  double s[3] = {sx, sy, sz};
  for (int col = 0; col < 3; ++col)
    for (int row = 0; row < 3; ++row) m.m[col * 4 + row] = r[col * 3 + row] * s[col];
  m.m[12] = tx, m.m[13] = ty, m.m[14] = tz;
  return m;
}

double number(const tinygltf::Value& object, const char* key, double fallback) {
  if (!object.IsObject() || !object.Has(key) || !object.Get(key).IsNumber()) return fallback;
  return object.Get(key).GetNumberAsDouble();
}

Wrap wrap_mode(int gl) {
  switch (gl) {
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return Wrap::ClampToEdge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return Wrap::MirroredRepeat;
    default: return Wrap::Repeat;
  }
}

class SceneBuilder {
 public:
  SceneBuilder(const GltfSource& source, Scene& scene, const std::string& file)
      : source_(source), model_(source.model), scene_(scene), file_(file) {}

  void build() {
    check_required_extensions();
    read_radbake_record();
    convert_images();
    convert_materials();
    visit_nodes();
    scene_.summary.nodes = model_.nodes.size();
    scene_.summary.meshes = model_.meshes.size();
    scene_.summary.materials = model_.materials.size();
    scene_.summary.textures = model_.textures.size();
    scene_.summary.lights = scene_.lights.size();
    for (const MeshInstance& inst : scene_.instances) scene_.summary.triangles += inst.triangle_count();
    if (dropped_back_primitives_) {
      // The earlier layout held the backs' charts beside the fronts'; kept for the fronts alone it
      // would leave their space empty and put the new backs on a page of their own.
      for (MeshInstance& inst : scene_.instances)
        if (inst.lightmap_image >= 0) inst.lightmap_image = -1, inst.texcoords[1].clear();
      scene_.warnings.push_back(std::to_string(dropped_back_primitives_) +
                                " back-face primitives of the bake this file came from are left out (their fronts are "
                                "double-sided again) and lightmap UVs are generated afresh");
    }
    if (colors_were_light_)
      scene_.warnings.push_back("COLOR_0 holds the light of the bake this file came from (extras.radbake); it is not read "
                                "as a base-colour multiplier (the file's own colours, if any, are in _SOURCE_COLOR_0)");
    if (scene_.summary.triangles == 0) refuse(file_, "/", "the scene has no triangles to bake");
  }

 private:
  void check_required_extensions() {
    for (const std::string& ext : model_.extensionsRequired)
      if (const GltfExtension* row = gltf_extension(ext); !row || !row->bakes_when_required)
        refuse(file_, "/extensionsRequired", "the file requires extension " + clipped(ext) + ", which radbake does not support");
  }

  std::vector<int> scene_roots() const {
    if (!model_.scenes.empty()) {
      return model_.scenes[size_t(std::max(model_.defaultScene, 0))].nodes;
    }
    // No scenes: every node that is nobody's child is a root.
    std::vector<char> is_child(model_.nodes.size(), 0);
    for (const tinygltf::Node& n : model_.nodes)
      for (int c : n.children) is_child[size_t(c)] = 1;
    std::vector<int> roots;
    for (size_t i = 0; i < model_.nodes.size(); ++i)
      if (!is_child[i]) roots.push_back(int(i));
    return roots;
  }

  // Depth first with a stack of its own: a chain of 100,000 nodes is a valid file. check_claims
  // has held the nodes to trees (one parent each), so every node is reached once.
  void visit_nodes() {
    // Pushed in reverse, so nodes are reached in the file's order, as the writer and goldens expect.
    std::vector<std::pair<int, Mat4>> stack;
    const std::vector<int> roots = scene_roots();
    for (auto root = roots.rbegin(); root != roots.rend(); ++root) stack.push_back({*root, Mat4{}});
    while (!stack.empty()) {
      const auto [index, parent] = stack.back();
      stack.pop_back();
      const tinygltf::Node& node = model_.nodes[size_t(index)];
      const Mat4 world = parent * local_transform(node);
      for (int i = 0; i < 16; ++i)
        if (!std::isfinite(world.m[i])) refuse(file_, node_pointer(index), "its world transform is not finite");
      if (node.mesh >= 0) add_mesh(index, world);
      auto light = node.extensions.find("KHR_lights_punctual");
      if (light != node.extensions.end() && light->second.Has("light"))
        add_light(light->second.Get("light").GetNumberAsInt(), index, world);
      if (node.camera >= 0) add_camera(node.camera, index, world);
      for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) stack.push_back({*child, world});
    }
  }

  static std::string node_pointer(int index) { return "/nodes/" + std::to_string(index); }

  // A world position radbake can bake: finite, and within kMaxCoordinate where floats still
  // resolve a room and Embree's bounds hold.
  void check_placed(Vec3 p, const std::string& pointer, const std::string& what) const {
    if (is_finite(p) && std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}) <= kMaxCoordinate) return;
    char at[96];
    std::snprintf(at, sizeof at, "(%g, %g, %g)", p.x, p.y, p.z);
    refuse(file_, pointer, what + " lands at " + at + " m, beyond the 1e7 m radbake bakes");
  }

  std::string describe_node(int index) const {
    const std::string& name = model_.nodes[size_t(index)].name;
    return name.empty() ? std::to_string(index) : "'" + clipped(name) + "'";
  }

  void add_mesh(int node_index, const Mat4& world) {
    const tinygltf::Node& node = model_.nodes[size_t(node_index)];
    const tinygltf::Mesh& mesh = model_.meshes[size_t(node.mesh)];
    if (node.skin >= 0)
      scene_.warnings.push_back("node " + describe_node(node_index) + " is skinned; it is baked in its node transform, not posed");
    // A radbake output shows the backs of double-sided faces as primitives of their own: the earlier
    // bake's output, not geometry. They are left out and their fronts made double-sided again, so
    // baking the output gives what baking the original gave (baker/back_faces makes them anew).
    std::set<size_t> fronts_with_backs;
    for (const tinygltf::Primitive& prim : mesh.primitives)
      if (back_faces_of(prim) >= 0) fronts_with_backs.insert(size_t(back_faces_of(prim)));
    for (size_t k = 0; k < mesh.primitives.size(); ++k) {
      const tinygltf::Primitive& prim = mesh.primitives[k];
      if (back_faces_of(prim) >= 0) {
        ++dropped_back_primitives_;
        continue;
      }
      ++scene_.summary.primitives;
      std::string where = "mesh '" + (mesh.name.empty() ? std::to_string(node.mesh) : clipped(mesh.name)) + "' primitive " + std::to_string(k);
      const std::string pointer = "/meshes/" + std::to_string(node.mesh) + "/primitives/" + std::to_string(k);
      int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
      if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        ++scene_.summary.skipped_primitives;
        scene_.warnings.push_back(where + " draws points or lines; skipped");
        continue;
      }
      auto pos = prim.attributes.find("POSITION");
      if (pos == prim.attributes.end()) refuse(file_, pointer + "/attributes", "has no POSITION");
      MeshInstance inst;
      inst.name = (node.name.empty() ? "node " + std::to_string(node_index) : clipped(node.name)) + " / " + where;
      inst.node = node_index;
      inst.mesh = node.mesh;
      inst.primitive = int(k);
      inst.mirrored = world.determinant3() < 0;
      inst.material = fronts_with_backs.count(k) ? double_sided(prim.material) : prim.material;

      int components;
      std::vector<float> p = accessor_floats(model_, pos->second, &components);
      const size_t vertex_count = p.size() / 3;
      inst.positions.resize(vertex_count);
      for (size_t v = 0; v < vertex_count; ++v) {
        Vec3 local{p[3 * v], p[3 * v + 1], p[3 * v + 2]};
        if (!is_finite(local))
          refuse(file_, pointer + "/attributes/POSITION", "has a non-finite value at vertex " + std::to_string(v));
        inst.positions[v] = world.transform_point(local);
        check_placed(inst.positions[v], node_pointer(node_index), "vertex " + std::to_string(v) + " of its mesh");
      }
      read_texcoords(prim, inst);
      if (inst.lightmap_uvs()) inst.lightmap_image = lightmap_image(prim.material);
      // A primitive radbake baked before holds that bake's light in COLOR_0 when the record says
      // so; it is light, not a base-colour multiplier, and the input's own colours are in
      // _SOURCE_COLOR_0 (or it had none). _BAKED_LIGHT, radbake's per-vertex light, is never read.
      const bool baked_before = color_0_holds_light_ && lightmap_image(prim.material, false) >= 0;
      read_colors(prim, inst, baked_before ? "_SOURCE_COLOR_0" : "COLOR_0", pointer);
      inst.color_0_was_light = baked_before && prim.attributes.count("COLOR_0");
      colors_were_light_ |= inst.color_0_was_light;

      std::vector<uint32_t> indices;
      if (prim.indices >= 0) {
        indices = accessor_indices(model_, prim.indices);
        for (size_t i = 0; i < indices.size(); ++i)
          if (indices[i] >= vertex_count)
            refuse(file_, pointer + "/indices", "index " + std::to_string(indices[i]) + " at position " + std::to_string(i) +
                                                    " is out of range (" + std::to_string(vertex_count) + " vertices)");
      } else {
        indices.resize(vertex_count);
        for (size_t i = 0; i < vertex_count; ++i) indices[i] = uint32_t(i);
      }
      if (mode == TINYGLTF_MODE_TRIANGLES && indices.size() % 3)
        scene_.warnings.push_back(where + ": index count is not a multiple of 3; the remainder is ignored");
      inst.triangles = triangle_list(indices, mode);
      read_normals(prim, world, p, inst, where);
      scene_.instances.push_back(std::move(inst));
    }
  }

  // Normals that are not unit vectors are repaired as the writer repairs them (io/gltf/vertex_repair.h,
  // which warns naming the attribute), so the bake shades what the output carries. `local` holds
  // the positions in the mesh's space.
  void read_normals(const tinygltf::Primitive& prim, const Mat4& world, const std::vector<float>& local,
                    MeshInstance& inst, const std::string& where) {
    auto it = prim.attributes.find("NORMAL");
    if (it == prim.attributes.end()) return;
    int components;
    std::vector<float> n = accessor_floats(model_, it->second, &components);
    repair_normals(n, local, inst.triangles);
    inst.normals.resize(inst.positions.size());
    for (size_t v = 0; v < inst.normals.size(); ++v) {
      Vec3 w = normalize(world.transform_normal({n[3 * v], n[3 * v + 1], n[3 * v + 2]}));
      if (!is_finite(w) || length(w) < 0.5f) {
        scene_.warnings.push_back(where + ": its node's transform flattens its normals; face normals are used instead");
        inst.normals.clear();
        return;
      }
      inst.normals[v] = w;
    }
  }

  // check_document has matched each attribute's type, and check_claims its count, to POSITION.
  void read_texcoords(const tinygltf::Primitive& prim, MeshInstance& inst) {
    for (int set = 0; set < 8; ++set) {
      auto it = prim.attributes.find("TEXCOORD_" + std::to_string(set));
      if (it == prim.attributes.end()) continue;
      int components;
      std::vector<float> uv = accessor_floats(model_, it->second, &components);
      inst.texcoords.resize(size_t(set) + 1);
      auto& out = inst.texcoords[size_t(set)];
      out.resize(inst.positions.size());
      // NaN or infinite coordinates read as 0, as the writer repairs them (io/gltf/vertex_repair.h,
      // which warns naming the attribute).
      for (float& c : uv) c = std::isfinite(c) ? c : 0.0f;
      for (size_t v = 0; v < out.size(); ++v) out[v] = {uv[2 * v], uv[2 * v + 1]};
    }
  }

  void read_colors(const tinygltf::Primitive& prim, MeshInstance& inst, const std::string& attribute,
                   const std::string& pointer) {
    auto it = prim.attributes.find(attribute);
    if (it == prim.attributes.end()) return;
    int components;
    std::vector<float> c = accessor_floats(model_, it->second, &components);
    // The schema holds COLOR_n to VEC3 or VEC4; an application attribute (_SOURCE_COLOR_0) may be anything.
    if (components != 3 && components != 4) {
      scene_.warnings.push_back(inst.name + ": " + attribute + " is not RGB or RGBA; its colours are not read");
      return;
    }
    inst.colors.resize(inst.positions.size());
    for (size_t v = 0; v < inst.colors.size(); ++v) {
      const float* e = &c[v * size_t(components)];
      // glTF bounds colours to [0, 1]; a brighter multiplier would reflect more light than arrives,
      // and the output, which keeps these colours, would not validate.
      for (int k = 0; k < components; ++k)
        if (!(e[k] >= 0.0f && e[k] <= 1.0f))
          refuse(file_, pointer + "/attributes/" + attribute,
                 "has " + std::to_string(e[k]) + " at vertex " + std::to_string(v) + "; colours lie in [0, 1]");
      inst.colors[v] = {e[0], e[1], e[2]};
    }
  }

  // The root's extras.radbake (or asset.extras.radbake), written by radbake's writer: whether
  // COLOR_0 of the primitives it baked holds light. `color_0_holds` says so ("source": the input's
  // colours; "light" or "prelit": light); a file from before that field always held light there,
  // and said so with color_0_intensity.
  void read_radbake_record() {
    for (const tinygltf::Value* extras : {&model_.extras, &model_.asset.extras}) {
      if (!extras->IsObject() || !extras->Has("radbake")) continue;
      const tinygltf::Value& record = extras->Get("radbake");
      if (!record.IsObject() || !record.Has("generator") || !record.Get("generator").IsString() ||
          record.Get("generator").Get<std::string>() != "radbake")
        continue;
      made_by_radbake_ = true;
      const tinygltf::Value& holds = record.Get("color_0_holds");
      color_0_holds_light_ = holds.IsString() ? holds.Get<std::string>() != "source" : record.Has("color_0_intensity");
      return;
    }
  }

  // The front primitive whose back faces `prim` is, when it is a back-face primitive radbake wrote
  // (extras.radbake.back_faces_of_primitive in a radbake output); -1 otherwise.
  int back_faces_of(const tinygltf::Primitive& prim) const {
    if (!made_by_radbake_ || !prim.extras.IsObject() || !prim.extras.Has("radbake")) return -1;
    const tinygltf::Value& record = prim.extras.Get("radbake");
    if (!record.IsObject() || !record.Has("back_faces_of_primitive")) return -1;
    const double front = number(record, "back_faces_of_primitive", -1);
    return front >= 0 && front < 1e9 && front == std::floor(front) ? int(front) : -1;
  }

  // A copy of the material with doubleSided set, made once per material.
  int double_sided(int material) {
    auto [it, added] = double_sided_copy_.emplace(material, -1);
    if (added) {
      Material copy = material_of(scene_, material);
      copy.double_sided = true;
      scene_.materials.push_back(std::move(copy));
      it->second = int(scene_.materials.size() - 1);
    }
    return it->second;
  }

  // The image a material's MOZ_lightmap texture shows, or -1: none, an index out of range, or (with
  // `reading_set_1`) a lightmap read from another set than TEXCOORD_1. The extension is only copied,
  // so nothing has checked its numbers before.
  int lightmap_image(int material, bool reading_set_1 = true) const {
    if (material < 0 || size_t(material) >= model_.materials.size()) return -1;
    const auto& extensions = model_.materials[size_t(material)].extensions;
    auto it = extensions.find("MOZ_lightmap");
    if (it == extensions.end() || !it->second.IsObject()) return -1;
    const tinygltf::Value& index = it->second.Get("index");
    if (!index.IsNumber() || (reading_set_1 && number(it->second, "texCoord", 0) != 1)) return -1;
    const double texture = index.GetNumberAsDouble();
    if (!(texture >= 0 && texture < double(model_.textures.size())) || texture != std::floor(texture)) return -1;
    const int source = model_.textures[size_t(texture)].source;
    return source >= 0 && size_t(source) < model_.images.size() ? source : -1;
  }

  // check_document has checked the light's type and bounded its numbers.
  void add_light(int index, int node_index, const Mat4& world) {
    const tinygltf::Light& in = model_.lights[size_t(index)];
    Light light;
    light.name = in.name.empty() ? "light " + std::to_string(index) : clipped(in.name);
    light.source_index = index;
    if (in.type == "point") light.type = LightType::Point;
    else if (in.type == "spot") light.type = LightType::Spot;
    else light.type = LightType::Directional;
    if (in.color.size() == 3) light.color = {float(in.color[0]), float(in.color[1]), float(in.color[2])};
    light.intensity = float(in.intensity);
    light.range = float(in.range);
    light.inner_cone_angle = float(in.spot.innerConeAngle);
    light.outer_cone_angle = float(in.spot.outerConeAngle);
    light.position = world.transform_point({0, 0, 0});
    light.direction = normalize(world.transform_direction({0, 0, -1}));
    if (light.type != LightType::Directional) check_placed(light.position, node_pointer(node_index), "its light");
    if (light.type != LightType::Point && !(length(light.direction) > 0.5f))
      refuse(file_, node_pointer(node_index), "light '" + light.name + "' has a degenerate direction (its node scales to zero)");
    scene_.lights.push_back(light);
  }

  // The camera looks down its node's -Z with +Y up (glTF 2.0 section 3.10.1); the node's scale
  // only lengthens the axes, a shear or a zero scale leaves no orientation (kept, not usable).
  void add_camera(int index, int node_index, const Mat4& world) {
    const tinygltf::Camera& in = model_.cameras[size_t(index)];
    SceneCamera c;
    c.name = in.name.empty() ? (model_.nodes[size_t(node_index)].name.empty() ? "camera " + std::to_string(index)
                                                                           : clipped(model_.nodes[size_t(node_index)].name))
                             : clipped(in.name);
    c.source = index;
    c.node = node_index;
    c.eye = world.transform_point({0, 0, 0});
    const Vec3 forward = world.transform_direction({0, 0, -1}), up = world.transform_direction({0, 1, 0});
    const Vec3 right = cross(forward, up);
    if (length(forward) > 0 && length(right) > 1e-6f * length(forward) * length(up)) {
      c.forward = normalize(forward);
      const Vec3 x = normalize(right);
      c.up = cross(x, c.forward);
    } else {
      c.forward = c.up = {0, 0, 0};
    }
    c.orthographic = in.type == "orthographic";
    if (c.orthographic) {
      c.xmag = float(in.orthographic.xmag), c.ymag = float(in.orthographic.ymag);
      c.znear = float(in.orthographic.znear), c.zfar = float(in.orthographic.zfar);
    } else {
      c.yfov = float(in.perspective.yfov), c.aspect = float(in.perspective.aspectRatio);
      c.znear = float(in.perspective.znear), c.zfar = float(in.perspective.zfar);
    }
    scene_.cameras.push_back(c);
  }

  TextureRef texture_ref(int texture_index, int tex_coord, const tinygltf::ExtensionMap& extensions) {
    TextureRef ref;
    if (texture_index < 0) return ref;
    const tinygltf::Texture& tex = model_.textures[size_t(texture_index)];
    if (tex.source < 0 || !usable_image_[size_t(tex.source)]) return ref;
    ref.image = tex.source;
    ref.tex_coord = tex_coord;
    if (tex.sampler >= 0 && size_t(tex.sampler) < model_.samplers.size()) {
      ref.wrap_s = wrap_mode(model_.samplers[size_t(tex.sampler)].wrapS);
      ref.wrap_t = wrap_mode(model_.samplers[size_t(tex.sampler)].wrapT);
    }
    auto t = extensions.find("KHR_texture_transform");
    if (t != extensions.end()) {
      const tinygltf::Value& v = t->second;
      if (v.Has("offset") && v.Get("offset").ArrayLen() == 2)
        ref.transform.offset = {float(v.Get("offset").Get(0).GetNumberAsDouble()), float(v.Get("offset").Get(1).GetNumberAsDouble())};
      if (v.Has("scale") && v.Get("scale").ArrayLen() == 2)
        ref.transform.scale = {float(v.Get("scale").Get(0).GetNumberAsDouble()), float(v.Get("scale").Get(1).GetNumberAsDouble())};
      ref.transform.rotation = float(number(v, "rotation", 0));
      ref.tex_coord = int(number(v, "texCoord", tex_coord));
    }
    return ref;
  }

  void convert_images() {
    usable_image_.assign(model_.images.size(), 0);
    for (size_t i = 0; i < model_.images.size(); ++i) {
      const tinygltf::Image& in = model_.images[i];
      Image out;
      out.name = in.name.empty() ? (in.uri.empty() ? "image " + std::to_string(i) : clipped(in.uri)) : clipped(in.name);
      bool decoded = in.width > 0 && in.height > 0 && in.component == 4 && (in.bits == 8 || in.bits == 16) &&
                     in.image.size() == size_t(in.width) * size_t(in.height) * 4 * size_t(in.bits / 8);
      if (!decoded) {
        // The one warning about the image: the writer leaves out what unwritable_image names.
        const std::string why = unwritable_image(source_, i), image = "/images/" + std::to_string(i) + " ('" + out.name + "')";
        scene_.warnings.push_back((why.empty() ? image + " is WebP, which radbake does not decode"
                                               : "dropped " + image + " from the output (" + why + ")") +
                                  "; the bake ignores textures using it");
      } else {
        out.width = in.width;
        out.height = in.height;
        out.bits = in.bits;
        out.pixels = in.image;
        usable_image_[i] = 1;
      }
      scene_.images.push_back(std::move(out));
    }
  }

  // What the material asks for that diffuse radiosity leaves out, each only where it has an effect
  // (a factor of zero switches it off). The metallic part is judged by the plan, which sees the
  // resolved factor.
  static std::vector<std::string> unsimulated_features(const tinygltf::Material& in) {
    std::vector<std::string> out;
    auto active = [&](const char* extension, const char* factor, double fallback) {
      auto it = in.extensions.find(extension);
      return it != in.extensions.end() && (factor == nullptr || number(it->second, factor, fallback) > 0);
    };
    if (active("KHR_materials_transmission", nullptr, 0) &&
        in.extensions.at("KHR_materials_transmission").Has("transmissionTexture"))
      out.push_back("the transmission texture (KHR_materials_transmission; its factor is read)");
    if (active("KHR_materials_diffuse_transmission", "diffuseTransmissionFactor", 0))
      out.push_back("diffuse transmission (KHR_materials_diffuse_transmission)");
    if (active("KHR_materials_volume", "thicknessFactor", 0)) out.push_back("volume (KHR_materials_volume)");
    if (active("KHR_materials_specular", "specularFactor", 1)) out.push_back("specular (KHR_materials_specular)");
    if (active("KHR_materials_clearcoat", "clearcoatFactor", 0)) out.push_back("clearcoat (KHR_materials_clearcoat)");
    if (active("KHR_materials_sheen", nullptr, 0)) out.push_back("sheen (KHR_materials_sheen)");
    if (active("KHR_materials_iridescence", "iridescenceFactor", 0)) out.push_back("iridescence (KHR_materials_iridescence)");
    return out;
  }

  void convert_materials() {
    for (const tinygltf::Material& in : model_.materials) {
      Material m;
      m.name = in.name;
      const auto& pbr = in.pbrMetallicRoughness;
      if (pbr.baseColorFactor.size() == 4) {
        m.base_color = {float(pbr.baseColorFactor[0]), float(pbr.baseColorFactor[1]), float(pbr.baseColorFactor[2])};
        m.base_alpha = float(pbr.baseColorFactor[3]);
      }
      m.base_color_texture = texture_ref(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, pbr.baseColorTexture.extensions);
      m.metallic = float(pbr.metallicFactor);
      m.metallic_roughness_texture = texture_ref(pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
                                                 pbr.metallicRoughnessTexture.extensions);
      if (in.emissiveFactor.size() == 3)
        m.emissive = {float(in.emissiveFactor[0]), float(in.emissiveFactor[1]), float(in.emissiveFactor[2])};
      m.emissive_texture = texture_ref(in.emissiveTexture.index, in.emissiveTexture.texCoord, in.emissiveTexture.extensions);
      m.normal_texture = texture_ref(in.normalTexture.index, in.normalTexture.texCoord, in.normalTexture.extensions);
      m.normal_scale = std::isfinite(in.normalTexture.scale) ? float(std::clamp(in.normalTexture.scale, -100.0, 100.0)) : 1.0f;
      auto strength = in.extensions.find("KHR_materials_emissive_strength");
      if (strength != in.extensions.end()) m.emissive_strength = float(number(strength->second, "emissiveStrength", 1.0));
      m.double_sided = in.doubleSided;
      m.alpha_mode = in.alphaMode == "MASK" ? AlphaMode::Mask : in.alphaMode == "BLEND" ? AlphaMode::Blend : AlphaMode::Opaque;
      m.alpha_cutoff = float(in.alphaCutoff);
      auto transmission = in.extensions.find("KHR_materials_transmission");
      if (transmission != in.extensions.end())
        m.transmission = std::clamp(float(number(transmission->second, "transmissionFactor", 0.0)), 0.0f, 1.0f);
      auto ior = in.extensions.find("KHR_materials_ior");
      if (ior != in.extensions.end()) m.ior = float(std::clamp(number(ior->second, "ior", 1.5), 1.0, 5.0));
      if (in.extras.IsObject() && in.extras.Has("visible_transmittance")) {
        const tinygltf::Value& tau = in.extras.Get("visible_transmittance");
        const double value = tau.IsNumber() ? tau.GetNumberAsDouble() : -1;
        if (!(value >= 0 && value <= 1))
          throw InputError("material '" + clipped(in.name) + "': extras.visible_transmittance must be a number 0..1");
        m.visible_transmittance = float(value);
      }
      m.unsimulated = unsimulated_features(in);
      scene_.materials.push_back(std::move(m));
    }
  }

  const GltfSource& source_;
  const tinygltf::Model& model_;
  Scene& scene_;
  const std::string& file_;
  std::vector<char> usable_image_;
  bool made_by_radbake_ = false;      // the file is a radbake output (extras.radbake)
  bool color_0_holds_light_ = false;  // whose COLOR_0 holds light
  size_t dropped_back_primitives_ = 0;
  std::map<int, int> double_sided_copy_;  // material -> its double-sided copy in Scene::materials
  bool colors_were_light_ = false;    // and a primitive's COLOR_0 was left unread for it
};

}  // namespace

std::vector<std::string_view> scene_contents(const LoadedScene& loaded) {
  const GltfSource& source = *loaded.source;
  auto bytes = [](const std::vector<unsigned char>& data) {
    return std::string_view(reinterpret_cast<const char*>(data.data()), data.size());
  };
  std::vector<std::string_view> parts = {source.json_text};
  for (const auto& buffer : source.model.buffers) parts.push_back(bytes(buffer.data));
  for (const auto& image : source.model.images) parts.push_back(bytes(image.image));
  return parts;
}

LoadedScene load_gltf(const std::string& path, const LoadOptions& options) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    throw InputError(clipped(path) + (fs::exists(path, ec) ? ": not a regular file (a folder, pipe or device)" : ": no such file"));
  if (fs::file_size(path, ec) > 0xffffffffu) throw InputError(clipped(path) + ": file larger than 4 GiB");
  auto src = std::make_shared<GltfSource>();
  src->path = path;
  src->base_dir = fs::path(path).parent_path().string();
  LoadedScene out;
  std::vector<uint8_t> bytes =
      read_regular_bytes(path, "scene", std::min<uint64_t>(0xffffffffu, memory_limit(options.max_memory_bytes)));
  src->binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  if (src->binary) split_glb(bytes, path, *src);
  else src->json_text.assign(bytes.begin(), bytes.end()), bytes = {};
  // Counted before any parser recurses into it.
  check_nesting(src->json_text, path);
  // Parsed once: both checks read this document, and what the first one drops or declares is
  // written back for tinygltf, which parses the text once more into its own model.
  nlohmann::ordered_json doc;
  try {
    doc = nlohmann::ordered_json::parse(src->json_text);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(clipped(path) + ": not valid JSON (syntax error at byte " + std::to_string(e.byte) + ")");
  } catch (const nlohmann::json::out_of_range&) {
    throw InputError(clipped(path) + ": not valid JSON (a number too large for a double, such as 1e999)");
  }
  if (check_document(doc, path, out.scene.warnings)) {
    src->json_text = doc.dump();
    if (src->binary) bytes = glb_bytes(src->json_text, src->glb_bin);
  }
  ResourceEstimate estimate = check_claims(doc, path, src->binary ? src->glb_bin.size() : SIZE_MAX);
  // The file is held as read, as JSON text and as tinygltf's model while loading.
  estimate.data_bytes += 3 * (src->binary ? bytes.size() : src->json_text.size());
  check_budget(estimate, options, path);
  FileAccess access = resolve_files(doc, path, src->base_dir, options.allow_external_files);
  doc = nullptr;  // freed before tinygltf builds its model
  access.max_memory_bytes = options.max_memory_bytes;
  access.estimate = &estimate;

  tinygltf::TinyGLTF loader;
  restrict_file_access(loader, access);
  std::string err, warn;
  bool ok = false;
  try {
    // No base folder: the file callbacks resolve every URI, from the list resolve_files made.
    ok = src->binary ? loader.LoadBinaryFromMemory(&src->model, &err, &warn, bytes.data(), unsigned(bytes.size()), "")
                     : loader.LoadASCIIFromString(&src->model, &err, &warn, src->json_text.data(),
                                                  unsigned(src->json_text.size()), "");
  } catch (const std::exception&) {
    ok = false;
    err = "its parser failed";
  }
  if (!access.error.empty()) throw InputError(access.error);
  if (!ok) throw InputError(clipped(path) + ": not a glTF file radbake can read (tinygltf: '" + clipped(one_line(err)) + "')");
  src->image_files = std::move(access.image_files);
  src->image_types = std::move(access.image_types);

  if (!warn.empty()) out.scene.warnings.push_back(one_line(warn));
  SceneBuilder(*src, out.scene, path).build();
  out.source = std::move(src);
  out.estimate = estimate;
  return out;
}

}  // namespace radbake
