#include "io/gltf/display_gltf.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <tuple>
#include <nlohmann/json.hpp>

#include "io/gltf/gltf_binary.h"
#include "io/gltf/gltf_source.h"
#include "io/lightmaps/lightmap_images.h"
#include "io/files/written_file.h"

namespace radbake {
namespace {

using json = nlohmann::ordered_json;

constexpr int kLinear = 9729, kClampToEdge = 33071;

int gl_wrap(Wrap w) { return w == Wrap::ClampToEdge ? 33071 : w == Wrap::MirroredRepeat ? 33648 : 10497; }

Vec2 transformed(const TextureTransform& t, Vec2 uv) {
  Vec2 s{uv.x * t.scale.x, uv.y * t.scale.y};
  float c = std::cos(t.rotation), r = std::sin(t.rotation);
  return {c * s.x - r * s.y + t.offset.x, r * s.x + c * s.y + t.offset.y};
}

// The unit quaternion (x, y, z, w) of the rotation whose columns are `right`, `up` and `back`.
json quaternion(Vec3 right, Vec3 up, Vec3 back) {
  const double m00 = right.x, m10 = right.y, m20 = right.z, m01 = up.x, m11 = up.y, m21 = up.z, m02 = back.x,
               m12 = back.y, m22 = back.z;
  double x, y, z, w;
  const double trace = m00 + m11 + m22;
  if (trace > 0) {
    const double s = 2 * std::sqrt(trace + 1);
    w = s / 4, x = (m21 - m12) / s, y = (m02 - m20) / s, z = (m10 - m01) / s;
  } else if (m00 > m11 && m00 > m22) {
    const double s = 2 * std::sqrt(1 + m00 - m11 - m22);
    w = (m21 - m12) / s, x = s / 4, y = (m01 + m10) / s, z = (m02 + m20) / s;
  } else if (m11 > m22) {
    const double s = 2 * std::sqrt(1 + m11 - m00 - m22);
    w = (m02 - m20) / s, x = (m01 + m10) / s, y = s / 4, z = (m12 + m21) / s;
  } else {
    const double s = 2 * std::sqrt(1 + m22 - m00 - m11);
    w = (m10 - m01) / s, x = (m02 + m20) / s, y = (m12 + m21) / s, z = s / 4;
  }
  const double n = std::sqrt(x * x + y * y + z * z + w * w);
  return {x / n, y / n, z / n, w / n};
}

// A camera as glTF writes it, from tinygltf's reading (which gives 0 for an absent aspect ratio
// or far plane).
json camera_json(const tinygltf::Camera& c) {
  json out = {{"type", c.type}};
  if (!c.name.empty()) out["name"] = c.name;
  if (c.type == "perspective") {
    json p = {{"yfov", c.perspective.yfov}, {"znear", c.perspective.znear}};
    if (c.perspective.aspectRatio > 0) p["aspectRatio"] = c.perspective.aspectRatio;
    if (c.perspective.zfar > 0) p["zfar"] = c.perspective.zfar;
    out["perspective"] = p;
  } else {
    out["orthographic"] = {{"xmag", c.orthographic.xmag}, {"ymag", c.orthographic.ymag},
                           {"zfar", c.orthographic.zfar}, {"znear", c.orthographic.znear}};
  }
  return out;
}

// An input vertex attribute at a display vertex.
template <typename T>
T blend(const std::vector<T>& per_vertex, const std::vector<uint32_t>& source_vertex, const RefinedVertex& v) {
  return blend<T>(v, [&](uint32_t atlas_vertex) { return per_vertex[source_vertex[atlas_vertex]]; });
}

class DisplayWriter {
 public:
  explicit DisplayWriter(const DisplayInput& in) : in_(in), bin_(doc_, 0) {
    doc_["asset"] = {{"version", "2.0"}, {"generator", "radbake"}};
    doc_["extensionsUsed"] = json::array({"KHR_materials_unlit"});
    for (const char* key : {"scenes", "nodes", "meshes", "materials", "textures", "images", "samplers", "cameras",
                            "accessors", "bufferViews", "buffers"})
      doc_[key] = json::array();
  }

  DisplayOutput write(const std::string& folder, const std::string& name) {
    const Scene& scene = *in_.scene;
    has_back_.assign(scene.instances.size(), 0);
    for (const MeshInstance& inst : scene.instances)
      if (inst.back_of >= 0) has_back_[size_t(inst.back_of)] = 1;
    if (!in_.vertex_lit) add_prelit_pages();
    json scene_nodes = json::array();
    for (size_t i = 0; i < scene.instances.size(); ++i) {
      if ((*in_.meshes)[i].triangles.empty()) continue;
      add_instance(i);
      scene_nodes.push_back(doc_["nodes"].size() - 1);
    }
    DisplayOutput out;
    out.camera = add_cameras(scene_nodes);
    out.camera_added = camera_added_;
    doc_["scenes"].push_back({{"name", "radbake display"}, {"nodes", scene_nodes}});
    doc_["scene"] = 0;
    describe();
    for (const char* key : {"textures", "images", "samplers", "cameras"})
      if (doc_[key].empty()) doc_.erase(key);
    doc_["buffers"].push_back({{"byteLength", bin_.data().size()}});
    out.file = name + "_display.glb";
    out.triangles = triangles_;
    write_glb((std::filesystem::path(folder) / out.file).string());
    return out;
  }

 private:
  // The input's cameras in its displayed scene, each a root node placed where its node's world
  // transform puts it (the geometry here is in world space); or, where there is none, the bake's.
  // Returns what the file opens on, for the report.
  std::string add_cameras(json& scene_nodes) {
    size_t kept = 0, degenerate = 0;
    std::string first;
    if (in_.source)
      for (const SceneCamera& c : in_.scene->cameras) {
        if (!c.usable()) {
          ++degenerate;
          continue;
        }
        add_camera(camera_json(in_.source->model.cameras[size_t(c.source)]), c.name, {c.eye.x, c.eye.y, c.eye.z},
                   c.forward, c.up, scene_nodes);
        if (kept++ == 0) first = c.name;
      }
    const std::string left_out =
        degenerate > 0 ? " (" + std::to_string(degenerate) + " left out: their nodes' scale leaves no view direction)" : "";
    if (kept > 0)
      return "the input's " + (kept == 1 ? "camera '" + first + "'" : std::to_string(kept) + " cameras, first '" + first + "'") +
             left_out;
    if (!in_.camera) return "none" + left_out;
    const DisplayCamera& c = *in_.camera;
    const json camera = {{"type", "perspective"}, {"name", "radbake"},
                         {"perspective", {{"yfov", c.yfov}, {"znear", c.znear}}}};
    add_camera(camera, "radbake camera", {c.eye.x, c.eye.y, c.eye.z}, c.forward, {0, 1, 0}, scene_nodes);
    camera_added_ = true;
    return "added, the input has none" + left_out + ": " + c.why;
  }

  // A root node at `translation` looking along `forward` with `up` as near up as it can be.
  void add_camera(const json& camera, const std::string& name, const json& translation, Vec3 forward, Vec3 up,
                  json& scene_nodes) {
    const Vec3 f = normalize(forward), x = normalize(cross(forward, up)), y = cross(x, f);
    doc_["cameras"].push_back(camera);
    doc_["nodes"].push_back({{"name", name}, {"camera", doc_["cameras"].size() - 1},
                             {"translation", translation}, {"rotation", quaternion(x, y, -f)}});
    scene_nodes.push_back(doc_["nodes"].size() - 1);
  }

  void add_prelit_pages() {
    doc_["samplers"].push_back(sampler(kClampToEdge, kClampToEdge));
    for (size_t p = 0; p < in_.pages->pages.size(); ++p) {
      doc_["images"].push_back({{"name", "prelit page " + std::to_string(p)},
                                {"bufferView", bin_.add_view(encode_display_png(in_.pages->pages[p], in_.exposure.exposure))},
                                {"mimeType", "image/png"}});
      doc_["textures"].push_back({{"sampler", 0}, {"source", doc_["images"].size() - 1}});
    }
  }

  // No mipmaps: a chart's neighbours are a few texels away, and mip levels average them in (see
  // docs/mip_bleeding.md).
  static json sampler(int wrap_s, int wrap_t) {
    return {{"magFilter", kLinear}, {"minFilter", kLinear}, {"wrapS", wrap_s}, {"wrapT", wrap_t}};
  }

  static json unlit(const std::string& name, bool double_sided) {
    json m = {{"name", name},
              // What a viewer without KHR_materials_unlit shows: the extension's recommended fallback.
              {"pbrMetallicRoughness", {{"metallicFactor", 0}, {"roughnessFactor", 0.9}}},
              {"extensions", {{"KHR_materials_unlit", json::object()}}}};
    if (double_sided) m["doubleSided"] = true;
    return m;
  }

  // A face with a back-face twin shows only its own side; other double-sided faces show their one
  // light on both sides.
  bool double_sided(size_t i) const {
    const MeshInstance& inst = in_.scene->instances[i];
    return inst.back_of < 0 && !has_back_[i] && material_of(*in_.scene, inst.material).double_sided;
  }

  int page_material(int page, bool two_sided, float alpha) {
    auto key = std::make_tuple(page, two_sided, alpha);
    auto found = page_materials_.find(key);
    if (found != page_materials_.end()) return found->second;
    json m = unlit("prelit page " + std::to_string(page) + (two_sided ? " (double-sided)" : ""), two_sided);
    m["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", page}};
    blend_by_alpha(m, alpha);
    doc_["materials"].push_back(m);
    return page_materials_[key] = int(doc_["materials"].size() - 1);
  }

  // An alpha-blended surface (glass modelled as BLEND) is blended here too, by its base alpha, so
  // what is behind it shows as a viewer shows the engine file (its texture's alpha is not read).
  float alpha_of(size_t instance) const {
    const Material& m = material_of(*in_.scene, in_.scene->instances[instance].material);
    return m.alpha_mode == AlphaMode::Blend ? std::clamp(m.base_alpha, 0.0f, 1.0f) : 1.0f;
  }

  static void blend_by_alpha(json& m, float alpha) {
    if (!(alpha < 1)) return;
    m["name"] = m["name"].get<std::string>() + " (blended)";
    m["alphaMode"] = "BLEND";
    json& factor = m["pbrMetallicRoughness"]["baseColorFactor"];
    if (!factor.is_array()) factor = {1.0, 1.0, 1.0, 1.0};
    factor[3] = alpha;
  }

  // Vertex-lit: the material's diffuse reflectance as the unlit base colour (its texture too),
  // which COLOR_0 (the pre-lit light on a white surface) multiplies. Emitters are shown white,
  // their luminance in COLOR_0.
  int vertex_material(int material, bool two_sided, bool textured, float alpha) {
    auto key = std::make_tuple(material, two_sided, textured, alpha);
    auto found = vertex_materials_.find(key);
    if (found != vertex_materials_.end()) return found->second;
    const Material& source = material_of(*in_.scene, material);
    json m = unlit(source.name.empty() ? "material " + std::to_string(material) : source.name, two_sided);
    if (shows_reflectance(material)) {
      const Rgb albedo = source.base_color * (1 - source.metallic);
      m["pbrMetallicRoughness"]["baseColorFactor"] = {albedo.x, albedo.y, albedo.z, 1.0};
      if (textured) m["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", base_texture(source.base_color_texture)}};
    }
    blend_by_alpha(m, alpha);
    doc_["materials"].push_back(m);
    return vertex_materials_[key] = int(doc_["materials"].size() - 1);
  }

  bool shows_reflectance(int material) const {
    return in_.lightmap_is_irradiance && !material_of(*in_.scene, material).emits();
  }

  int base_texture(const TextureRef& ref) {
    auto found = image_textures_.find(ref.image);
    if (found != image_textures_.end()) return found->second;
    const Image& image = in_.scene->images[size_t(ref.image)];
    std::vector<uint8_t> rgb(size_t(image.width) * size_t(image.height) * 3);
    for (size_t p = 0; p < size_t(image.width) * size_t(image.height); ++p)
      for (size_t c = 0; c < 3; ++c)
        rgb[3 * p + c] = image.bits == 16 ? uint8_t(reinterpret_cast<const uint16_t*>(image.pixels.data())[4 * p + c] >> 8)
                                          : image.pixels[4 * p + c];
    doc_["samplers"].push_back(sampler(gl_wrap(ref.wrap_s), gl_wrap(ref.wrap_t)));
    doc_["images"].push_back({{"name", image.name}, {"bufferView", bin_.add_view(encode_png(image.width, image.height, rgb))},
                              {"mimeType", "image/png"}});
    doc_["textures"].push_back({{"sampler", doc_["samplers"].size() - 1}, {"source", doc_["images"].size() - 1}});
    return image_textures_[ref.image] = int(doc_["textures"].size() - 1);
  }

  void add_instance(size_t i) {
    const MeshInstance& inst = in_.scene->instances[i];
    const AtlasMesh& lm = in_.atlas->meshes[i];
    const RefinedMesh& mesh = (*in_.meshes)[i];
    const size_t n = mesh.vertices.size();
    std::vector<float> positions, normals, uvs, colors;
    for (const RefinedVertex& v : mesh.vertices) {
      const Vec3 p = blend(inst.positions, lm.source_vertex, v);
      positions.insert(positions.end(), {p.x, p.y, p.z});
      if (!inst.normals.empty()) {
        Vec3 nrm = normalize(blend(inst.normals, lm.source_vertex, v));
        // A triangle whose corners face opposite ways blends to no direction; glTF needs unit normals.
        if (!(length(nrm) > 0.5f)) nrm = inst.normals[lm.source_vertex[v.corner[0]]];
        normals.insert(normals.end(), {nrm.x, nrm.y, nrm.z});
      }
    }
    json attributes = {{"POSITION", bin_.add(as_bytes(positions), n, "VEC3", kFloat, false, kArrayBuffer, true)}};
    if (!normals.empty()) attributes["NORMAL"] = bin_.add(as_bytes(normals), n, "VEC3", kFloat, false, kArrayBuffer, false);
    int material;
    if (!in_.vertex_lit) {
      for (const RefinedVertex& v : mesh.vertices) {
        const Vec2 uv = blend<Vec2>(v, [&](uint32_t atlas_vertex) { return lm.uvs[atlas_vertex]; });
        uvs.insert(uvs.end(), {uv.x, uv.y});
      }
      material = page_material(lm.page, double_sided(i), alpha_of(i));
    } else {
      const Material& source = material_of(*in_.scene, inst.material);
      const TextureRef& ref = source.base_color_texture;
      const bool reflects = shows_reflectance(inst.material);
      const std::vector<Vec2>* set = ref.present() && size_t(ref.tex_coord) < inst.texcoords.size() &&
                                             !inst.texcoords[size_t(ref.tex_coord)].empty()
                                         ? &inst.texcoords[size_t(ref.tex_coord)] : nullptr;
      // Luminance of what the surface emits, cd/m2 (the emissive texture is not read here).
      const Rgb emitted = source.emits() ? source.emissive * (source.emissive_strength * in_.emission_scale) : Rgb{};
      const bool textured = reflects && set;
      for (size_t k = 0; k < n; ++k) {
        const RefinedVertex& v = mesh.vertices[k];
        if (textured) {
          Vec2 uv = transformed(ref.transform, blend(*set, lm.source_vertex, v));
          // Huge coordinates under a large texture transform overflow; glTF's floats are finite.
          if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) uv = {0, 0};
          uvs.insert(uvs.end(), {uv.x, uv.y});
        }
        Rgb seen = prelit_vertex(mesh.values[k]);
        if (!reflects && in_.lightmap_is_irradiance) seen = seen * (source.base_color * (1 - source.metallic)) + emitted;
        for (int c = 0; c < 3; ++c) colors.push_back(std::clamp(seen[c] * in_.exposure.exposure, 0.0f, 1.0f));
      }
      material = vertex_material(inst.material, double_sided(i), textured, alpha_of(i));
      attributes["COLOR_0"] = bin_.add(as_bytes(colors), n, "VEC3", kFloat, false, kArrayBuffer, false);
    }
    if (!uvs.empty()) attributes["TEXCOORD_0"] = bin_.add(as_bytes(uvs), n, "VEC2", kFloat, false, kArrayBuffer, false);
    std::vector<uint32_t> triangles = mesh.triangles;
    // A mirrored node's front faces are clockwise in world space; here the transform is the identity.
    if (inst.mirrored)
      for (size_t t = 0; t + 2 < triangles.size(); t += 3) std::swap(triangles[t + 1], triangles[t + 2]);
    const auto [indices, type] = index_bytes(triangles, n);
    json primitive = {{"attributes", attributes},
                      {"indices", bin_.add(indices, triangles.size(), "SCALAR", type, false, kElementArrayBuffer, false)},
                      {"material", material}};
    doc_["meshes"].push_back({{"name", inst.name}, {"primitives", json::array({primitive})}});
    doc_["nodes"].push_back({{"name", inst.name}, {"mesh", doc_["meshes"].size() - 1}});
    triangles_ += triangles.size() / 3;
  }

  void describe() {
    json info = {
        {"generator", "radbake"},
        {"shows", in_.vertex_lit ? "vertex-lit: base colour x COLOR_0" : "pre-lit pages on TEXCOORD_0"},
        {"quantity", "luminance"},
        {"unit", "cd/m2"},
        {"display", "linear display value = luminance * display_exposure, clipped to 1, sRGB-encoded"},
        {"display_exposure", in_.exposure.exposure},
        {"exposure_automatic", in_.exposure.automatic},
        {"exposure_method", in_.exposure.method},
        {"median_lit_luminance", in_.exposure.median_lit_luminance},
    };
    if (!in_.vertex_lit) info["prelit_detail"] = in_.pages->detail;
    doc_["extras"] = {{"radbake", info}};
  }

  void write_glb(const std::string& path) {
    std::string text = doc_.dump();
    while (text.size() % 4) text.push_back(' ');
    std::vector<uint8_t> binary = bin_.data();
    while (binary.size() % 4) binary.push_back(0);
    auto u32 = [](std::ofstream& out, uint32_t v) { out.write(reinterpret_cast<const char*>(&v), 4); };
    std::ofstream out(path, std::ios::binary);
    u32(out, 0x46546C67);  // "glTF"
    u32(out, 2);
    u32(out, uint32_t(12 + 8 + text.size() + 8 + binary.size()));
    u32(out, uint32_t(text.size()));
    u32(out, 0x4E4F534A);  // "JSON"
    out.write(text.data(), std::streamsize(text.size()));
    u32(out, uint32_t(binary.size()));
    u32(out, 0x004E4942);  // "BIN\0"
    out.write(reinterpret_cast<const char*>(binary.data()), std::streamsize(binary.size()));
    close_written(out, path);
  }

  const DisplayInput& in_;
  json doc_;
  bool camera_added_ = false;
  BinaryWriter bin_;
  std::vector<uint8_t> has_back_;
  std::map<std::tuple<int, bool, float>, int> page_materials_;
  std::map<std::tuple<int, bool, bool, float>, int> vertex_materials_;
  std::map<int, int> image_textures_;
  size_t triangles_ = 0;
};

}  // namespace

DisplayOutput write_display_gltf(const DisplayInput& input, const std::string& folder, const std::string& name) {
  return DisplayWriter(input).write(folder, name);
}

}  // namespace radbake
