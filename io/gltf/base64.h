// Base64 (RFC 4648's alphabet, with padding) for data URIs, which glTF allows for buffers and images.
#pragma once

#include <string>

namespace radbake {

std::string to_base64(const std::string& bytes);
// The bytes `text` encodes; "" when it holds a character outside the alphabet. Decoding stops at '='.
std::string from_base64(const std::string& text);

}  // namespace radbake
