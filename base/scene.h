// The scene as the core sees it: plain data in world space, metres and photometric units.
// io/ fills it from glTF; nothing in baker/ or uv/ knows which file format it came from.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/math.h"

namespace radbake {

// The brightest light radbake bakes. Beyond these, float products in the bake (intensity x colour
// / distance^2, luminance x area) come near float's 3.4e38 and the energy balance turns to NaN.
// The sun gives 1.2e5 lux and its disc 1.6e9 cd/m2, so real scenes stay many orders below.
constexpr double kMaxLightIntensity = 1e20;  // candela (point, spot) or lux (directional), times colour
constexpr double kMaxLuminance = 1e20;       // cd/m2: emissiveFactor x emissiveStrength x --emission-scale

// Pixels as stored in the file, RGBA, 8 or 16 bits per channel, rows top to bottom. No colour
// decoding yet: one image may be an sRGB colour texture for one material and linear data for another.
struct Image {
  std::string name;
  int width = 0, height = 0;
  int bits = 8;                 // 8 or 16
  std::vector<uint8_t> pixels;  // width * height * 4 channels, native-endian uint16 when bits = 16

  // Channel c of pixel (x, y) in [0, 1].
  float channel(int x, int y, int c) const {
    size_t i = (size_t(y) * size_t(width) + size_t(x)) * 4 + size_t(c);
    if (bits == 16) return float(reinterpret_cast<const uint16_t*>(pixels.data())[i]) / 65535.0f;
    return float(pixels[i]) / 255.0f;
  }
};

enum class Wrap { Repeat, ClampToEdge, MirroredRepeat };

// KHR_texture_transform: uv' = T * R * S * uv.
struct TextureTransform {
  Vec2 offset{0, 0};
  float rotation = 0;  // radians, counter-clockwise in UV space
  Vec2 scale{1, 1};
};

struct TextureRef {
  int image = -1;     // index into Scene::images; -1 means no texture
  int tex_coord = 0;  // which TEXCOORD_n set (after KHR_texture_transform's texCoord override)
  Wrap wrap_s = Wrap::Repeat, wrap_t = Wrap::Repeat;
  TextureTransform transform;

  bool present() const { return image >= 0; }
};

// glTF alphaMode: how the base colour's alpha makes a surface partly absent.
enum class AlphaMode {
  Opaque,  // alpha ignored
  Mask,    // present where alpha >= alpha_cutoff, absent elsewhere (leaves, fences, grilles)
  Blend,   // a fraction alpha present: 1 - alpha of the light passes
};

struct Material {
  std::string name;
  Rgb base_color{1, 1, 1};  // linear, multiplies the sRGB-decoded base colour texture
  float base_alpha = 1;     // multiplies the base colour texture's alpha
  TextureRef base_color_texture;
  AlphaMode alpha_mode = AlphaMode::Opaque;
  float alpha_cutoff = 0.5f;
  // Glazing, read as a thin pane: KHR_materials_transmission's factor is the share of the light
  // that meets the pane and goes through it (specular, undeviated), KHR_materials_ior gives a clear
  // pane's losses, and extras.visible_transmittance (0..1) a real glazing's measured one.
  float transmission = 0;
  float ior = 1.5f;
  float visible_transmittance = -1;  // < 0: not given
  float metallic = 1;  // glTF default; diffuse reflectance is scaled by (1 - metallic)
  TextureRef metallic_roughness_texture;  // metallic in the blue channel
  Rgb emissive{0, 0, 0};  // linear emissiveFactor
  float emissive_strength = 1;  // KHR_materials_emissive_strength
  TextureRef emissive_texture;
  TextureRef normal_texture;  // tangent-space normals (glTF: +X along u, +Y against v, +Z out)
  float normal_scale = 1;     // normalTexture.scale: multiplies the map's X and Y
  bool double_sided = false;
  // Features of the source material that diffuse radiosity leaves out (transmission, specular,
  // volume...), named for the user by io/; the plan warns about them.
  std::vector<std::string> unsimulated;

  bool emits() const { return emissive_strength > 0 && max_component(emissive) > 0; }
};

// One glTF mesh primitive as placed by one node: a mesh used by three nodes gives three
// instances, because each instance is lit differently and gets its own lightmap.
struct MeshInstance {
  std::string name;
  int node = -1, mesh = -1, primitive = -1;  // where it came from, for the writer
  int material = -1;   // index into Scene::materials; -1 is the glTF default material
  bool mirrored = false;  // the node transform has a negative determinant: front faces are clockwise
  std::vector<Vec3> positions;  // world space, metres
  std::vector<Vec3> normals;    // world space, unit length; empty when the primitive has none
  std::vector<std::vector<Vec2>> texcoords;  // TEXCOORD_n at index n (empty sets for gaps)
  std::vector<Rgb> colors;       // COLOR_0 (multiplies the base colour); empty when absent
  // COLOR_0 in the file is the light of an earlier radbake bake, not colours: `colors` came from
  // its _SOURCE_COLOR_0 (or are none), and the writer replaces COLOR_0 instead of keeping it.
  bool color_0_was_light = false;
  // The lightmap page the file lays TEXCOORD_1 out on, when its material names one (MOZ_lightmap
  // reading TEXCOORD_1): an index into Scene::images, whose size is the page's. Instances naming
  // one page keep sharing it when their layouts allow (uv/atlas.h). -1: none.
  int lightmap_image = -1;
  std::vector<uint32_t> triangles;  // three vertex indices per triangle (strips, fans expanded)
  // A back-face twin (baker/surface/back_faces.h): the back of instance `back_of`'s double-sided triangles
  // front_triangle[t], as triangles of their own (same vertices, reversed winding, flipped normals)
  // with texels of their own. -1 for an instance read from the file.
  int back_of = -1;
  std::vector<uint32_t> front_triangle;

  size_t vertex_count() const { return positions.size(); }
  size_t triangle_count() const { return triangles.size() / 3; }
  const std::vector<Vec2>* lightmap_uvs() const {
    return texcoords.size() > 1 && !texcoords[1].empty() ? &texcoords[1] : nullptr;
  }
};

enum class LightType { Point, Spot, Directional };

// KHR_lights_punctual, in the extension's units.
struct Light {
  std::string name;
  LightType type = LightType::Point;
  Rgb color{1, 1, 1};
  float intensity = 1;  // candela for point and spot, lux for directional
  Vec3 position;        // world space (unused for directional)
  Vec3 direction{0, 0, -1};  // unit, the way the light travels (the node's -Z)
  float range = 0;      // metres; 0 means unlimited
  float inner_cone_angle = 0, outer_cone_angle = 0.7853982f;  // radians, spot only
  int source_index = -1;  // which of the file's lights this is, for the writer
};

struct SceneSummary {
  size_t nodes = 0, meshes = 0, primitives = 0, skipped_primitives = 0, triangles = 0;
  size_t materials = 0, textures = 0, lights = 0;
};

// A camera node of the file, in world space: where a viewer opening the file looks from.
struct SceneCamera {
  std::string name;
  int source = -1;     // index into the file's cameras
  int node = -1;       // the node that places it
  Vec3 eye;            // world space, metres
  Vec3 forward{0, 0, -1}, up{0, 1, 0};  // unit, orthogonal; zero when the node's transform leaves no direction
  bool orthographic = false;
  float yfov = 0.8f;   // radians, vertical (perspective)
  float aspect = 0;    // width / height; 0: the viewer's
  float xmag = 1, ymag = 1;  // half-extents, metres (orthographic)
  float znear = 0.01f, zfar = 0;  // metres; zfar 0: infinite
  bool usable() const { return length(forward) > 0.5f; }
};

struct Scene {
  std::vector<MeshInstance> instances;
  std::vector<Material> materials;
  std::vector<Image> images;
  std::vector<Light> lights;
  // The default scene's camera nodes in the order of a depth-first walk from its roots, children
  // in order: a viewer opens the file on the first.
  std::vector<SceneCamera> cameras;
  SceneSummary summary;
  std::vector<std::string> warnings;
};

// The material a primitive without one uses (glTF 2.0 section 3.9.6: all defaults).
inline const Material& material_of(const Scene& scene, int index) {
  static const Material default_material{};
  return index >= 0 ? scene.materials[size_t(index)] : default_material;
}

}  // namespace radbake
