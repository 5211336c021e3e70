#include "baker/pipeline/finite_checks.h"

#include <cmath>
#include <string>

#include "base/errors.h"

namespace radbake {
namespace {

bool finite(const Rgb& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string triangle_text(const FiniteCheckContext& where, uint32_t t) {
  return "triangle " + std::to_string(t) + " of '" + where.scene.instances[where.surface.instance[t]].name + "'";
}

std::string element_text(const FiniteCheckContext& where, size_t i) {
  const Elements& e = where.elements;
  const uint32_t width = uint32_t(where.surface.pages[e.page[i]].width);
  return "element " + std::to_string(i) + " (page " + std::to_string(e.page[i]) + ", texel " +
         std::to_string(e.texel[i] % width) + ", " + std::to_string(e.texel[i] / width) + "), " +
         triangle_text(where, e.triangle[i]);
}

std::string patch_text(const FiniteCheckContext& where, const Patches& patches, size_t p) {
  return "patch " + std::to_string(p) + " (" + element_text(where, patches.members[patches.first_member[p]]) + ")";
}

[[noreturn]] void fail(const char* stage, const std::string& what) {
  throw NonFiniteValue("a non-finite value after " + std::string(stage) + ": " + what +
                       "; this is a bug in radbake, please report it with the scene");
}

}  // namespace

void check_elements(const FiniteCheckContext& where) {
  const Elements& e = where.elements;
  for (size_t i = 0; i < e.size(); ++i)
    if (!is_finite(e.position[i]) || !std::isfinite(e.area[i]) || !finite(e.reflectance[i]) || !finite(e.emission[i]))
      fail("elements", "the position, area or material of " + element_text(where, i));
}

void check_element_values(const char* stage, const std::vector<Rgb>& values, const FiniteCheckContext& where,
                          const std::vector<uint32_t>& patch_of_element) {
  for (size_t i = 0; i < values.size(); ++i) {
    if (finite(values[i])) continue;
    std::string patch;
    if (!patch_of_element.empty() && patch_of_element[i] != UINT32_MAX)
      patch = ", patch " + std::to_string(patch_of_element[i]);
    fail(stage, element_text(where, i) + patch);
  }
}

void check_patches(const char* stage, const Patches& patches, const PatchTransport& transport,
                   const std::vector<Rgb>& values, const FiniteCheckContext& where) {
  for (size_t p = 0; p < patches.size(); ++p) {
    if (!std::isfinite(patches.area[p]) || !finite(patches.reflectance[p]) || !finite(patches.emission[p]))
      fail(stage, "the area or material of " + patch_text(where, patches, p));
    for (uint64_t k = transport.row_start[p]; k < transport.row_start[p + 1]; ++k)
      if (!std::isfinite(transport.form_factor[k]))
        fail(stage, "the form factor from " + patch_text(where, patches, p) + " to patch " +
                        std::to_string(transport.target[k]));
    if (p < values.size() && !finite(values[p])) fail(stage, "the light of " + patch_text(where, patches, p));
  }
}

void check_vertex_values(const std::vector<std::vector<Rgb>>& values, const Scene& scene) {
  for (size_t m = 0; m < values.size(); ++m)
    for (size_t v = 0; v < values[m].size(); ++v)
      if (!finite(values[m][v]))
        fail("vertex values", "vertex " + std::to_string(v) + " of '" + scene.instances[m].name + "'");
}

}  // namespace radbake
