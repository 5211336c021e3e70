// Where radbake's own files are: the viewer's page and the part of three.js it imports, the
// three.js plugin, the gltf-transform config and the Blender add-on. An installed radbake finds
// them in share/radbake beside the bin folder it runs from (cmake --install, the Debian package);
// one run from its build directory, in the share/radbake the build stages there.
#pragma once

#include <filesystem>

namespace radbake {

// ../share/radbake from the running executable's folder, then share/radbake beside it: the first
// that holds the viewer (web/viewer/index.html and three.js); else throws an InputError naming
// where it looked.
std::filesystem::path viewer_share_folder();

}  // namespace radbake
