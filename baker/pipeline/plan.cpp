#include "baker/pipeline/plan.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>

#include "base/errors.h"

namespace radbake {
namespace {

// Above this many plane-vertex tests the convexity check is skipped (and shadow rays kept): it
// costs more than the shadow rays it could save.
constexpr double kMaxConvexityTests = 2e8;

std::string quoted(const std::string& name, const char* fallback) {
  return name.empty() ? fallback : "'" + name + "'";
}

std::string light_name(const Scene& scene, size_t l) {
  return "light " + quoted(scene.lights[l].name, ("#" + std::to_string(l)).c_str());
}

std::string material_name(const Scene& scene, int m) {
  return m < 0 ? "the default material" : quoted(scene.materials[size_t(m)].name, ("#" + std::to_string(m)).c_str());
}

std::string metres(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g m", v);
  return text;
}

// Each material index an instance with triangles uses, once (-1 for the glTF default material).
std::vector<int> used_materials(const Scene& scene) {
  std::vector<int> used;
  for (const MeshInstance& inst : scene.instances)
    if (inst.triangle_count() > 0 && std::find(used.begin(), used.end(), inst.material) == used.end())
      used.push_back(inst.material);
  std::sort(used.begin(), used.end());
  return used;
}

template <typename F>
void for_each_triangle(const Scene& scene, F&& f) {
  for (const MeshInstance& inst : scene.instances)
    for (size_t t = 0; t + 2 < inst.triangles.size(); t += 3) {
      const Vec3 corners[3] = {inst.positions[inst.triangles[t]], inst.positions[inst.triangles[t + 1]],
                               inst.positions[inst.triangles[t + 2]]};
      f(inst, corners);
    }
}

bool is_grey(Rgb c) { return c.x == c.y && c.y == c.z; }

bool image_is_grey(const Image& image) {
  const size_t bytes = image.bits / 8;
  for (size_t p = 0; p + 4 * bytes <= image.pixels.size(); p += 4 * bytes)
    if (!std::equal(&image.pixels[p], &image.pixels[p + bytes], &image.pixels[p + bytes]) ||
        !std::equal(&image.pixels[p], &image.pixels[p + bytes], &image.pixels[p + 2 * bytes]))
      return false;
  return true;
}

bool texture_is_grey(const Scene& scene, const TextureRef& ref) {
  return !ref.present() || image_is_grey(scene.images[size_t(ref.image)]);
}

// Colour scaled to a largest component of 1 (black stays black).
Rgb chromaticity(Rgb c) {
  float m = max_component(c);
  return m > 0 ? c / m : Rgb{};
}

bool same_colour(Rgb a, Rgb b) {
  for (int c = 0; c < 3; ++c)
    if (std::fabs(a[c] - b[c]) > 1e-6f) return false;
  return true;
}

// Zero reflectance for sure, from the factors alone: black, or fully metallic without a texture
// that could lower the metallic factor.
bool reflects_nothing(const Material& m) {
  return max_component(m.base_color) <= 0 || (m.metallic >= 1 && !m.metallic_roughness_texture.present());
}

bool varies(const Scene& scene, int m) {
  const Material& mat = material_of(scene, m);
  return mat.base_color_texture.present() || mat.metallic_roughness_texture.present() ||
         (mat.emits() && mat.emissive_texture.present());
}

struct Plane {
  Vec3 normal;
  double offset;  // normal . x for points x on the plane
};

// The distinct planes of the scene's triangles, rounded so that a tessellated wall is one plane.
std::vector<Plane> triangle_planes(const Scene& scene, double scene_size) {
  std::map<std::array<long long, 4>, Plane> planes;
  for_each_triangle(scene, [&](const MeshInstance& inst, const Vec3(&c)[3]) {
    Vec3 n = cross(c[1] - c[0], c[2] - c[0]);
    if (inst.mirrored) n = -n;
    float len = length(n);
    if (!(len > 0) || !std::isfinite(len)) return;
    n = n / len;
    double offset = (double(n.x) * c[0].x + double(n.y) * c[0].y + double(n.z) * c[0].z);
    std::array<long long, 4> key = {std::llround(n.x * 1e5), std::llround(n.y * 1e5), std::llround(n.z * 1e5),
                                    std::llround(offset / scene_size * 1e5)};
    planes.emplace(key, Plane{n, offset});
  });
  std::vector<Plane> out;
  for (auto& [key, plane] : planes) out.push_back(plane);
  return out;
}

double signed_distance(const Plane& p, Vec3 x) {
  return double(p.normal.x) * x.x + double(p.normal.y) * x.y + double(p.normal.z) * x.z - p.offset;
}

// Empty when the scene is a convex enclosure with every traced light inside: each triangle's plane has
// every vertex and every punctual light on its front side, so any two points on the surfaces see
// each other (the segment between them lies inside the intersection of the front half-spaces).
// Otherwise, the reason it is not.
std::string why_not_convex(const Scene& scene, const std::vector<uint8_t>& light_traced) {
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  size_t vertices = 0;
  for (const MeshInstance& inst : scene.instances)
    for (Vec3 p : inst.positions) {
      for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], p[c]), hi[c] = std::max(hi[c], p[c]);
      ++vertices;
    }
  const double size = std::max(double(length(hi - lo)), 1e-30);
  const double tolerance = 1e-5 * size;  // flatness that still counts as on the plane
  std::vector<Plane> planes = triangle_planes(scene, size);
  if (double(planes.size()) * double(vertices) > kMaxConvexityTests)
    return "not checked for convexity: " + std::to_string(planes.size()) + " planes";
  for (const Plane& plane : planes) {
    for (const MeshInstance& inst : scene.instances)
      for (Vec3 p : inst.positions)
        if (signed_distance(plane, p) < -tolerance) return "some surface can hide another";
    for (size_t l = 0; l < scene.lights.size(); ++l) {
      const Light& light = scene.lights[l];
      if (!light_traced[l]) continue;
      bool inside = light.type == LightType::Directional ? dot(plane.normal, -light.direction) >= 0
                                                         : signed_distance(plane, light.position) >= -tolerance;
      if (!inside) return light_name(scene, l) + " is outside the enclosure";
    }
  }
  return {};
}

// Distance from p to the nearest point of triangle abc (Ericson, Real-Time Collision Detection 5.1.5).
float distance_to_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  Vec3 ab = b - a, ac = c - a, ap = p - a;
  float d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return length(p - a);
  Vec3 bp = p - b;
  float d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return length(p - b);
  float vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return length(p - (a + ab * (d1 / (d1 - d3))));
  Vec3 cp = p - c;
  float d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return length(p - c);
  float vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return length(p - (a + ac * (d2 / (d2 - d6))));
  float va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return length(p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))));
  float denom = 1 / (va + vb + vc);
  return length(p - (a + ab * (vb * denom) + ac * (vc * denom)));
}

}  // namespace

bool light_can_reach(const Light& light, const Vec3 (&corners)[3]) {
  Vec3 normal = cross(corners[1] - corners[0], corners[2] - corners[0]);
  if (light.type == LightType::Directional) return dot(normal, -light.direction) > 0;
  if (!(dot(normal, light.position - corners[0]) > 0)) return false;  // behind or in its plane
  if (light.range > 0 && distance_to_triangle(light.position, corners[0], corners[1], corners[2]) >= light.range)
    return false;
  if (light.type != LightType::Spot) return true;
  // glTF caps the cone at 90 degrees: a triangle wholly behind the light is outside it.
  if (std::all_of(corners, corners + 3, [&](Vec3 c) { return dot(c - light.position, light.direction) <= 0; }))
    return false;
  Vec3 centre = (corners[0] + corners[1] + corners[2]) / 3.0f;
  float radius = std::max({length(corners[0] - centre), length(corners[1] - centre), length(corners[2] - centre)});
  Vec3 to_centre = centre - light.position;
  float distance = length(to_centre);
  if (distance <= radius) return true;
  float off_axis = std::acos(std::clamp(dot(to_centre / distance, light.direction), -1.0f, 1.0f));
  return off_axis - std::asin(radius / distance) < light.outer_cone_angle;
}

namespace {

void decide(EffectPlan& plan, std::string effect, std::string choice, std::string reason) {
  plan.decisions.push_back({std::move(effect), std::move(choice), std::move(reason)});
}

std::vector<int> emitting_materials(const Scene& scene, const std::vector<int>& used) {
  std::vector<int> emitting;
  for (int m : used)
    if (material_of(scene, m).emits()) emitting.push_back(m);
  return emitting;
}

// Light sources: lights that can reach some triangle's front, and emitting materials. A scene
// that nothing lights is refused here, before anything is built.
void plan_light_sources(const Scene& scene, const PlanOptions& options, const std::vector<int>& emitting,
                        EffectPlan& plan) {
  plan.light_traced.assign(scene.lights.size(), 0);
  for (size_t l = 0; l < scene.lights.size(); ++l) {
    const Light& light = scene.lights[l];
    if (options.simulate_everything) {
      plan.light_traced[l] = 1;
      continue;
    }
    if (!(light.intensity > 0)) {
      decide(plan, light_name(scene, l), "culled: no shadow rays", "its intensity is zero");
      continue;
    }
    for_each_triangle(scene, [&](const MeshInstance& inst, const Vec3(&c)[3]) {
      if (plan.light_traced[l]) return;
      const Vec3 front[3] = {c[0], inst.mirrored ? c[2] : c[1], inst.mirrored ? c[1] : c[2]};
      plan.light_traced[l] = light_can_reach(light, front);
    });
    if (plan.light_traced[l]) continue;
    std::string why = light.type == LightType::Spot ? "no surface front inside its cone" : "no surface faces it";
    if (light.range > 0) why += " within its range of " + metres(light.range);
    decide(plan, light_name(scene, l), "culled: no shadow rays", why);
  }
  if (emitting.empty() && scene.lights.empty() && !options.sky)
    throw InputError("nothing in the scene emits light: no KHR_lights_punctual light and no emissive material");
  if (emitting.empty() && !options.sky &&
      std::none_of(plan.light_traced.begin(), plan.light_traced.end(), [](uint8_t t) { return t; }))
    throw InputError("no light reaches a surface: every light is behind the surfaces, out of range or aimed away, "
                     "and no material emits");
}

// What the bake leaves out, a warning per feature naming its materials.
void warn_unsimulated(const Scene& scene, const std::vector<int>& used, EffectPlan& plan) {
  std::map<std::string, std::vector<std::string>> left_out;  // feature -> materials
  for (int m : used) {
    const Material& mat = material_of(scene, m);
    for (const std::string& feature : mat.unsimulated) left_out[feature].push_back(material_name(scene, m));
    if (mat.metallic > 0 || mat.metallic_roughness_texture.present())
      left_out["metallic reflection"].push_back(material_name(scene, m));
  }
  for (const auto& [feature, materials] : left_out) {
    std::string list;
    for (const std::string& name : materials) list += (list.empty() ? "" : ", ") + name;
    plan.warnings.push_back(feature + " is not simulated (" + list +
                            "): radbake bakes diffuse light only, so these surfaces are baked opaque, with their diffuse reflectance alone");
  }
}

void plan_interreflection(const Scene& scene, const std::vector<int>& used, const PlanOptions& options,
                          EffectPlan& plan) {
  size_t reflecting = 0;
  for (int m : used) reflecting += !reflects_nothing(material_of(scene, m));
  if (options.direct_only) {
    plan.interreflection = false;
    decide(plan, "interreflection", "skipped", "asked for direct light only");
  } else if (reflecting == 0) {
    plan.interreflection = false;
    decide(plan, "interreflection", "skipped", "no material reflects light (all black or fully metallic)");
  } else {
    decide(plan, "interreflection", "solved",
           std::to_string(reflecting) + " of " + std::to_string(used.size()) + " materials reflect light");
  }
}

// Colour channels: one when every reflectance is grey and every emitter has one colour.
void plan_colour_channels(const Scene& scene, const std::vector<int>& used, const std::vector<int>& emitting,
                          const PlanOptions& options, EffectPlan& plan) {
  std::string coloured;
  for (int m : used) {
    const Material& mat = material_of(scene, m);
    if (coloured.empty() && (!is_grey(mat.base_color) || !texture_is_grey(scene, mat.base_color_texture)))
      coloured = material_name(scene, m) + " is coloured";
  }
  for (const MeshInstance& inst : scene.instances)
    for (Rgb c : inst.colors)
      if (coloured.empty() && !is_grey(c)) coloured = "mesh " + quoted(inst.name, "") + " has coloured vertices";
  std::vector<Rgb> colours;
  for (int m : emitting) {
    const Material& mat = material_of(scene, m);
    colours.push_back(chromaticity(mat.emissive));
    if (!texture_is_grey(scene, mat.emissive_texture)) colours.push_back({});  // varies: no single colour
  }
  for (size_t l = 0; l < scene.lights.size(); ++l)
    if (plan.light_traced[l]) colours.push_back(chromaticity(scene.lights[l].color));
  if (options.sky) colours.push_back(Rgb{1, 1, 1});
  bool one_colour = !colours.empty() && std::all_of(colours.begin(), colours.end(),
                                                    [&](Rgb c) { return same_colour(c, colours.front()); });
  if (!plan.interreflection) return;  // nothing to solve, in any number of channels
  if (!coloured.empty()) {
    decide(plan, "colour channels", "3 solved", coloured);
  } else if (!one_colour) {
    decide(plan, "colour channels", "3 solved", "every material is grey, but the lights differ in colour");
  } else {
    plan.one_channel = true;
    plan.light_colour = colours.front();
    decide(plan, "colour channels", "1 solved, scaled by the light colour",
           "every material is grey and every light has the same colour");
  }
}

void plan_textures(const Scene& scene, const std::vector<int>& used, EffectPlan& plan) {
  size_t varying = 0;
  for (int m : used) varying += varies(scene, m);
  bool vertex_colours = std::any_of(scene.instances.begin(), scene.instances.end(),
                                    [](const MeshInstance& inst) { return !inst.colors.empty(); });
  if (varying == 0 && !vertex_colours) {
    plan.texture_sampling = false;
    decide(plan, "textures", "not sampled: one reflectance and emission per material",
           "no material has a texture and no mesh has vertex colours");
  } else {
    decide(plan, "textures", "box-filtered over each texel where the material varies",
           std::to_string(varying) + " materials have textures" + (vertex_colours ? ", some meshes vertex colours" : ""));
  }
}

// Double-sided backs, as baker/surface/back_faces.cpp gave them (or not) triangles of their own.
void report_double_sided_backs(const Scene& scene, EffectPlan& plan) {
  size_t double_sided = 0, twins = 0;
  for (const MeshInstance& inst : scene.instances) {
    if (inst.back_of >= 0) twins += inst.triangle_count();
    else if (material_of(scene, inst.material).double_sided) double_sided += inst.triangle_count();
  }
  if (double_sided == 0) return;
  const std::string kept = std::to_string(double_sided - twins);
  decide(plan, "double-sided backs",
         std::to_string(twins) + " of " + std::to_string(double_sided) + " baked with texels of their own",
         twins == double_sided ? "every one can receive light: on an open surface or a light behind it"
                               : kept + " are on closed shells with no light behind them: they show their front's texel");
}

void plan_shadows(const Scene& scene, const PlanOptions& options, EffectPlan& plan) {
  std::string hidden = why_not_convex(scene, plan.light_traced);
  if (!hidden.empty()) {
    decide(plan, "shadows", "traced", hidden);
    return;
  }
  plan.shadow_rays = false;
  if (options.sky)
    decide(plan, "shadows", "traced for the sky and the sun only",
           "they shine from outside; the scene is convex with its own lights inside, which need none");
  else
    decide(plan, "shadows", "no shadow rays", "the scene is a convex enclosure with every light inside: nothing can "
                                              "shadow anything");
}

}  // namespace

EffectPlan plan_effects(const Scene& scene, const PlanOptions& options) {
  EffectPlan plan;
  const std::vector<int> used = used_materials(scene);
  const std::vector<int> emitting = emitting_materials(scene, used);
  plan_light_sources(scene, options, emitting, plan);
  warn_unsimulated(scene, used, plan);
  if (options.simulate_everything) {
    plan.exhaustive = true;
    decide(plan, "everything", "simulated", "asked to simulate every effect whatever the scene");
    return plan;
  }
  plan_interreflection(scene, used, options, plan);
  plan_colour_channels(scene, used, emitting, options, plan);
  plan_textures(scene, used, plan);
  report_double_sided_backs(scene, plan);
  plan_shadows(scene, options, plan);
  return plan;
}

}  // namespace radbake
