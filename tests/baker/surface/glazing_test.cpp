// The glazing models (baker/surface/glazing.h) against published angular data for real panes.
#include <gtest/gtest.h>

#include <cmath>

#include "baker/surface/glazing.h"
#include "support/closed_forms.h"

namespace radbake {
namespace {

double cosine_of(double degrees) { return std::cos(degrees * M_PI / 180); }

// CIE 171:2006's 6 mm clear glass (test::clear_glass_transmittance: Tregenza and Sharples'
// polynomial, as the report quotes it), relative to its 0.8788 along the normal. The default model
// with the glass's 0.8788 and n = 1.52 follows it within 0.5% at every degree to 80 (measured worst
// 0.42% at 61 degrees); absorption-free Fresnel faces pass 3% too much at 80 degrees.
TEST(Glazing, FresnelWithAbsorptionFollowsCie171sClearGlass) {
  const double tau = test::clear_glass_transmittance(1);
  const PaneCurve absorbing(GlazingModel::FresnelAbsorbing, 1.52f, float(tau)), faces(GlazingModel::Fresnel, 1.52f, float(tau));
  double worst = 0;
  for (int degrees = 0; degrees <= 80; ++degrees) {
    const double published = test::clear_glass_transmittance(cosine_of(degrees)) / tau;
    const double ours = absorbing.relative(float(cosine_of(degrees)));
    worst = std::max(worst, std::fabs(ours / published - 1));
    EXPECT_NEAR(ours, published, 0.005 * published) << degrees << " degrees";
  }
  RecordProperty("worst_relative_difference", std::to_string(worst));
  EXPECT_GT(faces.relative(float(cosine_of(80))), 1.025 * test::clear_glass_transmittance(cosine_of(80)) / tau);
  // The CIE model is the polynomial itself.
  const PaneCurve cie(GlazingModel::Cie171, 1.52f, 0.7f);
  for (int degrees : {0, 30, 60, 80})
    EXPECT_NEAR(cie.relative(float(cosine_of(degrees))), test::clear_glass_transmittance(cosine_of(degrees)) / tau, 1e-5);
}

// ESP-r's optics database (ESP-rSource databases/optics.db3): 6 mm clear float (SCF8783_06nb) and
// 6 mm bronze (SAZ5060_06nb), direct transmittance at 0, 40, 55, 70 and 80 degrees. With each pane's
// own normal transmittance the absorbing model gives both shapes within 0.5% (measured 0.18% and
// 0.28% at worst): a tinted pane falls faster than a clear one, which a curve scaled from clear
// faces cannot show (41% high for the bronze at 80 degrees).
TEST(Glazing, APaneOfLowTransmittanceFallsFasterAsItsGlassAbsorbsMore) {
  const double angles[4] = {40, 55, 70, 80};
  const double clear[5] = {0.779, 0.759, 0.717, 0.581, 0.348}, bronze[5] = {0.457, 0.421, 0.379, 0.290, 0.161};
  for (const double* pane : {clear, bronze}) {
    const PaneCurve curve(GlazingModel::FresnelAbsorbing, 1.52f, float(pane[0]));
    for (int k = 0; k < 4; ++k) {
      const double published = pane[k + 1] / pane[0];
      EXPECT_NEAR(curve.relative(float(cosine_of(angles[k]))), published, 0.005 * published)
          << "normal transmittance " << pane[0] << ", " << angles[k] << " degrees";
    }
  }
  const PaneCurve faces(GlazingModel::Fresnel, 1.52f, 0.457f);
  EXPECT_GT(faces.relative(float(cosine_of(80))), 1.3 * bronze[4] / bronze[0]);
  // What passes of diffuse light falls with it too: hemispherical over normal.
  EXPECT_LT(PaneCurve(GlazingModel::FresnelAbsorbing, 1.52f, 0.457f).diffuse_ratio(),
            PaneCurve(GlazingModel::FresnelAbsorbing, 1.52f, 0.779f).diffuse_ratio());
}

// A pane asked to pass all clear faces can (or more) absorbs nothing: the two Fresnel models agree.
TEST(Glazing, AClearPaneAbsorbsNothing) {
  const float clear = PaneCurve(GlazingModel::Fresnel, 1.5f, 1).clear_faces();
  EXPECT_NEAR(clear, 0.9231, 1e-4);  // (1 - r0) / (1 + r0), r0 = 0.04
  const PaneCurve absorbing(GlazingModel::FresnelAbsorbing, 1.5f, clear), faces(GlazingModel::Fresnel, 1.5f, clear);
  for (int degrees = 0; degrees <= 85; degrees += 5)
    EXPECT_NEAR(absorbing.relative(float(cosine_of(degrees))), faces.relative(float(cosine_of(degrees))), 1e-5);
  EXPECT_EQ(absorbing.relative(0), 0.0f);
  EXPECT_NEAR(absorbing.relative(1), 1.0f, 1e-6);
}

}  // namespace
}  // namespace radbake
