#include "uv/atlas.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

#include "base/errors.h"
#include "base/progress.h"
#include "uv/charts.h"
#include "uv/half_edge_mesh.h"

namespace radbake {

void UnwrapProgress::at(double fraction_of_step) {
  fraction_ = fraction_of_step;
  if (!callback_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_call_ < std::chrono::milliseconds(50)) return;
  last_call_ = now;
  if (!callback_("lightmap uvs", from_ + (to_ - from_) * std::min(fraction_of_step, 1.0))) throw Cancelled();
}

namespace {

// Shares of the unwrap's progress: charts (grown and flattened), then packing, then measuring.
constexpr double kChartsEnd = 0.6, kPackingEnd = 0.95;
// Packing attempts: one, or a search for the automatic density (below).
constexpr int kMostPackings = 48;
// The automatic density's pages grow by twos: the smallest page that holds the texel budget to a
// factor of sqrt(2) is chosen, then filled as far as it goes, up to kMostFill times the budget
// (scenes of many small charts, whose padding takes most of a page, use it better so).
constexpr double kBudgetLatitude = 1.41421356, kMostFill = 2.0;

double world_area(const MeshView& mesh) {
  double area = 0;
  for (size_t t = 0; t < mesh.triangle_count; ++t) {
    const uint32_t* tri = mesh.triangles + 3 * t;
    Vec3 p0 = mesh.positions[tri[0]];
    float a = length(cross(mesh.positions[tri[1]] - p0, mesh.positions[tri[2]] - p0));
    if (std::isfinite(a)) area += 0.5 * a;
  }
  return area;
}

double uv_area(const MeshView& mesh) {
  double area = 0;
  for (size_t t = 0; t < mesh.triangle_count; ++t) {
    const uint32_t* tri = mesh.triangles + 3 * t;
    Vec2 u0 = mesh.lightmap_uvs[tri[0]];
    area += 0.5 * std::fabs(cross2(mesh.lightmap_uvs[tri[1]] - u0, mesh.lightmap_uvs[tri[2]] - u0));
  }
  return area;
}

int largest_power_of_two_at_most(int v) {
  int p = 1;
  while (p <= v / 2) p *= 2;
  return p;
}

int smallest_power_of_two_at_least(int v) {
  int p = 1;
  while (p < v) p *= 2;
  return p;
}

// A kept TEXCOORD_1 layout gets a page of its own, square, sized so its texels match the density.
int page_side_for_own_uvs(const MeshView& mesh, float density, int max_page_size) {
  double uv = uv_area(mesh);
  double side = uv > 0 ? density * std::sqrt(world_area(mesh) / uv) : 16;
  return std::clamp((int(std::ceil(side)) + 3) / 4 * 4, 16, max_page_size);
}

AtlasMesh keep_own_uvs(const MeshView& mesh, int page, uint32_t& next_chart) {
  AtlasMesh out;
  out.kept_input_uvs = true;
  out.page = page;
  out.source_vertex.resize(mesh.vertex_count);
  for (size_t v = 0; v < mesh.vertex_count; ++v) out.source_vertex[v] = uint32_t(v);
  out.triangles.assign(mesh.triangles, mesh.triangles + 3 * mesh.triangle_count);
  out.uvs.assign(mesh.lightmap_uvs, mesh.lightmap_uvs + mesh.vertex_count);
  uint32_t largest = 0;
  out.triangle_chart = uv_islands(mesh, mesh.lightmap_uvs);
  for (uint32_t& c : out.triangle_chart) largest = std::max(largest, c), c += next_chart;
  next_chart += largest + 1;
  return out;
}

// Splits vertices along chart borders and writes each corner's page coordinates.
AtlasMesh lay_out_charts(const MeshView& mesh, const std::vector<const Chart*>& charts,
                         const std::vector<const ChartPlacement*>& placements, const AtlasPage& page,
                         int page_index, uint32_t first_chart) {
  AtlasMesh out;
  out.page = page_index;
  out.triangles.assign(3 * mesh.triangle_count, 0);
  out.triangle_chart.assign(mesh.triangle_count, UINT32_MAX);
  // (input vertex, chart, its place there) -> output vertex. The place is part of the key, as one
  // input vertex can lie twice in a chart: a face that could not join the mesh's connectivity
  // (three faces on an edge) got copies of its corners and may be hinged onto the chart elsewhere.
  std::map<std::tuple<uint32_t, uint32_t, float, float>, uint32_t> vertex_of;
  auto emit = [&](uint32_t source, uint32_t chart, Vec2 uv) {
    auto [it, inserted] = vertex_of.emplace(std::make_tuple(source, chart, uv.x, uv.y), uint32_t(out.source_vertex.size()));
    if (inserted) {
      out.source_vertex.push_back(source);
      out.uvs.push_back(uv);
    }
    return it->second;
  };
  for (size_t c = 0; c < charts.size(); ++c) {
    const Chart& chart = *charts[c];
    for (size_t i = 0; i < chart.triangles.size(); ++i) {
      uint32_t t = chart.triangles[i];
      out.triangle_chart[t] = first_chart + uint32_t(c);
      for (int k = 0; k < 3; ++k) {
        Vec2 texel = placed_corner(chart, *placements[c], 3 * i + size_t(k));
        out.triangles[3 * t + k] =
            emit(mesh.triangles[3 * t + k], uint32_t(c), {texel.x / float(page.width), texel.y / float(page.height)});
      }
    }
  }
  // Triangles without a chart cover no texel; their corners sit at the page origin, in the padding.
  for (size_t t = 0; t < mesh.triangle_count; ++t)
    if (out.triangle_chart[t] == UINT32_MAX)
      for (int k = 0; k < 3; ++k) out.triangles[3 * t + k] = emit(mesh.triangles[3 * t + k], UINT32_MAX, {0, 0});
  return out;
}

// Charts of every mesh that needs them, and the metres of seam between them.
std::vector<Chart> make_charts(const std::vector<MeshView>& meshes, const std::vector<bool>& generate,
                               const AtlasOptions& options, float density, double* seam_length,
                               UnwrapProgress& progress) {
  ChartOptions chart_options;
  chart_options.max_normal_deviation_degrees = options.max_chart_normal_deviation;
  chart_options.hard_edge_degrees = options.hard_edge_angle;
  // Below about 4 x 4 texels, or 4 texels across, a chart holds less than its padding costs.
  chart_options.small_chart_area = 16.0f / (density * density);
  chart_options.sliver_width = 4.0f / density;
  chart_options.texel_size = 1.0f / density;
  std::vector<Chart> charts;
  double triangles = 0, done = 0;
  for (size_t m = 0; m < meshes.size(); ++m) triangles += generate[m] ? double(meshes[m].triangle_count) : 0;
  for (size_t m = 0; m < meshes.size(); ++m) {
    if (!generate[m]) continue;
    const double from = kChartsEnd * done / triangles, mid = kChartsEnd * (done + 0.5 * double(meshes[m].triangle_count)) / triangles;
    done += double(meshes[m].triangle_count);
    progress.step(from, mid);
    HalfEdgeMesh hm = build_half_edge_mesh(meshes[m]);
    int count = 0;
    std::vector<int> chart_of_face = grow_charts(hm, chart_options, &count, progress);
    progress.step(mid, kChartsEnd * done / triangles);
    std::vector<Chart> mine = flatten_charts(hm, chart_of_face, count, uint32_t(m), chart_options, options.rotate_charts, progress);
    // Seams: mesh edges whose two faces ended up in different charts.
    std::vector<int> final_chart(meshes[m].triangle_count, -1);
    for (size_t c = 0; c < mine.size(); ++c)
      for (uint32_t t : mine[c].triangles) final_chart[t] = int(c);
    for (auto e : hm.mesh.edges()) {
      if (e.is_boundary()) continue;
      int a = final_chart[hm.input_triangle[size_t(e.h0().face().idx())]];
      int b = final_chart[hm.input_triangle[size_t(e.h1().face().idx())]];
      if (a != b) *seam_length += double(hm.mesh.calc_edge_length(e));
    }
    charts.insert(charts.end(), std::make_move_iterator(mine.begin()), std::make_move_iterator(mine.end()));
  }
  return charts;
}

void check_options(const AtlasOptions& options) {
  if (options.max_page_size < 16 || options.max_page_size > 16384)
    throw InputError("maximum page size must be 16..16384 texels");
  if (options.padding < 0 || options.padding > 64) throw InputError("padding must be 0..64 texels");
  if (!(options.texel_density >= 0)) throw InputError("texel density must be positive");
}

// The meshes that keep the TEXCOORD_1 layout they came with, on pages of their own after the
// generated ones.
struct KeptLayouts {
  std::vector<int> own_page;  // per mesh: its page in `pages`, or -1
  std::vector<AtlasPage> pages;
  std::vector<bool> generate;  // per mesh: its UVs are generated
};

KeptLayouts keep_input_layouts(const std::vector<MeshView>& meshes, const AtlasOptions& options, float density,
                               std::vector<std::string>& warnings) {
  KeptLayouts kept{std::vector<int>(meshes.size(), -1), {}, std::vector<bool>(meshes.size(), true)};
  auto keep = [&](const std::vector<size_t>& group, AtlasPage page, const std::string& problem) {
    if (!problem.empty())
      for (size_t m : group) warnings.push_back("mesh '" + meshes[m].name + "': " + problem + "; used anyway");
    for (size_t m : group) kept.own_page[m] = int(kept.pages.size()), kept.generate[m] = false;
    kept.pages.push_back(page);
  };
  const bool may_keep = options.input_uvs != InputUvPolicy::Generate;
  // Meshes the file lays out on one page (a re-bake of radbake's own output, or another baker's)
  // are checked together at that page's size and keep sharing it. When they cannot (their charts
  // touch, or the page is larger than allowed), their UVs are generated: a page per mesh, the
  // fallback below, would leave each page mostly empty, as each layout covers only its share.
  std::vector<bool> decided(meshes.size(), false);
  std::map<int, std::vector<size_t>> on_input_page;
  for (size_t m = 0; m < meshes.size(); ++m)
    if (may_keep && meshes[m].lightmap_uvs && meshes[m].uv_page >= 0 && meshes[m].uv_page_width > 0 &&
        meshes[m].uv_page_height > 0)
      on_input_page[meshes[m].uv_page].push_back(m);
  for (const auto& [input_page, group] : on_input_page) {
    std::vector<const MeshView*> views;
    for (size_t m : group) views.push_back(&meshes[m]), decided[m] = true;
    const AtlasPage page{meshes[group[0]].uv_page_width, meshes[group[0]].uv_page_height};
    const std::string size = std::to_string(page.width) + "x" + std::to_string(page.height);
    const bool too_large = page.width > options.max_page_size || page.height > options.max_page_size;
    const std::string problem = too_large ? "the page is larger than " + std::to_string(options.max_page_size) + " texels"
                                          : lightmap_uv_problem(views, page.width, page.height);
    if (!too_large && (problem.empty() || options.input_uvs == InputUvPolicy::KeepAll)) {
      keep(group, page, problem);
      continue;
    }
    warnings.push_back(std::to_string(group.size()) + (group.size() == 1 ? " mesh" : " meshes") + " laid out on one " +
                       size + " input lightmap page: " + problem + "; generating lightmap UVs");
  }
  for (size_t m = 0; m < meshes.size(); ++m) {
    if (!may_keep || !meshes[m].lightmap_uvs || decided[m]) continue;
    int side = page_side_for_own_uvs(meshes[m], density, options.max_page_size);
    std::string problem = lightmap_uv_problem(meshes[m], side);
    if (problem.empty() || options.input_uvs == InputUvPolicy::KeepAll) {
      keep({m}, {side, side}, problem);
      continue;
    }
    warnings.push_back("mesh '" + meshes[m].name + "': " + problem + "; generating lightmap UVs");
  }
  return kept;
}

bool fits_one_page(const PackResult& r) { return r.pages.size() == 1 && r.downscaled_meshes.empty(); }

// Packs the generated charts, each packing a share of the progress bar.
class Packer {
 public:
  Packer(const std::vector<Chart>& charts, size_t meshes, const AtlasOptions& options, UnwrapProgress& progress)
      : charts_(charts), meshes_(meshes), options_(options), progress_(progress) {}

  PackResult operator()(float density, PackGoal goal, AtlasPage page) {
    const double share = (kPackingEnd - kChartsEnd) / kMostPackings;
    progress_.step(kChartsEnd + share * packings_, kChartsEnd + share * (packings_ + 1));
    packings_ = std::min(packings_ + 1, kMostPackings - 1);
    return pack_charts(charts_, meshes_, density, page, options_.padding, options_.rotate_charts, goal, progress_);
  }

  // The highest density up to `cap` whose charts fit one `page`, and its packing; false when none
  // does. A bracket round the first try, then narrowed to 0.1%. Each try guesses from the last:
  // a page filled to a share f suggests sqrt(1/f) times the density, charts placed up to a share
  // p before one did not fit suggest sqrt(p) times; guesses stay inside the bracket, and halve it
  // when they would not shrink it.
  bool most_that_fits(AtlasPage page, float first, float cap, float& density, PackResult& packed) {
    float lo = 0, hi = 0;  // highest known to fit, lowest known not to
    PackResult best;
    float next = std::min(first, cap);
    for (int step = 0; step < 40; ++step) {
      const float d = next;
      PackResult r = (*this)(d, PackGoal::OnePageOrNothing, page);
      float guess;
      if (fits_one_page(r)) {
        const double filled = double(r.pages[0].width) * r.pages[0].height / (double(page.width) * page.height);
        guess = d * float(std::sqrt(1 / std::max(filled, 0.25)));
        lo = d, best = std::move(r);
        if (lo >= cap) break;
      } else {
        guess = d * float(std::sqrt(std::max(r.placed_share, 0.25))) * 0.99f;
        hi = d;
      }
      if (lo > 0 && hi > 0 && hi - lo <= 0.001f * lo) break;
      if (hi == 0) next = std::min(std::max(guess, lo * 1.05f), cap);
      else if (lo == 0) next = std::min(guess, hi * 0.95f);
      else next = guess > lo + 0.25f * (hi - lo) && guess < hi - 0.25f * (hi - lo) ? guess : 0.5f * (lo + hi);
    }
    if (lo == 0) return false;
    density = lo;
    packed = std::move(best);
    return true;
  }

 private:
  const std::vector<Chart>& charts_;
  size_t meshes_;
  const AtlasOptions& options_;
  UnwrapProgress& progress_;
  int packings_ = 0;
};

// The generated charts packed, at the density chosen for them.
struct PackedCharts {
  PackResult result;
  float density = 0;
  AtlasPage smallest_holding_budget{0, 0};  // the automatic density's page, when one held the budget
};

// `density`: the given density, or the automatic one's first guess; `budget_density` spends the
// texel budget over the surface.
PackedCharts pack_at_chosen_density(const std::vector<Chart>& charts, size_t meshes, const AtlasOptions& options,
                                    int page_size, float density, float budget_density, UnwrapProgress& progress,
                                    std::vector<std::string>& warnings) {
  Packer pack(charts, meshes, options, progress);
  PackedCharts out;
  out.density = density;
  const AtlasPage largest_page{page_size, page_size};
  // The automatic density on power-of-two pages: the smallest page, square or twice as wide as
  // high, that holds the texel budget within kBudgetLatitude, filled up to kMostFill of it
  // (engines allocate the whole page, so a budget on a page twice its size is half empty: the
  // Cornell box's 50,000 texels were 39% of a 1024 x 128 page).
  const double least_texels = double(options.automatic_texels) / kBudgetLatitude;
  if (options.texel_density == 0 && !options.any_page_size && !charts.empty())
    for (int side = 16; side <= page_size && out.smallest_holding_budget.width == 0; side *= 2)
      for (AtlasPage page : {AtlasPage{side, side / 2}, AtlasPage{side, side}}) {
        if (page.height < 16 || double(page.width) * page.height < least_texels) continue;
        if (fits_one_page(pack(budget_density / float(std::sqrt(kBudgetLatitude)), PackGoal::OnePageOrNothing, page))) {
          out.smallest_holding_budget = page;
          break;
        }
      }
  if (out.smallest_holding_budget.width > 0) {
    const float most_density = budget_density * float(std::sqrt(kMostFill));
    pack.most_that_fits(out.smallest_holding_budget, most_density, most_density, out.density, out.result);
  } else if (charts.empty() || (options.texel_density > 0 && !options.fit_one_page)) {
    out.result = pack(out.density, PackGoal::AsManyPagesAsNeeded, largest_page);
  } else if (!pack.most_that_fits(largest_page, out.density,
                                  options.texel_density > 0 ? options.texel_density : budget_density, out.density,
                                  out.result)) {
    out.result = pack(out.density, PackGoal::AsManyPagesAsNeeded, largest_page);
    warnings.push_back("the charts do not fit one " + std::to_string(page_size) + "-texel page at any density; using " +
                       std::to_string(out.result.pages.size()) + " pages");
  }
  return out;
}

// Atlas::density_choice: how the density came about, in words.
std::string density_choice(const AtlasOptions& options, const Atlas& atlas, const PackedCharts& packed,
                           float budget_density, int page_size) {
  char choice[240];
  if (options.texel_density > 0)
    std::snprintf(choice, sizeof choice, atlas.density_lowered ? "given, lowered to fit one page" : "given");
  else if (packed.smallest_holding_budget.width > 0)
    std::snprintf(choice, sizeof choice,
                  "automatic: %dx%d, the smallest power-of-two page that holds %zu texels over %.3g m2 of surface "
                  "(to a factor of 1.41), filled up to twice that",
                  packed.smallest_holding_budget.width, packed.smallest_holding_budget.height,
                  options.automatic_texels, atlas.surface_area);
  else if (packed.density >= budget_density * 0.999f)
    std::snprintf(choice, sizeof choice, "automatic: %zu texels over %.3g m2 of surface", options.automatic_texels,
                  atlas.surface_area);
  else
    std::snprintf(choice, sizeof choice, "automatic: the most that fits one %d-texel page (%zu texels over %.3g m2 would not)",
                  page_size, options.automatic_texels, atlas.surface_area);
  return choice;
}

// Each mesh's lightmap UVs: its charts where they were placed, or its own layout on its page.
void lay_out_meshes(const std::vector<MeshView>& meshes, const std::vector<Chart>& charts, const PackResult& packed,
                    const KeptLayouts& kept, UnwrapProgress& progress, Atlas& atlas) {
  std::vector<std::vector<const Chart*>> charts_of(meshes.size());
  std::vector<std::vector<const ChartPlacement*>> placements_of(meshes.size());
  for (size_t c = 0; c < charts.size(); ++c) {
    charts_of[charts[c].mesh].push_back(&charts[c]);
    placements_of[charts[c].mesh].push_back(&packed.placements[c]);
  }
  // Only degenerate triangles to generate for: they still need a page to point at.
  if (atlas.pages.empty() && std::count(kept.generate.begin(), kept.generate.end(), true)) atlas.pages.push_back({16, 16});
  const int first_kept_page = int(atlas.pages.size());
  atlas.pages.insert(atlas.pages.end(), kept.pages.begin(), kept.pages.end());
  uint32_t next_chart = 0;
  for (size_t m = 0; m < meshes.size(); ++m) {
    progress.poll();
    if (kept.own_page[m] >= 0) {
      atlas.meshes[m] = keep_own_uvs(meshes[m], first_kept_page + kept.own_page[m], next_chart);
      continue;
    }
    int page = placements_of[m].empty() ? 0 : placements_of[m][0]->page;
    atlas.meshes[m] = lay_out_charts(meshes[m], charts_of[m], placements_of[m], atlas.pages[size_t(page)], page, next_chart);
    next_chart += uint32_t(charts_of[m].size());
  }
  atlas.chart_count = next_chart;
}

}  // namespace

Atlas ensure_lightmap_uvs(const std::vector<MeshView>& meshes, const AtlasOptions& options) {
  check_options(options);
  const auto start = std::chrono::steady_clock::now();
  UnwrapProgress progress(options.progress);

  Atlas atlas;
  atlas.meshes.resize(meshes.size());
  atlas.requested_density = options.texel_density;
  // Charts are packed into a page of this side, and each page is then trimmed to what it uses:
  // to a power of two, or with any_page_size to a multiple of 4. The automatic density is the
  // highest whose charts fit this page, so a power-of-two page is filled, not padded afterwards.
  const int page_size = options.any_page_size ? options.max_page_size : largest_power_of_two_at_most(options.max_page_size);
  double total_area = 0;
  for (const MeshView& m : meshes) total_area += world_area(m);
  atlas.surface_area = total_area;
  // The automatic density: the texel budget over the surface, or what fills one page if less
  // (guessed at 70% of the page, what the packer usually reaches, then searched).
  const float budget_density = float(std::sqrt(double(std::max<size_t>(1, options.automatic_texels)) / std::max(total_area, 1e-12)));
  const float guess = std::min(budget_density, float(page_size * std::sqrt(0.7 / std::max(total_area, 1e-12))));
  const float first_density = options.texel_density > 0 ? options.texel_density : guess;

  const KeptLayouts kept = keep_input_layouts(meshes, options, first_density, atlas.warnings);
  double seam_length = 0;
  const std::vector<Chart> charts = make_charts(meshes, kept.generate, options, first_density, &seam_length, progress);
  const PackedCharts packed = pack_at_chosen_density(charts, meshes.size(), options, page_size, first_density,
                                                     budget_density, progress, atlas.warnings);
  const float density = packed.density;
  atlas.density_lowered = options.texel_density > 0 && density < options.texel_density;
  if (atlas.density_lowered)
    atlas.warnings.push_back("the density was lowered from " + std::to_string(options.texel_density) + " to " +
                             std::to_string(density) + " texels/m to fit one page");
  atlas.texel_density = density;
  atlas.density_choice = density_choice(options, atlas, packed, budget_density, page_size);
  atlas.pages = packed.result.pages;
  // Trimming only takes empty texels off the top and right: charts keep their texel positions, and
  // lay_out_charts divides by the final page size.
  if (!options.any_page_size)
    for (AtlasPage& p : atlas.pages)
      p.width = smallest_power_of_two_at_least(p.width), p.height = smallest_power_of_two_at_least(p.height);
  for (uint32_t m : packed.result.downscaled_meshes)
    atlas.warnings.push_back("mesh '" + meshes[m].name + "' is too large for one " + std::to_string(page_size) +
                             "-texel page at " + std::to_string(density) + " texels/m and was scaled down");
  lay_out_meshes(meshes, charts, packed.result, kept, progress, atlas);
  progress.step(kPackingEnd, 1);
  atlas.stats = measure_atlas(meshes, atlas, options.padding);
  atlas.stats.seam_length = seam_length;
  atlas.stats.seconds = seconds_since(start);
  return atlas;
}

}  // namespace radbake
