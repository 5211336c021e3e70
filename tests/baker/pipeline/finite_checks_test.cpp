// The stage checks: a NaN or infinity is stopped where it appears, with where it sits.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "baker/pipeline/bake.h"
#include "baker/pipeline/finite_checks.h"
#include "baker/surface/elements.h"
#include "baker/surface/material_sampler.h"
#include "baker/surface/surface.h"
#include "base/errors.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

struct Quad {
  Scene scene;
  Atlas atlas;
  Surface surface;
  Elements elements;
  Quad() {
    int m = test::add_material(scene, {0.5f, 0.5f, 0.5f});
    test::add_quad(scene, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, m, "the floor");
    atlas = test::unwrap(scene, {8.0f, 64, 2});
    surface = build_surface(scene, atlas);
    MaterialSampler materials(scene, surface);
    Progress progress;
    elements = build_elements(surface, materials, {}, progress);
  }
};

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const NonFiniteValue& e) {
    return e.what();
  }
  return "";
}

TEST(FiniteChecks, ANanInOneElementNamesTheStageTheElementItsTexelTriangleAndMesh) {
  Quad q;
  std::vector<Rgb> values(q.elements.size(), Rgb{1, 1, 1});
  const size_t bad = values.size() / 2;
  values[bad].y = std::nanf("");
  const std::string text = message_of([&] { check_element_values("direct light", values, {q.scene, q.surface, q.elements}); });
  const uint32_t width = uint32_t(q.surface.pages[0].width);
  EXPECT_NE(text.find("after direct light"), std::string::npos) << text;
  EXPECT_NE(text.find("element " + std::to_string(bad)), std::string::npos) << text;
  EXPECT_NE(text.find("texel " + std::to_string(q.elements.texel[bad] % width) + ", " +
                      std::to_string(q.elements.texel[bad] / width)),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("triangle " + std::to_string(q.elements.triangle[bad])), std::string::npos) << text;
  EXPECT_NE(text.find("the floor"), std::string::npos) << text;
}

TEST(FiniteChecks, AnInfiniteVertexValueIsStoppedAndFiniteValuesPass) {
  Quad q;
  std::vector<Rgb> values(q.elements.size(), Rgb{1, 1, 1});
  EXPECT_NO_THROW(check_element_values("the final gather", values, {q.scene, q.surface, q.elements}));
  std::vector<std::vector<Rgb>> vertices{{Rgb{1, 1, 1}, Rgb{INFINITY, 0, 0}}};
  EXPECT_NE(message_of([&] { check_vertex_values(vertices, q.scene); }).find("vertex 1 of"), std::string::npos);
}

TEST(FiniteChecks, AnInfiniteEmissionIsStoppedWhereTheElementsAreMade) {
  Quad q;
  EXPECT_NO_THROW(check_elements({q.scene, q.surface, q.elements}));
  q.elements.emission[0].x = INFINITY;
  const std::string text = message_of([&] { check_elements({q.scene, q.surface, q.elements}); });
  EXPECT_NE(text.find("after elements: the position, area or material of element 0"), std::string::npos) << text;
}

TEST(FiniteChecks, AnEmissionScaleThatMultipliesALuminancePastTheBoundIsRefusedBeforeBaking) {
  // 1e15 cd/m2 passes the loader's bound of 1e20; times an emission scale of 1e9 it would not,
  // and exitance times a large area would overflow float.
  Scene scene;
  int lamp = test::add_material(scene, {0.5f, 0.5f, 0.5f}, {1, 1, 1}, 1e15f);
  test::add_quad(scene, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, lamp, "lamp");
  const Atlas atlas = test::unwrap(scene, {8.0f, 64, 2});
  BakeOptions options;
  options.emission_scale = 1e9f;
  try {
    bake(scene, atlas, options);
    FAIL() << "baked";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cd/m2 under the emission scale 1e+09, above the 1e+20"), std::string::npos)
        << e.what();
  }
  options.emission_scale = 1e4f;  // 1e19 cd/m2: within the bound, and finite
  EXPECT_NO_THROW(bake(scene, atlas, options));
}

}  // namespace
}  // namespace radbake
