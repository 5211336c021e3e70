#include "io/gltf/gltf_extensions.h"

namespace radbake {

namespace {

// The Khronos material extensions without a row of their own: checked for their schemas' common
// shape (*Factor numbers, *Texture references) and dropped when invalid; a file requiring one is
// refused.
const GltfExtension kOtherMaterialExtension = {"KHR_materials_", kOnMaterial, false, false, false};

}  // namespace

const std::vector<GltfExtension>& gltf_extensions() {
  static const std::vector<GltfExtension> rows = {
      // name, sits on, refused when invalid, bakes when required, references known; what radbake does with it
      {"KHR_lights_punctual", kOnDocument | kOnNode, true, true, true},  // point, spot and directional lights
      {"KHR_materials_emissive_strength", kOnMaterial, true, true, true},  // emission past 1
      {"KHR_texture_transform", kOnTextureInfo, true, true, true},  // textures' UV offset, rotation, scale and set
      {"KHR_mesh_quantization", 0, false, true, true},  // vertex attributes stored as integers
      {"KHR_materials_transmission", kOnMaterial, false, false, true},  // its factor: glazing's (its texture warned of)
      {"KHR_materials_ior", kOnMaterial, false, false, true},  // with transmission, the pane's reflectance
      {"KHR_materials_pbrSpecularGlossiness", kOnMaterial, false, false, false},  // converted to metallic-roughness
      {"KHR_materials_diffuse_transmission", kOnMaterial, false, false, false},  // warned of: not simulated
      {"KHR_materials_volume", kOnMaterial, false, false, true},  // warned of: not simulated
      {"KHR_materials_specular", kOnMaterial, false, false, true},  // warned of: not simulated
      {"KHR_materials_clearcoat", kOnMaterial, false, false, true},  // warned of: not simulated
      {"KHR_materials_sheen", kOnMaterial, false, false, true},  // warned of: not simulated
      {"KHR_materials_iridescence", kOnMaterial, false, false, true},  // warned of: not simulated
      {"KHR_materials_anisotropy", kOnMaterial, false, false, true},  // copied; not simulated
      {"KHR_materials_dispersion", kOnMaterial, false, false, true},  // copied; not simulated
      {"KHR_materials_variants", 0, false, false, true},  // copied, with the materials its variants name
      {"KHR_materials_unlit", kOnMaterial, false, false, true},  // written on the display file's materials
      {"KHR_texture_basisu", 0, false, false, true},  // copied, with the KTX2 images it names
      {"EXT_texture_webp", 0, false, false, true},  // copied, with the WebP images it names
      {"EXT_texture_avif", 0, false, false, true},  // copied, with the AVIF images it names
      {"EXT_mesh_gpu_instancing", 0, false, false, true},  // copied, with its accessors
      {"MOZ_lightmap", 0, false, false, true},  // written: each material's lightmap; read back on a re-bake
  };
  return rows;
}

const GltfExtension* gltf_extension(const std::string& name) {
  for (const GltfExtension& row : gltf_extensions())
    if (name == row.name) return &row;
  if (name.compare(0, 14, "KHR_materials_") == 0) return &kOtherMaterialExtension;
  return nullptr;
}

}  // namespace radbake
