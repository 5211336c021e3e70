#include "io/lightmaps/directional_outputs.h"

#include <algorithm>
#include <cmath>

#include "io/lightmaps/page_encodings.h"

namespace radbake {
namespace {

// The value under which a share `q` of the valid texels' components of `sets` lie.
float quantile(const std::vector<const std::vector<LightmapPage>*>& sets, double q) {
  std::vector<float> values;
  for (const auto* set : sets)
    for (const LightmapPage& page : *set)
      for (size_t t = 0; t < page.texels.size(); ++t)
        if (page.valid[t])
          for (int c = 0; c < 3; ++c) values.push_back(page.texels[t][c]);
  if (values.empty()) return 0;
  const size_t k = std::min(values.size() - 1, size_t(std::floor(q * double(values.size() - 1))));
  std::nth_element(values.begin(), values.begin() + long(k), values.end());
  return values[k];
}

void write_set(DirectionalSet& set, const std::vector<LightmapPage>& pages, const std::string& folder,
               const std::string& name) {
  set.files = write_pages(pages, folder, name + "_" + set.coefficient, EightBitRange{set.scale, set.offset, false});
}

}  // namespace

DirectionalFiles write_directional(Directional mode, const std::vector<std::vector<LightmapPage>>& sets,
                                   const std::string& folder, const std::string& name) {
  DirectionalFiles files;
  if (mode == Directional::None || sets.empty()) return files;
  if (mode == Directional::Dominant) {
    files.mode = "dominant";
    DirectionalSet set{"dominant_direction", 2.0f, -1.0f, {}};  // length <= 1: png = dir / 2 + 0.5
    write_set(set, sets[0], folder, name);
    files.sets.push_back(set);
    return files;
  }
  files.mode = "sh";
  // c0 from its 0.1st to its 99.9th percentile (a few texels by a lamp may clip in the PNG, never
  // in the EXR); the three c1 pages share one range, symmetric about zero, so they stay a vector.
  const float low = std::min(0.0f, quantile({&sets[0]}, 0.001)), high = std::max(quantile({&sets[0]}, 0.999), low + 1e-6f);
  const float reach = std::max({-quantile({&sets[1], &sets[2], &sets[3]}, 0.0005),
                                quantile({&sets[1], &sets[2], &sets[3]}, 0.9995), 1e-6f});
  const char* names[4] = {"c0", "c1x", "c1y", "c1z"};
  for (size_t k = 0; k < 4; ++k) {
    DirectionalSet set{std::string("sh_") + names[k], k == 0 ? high - low : 2 * reach, k == 0 ? low : -reach, {}};
    write_set(set, sets[k], folder, name);
    files.sets.push_back(set);
  }
  return files;
}

}  // namespace radbake
