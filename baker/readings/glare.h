// Daylight glare probability (Wienold and Christoffersen 2006) from a luminance image over the
// hemisphere in front of an eye, as evalglare computes it:
//
//   DGP = 5.87e-5 Ev + 9.18e-2 log10(1 + sum_s Ls^2 ws / (Ev^1.87 Ps^2)) + 0.16
//
// Ev the vertical illuminance at the eye (lux), and for each glare source s its luminance Ls
// (cd/m2), solid angle ws (sr) and Guth position index Ps (Iwata's below the line of sight, as
// evalglare takes it). Glare sources are what evalglare's defaults find: pixels brighter than five
// times the image's mean luminance, each joining the source whose centre is within 0.2 rad of it,
// sources within 0.2 rad of each other merged (evalglare also splits off peaks over
// 50,000 cd/m2 as sources of their own: not done here, so a sun seen through a window is part of
// the window's source, which gives a DGP of 1 either way).
#pragma once

#include <cstddef>
#include <vector>

#include "base/math.h"

namespace radbake {

// A fisheye luminance image: equidistant (Radiance's -vta angular fisheye), 180 degrees across
// the width and height, centred on the view direction; pixels outside the circle are not looked
// at. Rows top to bottom.
struct FisheyeImage {
  int size = 0;                 // pixels per side
  std::vector<float> luminance; // cd/m2, size x size
  Vec3 view{0, 0, -1}, up{0, 1, 0};  // unit, perpendicular
};

// The direction of pixel (x, y)'s centre, and its solid angle (sr); false outside the circle.
bool fisheye_pixel(const FisheyeImage& image, int x, int y, Vec3* direction, double* solid_angle);

// Guth's position index of a source in `direction`, for an eye looking along `view` with `up`
// (Luckiesh and Guth 1949, Guth 1963); below the line of sight Iwata's, as evalglare takes it; 16
// (the table's largest) behind the eye.
double position_index(Vec3 direction, Vec3 view, Vec3 up);

struct GlareSource {
  double luminance = 0;    // cd/m2, solid-angle weighted mean
  double solid_angle = 0;  // sr
  double position_index = 1;
  Vec3 direction;          // solid-angle weighted mean, unit
};

struct Glare {
  double vertical_illuminance = 0;  // lux, from the image
  double mean_luminance = 0;        // cd/m2, over the hemisphere
  double threshold = 0;             // cd/m2, what counts as a source
  std::vector<GlareSource> sources;
  double dgp = 0;
};

// DGP from Ev and the sources, Wienold's formula (clamped to 1).
double daylight_glare_probability(double vertical_illuminance, const std::vector<GlareSource>& sources);

// Ev, the sources and DGP of a fisheye image.
Glare evaluate_glare(const FisheyeImage& image);

}  // namespace radbake
