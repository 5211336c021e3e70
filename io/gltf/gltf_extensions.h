// The glTF extensions radbake reads or writes, in one table. The check (gltf_check.cpp), the loader
// (gltf_loader.cpp) and the writers (gltf_writer.cpp, display_gltf.cpp) ask it, so they cannot
// disagree about an extension; an extension that is not in it is copied through as it is.
// Adding a reader for an extension starts with its row here.
#pragma once

#include <string>
#include <vector>

namespace radbake {

// The kinds of glTF object an extension may sit on, as bits (the validator's
// UNEXPECTED_EXTENSION_OBJECT names an extension found elsewhere).
enum ExtendedObject : unsigned { kOnDocument = 1, kOnNode = 2, kOnMaterial = 4, kOnTextureInfo = 8 };

struct GltfExtension {
  const char* name;
  // The objects it may sit on (ExtendedObject bits); 0: not checked, wherever it sits.
  unsigned sits_on;
  // The check validates its objects, and an invalid one refuses the file (radbake reads it); in
  // extensionsRequired with nothing using it, it is dropped. Else an invalid one is dropped.
  bool refused_when_invalid;
  // A file that lists it in extensionsRequired bakes: radbake honours all of it.
  bool bakes_when_required;
  // What its objects refer to (textures, accessors, materials) is known, so the objects nothing
  // refers to can be pruned from the output (gltf_prune.cpp); any other extension keeps them all.
  bool references_known;
};

// Every row; gltf_extensions.cpp says beside each what radbake does with the extension.
const std::vector<GltfExtension>& gltf_extensions();

// The row of `name`, or, for a Khronos material extension without one, the row that every
// KHR_materials_ extension shares; nullptr for any other extension.
const GltfExtension* gltf_extension(const std::string& name);

}  // namespace radbake
