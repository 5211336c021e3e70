// The CAD model that baked to NaN: Khronos' 2CylinderEngine (Debian's assimp-testmodels) under one
// point light. Ray-cast form factors of a small patch in a crevice, every ray of which landed on
// a large neighbour that sent almost none back, asked the reciprocity balance for more exchange
// than the neighbour's row could hold; its scale factors ran off to 0 and infinity and overflowed.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "baker/pipeline/bake.h"
#include "baker/transport/patch_transport.h"
#include "base/errors.h"
#include "hard_case_checks.h"
#include "io/gltf/gltf_loader.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

const char* kEngine = "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";

// The shape of the rows the engine produced, on two patches: patch 0 (5.35 m2) sends all of its
// light onto patch 1, and patch 1 (100 m2) sent only 0.039 m2-worth back (the rest escaped).
TEST(CadEngine, ReciprocityBalanceOfRowsThatAdmitNoScalingStaysFiniteAndCreatesNoLight) {
  Patches patches;
  patches.area = {5.35f, 100.0f};
  MeasuredRows rows;
  rows.resize(2);
  rows.rows[0] = {{1, 1.0f}};
  rows.rows[1] = {{0, 0.039f / 100.0f}};
  const PatchTransport t = balanced_transport(patches, rows);
  for (size_t p = 0; p < 2; ++p) {
    double sum = 0;
    for (uint64_t k = t.row_start[p]; k < t.row_start[p + 1]; ++k) {
      ASSERT_TRUE(std::isfinite(t.form_factor[k])) << "patch " << p;
      sum += t.form_factor[k];
    }
    // What a row hands on is at most what its rays measured landing (1 and 0.00039): bounds the
    // light the balance may create, relative, in float.
    const double measured = p == 0 ? 1.0 : 0.039 / 100.0;
    EXPECT_LE(sum, measured * (1 + 1e-6)) << "patch " << p;
  }
}

TEST(CadEngine, TheTwoCylinderEngineUnderOnePointLightBakesFinite) {
  if (!std::filesystem::exists(kEngine)) GTEST_FAIL() << kEngine << " is missing: apt-get install assimp-testmodels";
  LoadedScene loaded = load_gltf(kEngine);
  Scene& scene = loaded.scene;
  // The light of the report: above the middle of the model (millimetres read as metres), 0.6 of
  // its height over its top.
  Light bulb;
  bulb.type = LightType::Point;
  bulb.intensity = 1e8f;
  bulb.position = {-0.80f, 297.38f, -2.37f};
  scene.lights.push_back(bulb);
  BakeOptions options;
  options.gather.rays = 4;  // the NaN came from the form factors; the gather only costs time here
  const Atlas atlas = test::unwrap(scene, AtlasOptions{});
  BakeResult result;
  ASSERT_NO_THROW(result = bake(scene, atlas, options));
  test::expect_finite_and_non_negative(result);
  // The balance the report printed as -nan%: light conserved to a fraction of a percent.
  ASSERT_TRUE(result.report.balance.measured);
  EXPECT_LT(std::fabs(result.report.balance.relative_error), 0.01);
}

}  // namespace
}  // namespace radbake
