// Diffuse reflectance and emission from the glTF material model: factors, sRGB-decoded textures
// through KHR_texture_transform, vertex colours, (1 - metallic), emissive strength in cd/m2.
#include <gtest/gtest.h>

#include "baker/surface/material_sampler.h"
#include "baker/surface/surface.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

// A 2 x 1 texture: left texel red (255, 0, 0), right texel mid-grey (128, 128, 128).
Image two_texel_image() {
  Image img;
  img.width = 2;
  img.height = 1;
  img.pixels = {255, 0, 0, 255, 128, 128, 128, 255};
  return img;
}

struct Sampled {
  Scene scene;
  Atlas atlas;
  Surface surface;
};

Sampled textured_quad(const TextureRef& ref, Rgb base, float metallic) {
  Sampled s;
  s.scene.images.push_back(two_texel_image());
  int m = test::add_material(s.scene, base);
  s.scene.materials[size_t(m)].base_color_texture = ref;
  s.scene.materials[size_t(m)].metallic = metallic;
  test::add_quad(s.scene, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, m);
  // UVs across the quad: u from 0 to 1 along x.
  s.scene.instances[0].texcoords = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  s.atlas = test::unwrap(s.scene, {16.0f, 64, 2});
  s.surface = build_surface(s.scene, s.atlas);
  return s;
}

float srgb(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

TEST(MaterialSampler, TextureIsSrgbDecodedAndScaledByFactorAndOneMinusMetallic) {
  TextureRef ref;
  ref.image = 0;
  ref.wrap_s = ref.wrap_t = Wrap::ClampToEdge;
  Sampled s = textured_quad(ref, {1, 0.5f, 1}, 0.25f);
  MaterialSampler sampler(s.scene, s.surface);
  // Triangle 0 spans corners 0,1,2: barycentrics (b1, b2) = (0.75, 0) is u = 0.75, the grey texel.
  Rgb right = sampler.reflectance(0, {0.9f, 0.05f}, 0.01f);
  const float grey = srgb(128 / 255.0f);
  EXPECT_NEAR(right.x, grey * 1.0f * 0.75f, 1e-4f);
  EXPECT_NEAR(right.y, grey * 0.5f * 0.75f, 1e-4f);
  Rgb left = sampler.reflectance(0, {0.05f, 0.0f}, 0.01f);  // u = 0.05: the red texel
  EXPECT_NEAR(left.x, 1.0f * 0.75f, 1e-4f);
  EXPECT_NEAR(left.y, 0.0f, 1e-4f);
}

TEST(MaterialSampler, TextureTransformMovesTheLookup) {
  TextureRef ref;
  ref.image = 0;
  ref.wrap_s = ref.wrap_t = Wrap::Repeat;
  ref.transform.offset = {0.5f, 0};  // shifts u by half the texture: red and grey swap
  Sampled s = textured_quad(ref, {1, 1, 1}, 0);
  MaterialSampler sampler(s.scene, s.surface);
  // u = 0.25 now reads the grey texel's centre (0.75), u = 0.75 wraps round to the red one's.
  EXPECT_NEAR(sampler.reflectance(0, {0.25f, 0.0f}, 0.01f).y, srgb(128 / 255.0f), 1e-4f);
  EXPECT_NEAR(sampler.reflectance(0, {0.75f, 0.0f}, 0.01f).y, 0.0f, 1e-4f);
}

TEST(MaterialSampler, EmissionIsPiTimesFactorTimesStrength) {
  Scene scene;
  int m = test::add_material(scene, {0, 0, 0}, {1, 0.5f, 0.25f}, 40);
  test::add_quad(scene, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, m);
  Atlas atlas = test::unwrap(scene, {16.0f, 64, 2});
  Surface surface = build_surface(scene, atlas);
  MaterialSampler sampler(scene, surface);
  Rgb e = sampler.emission(0, {0.3f, 0.3f}, 1);
  EXPECT_FLOAT_EQ(e.x, float(M_PI) * 40);  // lm/m2 from 40 cd/m2
  EXPECT_FLOAT_EQ(e.z, float(M_PI) * 10);
}

TEST(MaterialSampler, EmissiveTextureScalesTheEmission) {
  Scene scene;
  scene.images.push_back(two_texel_image());
  int m = test::add_material(scene, {0, 0, 0}, {1, 1, 1}, 10);
  scene.materials[size_t(m)].emissive_texture.image = 0;
  scene.materials[size_t(m)].emissive_texture.wrap_s = Wrap::ClampToEdge;
  test::add_quad(scene, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, m);
  scene.instances[0].texcoords = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  Atlas atlas = test::unwrap(scene, {16.0f, 64, 2});
  Surface surface = build_surface(scene, atlas);
  MaterialSampler sampler(scene, surface);
  EXPECT_FALSE(sampler.is_uniform(0));
  Rgb red = sampler.emission(0, {0.05f, 0.0f}, 0.01f), grey = sampler.emission(0, {0.9f, 0.05f}, 0.01f);
  EXPECT_NEAR(red.x, float(M_PI) * 10, 1e-3f);
  EXPECT_NEAR(red.y, 0.0f, 1e-4f);
  EXPECT_NEAR(grey.y, float(M_PI) * 10 * srgb(128 / 255.0f), 1e-3f);
}

}  // namespace
}  // namespace radbake
