// The sky dome cut into patches for daylight coefficients: Tregenza's 145 (Tregenza 1987; CIE
// 108:1994), or Reinhart's subdivision of them, m x m per patch (m = 1 is Tregenza's; m = 2 gives
// 577 patches, m = 4 gives 2305), as Radiance's reinhart.cal numbers rows: row r of 7m rows spans
// altitudes [r a, (r + 1) a), a = 90 / (7m + 0.5) degrees, and holds m times Tregenza's count for
// its band (30, 30, 24, 24, 18, 12, 6); the zenith cap above the last row is one patch. Within a
// row, patches run from north toward east, patch 0 starting at north.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace radbake {

class SkyPatches {
 public:
  explicit SkyPatches(int subdivision = 1);  // 1..8

  size_t size() const { return first_of_row_.back() + 1; }  // rows' patches and the cap
  int subdivision() const { return m_; }
  // The patch a direction above the horizon falls in, from its altitude and azimuth (radians;
  // azimuth from north toward east, any turn).
  size_t patch_at(double altitude, double azimuth) const;
  // Centre of patch k: altitude and azimuth, radians (the cap's centre is the zenith).
  void centre(size_t k, double* altitude, double* azimuth) const;
  double solid_angle(size_t k) const;  // steradians; all of them add up to 2 pi
  // Up to four patches and weights (adding up to 1) that interpolate a quantity known at the
  // patches' centres to a direction: linearly in azimuth between the two centres of a row on
  // either side of it, and in altitude between the two rows whose centres' altitudes bracket it
  // (below the lowest row's centres, that row alone; above the highest's, toward the cap's).
  std::vector<std::pair<size_t, double>> interpolation(double altitude, double azimuth) const;
  // Patch k's altitudes [low, high] and azimuths [west edge, east edge] (the cap: all azimuths).
  void bounds(size_t k, double* altitude_low, double* altitude_high, double* azimuth_low, double* azimuth_high) const;

 private:
  int m_;
  double row_height_;                // radians
  std::vector<size_t> first_of_row_;  // per row, then the cap's index
  std::vector<int> count_of_row_;
};

}  // namespace radbake
