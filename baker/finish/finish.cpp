#include "baker/finish/finish.h"

#include <algorithm>
#include <cmath>

namespace radbake {

void dilate_page(LightmapPage& page) {
  // Ring by ring: each empty texel takes the mean of its already-filled 8-neighbours, until the
  // whole page is filled.
  const int w = page.width, h = page.height;
  std::vector<uint8_t> filled(page.valid);
  std::vector<int> frontier, next;
  auto consider = [&](int x, int y, std::vector<int>& into) {
    if (x < 0 || y < 0 || x >= w || y >= h) return;
    int idx = y * w + x;
    if (filled[size_t(idx)] == 0) {
      filled[size_t(idx)] = 2;  // queued
      into.push_back(idx);
    }
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (page.valid[size_t(y * w + x)])
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) consider(x + dx, y + dy, frontier);
  while (!frontier.empty()) {
    std::vector<Rgb> ring(frontier.size());
    for (size_t k = 0; k < frontier.size(); ++k) {
      int x = frontier[k] % w, y = frontier[k] / w, count = 0;
      Rgb acc{};
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= w || ny >= h || filled[size_t(ny * w + nx)] != 1) continue;
          acc += page.texels[size_t(ny * w + nx)];
          ++count;
        }
      ring[k] = count ? acc / float(count) : Rgb{};
    }
    next.clear();
    for (size_t k = 0; k < frontier.size(); ++k) {
      page.texels[size_t(frontier[k])] = ring[k];
      filled[size_t(frontier[k])] = 1;
    }
    for (int idx : frontier)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) consider(idx % w + dx, idx / w + dy, next);
    frontier.swap(next);
  }
}

std::vector<LightmapPage> compose_pages(const Elements& e, const std::vector<Rgb>& values,
                                        const std::vector<AtlasPage>& pages, bool dilate) {
  std::vector<LightmapPage> out(pages.size());
  for (size_t p = 0; p < pages.size(); ++p) {
    out[p].width = pages[p].width;
    out[p].height = pages[p].height;
    out[p].texels.assign(size_t(pages[p].width) * pages[p].height, Rgb{});
    out[p].valid.assign(out[p].texels.size(), 0);
  }
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i)) continue;
    out[e.page[i]].texels[e.texel[i]] = values[i];
    out[e.page[i]].valid[e.texel[i]] = 1;
  }
  if (dilate)
    for (LightmapPage& page : out) dilate_page(page);
  return out;
}

namespace {

// Least-squares plane v = a + b dx + c dy through (dx, dy, v) samples; false when they are
// collinear or too few.
bool fit_plane(const std::vector<Vec3>& offsets_and_weight, const std::vector<Rgb>& v, Rgb& at_origin) {
  double m[3][3] = {}, rhs[3][3] = {};
  for (size_t k = 0; k < v.size(); ++k) {
    double row[3] = {1.0, offsets_and_weight[k].x, offsets_and_weight[k].y};
    double w = offsets_and_weight[k].z;
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) m[a][b] += w * row[a] * row[b];
      for (int c = 0; c < 3; ++c) rhs[c][a] += w * row[a] * v[k][c];
    }
  }
  double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  if (v.size() < 3 || !(std::fabs(det) > 1e-6 * m[0][0] * m[0][0] * m[0][0])) return false;
  for (int c = 0; c < 3; ++c) {
    // Cramer's rule for the constant term only: the value at the vertex.
    const double* r = rhs[c];
    double det_a = r[0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (r[1] * m[2][2] - m[1][2] * r[2]) +
                   m[0][2] * (r[1] * m[2][1] - m[1][1] * r[2]);
    at_origin[c] = float(det_a / det);
  }
  return true;
}

}  // namespace

std::vector<std::vector<Rgb>> vertex_values(const Elements& e, const Surface& surface, const Atlas& atlas,
                                            const std::vector<LightmapPage>& pages, const std::vector<Rgb>& values) {
  std::vector<std::vector<Rgb>> out(atlas.meshes.size());
  std::vector<Vec3> samples;
  std::vector<Rgb> sample_values;
  for (size_t m = 0; m < atlas.meshes.size(); ++m) {
    const AtlasMesh& mesh = atlas.meshes[m];
    const LightmapPage& page = pages[size_t(mesh.page)];
    std::vector<uint32_t> chart_of_vertex(mesh.uvs.size(), UINT32_MAX);
    for (size_t t = 0; t < mesh.triangle_chart.size(); ++t)
      for (int k = 0; k < 3; ++k) chart_of_vertex[mesh.triangles[3 * t + k]] = mesh.triangle_chart[t];
    out[m].resize(mesh.uvs.size());
    for (size_t v = 0; v < mesh.uvs.size(); ++v) {
      Vec2 p{mesh.uvs[v].x * page.width, mesh.uvs[v].y * page.height};
      Rgb value{};
      bool found = false;
      for (float radius : {2.0f, 3.0f, 6.0f}) {
        samples.clear();
        sample_values.clear();
        Rgb highest{};
        int x0 = std::max(0, int(std::floor(p.x - radius))), x1 = std::min(page.width - 1, int(std::floor(p.x + radius)));
        int y0 = std::max(0, int(std::floor(p.y - radius))), y1 = std::min(page.height - 1, int(std::floor(p.y + radius)));
        for (int y = y0; y <= y1; ++y)
          for (int x = x0; x <= x1; ++x) {
            int32_t i = e.element_at[size_t(mesh.page)][size_t(y) * page.width + x];
            if (i < 0 || !e.valid(size_t(i)) || surface.chart[e.triangle[size_t(i)]] != chart_of_vertex[v]) continue;
            float dx = x + 0.5f - p.x, dy = y + 0.5f - p.y;
            if (dx * dx + dy * dy > radius * radius) continue;
            samples.push_back({dx, dy, 1.0f / (1.0f + dx * dx + dy * dy)});
            sample_values.push_back(values[size_t(i)]);
            for (int c = 0; c < 3; ++c) highest[c] = std::max(highest[c], values[size_t(i)][c]);
          }
        // A corner vertex has few texels around it: widen the search before settling for a mean.
        if (samples.empty() || (samples.size() < 3 && radius < 6.0f)) continue;
        if (!fit_plane(samples, sample_values, value)) {
          double weight = 0;
          value = {};
          for (size_t k = 0; k < samples.size(); ++k) value += sample_values[k] * samples[k].z, weight += samples[k].z;
          value = value / float(weight);
        }
        // Extrapolation past an edge follows the gradient but may not invent light or darkness.
        for (int c = 0; c < 3; ++c) value[c] = std::clamp(value[c], 0.0f, 2.0f * highest[c]);
        found = true;
        break;
      }
      if (!found) {
        int x = std::clamp(int(p.x), 0, page.width - 1), y = std::clamp(int(p.y), 0, page.height - 1);
        value = page.texels[size_t(y) * page.width + x];
      }
      out[m][v] = value;
    }
  }
  return out;
}

}  // namespace radbake
