// The two sample scenes: light is conserved in the Cornell box, its blocks show colour bleeding,
// and Ferren's white boards pick up the colours of the boards they face.
#include <gtest/gtest.h>

#include "io/gltf/gltf_loader.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

test::Baked bake_sample(const std::string& path, int page) {
  LoadedScene s = load_gltf(test::source_path(path));
  AtlasOptions atlas;
  atlas.max_page_size = page;
  return test::bake_scene(s.scene, atlas, {});
}

class CornellBox : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { baked = new test::Baked(bake_sample("samples/cornell_box/cornell_box.gltf", 256)); }
  static void TearDownTestSuite() { delete baked; }
  static test::Baked* baked;
};
test::Baked* CornellBox::baked = nullptr;

TEST_F(CornellBox, ConservesLight) {
  const EnergyBalance& b = baked->result.report.balance;
  RecordProperty("relative_error", std::to_string(b.relative_error));
  EXPECT_GT(b.emitted, 0);
  EXPECT_GT(b.escaped, 0.1 * b.emitted);  // the front of the box is open
  // Emitted = absorbed + escaped (+ lost to back faces) within 0.5%.
  EXPECT_LT(std::fabs(b.relative_error), 0.005);
  EXPECT_TRUE(baked->result.report.converged);
  EXPECT_LE(baked->result.report.unshot_relative, 1e-3);
}

// Chromaticity r / g of the irradiance on the short block's vertical faces that look toward +x
// (the red wall) or -x (the green wall).
double red_over_green(const BakeResult& r, float facing_x) {
  Rgb e = test::mean_irradiance(r, [&](Vec3 p, Vec3 n) {
    bool on_short_block = p.x > 0.075f && p.x < 0.295f && p.z > 0.06f && p.z < 0.28f && p.y > 0.01f && p.y < 0.16f;
    return on_short_block && n.x * facing_x > 0.5f && std::fabs(n.y) < 0.1f;
  });
  return e.x / e.y;
}

TEST_F(CornellBox, BlockFacesBleedTheWallsColours) {
  double toward_red = red_over_green(baked->result, +1), toward_green = red_over_green(baked->result, -1);
  RecordProperty("toward_red_r_over_g", std::to_string(toward_red));
  RecordProperty("toward_green_r_over_g", std::to_string(toward_green));
  // The light itself is warm (r/g 1/0.85); the wall colours must move both faces well away from
  // it and from each other. 20% apart is a clear, measured bleed, far above the gather's noise.
  EXPECT_GT(toward_red, 1.2 * toward_green);
}

TEST(Ferren, WhiteBoardsPickUpTheColoursTheyFace) {
  test::Baked b = bake_sample("samples/ferren/ferren.gltf", 512);
  // Board i's white front (normal (+x, -z)/sqrt 2) faces board i+1's coloured back:
  // 0 sees yellow, 1 sees green, 2 sees blue, 3 sees magenta.
  std::vector<Rgb> share;
  for (int i = 0; i < 4; ++i) {
    float cx = -0.6f + 0.3f * i;
    Rgb e = test::mean_irradiance(b.result, [&](Vec3 p, Vec3 n) {
      return n.x > 0.69f && n.z < -0.69f && std::fabs(p.x - cx) < 0.16f && p.y > 0.1f && p.y < 0.9f;
    });
    share.push_back(e / sum(e));
  }
  for (int i = 0; i < 4; ++i)
    RecordProperty("front_" + std::to_string(i), std::to_string(share[size_t(i)].x) + " " +
                                                     std::to_string(share[size_t(i)].y) + " " +
                                                     std::to_string(share[size_t(i)].z));
  // Facing blue: bluer than the faces facing yellow and green.
  EXPECT_GT(share[2].z, share[0].z * 1.1f);
  EXPECT_GT(share[2].z, share[1].z * 1.1f);
  // Facing green: greener than the faces facing blue and magenta.
  EXPECT_GT(share[1].y, share[2].y * 1.1f);
  EXPECT_GT(share[1].y, share[3].y * 1.1f);
  // Facing magenta: redder than the faces facing green and blue.
  EXPECT_GT(share[3].x, share[1].x * 1.1f);
  EXPECT_GT(share[3].x, share[2].x * 1.1f);
  // Facing yellow: less blue than the face facing blue.
  EXPECT_LT(share[0].z * 1.1f, share[2].z);
}

}  // namespace
}  // namespace radbake
