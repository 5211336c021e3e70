// Internal to io/: the vertex data the engine file copies from its input, made what the Khronos
// glTF-Validator accepts. glTF holds every float to a finite value (ACCESSOR_INVALID_FLOAT), NORMAL
// and TANGENT to unit vectors (ACCESSOR_VECTOR3_NON_UNIT), TANGENT's w to 1 or -1
// (ACCESSOR_INVALID_SIGN) and float colours to [0, 1] (ACCESSOR_NON_CLAMPED). An attribute whose data
// breaks one is repaired, or dropped where it cannot be, with one warning naming its JSON pointer
// (docs/hostile_input.md).
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace radbake {

// What glTF asks of an attribute's values.
enum class VertexUse {
  Normal,        // NORMAL: unit vectors
  Tangent,       // TANGENT: unit xyz, w = +-1
  Color,         // COLOR_n: in [0, 1]
  Value,         // any other attribute: finite
  Displacement,  // a morph target's: finite
};

VertexUse vertex_use(const std::string& attribute, bool morph_target);

// Normals (three floats each) made unit vectors: renormalised where they have a direction, else
// the area-weighted normal of the vertex's triangles (`positions` three floats per vertex in the
// normals' space, `triangles` three indices each), else +Y.
struct NormalRepair {
  size_t renormalised = 0, recomputed = 0;  // normals
};
NormalRepair repair_normals(std::vector<float>& normals, const std::vector<float>& positions,
                            const std::vector<uint32_t>& triangles);

// An input accessor's elements repaired, as floats.
struct RepairedAccessor {
  std::vector<float> values;  // `components` per element, as many elements as the input accessor
  size_t components = 0;
};

class VertexRepairs {
 public:
  // Reads every attribute and morph target of every primitive in `doc` (the checked document, whose
  // accessors are `model`'s) and drops from `doc` the attributes that cannot be repaired: tangents
  // of zero length or not finite (viewers compute tangents where a file has none), with the
  // primitive's morph-target tangents.
  VertexRepairs(const tinygltf::Model& model, nlohmann::ordered_json& doc, std::vector<std::string>& warnings);

  // The repaired elements of input accessor `accessor` read for `use`; nullptr when it needs none.
  const RepairedAccessor* find(int accessor, VertexUse use) const;
  // Whether an attribute reads a repaired copy of `accessor` (so the input's is not written).
  bool replaces(int accessor) const;

 private:
  using Key = std::pair<int, VertexUse>;
  std::map<Key, RepairedAccessor> repaired_;
};

}  // namespace radbake
