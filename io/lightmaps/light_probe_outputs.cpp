#include "io/lightmaps/light_probe_outputs.h"

#include <filesystem>
#include <fstream>

#include "base/errors.h"
#include "io/files/written_file.h"

namespace radbake {

nlohmann::ordered_json light_probes_json(const LightProbes& probes) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const LightProbe& p : probes.probes) {
    nlohmann::ordered_json sh = nlohmann::ordered_json::array();
    for (const Rgb& c : p.radiance) sh.push_back({c.x, c.y, c.z});
    list.push_back({{"position", {p.position.x, p.position.y, p.position.z}}, {"sh", sh}});
  }
  return {
      {"count", probes.probes.size()},
      {"spacing_m", probes.spacing},
      {"bounds_m", {{probes.lo.x, probes.lo.y, probes.lo.z}, {probes.hi.x, probes.hi.y, probes.hi.z}}},
      {"grid_points", probes.grid_points},
      {"pruned_inside_solids", probes.inside},
      {"sh", "L2 spherical harmonics of the incident radiance, cd/m2 per basis function, RGB; real orthonormal "
             "basis in the order (l,m) = (0,0) (1,-1) (1,0) (1,1) (2,-2) (2,-1) (2,0) (2,1) (2,2); Y00 = 0.282095, "
             "Y1-1 = 0.488603 y, Y10 = 0.488603 z, Y11 = 0.488603 x, Y2-2 = 1.092548 xy, Y2-1 = 1.092548 yz, "
             "Y20 = 0.315392 (3z^2 - 1), Y21 = 1.092548 xz, Y22 = 0.546274 (x^2 - y^2); glTF world axes, +Y up"},
      {"irradiance", "lux on a surface of unit normal n: sum of A_l L_lm Y_lm(n), A_0 = pi, A_1 = 2 pi / 3, "
                     "A_2 = pi / 4 (Ramamoorthi and Hanrahan 2001)"},
      {"probes", list},
  };
}

std::string write_light_probes(const LightProbes& probes, const std::string& folder, const std::string& name) {
  const std::string file = name + "_probes.json";
  const std::string path = (std::filesystem::path(folder) / file).string();
  std::ofstream out(path);
  out << light_probes_json(probes).dump() << "\n";
  close_written(out, path);
  return file;
}

}  // namespace radbake
