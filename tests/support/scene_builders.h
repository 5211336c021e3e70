// Scenes built in code for the tests: plain Scene data, as io/ would produce it from glTF.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "baker/pipeline/bake_options.h"
#include "baker/pipeline/bake_result.h"
#include "baker/surface/ray_tracer.h"
#include "baker/surface/surface.h"
#include "base/scene.h"
#include "uv/atlas.h"

namespace radbake::test {

std::string source_path(const std::string& relative);  // inside the repository

// A dielectric (metallic 0) material; `double_sided` as glTF's doubleSided.
int add_material(Scene& scene, Rgb base_color, Rgb emissive = {0, 0, 0}, float emissive_strength = 1.0f,
                 bool double_sided = false);

// A mesh instance from world-space positions and three indices per triangle, without normals (the
// baker then uses face normals); fronts wind counter-clockwise.
void add_mesh(Scene& scene, std::vector<Vec3> positions, std::vector<uint32_t> triangles, int material,
              const std::string& name = "mesh");

// A quad corner, corner + u, corner + u + v, corner + v (two triangles); its front faces u x v.
void add_quad(Scene& scene, Vec3 corner, Vec3 u, Vec3 v, int material, const std::string& name = "quad");

// Six quads of an axis-aligned box facing inward (a room) or outward (a block); material per face
// in the order -x, +x, -y, +y, -z, +z.
void add_box(Scene& scene, Vec3 lo, Vec3 hi, bool inward, const int (&materials)[6], const std::string& name = "box");
void add_box(Scene& scene, Vec3 lo, Vec3 hi, bool inward, int material, const std::string& name = "box");

// A closed 2 m room of grey walls with a point light of 50 cd in it, a convex enclosure; with a
// block (0.5 x 0.6 x 0.5 m) standing in it, surfaces hide each other.
Scene lit_room(float reflectance, Rgb light_colour, bool with_block);

// The closed room whose ceiling glows (300 cd/m2), with the point light too: still convex.
Scene glowing_ceiling_room();

// A 3 m floor with a block on it, one point light that lights them, one 3 m above with a 1 m
// range, and a spot aimed at the sky: the last two reach no surface.
Scene floor_with_lights_out_of_reach();

Atlas unwrap(const Scene& scene, const AtlasOptions& options);

// The stages a bake runs before any light: the surface of `scene` unwrapped with `options`, its
// ray tracer, and its elements with their samples placed (seed 1).
struct PlacedElements {
  Surface surface;
  std::unique_ptr<RayTracer> tracer;
  Elements elements;
};
std::unique_ptr<PlacedElements> placed_elements(const Scene& scene, const AtlasOptions& options);

// 8 texels a metre: rooms of a few metres bake in a blink, fine enough for readings in the air.
AtlasOptions coarse_atlas();

// A sky of the same luminance (cd/m2) everywhere above the horizon, alone.
BakeOptions under_a_uniform_sky(float luminance);

// A dense curved surface: a torus (major radius 1 m) with bumps, `rings` x `segments` quads
// split into triangles. 250 x 200 gives 100,000 triangles.
MeshInstance bumpy_torus(int rings, int segments);

struct Baked {
  Atlas atlas;
  BakeResult result;
};
// Gives double-sided backs their twins (add_back_faces), unwraps and bakes, as the command does.
Baked bake_scene(Scene scene, const AtlasOptions& atlas_options, const BakeOptions& options);

// True when both bakes' lightmap pages are bit for bit the same.
bool same_pages(const std::vector<LightmapPage>& a, const std::vector<LightmapPage>& b);

// Area-weighted mean irradiance (lux) over valid elements whose sample point and normal pass `where`.
Rgb mean_irradiance(const BakeResult& r, const std::function<bool(Vec3 position, Vec3 normal)>& where,
                    size_t* count = nullptr);

// The whole command in-process: load, unwrap, bake, write lightmaps and glTF into `folder`
// (created). Returns the output glTF's path.
std::string bake_file_to_folder(const std::string& input, const std::string& folder, const AtlasOptions& atlas_options,
                                const BakeOptions& options = {});

// A fresh empty folder in the running test's own folder under the temp directory.
std::string fresh_folder(const std::string& name);

// Writes `text` to a file in the running test's own folder and returns its path.
std::string write_text_file(const std::string& name, const std::string& text);

}  // namespace radbake::test
