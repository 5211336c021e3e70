#include "baker/surface/glazing.h"

#include <algorithm>
#include <cmath>

namespace radbake {
namespace {

// Fresnel's reflectances of one face for light arriving at cosine c from air into index n: s and p.
void face_reflectance(double c, double n, double* rs, double* rp) {
  const double sin_inside = std::sqrt(std::max(0.0, 1 - c * c)) / n;
  const double cos_inside = std::sqrt(std::max(0.0, 1 - sin_inside * sin_inside));
  const double s = (c - n * cos_inside) / (c + n * cos_inside), p = (cos_inside - n * c) / (cos_inside + n * c);
  *rs = s * s, *rp = p * p;
}

double cos_inside(double c, double n) {
  const double sin_inside = std::sqrt(std::max(0.0, 1 - c * c)) / n;
  return std::sqrt(std::max(0.0, 1 - sin_inside * sin_inside));
}

// A slab of two faces of reflectance r, keeping d of the light on each pass through: what passes,
// summed over the light's bounces between the faces, (1 - r)^2 d / (1 - r^2 d^2).
double slab(double r, double d) { return (1 - r) * (1 - r) * d / (1 - r * r * d * d); }

// CIE 171:2006 test case 5.10's 6 mm clear glass, T(cos) (Tregenza and Sharples, "Daylighting
// algorithms" 2.34, as quoted on radiance-general, March 2017); 0.87881 along the normal. It dips
// below 0 within half a degree of grazing.
double cie171_glass(double c) {
  return std::max(0.0, -0.028378 + c * (3.156075 + c * (-3.058376 + c * (-1.428919 + c * (4.014235 + c * -1.775827)))));
}

}  // namespace

PaneCurve::PaneCurve(GlazingModel model, float ior, float normal_transmittance)
    : model_(model), ior_(std::isfinite(ior) && ior > 1 ? ior : 1.5f) {
  if (model_ == GlazingModel::FresnelAbsorbing) {
    // The single pass's internal transmittance t that gives the normal transmittance with the
    // faces' r0: tau = (1 - r0)^2 t / (1 - r0^2 t^2), solved for t (EnergyPlus's "Glass Optical
    // Properties Conversion", Radiance's trans.cal), in the form that is stable as r0 t -> 0. A
    // pane asked to pass more than clear faces can (1 - r0) / (1 + r0) absorbs nothing.
    const double n = ior_, r0 = ((n - 1) / (n + 1)) * ((n - 1) / (n + 1)), a = (1 - r0) * (1 - r0);
    const double tau = std::clamp(double(normal_transmittance), 0.0, 1.0);
    internal_ = tau >= (1 - r0) / (1 + r0) ? 1.0f : float(2 * tau / (std::sqrt(a * a + 4 * r0 * r0 * tau * tau) + a));
  }
  along_normal_ = absolute(1);
  // Cosine-weighted over the hemisphere, by the midpoint rule in cos (512 steps: 1e-5 of the
  // integral for these smooth curves).
  constexpr int kSteps = 512;
  double sum = 0;
  for (int k = 0; k < kSteps; ++k) {
    const double c = (k + 0.5) / kSteps;
    sum += 2 * c * relative(float(c)) / kSteps;
  }
  diffuse_ratio_ = float(sum);
}

float PaneCurve::absolute(float cosine) const {
  const double c = std::min(1.0, double(cosine));
  if (!(c > 1e-6)) return 0;
  if (model_ == GlazingModel::Cie171) return float(cie171_glass(c));
  double rs, rp;
  face_reflectance(c, ior_, &rs, &rp);
  const double d = model_ == GlazingModel::FresnelAbsorbing && internal_ < 1 ? std::pow(double(internal_), 1 / cos_inside(c, ior_)) : 1.0;
  return float(0.5 * (slab(rs, d) + slab(rp, d)));
}

float PaneCurve::relative(float cosine) const { return along_normal_ > 0 ? absolute(cosine) / along_normal_ : 0.0f; }

}  // namespace radbake
