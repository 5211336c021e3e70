// What a glTF file may make radbake read and hold, and what a bake of it is estimated to hold:
// the limits the loader checks a file's claims against before it allocates anything they size.
#pragma once

#include <cstdint>

namespace radbake {

// What a file may make radbake read and hold. The file's claims (counts, lengths, image sizes) are
// checked against these before anything sized from them is allocated.
struct LoadOptions {
  bool allow_external_files = false;   // follow URIs out of the scene's folder (absolute, ../, symlinks)
  uint64_t max_triangles = 20000000;   // triangles after instancing
  uint64_t max_memory_bytes = 0;       // estimated peak of the whole bake; 0: half the physical memory
};

// What a bake of the file will hold, estimated before it is read (see resource_budget.cpp).
struct ResourceEstimate {
  uint64_t triangles = 0;  // after instancing
  uint64_t vertices = 0;   // after instancing
  uint64_t texels = 0;     // lightmap page texels; 0 until the atlas options are known
  uint64_t data_bytes = 0; // the file, its buffers and decoded images, held while baking

  uint64_t bytes() const;  // estimated peak memory of the bake
};

}  // namespace radbake
