// Internal to uv/: the stages between a mesh and a packed atlas.
#pragma once

#include <chrono>
#include <cstdint>
#include <vector>

#include "base/math.h"
#include "base/progress.h"
#include "uv/atlas_page.h"

namespace radbake {

struct HalfEdgeMesh;  // uv/half_edge_mesh.h

// AtlasOptions::progress for the steps below. Each step (a mesh's charts, a packing attempt)
// spans part of the whole unwrap; at() reports the fraction of the step done, poll() only asks
// whether to stop. Both throw Cancelled when the callback says so, and call it at most every 50 ms,
// so they can sit in loops over faces.
class UnwrapProgress {
 public:
  explicit UnwrapProgress(const ProgressCallback& callback) : callback_(callback) {}
  void step(double from, double to) {
    from_ = from;
    to_ = to;
    at(0);
  }
  void at(double fraction_of_step);
  void poll() { at(fraction_); }

 private:
  const ProgressCallback& callback_;
  double from_ = 0, to_ = 1, fraction_ = 0;
  std::chrono::steady_clock::time_point last_call_{};
};

// A chart flattened into its own plane, before it is scaled to texels and packed.
struct Chart {
  uint32_t mesh = 0;
  std::vector<uint32_t> triangles;  // input triangle indices
  std::vector<Vec2> corner_uv;      // three per triangle in the input's corner order, metres
  Vec2 extent;                      // metres; the minimum corner is at (0, 0)
};

struct ChartOptions {
  float max_normal_deviation_degrees = 50;  // a chart's faces stay within this cone of its normal
  float hard_edge_degrees = 40;             // edges folding more than this are always seams
  float small_chart_area = 0;               // m^2; charts smaller than this merge into a neighbour
  float sliver_width = 0;                   // m; flattened charts thinner than this join a neighbour
  float texel_size = 0;                     // m; pieces thinner than this join a neighbour across any edge
                                            // when the two flatten together without more stretch
  // A curved chart holds at most this share of its mesh's area, so no chart wraps round a shape
  // (the top of a torus is a ring of normals all within any cone); flat charts are not capped.
  float max_curved_chart_fraction = 1.0f / 12;
};

// Groups faces into charts: seeds grown all at once over edges that are not hard, keeping each
// chart's normals in a cone, with the seeds moved to their charts' middles a few times (Lloyd
// relaxation, as xatlas does) so charts come out round; then tiny charts fold into a neighbour. Returns the
// chart of each OpenMesh face (-1 for none) and sets chart_count.
std::vector<int> grow_charts(const HalfEdgeMesh& mesh, const ChartOptions& options, int* chart_count,
                             UnwrapProgress& progress);

// Flattens each chart: planar ones by projection, curved ones by least-squares conformal maps
// (Levy et al. 2002) solved with Eigen. A chart whose map flips or overlaps itself is split in two
// until each piece maps cleanly. Then slivers and specks (options.sliver_width, small_chart_area)
// join a neighbour across an edge that is not hard, where the two flatten together cleanly and
// stretch no more than apart.
std::vector<Chart> flatten_charts(const HalfEdgeMesh& mesh, const std::vector<int>& chart_of_face, int chart_count,
                                  uint32_t mesh_index, const ChartOptions& options, bool may_rotate,
                                  UnwrapProgress& progress);

struct ChartPlacement {
  int page = -1;
  int x = 0, y = 0;       // texel offset of the chart's minimum corner
  float scale = 1;        // texels per metre for this chart
  int quarter_turns = 0;  // rotation by 90 degrees counter-clockwise, 0..3, about the minimum corner
};

struct PackResult {
  std::vector<ChartPlacement> placements;  // parallel to the charts
  std::vector<AtlasPage> pages;             // none when one page was asked for and is too small
  std::vector<uint32_t> downscaled_meshes;  // meshes shrunk to fit one page
  // With PackGoal::OnePageOrNothing, when the charts did not fit: the share of their area (by
  // bounding rectangle) that was placed before one did not, 0..1.
  double placed_share = 1;
};

enum class PackGoal {
  AsManyPagesAsNeeded,  // a mesh too large for a page at this density is shrunk, and reported
  OnePageOrNothing,     // stop as soon as it is clear that one page does not hold everything at this density
};

// Packs charts into pages of at most page_size texels, keeping all charts of one mesh on one page.
// Pages are trimmed to what they use, to a multiple of 4.
// Each chart is rasterised to the texels it covers and goes, largest first, to the lowest, then
// leftmost, spot where none of them comes closer than `padding` texels to another chart's: inside
// a ring-shaped chart, under an overhang, anywhere there is room (uv/chart_packing.cpp).
PackResult pack_charts(const std::vector<Chart>& charts, size_t mesh_count, float texel_density, AtlasPage page_size,
                       int padding, bool may_rotate, PackGoal goal, UnwrapProgress& progress);

// Where corner k of chart triangle i lands in the page, in texels.
Vec2 placed_corner(const Chart& chart, const ChartPlacement& at, size_t corner);

}  // namespace radbake
