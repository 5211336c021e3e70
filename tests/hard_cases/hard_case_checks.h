// What every hard case asserts besides its own closed form: the bake produced numbers a renderer
// can use. A NaN or infinity in one texel spreads through dilation and filtering; a negative value
// is light that does not exist.
#pragma once

#include "baker/bake.h"

namespace radbake::test {

// Every channel of every valid element's irradiance, every page texel (dilated gutters included)
// and every vertex value is finite and >= 0. Reports the first few offenders of each kind.
void expect_finite_and_non_negative(const BakeResult& result);

}  // namespace radbake::test
