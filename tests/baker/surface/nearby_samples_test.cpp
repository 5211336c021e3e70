// A hit on a part whose own chart holds no sample for it (a sill's strip between a frame and the
// room, a frame's step) takes the light of the nearest sample of another part in sight
// of it, never of one it cannot see: the inside of a closed box stays its own.
#include <gtest/gtest.h>

#include "baker/surface/hit_element.h"
#include "baker/surface/nearby_samples.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

// A 2 m floor with a 10 cm block held 30 cm over its middle, at 8 texels a metre, with the
// block's own texels made buried, as a stepped frame's are where no sample of theirs sees the
// faces round it. `hollow`: the block is a closed box seen from inside (its faces turned inward).
std::unique_ptr<test::PlacedElements> block_on_a_floor(bool hollow) {
  Scene scene;
  const int grey = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  test::add_quad(scene, {0, 0, 0}, {0, 0, 2}, {2, 0, 0}, grey, "floor");
  test::add_box(scene, {0.95f, 0.3f, 0.95f}, {1.05f, 0.4f, 1.05f}, hollow, grey, "block");
  auto placed = test::placed_elements(scene, test::coarse_atlas());
  Elements& e = placed->elements;
  for (size_t i = 0; i < e.size(); ++i)
    if (placed->surface.instance[e.triangle[i]] >= 1) e.flags[i] |= kBuried;  // the block's six faces
  index_samples(e, placed->surface);
  return placed;
}

HitElement standing_for_hit(const test::PlacedElements& p, Vec3 origin, Vec3 direction, uint32_t* instance) {
  const Hit hit = p.tracer->intersect_light_path(origin, direction, 0.0f, INFINITY);
  EXPECT_FALSE(hit.missed());
  *instance = p.surface.instance[hit.triangle];
  return element_standing_for(p.elements, p.surface, *p.tracer, hit, kFromTheOpen);
}

TEST(NearbySamples, AHitWithNoSampleOfItsOwnTakesTheNearestOneInSight) {
  const auto placed = block_on_a_floor(false);
  uint32_t struck = 0;
  // Onto the block's face towards +x.
  const HitElement standing = standing_for_hit(*placed, {1.5f, 0.35f, 1.0f}, {-1, 0, 0}, &struck);
  EXPECT_GE(struck, 1u) << "the ray should strike the block";
  ASSERT_GE(standing.element, 0) << "fate " << int(standing.fate);
  const Elements& e = placed->elements;
  const size_t k = size_t(standing.element);
  EXPECT_TRUE(e.valid(k));
  EXPECT_EQ(placed->surface.instance[e.triangle[k]], 0u) << "a floor texel stands for it";
  // In front of the face (the floor behind the block cannot see it) and within 4 texels (50 cm).
  EXPECT_GT(e.position[k].x, 1.05f);
  EXPECT_LT(length(e.position[k] - Vec3{1.05f, 0.35f, 1.0f}), 0.5f);
}

TEST(NearbySamples, NoSampleOutsideAClosedBoxStandsForItsInside) {
  const auto placed = block_on_a_floor(true);
  uint32_t struck = 0;
  // From the box's centre onto its inner face towards +x: floor texels lie within 4 texels of the
  // hit, but the box's walls stand between.
  const HitElement standing = standing_for_hit(*placed, {1.0f, 0.35f, 1.0f}, {1, 0, 0}, &struck);
  EXPECT_GE(struck, 1u);
  EXPECT_LT(standing.element, 0);
  EXPECT_TRUE(standing.fate == RayFate::BuriedElement || standing.fate == RayFate::OtherSide) << int(standing.fate);
}

// A board inside a closed box (the FZK-Haus's bed is boards stacked so): a point on the board's
// top looks up at the box's lid from inside, a back face. A ray that strikes it there takes no light
// and counts as struck inside geometry, with the closed spaces, not with the front faces in the open
// that no element stood for.
TEST(NearbySamples, AFrontFaceInsideAClosedBoxCountsAsInsideGeometry) {
  Scene scene;
  const int grey = test::add_material(scene, {0.5f, 0.5f, 0.5f});
  test::add_quad(scene, {0, 0, 0}, {0, 0, 2}, {2, 0, 0}, grey, "floor");
  test::add_box(scene, {0.5f, 0.3f, 0.5f}, {1.5f, 0.5f, 1.5f}, false, grey, "case");
  test::add_box(scene, {0.6f, 0.35f, 0.6f}, {1.4f, 0.45f, 1.4f}, false, grey, "board");
  const auto placed = test::placed_elements(scene, test::coarse_atlas());
  uint32_t struck = 0;
  // From the gap between the board and the lid, down onto the board's top.
  const HitElement inside = standing_for_hit(*placed, {1.0f, 0.47f, 1.0f}, {0, -1, 0}, &struck);
  EXPECT_EQ(struck, 10u) << "the ray should strike the board's top (instances: floor, case's six faces, board's)";
  EXPECT_LT(inside.element, 0);
  EXPECT_EQ(inside.fate, RayFate::InsideGeometry) << int(inside.fate);
  // The floor beside the case, struck from the room, has its own element.
  const HitElement open = standing_for_hit(*placed, {1.8f, 1.0f, 1.0f}, {0, -1, 0}, &struck);
  EXPECT_EQ(struck, 0u);
  EXPECT_GE(open.element, 0) << int(open.fate);
}

TEST(NearbySamples, NearestFirstWithinTheRadius) {
  const auto placed = block_on_a_floor(false);
  const Elements& e = placed->elements;
  const Vec3 at{0.5f, 0, 0.5f};
  const std::vector<uint32_t> near = samples_near(e, at, 0.3f, 1000);
  ASSERT_FALSE(near.empty());
  size_t within = 0;
  for (size_t i = 0; i < e.size(); ++i) within += e.valid(i) && length(e.position[i] - at) <= 0.3f;
  EXPECT_EQ(near.size(), within) << "every valid sample within the radius, and no other";
  for (size_t a = 1; a < near.size(); ++a)
    EXPECT_LE(length(e.position[near[a - 1]] - at), length(e.position[near[a]] - at));
  EXPECT_EQ(samples_near(e, at, 0.3f, 3).size(), 3u);
}

}  // namespace
}  // namespace radbake
