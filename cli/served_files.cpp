#include "cli/served_files.h"

#include <sstream>
#include <system_error>

namespace radbake {

ServedFile served_file(const std::filesystem::path& root, const std::string& relative) {
  namespace fs = std::filesystem;
  ServedFile out;
  out.refusal = Refusal::Forbidden;
  if (relative.empty() || relative.front() == '/' || relative.find('\\') != std::string::npos ||
      relative.find('\0') != std::string::npos || relative.find(':') != std::string::npos)
    return out;
  std::stringstream parts(relative);
  for (std::string part; std::getline(parts, part, '/');)
    if (part.empty() || part == "." || part == "..") return out;
  std::error_code error;
  const fs::path base = fs::canonical(root, error);
  if (error) return out;
  const fs::path file = fs::canonical(base / relative, error);
  if (error) {
    out.refusal = Refusal::NotFound;
    return out;
  }
  // Canonical resolves every link: a path that ends outside the folder went out through one.
  const std::string inside = base.string() + "/";
  if (file.string().compare(0, inside.size(), inside) != 0) return out;
  if (!fs::is_regular_file(file, error)) {
    out.refusal = Refusal::NotFound;
    return out;
  }
  out.path = file;
  out.refusal = Refusal::None;
  return out;
}

}  // namespace radbake
