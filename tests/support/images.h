// What radbake writes, read back as a viewer reads it: a PNG's pixels, an EXR's stored type.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace radbake::test {

// 8-bit RGB pixels, rows top to bottom, of a PNG of any colour type; empty (and the sizes -1)
// when it cannot be read.
std::vector<uint8_t> read_png_rgb(const std::string& path, int* width = nullptr, int* height = nullptr);

enum class ExrStorage { Half, Float, Other, Unreadable };
// How an EXR stores its R channel.
ExrStorage exr_storage(const std::string& path);

}  // namespace radbake::test
