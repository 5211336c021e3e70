#include "io/gltf/vertex_repair.h"

#include <algorithm>
#include <cmath>

#include "base/errors.h"
#include "base/math.h"
#include "io/gltf/gltf_source.h"

namespace radbake {
namespace {

using json = nlohmann::ordered_json;

// The validator allows a unit vector's length to miss 1 by 0.00674; vectors further off than this
// are renormalised, so what radbake writes passes with float rounding to spare.
constexpr double kUnitTolerance = 0.005;

// A direction for a vertex whose normal has none and whose faces give none either (it is in no
// triangle, or only in degenerate ones): any unit vector is valid there, and +Y is glTF's up.
constexpr Vec3 kNoDirection = {0, 1, 0};

enum class Verdict { Fine, Repaired, Dropped };

struct Finding {
  Verdict verdict = Verdict::Fine;
  std::string what;  // the warning after the pointer
};

std::string count_of(size_t n, size_t total, const char* things) {
  return std::to_string(n) + " of " + std::to_string(total) + " " + things;
}

// Scales (x, y, z) to unit length in place; false when it has no direction (zero or not finite).
bool to_unit(float* v) {
  const double x = v[0], y = v[1], z = v[2];
  const double len = std::sqrt(x * x + y * y + z * z);
  if (!std::isfinite(len) || !(len > 0)) return false;
  for (int c = 0; c < 3; ++c) v[c] = float(v[c] / len);
  return is_finite(Vec3{v[0], v[1], v[2]});
}

bool unit(const float* v) {
  const double x = v[0], y = v[1], z = v[2];
  return std::fabs(std::sqrt(x * x + y * y + z * z) - 1) <= kUnitTolerance;
}

class Repairer {
 public:
  Repairer(const tinygltf::Model& model, std::map<std::pair<int, VertexUse>, RepairedAccessor>& repaired)
      : model_(model), repaired_(repaired) {}

  // The finding for `accessor` read for `use` by primitive `prim`, once per accessor and use.
  const Finding& check(int accessor, VertexUse use, const json& prim) {
    auto [it, first] = findings_.emplace(std::make_pair(accessor, use), Finding{});
    if (first) it->second = examine(accessor, use, prim);
    return it->second;
  }

 private:
  Finding examine(int accessor, VertexUse use, const json& prim) {
    const tinygltf::Accessor& a = model_.accessors[size_t(accessor)];
    // Integers are finite, and normalized unsigned ones (the colours glTF allows) lie in [0, 1].
    const bool floats = a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
    if (!floats && use != VertexUse::Normal && use != VertexUse::Tangent) return {};
    RepairedAccessor out;
    int components = 0;
    try {
      out.values = accessor_floats(model_, accessor, &components);
    } catch (const InputError&) {
      return {};  // an accessor no baked primitive reads may point anywhere; the claims check bounded it
    }
    out.components = size_t(components);
    Finding found = use == VertexUse::Normal    ? normals(out, prim)
                    : use == VertexUse::Tangent ? tangents(out)
                                                : values(out, use == VertexUse::Color);
    if (found.verdict == Verdict::Repaired) repaired_[{accessor, use}] = std::move(out);
    return found;
  }

  static Finding values(RepairedAccessor& out, bool color) {
    size_t bad = 0;
    for (float& v : out.values) {
      const float fixed = !std::isfinite(v) ? 0.0f : color ? std::clamp(v, 0.0f, 1.0f) : v;
      bad += fixed != v;
      v = fixed;
    }
    if (bad == 0) return {};
    return {Verdict::Repaired, count_of(bad, out.values.size(), "values") +
                                   (color ? " outside [0, 1] or not finite; clamped (NaN to 0)"
                                          : " not finite (NaN or infinite); written as 0")};
  }

  Finding normals(RepairedAccessor& out, const json& prim) const {
    std::vector<float> positions;
    std::vector<uint32_t> triangles;
    try {
      int components;
      positions = accessor_floats(model_, prim["attributes"]["POSITION"].get<int>(), &components);
      std::vector<uint32_t> indices;
      if (prim.contains("indices")) {
        indices = accessor_indices(model_, prim["indices"].get<int>());
      } else {
        indices.resize(positions.size() / 3);
        for (size_t i = 0; i < indices.size(); ++i) indices[i] = uint32_t(i);
      }
      triangles = triangle_list(indices, prim.value("mode", TINYGLTF_MODE_TRIANGLES));
    } catch (const InputError&) {
      // Positions or indices radbake cannot read give no faces: the normals without a direction get +Y.
    }
    const NormalRepair r = repair_normals(out.values, positions, triangles);
    if (r.renormalised + r.recomputed == 0) return {};
    std::string what = count_of(r.renormalised + r.recomputed, out.values.size() / 3, "normals") + " not of unit length:";
    if (r.renormalised) what += " " + std::to_string(r.renormalised) + " renormalised" + (r.recomputed ? "," : "");
    if (r.recomputed) what += " " + std::to_string(r.recomputed) + " of no direction recomputed from their faces";
    return {Verdict::Repaired, what};
  }

  static Finding tangents(RepairedAccessor& out) {
    const size_t n = out.values.size() / 4;
    size_t lost = 0, repaired = 0;
    for (size_t v = 0; v < n; ++v) {
      float* e = &out.values[4 * v];
      bool changed = false;
      if (!unit(e)) {
        if (!to_unit(e)) ++lost;
        changed = true;
      }
      if (e[3] != 1.0f && e[3] != -1.0f) {
        e[3] = e[3] < 0 ? -1.0f : 1.0f;
        changed = true;
      }
      repaired += changed;
    }
    if (lost)
      return {Verdict::Dropped, count_of(lost, n, "tangents") +
                                    " of zero length or not finite; viewers compute tangents where a file has none"};
    if (repaired == 0) return {};
    return {Verdict::Repaired, count_of(repaired, n, "tangents") + " repaired: xyz renormalised, w made 1 or -1 by its sign (NaN: 1)"};
  }

  const tinygltf::Model& model_;
  std::map<std::pair<int, VertexUse>, RepairedAccessor>& repaired_;
  std::map<std::pair<int, VertexUse>, Finding> findings_;
};

// RFC 6901: "~" and "/" in a member name (an application attribute's) are escaped.
std::string child(const std::string& at, const std::string& key) {
  std::string escaped;
  for (char c : key) escaped += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
  return at + "/" + escaped;
}

}  // namespace

NormalRepair repair_normals(std::vector<float>& normals, const std::vector<float>& positions,
                            const std::vector<uint32_t>& triangles) {
  const size_t n = normals.size() / 3;
  NormalRepair r;
  std::vector<size_t> lost;  // vertices whose normal has no direction
  for (size_t v = 0; v < n; ++v) {
    float* e = &normals[3 * v];
    if (unit(e)) continue;
    if (to_unit(e)) ++r.renormalised;
    else lost.push_back(v);
  }
  if (lost.empty()) return r;
  // Each lost vertex's triangles, area-weighted (the cross product's length is twice the area),
  // their fronts counter-clockwise (glTF 2.0 section 3.7.2.1).
  std::vector<Vec3> faces(n);
  std::vector<char> wanted(n, 0);
  for (size_t v : lost) wanted[v] = 1;
  auto at = [&](uint32_t v) { return Vec3{positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]}; };
  for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const uint32_t a = triangles[t], b = triangles[t + 1], c = triangles[t + 2], last = std::max({a, b, c});
    if (last >= n || 3 * size_t(last) + 2 >= positions.size() || !(wanted[a] || wanted[b] || wanted[c])) continue;
    const Vec3 f = cross(at(b) - at(a), at(c) - at(a));
    if (!is_finite(f)) continue;
    for (uint32_t v : {a, b, c}) faces[v] += f;
  }
  for (size_t v : lost) {
    float* e = &normals[3 * v];
    e[0] = faces[v].x, e[1] = faces[v].y, e[2] = faces[v].z;
    if (!to_unit(e)) e[0] = kNoDirection.x, e[1] = kNoDirection.y, e[2] = kNoDirection.z;
  }
  r.recomputed = lost.size();
  return r;
}

VertexUse vertex_use(const std::string& attribute, bool morph_target) {
  if (morph_target) return VertexUse::Displacement;
  if (attribute == "NORMAL") return VertexUse::Normal;
  if (attribute == "TANGENT") return VertexUse::Tangent;
  if (attribute.rfind("COLOR_", 0) == 0) return VertexUse::Color;
  return VertexUse::Value;
}

VertexRepairs::VertexRepairs(const tinygltf::Model& model, json& doc, std::vector<std::string>& warnings) {
  if (!doc.contains("meshes")) return;
  Repairer repairer(model, repaired_);
  for (size_t m = 0; m < doc["meshes"].size(); ++m) {
    json& primitives = doc["meshes"][m]["primitives"];
    for (size_t k = 0; k < primitives.size(); ++k) {
      json& prim = primitives[k];
      const std::string at = "/meshes/" + std::to_string(m) + "/primitives/" + std::to_string(k);
      std::vector<std::string> dropped;
      for (auto it = prim["attributes"].begin(); it != prim["attributes"].end(); ++it) {
        const Finding& f = repairer.check(it.value().get<int>(), vertex_use(it.key(), false), prim);
        const std::string pointer = child(child(at, "attributes"), it.key());
        if (f.verdict == Verdict::Repaired) warnings.push_back(pointer + ": " + f.what);
        if (f.verdict == Verdict::Dropped) {
          warnings.push_back("dropped " + pointer + " from the output (" + f.what + ")");
          dropped.push_back(it.key());
        }
      }
      for (const std::string& name : dropped) prim["attributes"].erase(name);
      if (!prim.contains("targets")) continue;
      for (size_t t = 0; t < prim["targets"].size(); ++t) {
        json& target = prim["targets"][t];
        // A displacement of an attribute the primitive no longer has would have no base.
        for (const std::string& name : dropped) target.erase(name);
        for (auto it = target.begin(); it != target.end(); ++it) {
          const Finding& f = repairer.check(it.value().get<int>(), VertexUse::Displacement, prim);
          if (f.verdict == Verdict::Repaired)
            warnings.push_back(child(child(child(at, "targets"), std::to_string(t)), it.key()) + ": " + f.what);
        }
      }
    }
  }
}

const RepairedAccessor* VertexRepairs::find(int accessor, VertexUse use) const {
  auto it = repaired_.find({accessor, use});
  return it == repaired_.end() ? nullptr : &it->second;
}

bool VertexRepairs::replaces(int accessor) const {
  auto it = repaired_.lower_bound({accessor, VertexUse::Normal});
  return it != repaired_.end() && it->first.first == accessor;
}

}  // namespace radbake
