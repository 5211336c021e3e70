// The glTF metallic-roughness material reduced to what diffuse radiosity needs: diffuse
// reflectance and emitted exitance at a point of the surface, with textures box-filtered over the
// area a sample stands for.
#pragma once

#include <map>
#include <utility>
#include <vector>

#include "baker/surface/glazing.h"
#include "baker/surface/surface.h"
#include "base/math.h"
#include "base/scene.h"

namespace radbake {

// radbake reads glTF emission (emissiveFactor x emissiveTexture x emissive_strength) as luminance
// in cd/m2, as three.js and Filament do when lights are in candela and lux. A Lambertian emitter
// of luminance L has exitance pi * L lm/m2.
constexpr float kExitancePerEmissiveUnit = 3.14159265358979323846f;

// Reflectance above this is clamped: a closed room of reflectance 1 has no steady state.
constexpr float kMaxReflectance = 0.999f;

class MaterialSampler {
 public:
  // `emission_scale` multiplies every material's emission (a unit conversion for the source).
  // `glazing` says what panes pass along their normal where a material has no
  // extras.visible_transmittance of its own, and how they pass less obliquely.
  MaterialSampler(const Scene& scene, const Surface& surface, float emission_scale = 1, const Glazing& glazing = {});

  // `spacing` is the distance, in lightmap texels, between neighbouring samples of the caller; it
  // chooses the texture mip level so that each sample averages its share of the footprint.
  Rgb reflectance(uint32_t triangle, Vec2 bary, float spacing) const;
  Rgb emission(uint32_t triangle, Vec2 bary, float spacing) const;  // exitance, lm/m2
  // The most any point of the triangle emits, lm/m2: its emission with the texture at full.
  Rgb emission_bound(uint32_t triangle) const;

  // How much of the surface is there, 0..1: alpha under BLEND, 0 or 1 under MASK, else 1.
  float coverage(uint32_t triangle, Vec2 bary, float spacing) const;
  // The share of light travelling along `direction` that goes straight through the surface at a
  // point, 0..1: where it is absent, and through its glazing where it is there (the visible
  // transmittance along the normal, less at oblique incidence as for a clear pane of the
  // material's KHR_materials_ior). At full texture resolution: cut-outs are as sharp as their
  // texture.
  float transmittance(uint32_t triangle, Vec2 bary, Vec3 direction) const;
  // The same for light arriving from the whole hemisphere alike (cosine-weighted).
  float diffuse_transmittance(uint32_t triangle, Vec2 bary) const;
  // False for the triangles every ray stops at (opaque and no glazing): most of them.
  bool see_through(uint32_t triangle) const;
  // True for glazing: a material whose KHR_materials_transmission passes some light.
  bool glazing(uint32_t triangle) const;

  // The shading normal at a point, the material's normal map applied (tangents from the map's
  // texture coordinates, as viewers derive them for a mesh without TANGENT); the interpolated
  // normal where there is none. For showing baked directional light on the bumps (prelit_pages).
  Vec3 mapped_normal(uint32_t triangle, Vec2 bary, float spacing) const;

  // True when neither reflectance nor emission varies over the triangle (no textures, no COLOR_0).
  bool is_uniform(uint32_t triangle) const;
  bool emits(uint32_t triangle) const;

 private:
  struct Level {
    int width, height;
    std::vector<Vec3> texels;
  };
  struct Texture {
    std::vector<Level> levels;  // finest first, at most kMaxSampledSize per side
  };
  enum class Decode { Srgb, Linear, Alpha };  // Alpha: the fourth channel, in all three

  int texture_for(int image, Decode decode);
  Vec3 sample(const TextureRef& ref, int texture, uint32_t triangle, Vec2 bary, float spacing) const;

  const Scene& scene_;
  const Surface& surface_;
  float emission_scale_;
  std::vector<Texture> textures_;
  std::map<std::pair<int, Decode>, int> texture_of_image_;  // (image, decoding) -> textures_
  // Per material: index into textures_ for base colour, metallic, emission (-1 when absent).
  std::vector<int> base_texture_, metallic_texture_, emissive_texture_, alpha_texture_, normal_texture_;
  std::vector<float> pane_transmittance_;  // per material: what its glazing lets through along its normal
  std::vector<PaneCurve> pane_curve_;      // per material: its glazing at other angles
};

}  // namespace radbake
