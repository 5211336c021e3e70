#include <gtest/gtest.h>

#include "baker/final_gather.h"
#include "baker/material_sampler.h"
#include "baker/patch_transport.h"
#include "baker/ray_tracer.h"
#include "io/gltf.h"
#include "support/scene_builders.h"

namespace radbake {
TEST(Diagnostics, CornellReciprocity) {
  LoadedScene s = load_gltf(test::source_path("samples/cornell_box/cornell_box.gltf"));
  AtlasOptions ao;
  ao.max_page_size = 256;
  Atlas atlas = test::unwrap(s.scene, ao);
  Surface surface = build_surface(s.scene, atlas);
  RayTracer tracer(surface);
  MaterialSampler materials(s.scene, surface);
  Progress progress;
  Elements e = build_elements(surface, materials, {}, progress);
  place_samples(e, surface, tracer, 1, progress);
  for (int block : {1, 4, 16}) {
    PatchOptions po; po.block_size = block;
    Patches patches = build_patches(e, surface, po);
    PatchTransport t = trace_patch_transport(e, patches, surface, tracer, block == 1 ? 256 : 4096, std::vector<double>(patches.size(), 1.0), 1, progress);
    for (int pattern = 0; pattern < 2; ++pattern) {
      std::vector<Rgb> b(patches.size());
      for (size_t q = 0; q < patches.size(); ++q) {
        Vec3 c = e.position[patches.members[patches.first_member[q]]];
        float v = pattern == 0 ? 1.0f : c.y * 4 + c.x;
        b[q] = {v, v, v};
      }
      std::vector<Rgb> h = gather_indirect(e, patches, surface, tracer, b, 256, 1, progress);
      double gathered = 0, shot = 0;
      for (size_t i = 0; i < e.size(); ++i) if (e.valid(i)) gathered += h[i].x * e.area[i];
      for (size_t q = 0; q < patches.size(); ++q) shot += b[q].x * patches.area[q] * (1 - t.escaped[q] - t.lost[q]);
      printf("block %d pattern %d: gathered %f shot %f ratio %f\n", block, pattern, gathered, shot, gathered / shot);
    }
  }
}
}  // namespace radbake
