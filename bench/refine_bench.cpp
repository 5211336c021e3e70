// How well vertex light follows the lightmap as the mesh is refined (baker/finish/vertex_refinement.h):
// a scene is baked once, then refined at a range of triangle budgets; the table shows the
// triangles made, the relative RMS difference between vertex-interpolated light and the
// lightmap, and the time refinement took (best of three).
//
//   refine_bench [SCENE.gltf] [--page N] [--tolerance T] [--budget N (only this one)]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "baker/finish/vertex_refinement.h"
#include "baker/surface/back_faces.h"
#include "io/gltf/gltf_loader.h"
#include "support/scene_builders.h"

int main(int argc, char** argv) {
  using namespace radbake;
  std::string path = test::source_path("samples/cornell_box/cornell_box.gltf");
  int page = 256;
  float tolerance = RefinementOptions{}.tolerance;
  std::vector<size_t> budgets = {0, 500, 1000, 2000, 5000, 10000, 20000, 50000, 100000};
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--page") && i + 1 < argc) page = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--tolerance") && i + 1 < argc) tolerance = float(std::atof(argv[++i]));
    else if (!std::strcmp(argv[i], "--budget") && i + 1 < argc) budgets = {size_t(std::atoll(argv[++i]))};
    else path = argv[i];
  }
  LoadedScene loaded = load_gltf(path);
  AtlasOptions atlas_options;
  atlas_options.max_page_size = page;
  test::Baked baked = test::bake_scene(loaded.scene, atlas_options, {});
  // bake_scene added the back-face twins to its own copy: refine the scene the atlas was made for.
  Scene scene = loaded.scene;
  add_back_faces(scene);
  size_t texels = 0;
  for (const LightmapPage& p : baked.result.pages)
    for (uint8_t v : p.valid) texels += v;
  std::printf("%s: page %d, %zu covered texels, tolerance %g\n\n", path.c_str(), page, texels, double(tolerance));
  std::printf("| budget | triangles | relative RMS | refinement ms |\n|---:|---:|---:|---:|\n");
  for (size_t budget : budgets) {
    RefinementOptions options;
    options.max_triangles = budget;
    options.tolerance = tolerance;
    double best = 1e30;
    VertexRefinement r;
    for (int k = 0; k < 3; ++k) {
      auto start = std::chrono::steady_clock::now();
      r = refine_vertex_light(scene, baked.atlas, baked.result.pages, baked.result.vertex_values, options);
      best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    std::printf("| %zu | %zu | %.4f | %.1f |\n", budget, r.curve.triangles.back(), r.curve.rms_relative.back(),
                1e3 * best);
    if (budget == budgets.back()) {
      std::printf("\ncurve at budget %zu:\n", budget);
      for (size_t i = 0; i < r.curve.triangles.size(); ++i)
        std::printf("  %zu triangles: %.4f\n", r.curve.triangles[i], r.curve.rms_relative[i]);
    }
  }
  return 0;
}
