// How much light a pane of glazing passes at each angle of incidence, given what it passes along
// its normal. Three models, each with its published source (docs/daylight.md, "Glazing"):
//
// - FresnelAbsorbing (default): two Fresnel faces of the material's index and absorption in the
//   glass, the path through it growing as 1 / cos of the refracted angle, multiply reflected
//   between the faces: Radiance's `glass` (src/rt/glass.c) and EnergyPlus's uncoated glass. The
//   absorption is what the normal transmittance leaves after the faces' reflections. Within 0.42%
//   of CIE 171's 6 mm clear glass over 0-80 degrees, and of ESP-r's clear and bronze angular
//   tables within 0.3%.
// - Fresnel: the same faces without absorption (radbake's model before the CIE 171 tables), scaled
//   to the normal transmittance: a tinted or low pane keeps a clear pane's shape, 3% high at 80
//   degrees against CIE 171 for clear glass.
// - Cie171: CIE 171:2006's polynomial for 6 mm clear glass (Tregenza and Sharples), scaled to the
//   normal transmittance: the test cases 5.10 and 5.12 exactly, one shape whatever the pane.
#pragma once

namespace radbake {

enum class GlazingModel { FresnelAbsorbing, Fresnel, Cie171 };

// What a bake is told of its glazing (KHR_materials_transmission, read as a thin pane).
struct Glazing {
  // Visible transmittance along the normal, 0..1, for materials with no
  // extras.visible_transmittance of their own; < 0: a clear pane of the material's index.
  float transmittance = -1;
  GlazingModel model = GlazingModel::FresnelAbsorbing;  // how it passes less obliquely
};

// One pane's curve, for a material of index `ior` passing `normal_transmittance` along its normal.
class PaneCurve {
 public:
  PaneCurve(GlazingModel model, float ior, float normal_transmittance);
  // What passes at an angle of cosine `cosine` over what passes along the normal: 1 at 1, 0 at 0.
  float relative(float cosine) const;
  // What passes of light arriving from the whole hemisphere alike (cosine-weighted) over what
  // passes along the normal.
  float diffuse_ratio() const { return diffuse_ratio_; }
  // What the model passes along the normal with no absorption: two clear faces, (1 - r0) / (1 + r0)
  // (0.923 for n = 1.5) for the Fresnel models, CIE 171's 0.879 for its glass.
  float clear_faces() const { return along_normal_; }

 private:
  float absolute(float cosine) const;
  GlazingModel model_;
  float ior_;
  float internal_ = 1;  // FresnelAbsorbing: what one pass through the glass keeps along the normal
  float along_normal_ = 1, diffuse_ratio_ = 1;
};

}  // namespace radbake
