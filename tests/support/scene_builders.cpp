#include "support/scene_builders.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "baker/pipeline/bake.h"
#include "baker/surface/back_faces.h"
#include "baker/surface/elements.h"
#include "baker/surface/material_sampler.h"
#include "baker/surface/surface.h"
#include "io/gltf/gltf_loader.h"
#include "io/gltf/gltf_writer.h"
#include "io/lightmaps/page_encodings.h"

namespace radbake::test {

std::string source_path(const std::string& relative) { return std::string(RADBAKE_SOURCE_DIR) + "/" + relative; }

int add_material(Scene& scene, Rgb base_color, Rgb emissive, float emissive_strength, bool double_sided) {
  Material m;
  m.name = "material " + std::to_string(scene.materials.size());
  m.base_color = base_color;
  m.metallic = 0;
  m.emissive = emissive;
  m.emissive_strength = emissive_strength;
  m.double_sided = double_sided;
  scene.materials.push_back(m);
  return int(scene.materials.size() - 1);
}

void add_mesh(Scene& scene, std::vector<Vec3> positions, std::vector<uint32_t> triangles, int material,
              const std::string& name) {
  MeshInstance inst;
  inst.name = name;
  inst.node = int(scene.instances.size());
  inst.mesh = inst.node;
  inst.primitive = 0;
  inst.material = material;
  inst.positions = std::move(positions);
  inst.triangles = std::move(triangles);
  scene.summary.triangles += inst.triangle_count();
  scene.instances.push_back(std::move(inst));
}

void add_quad(Scene& scene, Vec3 corner, Vec3 u, Vec3 v, int material, const std::string& name) {
  add_mesh(scene, {corner, corner + u, corner + u + v, corner + v}, {0, 1, 2, 0, 2, 3}, material, name);
  Vec3 n = normalize(cross(u, v));
  scene.instances.back().normals = {n, n, n, n};
}

void add_box(Scene& scene, Vec3 lo, Vec3 hi, bool inward, const int (&m)[6], const std::string& name) {
  Vec3 d = hi - lo;
  Vec3 ex{d.x, 0, 0}, ey{0, d.y, 0}, ez{0, 0, d.z};
  // Each face listed with edges whose cross product points outward; inward flips the order.
  struct Face { Vec3 corner, u, v; };
  Face faces[6] = {{lo, ez, ey}, {lo + ex, ey, ez}, {lo, ex, ez}, {lo + ey, ez, ex}, {lo, ey, ex}, {lo + ez, ex, ey}};
  const char* names[6] = {"-x", "+x", "-y", "+y", "-z", "+z"};
  for (int f = 0; f < 6; ++f) {
    Face fc = faces[f];
    if (inward) std::swap(fc.u, fc.v);
    add_quad(scene, fc.corner, fc.u, fc.v, m[f], name + names[f]);
  }
}

void add_box(Scene& scene, Vec3 lo, Vec3 hi, bool inward, int material, const std::string& name) {
  const int m[6] = {material, material, material, material, material, material};
  add_box(scene, lo, hi, inward, m, name);
}

Scene lit_room(float reflectance, Rgb light_colour, bool with_block) {
  Scene scene;
  int grey = add_material(scene, {reflectance, reflectance, reflectance});
  add_box(scene, {0, 0, 0}, {2, 2, 2}, true, grey, "room");
  if (with_block) add_box(scene, {0.3f, 0, 0.3f}, {0.8f, 0.6f, 0.8f}, false, grey, "block");
  Light bulb;
  bulb.intensity = 50;
  bulb.color = light_colour;
  bulb.position = {1.1f, 1.3f, 0.9f};
  scene.lights.push_back(bulb);
  return scene;
}

Scene glowing_ceiling_room() {
  Scene scene = lit_room(0.6f, {1, 1, 1}, false);
  const int grey = scene.instances[0].material, lamp = add_material(scene, {0, 0, 0}, {1, 1, 1}, 300);
  scene.instances.clear();
  const int faces[6] = {grey, grey, grey, lamp, grey, grey};
  add_box(scene, {0, 0, 0}, {2, 2, 2}, true, faces, "room");
  return scene;
}

Scene floor_with_lights_out_of_reach() {
  Scene scene;
  int grey = add_material(scene, {0.5f, 0.5f, 0.5f});
  add_quad(scene, {0, 0, 3}, {3, 0, 0}, {0, 0, -3}, grey, "floor");
  add_box(scene, {1, 0, 1}, {1.6f, 0.8f, 1.6f}, false, grey, "block");
  Light lamp;
  lamp.intensity = 40;
  lamp.position = {2.2f, 1.5f, 2.2f};
  Light short_range = lamp;
  short_range.position = {1.5f, 3, 1.5f};
  short_range.range = 1;
  Light upward = lamp;
  upward.type = LightType::Spot;
  upward.direction = {0, 1, 0};
  scene.lights = {lamp, short_range, upward};
  return scene;
}

Atlas unwrap(const Scene& scene, const AtlasOptions& options) { return ensure_lightmap_uvs(mesh_views(scene), options); }

MeshInstance bumpy_torus(int rings, int segments) {
  MeshInstance inst;
  inst.name = "bumpy torus";
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      float u = 2 * float(M_PI) * i / rings, v = 2 * float(M_PI) * j / segments;
      float r = 0.35f + 0.03f * std::sin(7 * u) * std::sin(5 * v);
      inst.positions.push_back({(1 + r * std::cos(v)) * std::cos(u), r * std::sin(v), (1 + r * std::cos(v)) * std::sin(u)});
    }
  auto at = [&](int i, int j) { return uint32_t((i % rings) * segments + (j % segments)); };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j)
      inst.triangles.insert(inst.triangles.end(),
                            {at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i + 1, j)});
  return inst;
}

std::unique_ptr<PlacedElements> placed_elements(const Scene& scene, const AtlasOptions& options) {
  auto placed = std::make_unique<PlacedElements>();
  placed->surface = build_surface(scene, unwrap(scene, options));
  placed->tracer = std::make_unique<RayTracer>(placed->surface);
  MaterialSampler materials(scene, placed->surface);
  Progress progress;
  placed->elements = build_elements(placed->surface, materials, {}, progress);
  place_samples(placed->elements, placed->surface, *placed->tracer, 1, progress);
  return placed;
}

Baked bake_scene(Scene scene, const AtlasOptions& atlas_options, const BakeOptions& options) {
  add_back_faces(scene);
  Baked b;
  b.atlas = unwrap(scene, atlas_options);
  b.result = bake(scene, b.atlas, options);
  return b;
}

bool same_pages(const std::vector<LightmapPage>& a, const std::vector<LightmapPage>& b) {
  if (a.size() != b.size()) return false;
  for (size_t p = 0; p < a.size(); ++p)
    if (a[p].texels.size() != b[p].texels.size() ||
        std::memcmp(a[p].texels.data(), b[p].texels.data(), a[p].texels.size() * sizeof(Rgb)) != 0)
      return false;
  return true;
}

Rgb mean_irradiance(const BakeResult& r, const std::function<bool(Vec3, Vec3)>& where, size_t* count) {
  const Elements& e = r.elements;
  double sum[3] = {0, 0, 0}, area = 0;
  size_t n = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i) || !where(e.position[i], e.normal[i])) continue;
    for (int c = 0; c < 3; ++c) sum[c] += double(r.irradiance[i][c]) * e.area[i];
    area += e.area[i];
    ++n;
  }
  if (count) *count = n;
  if (area <= 0) return {0, 0, 0};
  return {float(sum[0] / area), float(sum[1] / area), float(sum[2] / area)};
}

std::string bake_file_to_folder(const std::string& input, const std::string& folder, const AtlasOptions& atlas_options,
                                const BakeOptions& options) {
  LoadedScene loaded = load_gltf(input);
  add_back_faces(loaded.scene);
  Baked b;
  b.atlas = unwrap(loaded.scene, atlas_options);
  b.result = bake(loaded.scene, b.atlas, options);
  std::filesystem::create_directories(folder);
  std::string name = std::filesystem::path(input).stem().string();
  LightmapFiles files = write_lightmaps(b.result.pages, folder, name, "irradiance", "lx", automatic_png_scale(b.result.pages));
  GltfOutput out = write_gltf(*loaded.source, loaded.scene, b.atlas, b.result.vertex_values, files, folder, name);
  return folder + "/" + out.gltf_file;
}

namespace {

// The running test's own folder under the temp directory: ctest runs cases side by side
// (./dev test), and two cases asking for the same name must not share the files. Named by a hash
// of the test's name, short: tests read error lines, which clip a path past 100 characters.
std::filesystem::path scratch_root() {
  const ::testing::TestInfo* running = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string test = running ? std::string(running->test_suite_name()) + "." + running->name()
                                   : "process " + std::to_string(getpid());
  uint32_t hash = 2166136261u;  // FNV-1a
  for (unsigned char c : test) hash = (hash ^ c) * 16777619u;
  char folder[32];
  std::snprintf(folder, sizeof folder, "rb_%08x", hash);
  const std::filesystem::path root = std::filesystem::path(::testing::TempDir()) / folder;
  std::filesystem::create_directories(root);
  return root;
}

}  // namespace

std::string fresh_folder(const std::string& name) {
  const std::filesystem::path p = scratch_root() / name;
  std::filesystem::remove_all(p);
  std::filesystem::create_directories(p);
  return p.string();
}

std::string write_text_file(const std::string& name, const std::string& text) {
  const std::filesystem::path p = scratch_root() / name;
  std::ofstream(p) << text;
  return p.string();
}

AtlasOptions coarse_atlas() {
  AtlasOptions atlas;
  atlas.texel_density = 8;
  return atlas;
}

BakeOptions under_a_uniform_sky(float luminance) {
  BakeOptions options;
  options.sky.enabled = true;
  options.sky.distribution.model = SkyModel::Uniform;
  options.sky.zenith_luminance = luminance;
  return options;
}

}  // namespace radbake::test
