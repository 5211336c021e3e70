// The size of one lightmap page.
#pragma once

namespace radbake {

struct AtlasPage {
  int width = 0, height = 0;  // texels
};

}  // namespace radbake
