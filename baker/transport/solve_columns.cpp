#include "baker/transport/solve_columns.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace radbake {
namespace {

// Columns swept together. A block's row is 128 bytes, and its exitance for the classroom's 1,547
// patches (200 kB) stays in cache through a sweep while the transport streams past once.
constexpr size_t kBlock = 32;
using Row = std::array<float, kBlock>;

// One channel's reflectance, and what the ambient term needs of it.
struct Channel {
  std::vector<float> reflectance;  // per patch
  // Per patch q: sum over its sources p of weight_qp rho_p, what q gathers per lux of its
  // enclosure's ambient light (every source of q shares q's enclosure).
  std::vector<float> ambient_gathered;
  // Per enclosure: 1 / (area (1 - mean reflectance)), what turns unshot power into ambient light
  // (solve_radiosity's Cohen et al. 1988 estimate).
  std::vector<double> ambient_per_unshot_power;
};

Channel channel_of(const Patches& patches, const IncomingRows& in, const Enclosures& enclosures, int c) {
  const size_t n = patches.size();
  Channel out;
  out.reflectance.resize(n);
  for (size_t p = 0; p < n; ++p) out.reflectance[p] = patches.reflectance[p][c];
  out.ambient_gathered.assign(n, 0.0f);
  for (size_t q = 0; q < n; ++q)
    for (uint64_t k = in.start[q]; k < in.start[q + 1]; ++k)
      out.ambient_gathered[q] += in.weight[k] * out.reflectance[in.source[k]];
  std::vector<double> area(enclosures.count, 0.0), reflected(enclosures.count, 0.0);
  for (size_t p = 0; p < n; ++p) {
    area[enclosures.of_patch[p]] += patches.area[p];
    reflected[enclosures.of_patch[p]] += double(out.reflectance[p]) * patches.area[p];
  }
  out.ambient_per_unshot_power.assign(enclosures.count, 0.0);
  for (size_t e = 0; e < enclosures.count; ++e)
    if (area[e] > 0) out.ambient_per_unshot_power[e] = 1.0 / (area[e] * (1.0 - std::min(reflected[e] / area[e], 0.999)));
  return out;
}

struct BlockOutcome {
  size_t sweeps = 0;
  bool converged = false;
};

// Adds to `h` what patch q gathers from the block's exitance `b`.
void gather_row(const IncomingRows& in, const std::vector<Row>& b, size_t q, Row& h) {
  for (uint64_t k = in.start[q]; k < in.start[q + 1]; ++k) {
    const float w = in.weight[k];
    const Row& source = b[in.source[k]];
    for (size_t j = 0; j < kBlock; ++j) h[j] += w * source[j];
  }
}

// Columns [first, first + width) in channel c: swept until no patch changes by more than the
// tolerance of its exitance, then the residual (what each would still change by) spread as the
// ambient term; what each patch gathers goes into channel c of `gathered` (every channel when
// `grey`).
BlockOutcome solve_block(const Patches& patches, const IncomingRows& in, const Enclosures& enclosures,
                         const Channel& channel, const std::vector<float>& direct, size_t columns, size_t first,
                         size_t width, const SolveOptions& options, int c, bool grey, std::vector<Rgb>& gathered) {
  const size_t n = patches.size();
  const std::vector<float>& rho = channel.reflectance;
  std::vector<Row> d(n, Row{}), b(n, Row{});
  for (size_t q = 0; q < n; ++q)
    for (size_t j = 0; j < width; ++j) {
      d[q][j] = direct[q * columns + first + j];
      b[q][j] = rho[q] * d[q][j];
    }
  const float tolerance = float(options.tolerance);
  BlockOutcome out;
  while (out.sweeps < options.max_iterations) {
    float worst = 0;  // largest change beyond the tolerance of the new exitance; > 0: still open
    for (size_t q = 0; q < n; ++q) {
      Row h = d[q];
      gather_row(in, b, q, h);
      for (size_t j = 0; j < kBlock; ++j) {
        const float next = rho[q] * h[j];
        worst = std::max(worst, std::fabs(next - b[q][j]) - tolerance * next);
        b[q][j] = next;  // Gauss-Seidel: used at once by the patches after q
      }
    }
    ++out.sweeps;
    if (!(worst > 0)) {
      out.converged = true;
      break;
    }
  }
  std::vector<Row> g(n, Row{});
  std::vector<std::array<double, kBlock>> unshot_power(enclosures.count, std::array<double, kBlock>{});
  for (size_t q = 0; q < n; ++q) {
    gather_row(in, b, q, g[q]);
    for (size_t j = 0; j < kBlock; ++j)
      unshot_power[enclosures.of_patch[q]][j] +=
          double(std::max(0.0f, rho[q] * (d[q][j] + g[q][j]) - b[q][j])) * patches.area[q];
  }
  for (size_t q = 0; q < n; ++q) {
    const uint32_t e = enclosures.of_patch[q];
    for (size_t j = 0; j < width; ++j) {
      float v = g[q][j];
      if (options.ambient_term)
        v += float(unshot_power[e][j] * channel.ambient_per_unshot_power[e]) * channel.ambient_gathered[q];
      Rgb& out_value = gathered[q * columns + first + j];
      if (grey) out_value = Rgb{v, v, v};
      else out_value[c] = v;
    }
  }
  return out;
}

}  // namespace

ColumnSolution solve_columns(const Patches& patches, const PatchTransport& transport, const std::vector<float>& direct,
                             size_t columns, const SolveOptions& options) {
  const size_t n = patches.size();
  const IncomingRows in = incoming_rows(patches, transport);
  const Enclosures enclosures = find_enclosures(transport);
  const bool grey = std::all_of(patches.reflectance.begin(), patches.reflectance.end(),
                                [](Rgb r) { return r.x == r.y && r.y == r.z; });
  const int channels = grey ? 1 : 3;
  std::vector<Channel> channel;
  for (int c = 0; c < channels; ++c) channel.push_back(channel_of(patches, in, enclosures, c));
  ColumnSolution out;
  out.columns = columns;
  out.gathered.assign(n * columns, Rgb{});
  const size_t blocks = (columns + kBlock - 1) / kBlock;
  std::vector<BlockOutcome> outcome(blocks * channels);
  tbb::parallel_for(size_t(0), outcome.size(), [&](size_t task) {
    const int c = int(task / blocks);
    const size_t first = (task % blocks) * kBlock;
    outcome[task] = solve_block(patches, in, enclosures, channel[c], direct, columns, first,
                                std::min(kBlock, columns - first), options, c, grey, out.gathered);
  });
  out.converged = true;
  for (const BlockOutcome& o : outcome) out.converged = out.converged && o.converged;
  return out;
}

}  // namespace radbake
