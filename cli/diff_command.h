// `radbake diff A B`: reads two bakes, compares them, prints the statistics, writes the
// difference images and says whether the thresholds hold. The comparison itself is
// baker/lightmap_difference; reading the bakes is io/bake_lightmaps.
#pragma once

#include "cli/command_line.h"

namespace radbake {

// Exit status: 0 when every threshold holds, 1 when one is exceeded. Throws InputError for
// bakes that cannot be read or compared.
int run_diff(const DiffCommand& cmd);

}  // namespace radbake
