// What every hard case asserts besides its own closed form: the bake produced numbers a renderer
// can use. A NaN or infinity in one texel spreads through dilation and filtering; a negative value
// is light that does not exist.
#pragma once

#include <functional>

#include "baker/pipeline/bake.h"

namespace radbake::test {

// Every channel of every valid element's irradiance, every page texel (dilated gutters included)
// and every vertex value is finite and >= 0. Reports the first few offenders of each kind.
void expect_finite_and_non_negative(const BakeResult& result);

// The worst relative difference between a valid element's irradiance (red channel) and
// `expected(position, normal)` in lux, over the elements `where` selects; `count` gets how many.
double worst_relative_error(const BakeResult& result, const std::function<bool(Vec3 position, Vec3 normal)>& where,
                            const std::function<double(Vec3 position, Vec3 normal)>& expected, size_t* count);

}  // namespace radbake::test
