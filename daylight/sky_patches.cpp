#include "daylight/sky_patches.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace radbake {

namespace {
constexpr int kTregenzaCounts[7] = {30, 30, 24, 24, 18, 12, 6};
}

SkyPatches::SkyPatches(int subdivision) : m_(subdivision) {
  if (m_ < 1 || m_ > 8) throw std::invalid_argument("sky subdivision must be 1..8");
  row_height_ = (M_PI / 2) / (7 * m_ + 0.5);
  size_t next = 0;
  for (int r = 0; r < 7 * m_; ++r) {
    first_of_row_.push_back(next);
    count_of_row_.push_back(kTregenzaCounts[r / m_] * m_);
    next += size_t(count_of_row_.back());
  }
  first_of_row_.push_back(next);  // the cap
}

size_t SkyPatches::patch_at(double altitude, double azimuth) const {
  const int rows = 7 * m_;
  const int r = int(std::floor(std::max(0.0, altitude) / row_height_));
  if (r >= rows) return first_of_row_.back();
  double turn = azimuth / (2 * M_PI);
  turn -= std::floor(turn);
  const int n = count_of_row_[size_t(r)];
  return first_of_row_[size_t(r)] + size_t(std::min(n - 1, int(turn * n)));
}

void SkyPatches::bounds(size_t k, double* altitude_low, double* altitude_high, double* azimuth_low,
                        double* azimuth_high) const {
  if (k == first_of_row_.back()) {
    *altitude_low = double(7 * m_) * row_height_, *altitude_high = M_PI / 2, *azimuth_low = 0, *azimuth_high = 2 * M_PI;
    return;
  }
  const size_t r = size_t(std::upper_bound(first_of_row_.begin(), first_of_row_.end() - 1, k) - first_of_row_.begin()) - 1;
  const double width = 2 * M_PI / count_of_row_[r];
  *altitude_low = double(r) * row_height_, *altitude_high = double(r + 1) * row_height_;
  *azimuth_low = double(k - first_of_row_[r]) * width, *azimuth_high = *azimuth_low + width;
}

void SkyPatches::centre(size_t k, double* altitude, double* azimuth) const {
  if (k == first_of_row_.back()) {
    *altitude = M_PI / 2, *azimuth = 0;
    return;
  }
  double a0, a1, z0, z1;
  bounds(k, &a0, &a1, &z0, &z1);
  *altitude = 0.5 * (a0 + a1), *azimuth = 0.5 * (z0 + z1);
}

std::vector<std::pair<size_t, double>> SkyPatches::interpolation(double altitude, double azimuth) const {
  const int rows = 7 * m_;
  // Row r's centres lie at altitude (r + 0.5) h; the cap's at the zenith.
  const double position = std::clamp(altitude, 0.0, M_PI / 2) / row_height_ - 0.5;
  const int below = int(std::floor(position));
  std::vector<std::pair<size_t, double>> out;
  auto in_row = [&](int r, double weight) {
    if (weight <= 0) return;
    if (r >= rows) {
      out.push_back({first_of_row_.back(), weight});
      return;
    }
    const int n = count_of_row_[size_t(r)];
    double at = azimuth / (2 * M_PI) * n - 0.5;  // in patch widths from patch 0's centre
    at -= std::floor(at / n) * n;
    const int left = int(std::floor(at)) % n, right = (left + 1) % n;
    const double t = at - std::floor(at);
    out.push_back({first_of_row_[size_t(r)] + size_t(left), weight * (1 - t)});
    out.push_back({first_of_row_[size_t(r)] + size_t(right), weight * t});
  };
  if (below < 0) {
    in_row(0, 1);
  } else if (below >= rows - 1) {
    // Between the top row's centres and the zenith, which the cap's centre is.
    const double top = (double(rows) - 0.5) * row_height_;
    const double t = std::clamp((altitude - top) / (M_PI / 2 - top), 0.0, 1.0);
    in_row(rows - 1, 1 - t);
    in_row(rows, t);
  } else {
    const double t = position - below;
    in_row(below, 1 - t);
    in_row(below + 1, t);
  }
  return out;
}

double SkyPatches::solid_angle(size_t k) const {
  double a0, a1, z0, z1;
  bounds(k, &a0, &a1, &z0, &z1);
  return (z1 - z0) * (std::sin(a1) - std::sin(a0));
}

}  // namespace radbake
