// The Cornell box's contact regions, where radiosity bakes are known to come out too bright (issue
// 13 measured them against Cycles): the foot of each block, the floor before the short block and
// the red wall along the floor. Shared by the near-field test and bench/accuracy_run, so that the
// regions the test bounds are the ones the bench reports.
#pragma once

#include <string>
#include <vector>

#include "baker/surface/elements.h"

namespace radbake::test {

struct RegionBias {
  std::string name;
  size_t texels = 0;
  double bias = 0;   // the region's mean lux over the reference's mean, minus one
  double noise = 0;  // the reference's standard error of that ratio (0 without its noise)
};

// Per region, samples/cornell_box's texels (metres, as the sample is modelled) compared with a
// reference for the same elements; `reference_noise`, per element standard errors, may be empty.
std::vector<RegionBias> cornell_region_biases(const Elements& elements, const std::vector<Rgb>& irradiance,
                                              const std::vector<Rgb>& reference,
                                              const std::vector<float>& reference_noise);

// Per element, 1 for those in any region: what a reference needs to trace.
std::vector<uint8_t> cornell_region_texels(const Elements& elements);

}  // namespace radbake::test
