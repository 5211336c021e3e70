#include "support/mip_bleeding.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "baker/finish/finish.h"
#include "io/lightmaps/page_encodings.h"
#include "uv/texel_coverage.h"

namespace radbake::test {
namespace {

struct Level {
  int width = 0, height = 0;
  std::vector<Rgb> texels;
};

// Box-filtered halvings down to 1 x 1, as glGenerateMipmap builds them for a power-of-two texture;
// a side already at 1 stays 1.
std::vector<Level> mip_chain(const LightmapPage& page) {
  std::vector<Level> chain(1, Level{page.width, page.height, page.texels});
  while (chain.back().width > 1 || chain.back().height > 1) {
    const Level& up = chain.back();
    Level down{std::max(1, up.width / 2), std::max(1, up.height / 2), {}};
    down.texels.resize(size_t(down.width) * size_t(down.height));
    for (int y = 0; y < down.height; ++y)
      for (int x = 0; x < down.width; ++x) {
        Rgb sum{};
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx) {
            int ux = std::min(2 * x + dx, up.width - 1), uy = std::min(2 * y + dy, up.height - 1);
            sum += up.texels[size_t(uy) * size_t(up.width) + size_t(ux)];
          }
        down.texels[size_t(y) * size_t(down.width) + size_t(x)] = sum / 4.0f;
      }
    chain.push_back(std::move(down));
  }
  return chain;
}

// Bilinear read at page coordinates uv in [0, 1]^2, clamped to the edge (the sampler's wrap).
Rgb bilinear(const Level& level, Vec2 uv) {
  const float x = uv.x * float(level.width) - 0.5f, y = uv.y * float(level.height) - 0.5f;
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  const float fx = x - float(x0), fy = y - float(y0);
  auto at = [&](int tx, int ty) {
    tx = std::clamp(tx, 0, level.width - 1);
    ty = std::clamp(ty, 0, level.height - 1);
    return level.texels[size_t(ty) * size_t(level.width) + size_t(tx)];
  };
  return (at(x0, y0) * (1 - fx) + at(x0 + 1, y0) * fx) * (1 - fy) + (at(x0, y0 + 1) * (1 - fx) + at(x0 + 1, y0 + 1) * fx) * fy;
}

// The PNG's code for a linear value, unrounded (so differences below one code still show).
double code(float linear, float scale) {
  double v = std::clamp(double(linear) / scale, 0.0, 1.0);
  return 255 * (v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055);
}

}  // namespace

MipBleedTable measure_mip_bleeding(const Scene& scene, int page_size, int padding, const BakeOptions& options) {
  AtlasOptions atlas_options;
  atlas_options.max_page_size = page_size;
  atlas_options.padding = padding;
  BakeOptions bake_options = options;
  bake_options.store = StoredQuantity::Irradiance;  // so the page is compose_pages(irradiance)
  const Baked b = bake_scene(scene, atlas_options, bake_options);
  const Elements& e = b.result.elements;
  const LightmapPage& page = b.result.pages[0];

  MipBleedTable table;
  table.padding = padding;
  table.width = page.width;
  table.height = page.height;
  table.png_scale = automatic_png_scale(b.result.pages);

  // The chart covering each texel of page 0, rasterised from the atlas as the elements were.
  std::vector<int64_t> owner(size_t(page.width) * size_t(page.height), -1);
  for (const AtlasMesh& m : b.atlas.meshes) {
    if (m.page != 0) continue;
    for (size_t t = 0; t < m.triangle_chart.size(); ++t) {
      if (m.triangle_chart[t] == UINT32_MAX) continue;
      Vec2 c[3];
      for (int k = 0; k < 3; ++k) {
        Vec2 uv = m.uvs[m.triangles[3 * t + size_t(k)]];
        c[k] = {uv.x * float(page.width), uv.y * float(page.height)};
      }
      for_each_covered_texel(c[0], c[1], c[2], page.width, page.height, [&](const TexelPiece& piece) {
        owner[size_t(piece.y) * size_t(page.width) + size_t(piece.x)] = m.triangle_chart[t];
      });
    }
  }
  std::map<int64_t, std::vector<size_t>> elements_of_chart;  // valid elements on page 0
  double level_sum = 0;
  size_t level_count = 0;
  for (size_t i = 0; i < e.size(); ++i) {
    if (e.page[i] != 0 || !e.valid(i)) continue;
    elements_of_chart[owner[e.texel[i]]].push_back(i);
    level_sum += (page.texels[e.texel[i]].x + page.texels[e.texel[i]].y + page.texels[e.texel[i]].z) / 3;
    ++level_count;
  }
  for (size_t t = 0; t < page.texels.size(); ++t)
    if (max_component(page.texels[t]) <= 0) {
      ++table.black_texels;
      table.black_covered_texels += page.valid[t] != 0;
    }
  const double floor = 0.1 * level_sum / double(std::max<size_t>(level_count, 1));

  const std::vector<Level> chain = mip_chain(page);
  table.levels.resize(chain.size());
  std::vector<size_t> visible(chain.size(), 0);
  size_t chart_texels = 0;
  for (size_t l = 0; l < chain.size(); ++l) table.levels[l].level = int(l), table.levels[l].side = std::max(chain[l].width, chain[l].height);

  Elements alone = e;
  for (const auto& [chart, members] : elements_of_chart) {
    // The page as it would be with this chart alone on it: the others' elements left to dilation.
    for (size_t i = 0; i < e.size(); ++i)
      alone.flags[i] = e.flags[i] | ((e.page[i] == 0 && owner[e.texel[i]] != chart) ? kBuried : 0);
    const std::vector<LightmapPage> alone_pages = compose_pages(alone, b.result.irradiance, b.atlas.pages);
    const std::vector<Level> alone_chain = mip_chain(alone_pages[0]);
    chart_texels += members.size();
    for (size_t i : members) {
      const int x = int(e.texel[i] % uint32_t(page.width)), y = int(e.texel[i] / uint32_t(page.width));
      const Vec2 centre{(float(x) + 0.5f) / float(page.width), (float(y) + 0.5f) / float(page.height)};
      const Rgb own = page.texels[e.texel[i]];
      for (size_t l = 0; l < chain.size(); ++l) {
        MipLevelBleed& row = table.levels[l];
        const Rgb read = bilinear(chain[l], centre), read_alone = bilinear(alone_chain[l], centre);
        double worst = 0;
        for (int c = 0; c < 3; ++c) {
          const double bleed = std::fabs(code(read[c], table.png_scale) - code(read_alone[c], table.png_scale));
          worst = std::max(worst, bleed);
          row.worst_relative = std::max(row.worst_relative, std::fabs(double(read[c]) - read_alone[c]) / std::max(double(read_alone[c]), floor));
          row.worst_code_vs_level0 =
              std::max(row.worst_code_vs_level0, std::fabs(code(read[c], table.png_scale) - code(own[c], table.png_scale)));
        }
        row.worst_code = std::max(row.worst_code, worst);
        visible[l] += worst >= 1;
      }
      // Anywhere in the texel at level 0: a 5 x 5 grid from corner to corner.
      for (int j = 0; j <= 4; ++j)
        for (int k = 0; k <= 4; ++k) {
          const Vec2 uv{(float(x) + float(k) / 4) / float(page.width), (float(y) + float(j) / 4) / float(page.height)};
          const Rgb read = bilinear(chain[0], uv), read_alone = bilinear(alone_chain[0], uv);
          for (int c = 0; c < 3; ++c)
            table.levels[0].anywhere_code = std::max(
                table.levels[0].anywhere_code, std::fabs(code(read[c], table.png_scale) - code(read_alone[c], table.png_scale)));
        }
    }
  }
  for (size_t l = 0; l < chain.size(); ++l) table.levels[l].share_visible = double(visible[l]) / double(std::max<size_t>(chart_texels, 1));
  return table;
}

}  // namespace radbake::test
