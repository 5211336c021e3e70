#include "baker/transport/interreflection.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "baker/sharing/byte_stream.h"
#include "baker/sharing/shared_stage.h"
#include "baker/transport/free_path.h"
#include "baker/transport/hemicube_transport.h"
#include "base/errors.h"
#include "base/progress.h"

namespace radbake {
namespace {

// Per patch: the area-weighted mean direct irradiance, and the power (lm, summed over RGB) leaving
// on the first bounce, which weights the ray-cast form factors.
void first_bounce(const Elements& elements, const Patches& patches, const std::vector<Rgb>& direct,
                  std::vector<Rgb>& patch_direct, std::vector<double>& power) {
  patch_direct.assign(patches.size(), Rgb{});
  power.assign(patches.size(), 0);
  for (size_t p = 0; p < patches.size(); ++p) {
    Rgb total{};
    for (uint32_t k = patches.first_member[p]; k < patches.first_member[p + 1]; ++k) {
      uint32_t i = patches.members[k];
      total += direct[i] * elements.area[i];
    }
    patch_direct[p] = patches.area[p] > 0 ? total / patches.area[p] : Rgb{};
    Rgb leaving = patches.emission[p] + patches.reflectance[p] * patch_direct[p];
    power[p] = double(sum(leaving)) * patches.area[p];
  }
}

void measure(const Elements& elements, const Patches& patches, const Surface& surface, const RayTracer& tracer,
             const FormFactorOptions& options, const std::vector<double>& power, const std::vector<uint32_t>& which,
             uint64_t seed, Progress& progress, MeasuredRows& rows) {
  if (options.method == FormFactorMethod::Hemicube)
    measure_hemicube_rows(elements, patches, surface, tracer, options.hemicube_resolution, which, seed, progress, rows);
  else
    measure_ray_cast_rows(elements, patches, surface, tracer, options.rays_per_patch, power, which, seed, progress,
                          rows);
}

// The rows of the patches in `which`, measured across the team in chunks of a few patches; the
// first process gets them all in `rows`, the others keep none.
void measure_shared(const Elements& elements, const Patches& patches, const Surface& surface, const RayTracer& tracer,
                    const FormFactorOptions& options, const std::vector<double>& power,
                    const std::vector<uint32_t>& which, uint64_t seed, const std::string& stage_name, Team& team,
                    const Sharing& sharing, Progress& progress, MeasuredRows& rows) {
  const std::vector<size_t> starts = chunk_starts(which.size(), which.size() / 256, 1, 1, {});
  MeasuredRows scratch;
  scratch.resize(patches.size());
  Progress quiet;
  SharedStage stage;
  stage.name = stage_name;
  stage.chunks = starts.size() - 1;
  stage.compute = [&](size_t chunk) {
    const std::vector<uint32_t> some(which.begin() + std::ptrdiff_t(starts[chunk]),
                                     which.begin() + std::ptrdiff_t(starts[chunk + 1]));
    measure(elements, patches, surface, tracer, options, power, some, seed, quiet, scratch);
    ByteWriter out;
    for (uint32_t p : some) {
      out.put(uint64_t(scratch.rows[p].size()));
      for (auto [q, f] : scratch.rows[p]) {
        out.put(q);
        out.put(f);
      }
      out.put(scratch.escaped[p]);
      out.put(scratch.lost[p]);
      out.put(scratch.rays[p]);
      out.put(scratch.fates[p]);
      MeasuredRow().swap(scratch.rows[p]);
    }
    return out.bytes();
  };
  stage.take = [&](size_t chunk, const Bytes& result) {
    ByteReader in(result);
    for (size_t w = starts[chunk]; w < starts[chunk + 1]; ++w) {
      const uint32_t p = which[w];
      const uint64_t count = in.get<uint64_t>();
      if (count > patches.size()) throw TruncatedBytes();
      rows.rows[p].resize(count);
      for (auto& [q, f] : rows.rows[p]) {
        q = in.get<uint32_t>();
        f = in.get<float>();
        if (q >= patches.size()) throw TruncatedBytes();
      }
      rows.escaped[p] = in.get<float>();
      rows.lost[p] = in.get<float>();
      rows.rays[p] = in.get<uint32_t>();
      rows.fates[p] = in.get<RayFates>();
    }
  };
  run_shared_stage(stage, team, sharing.store, sharing.resume, tracer, progress);
}

// The first process's solution, and whether to split, to the others: they split their patches
// the same way and gather from the same exitance.
void share_solution(Team& team, RadiositySolution& solution, std::vector<uint8_t>& split) {
  ByteWriter out;
  if (team.first()) {
    out.put_vector(solution.exitance);
    out.put_vector(split);
  }
  team.broadcast_from_first("radiosity", out.bytes());
  if (team.first()) return;
  ByteReader in(out.bytes());
  solution.exitance = in.get_vector<Rgb>();
  split = in.get_vector<uint8_t>();
}

// A share of a carried row that landed on a patch split since: it goes to the pieces once their
// own rows are measured.
struct PendingShare {
  uint32_t from;    // fine patch whose row it is
  uint32_t target;  // coarse patch it landed on
  float share;
};

// Rows of the patches that were not split carry over to the finer patches; their shares landing on
// split patches wait in `pending`. The pieces of every coarse patch are returned in `pieces`, and
// the fine patches whose rows are still to be measured in `fresh`.
MeasuredRows carry_rows(const Patches& coarse, const Patches& fine, const std::vector<uint8_t>& split,
                        const MeasuredRows& rows, std::vector<uint32_t>& fresh,
                        std::vector<std::vector<uint32_t>>& pieces, std::vector<PendingShare>& pending) {
  const size_t n = coarse.size();
  std::vector<uint32_t> same(n, UINT32_MAX);
  pieces.assign(n, {});
  for (size_t p = 0; p < n; ++p) {
    for (uint32_t k = coarse.first_member[p]; k < coarse.first_member[p + 1]; ++k) {
      uint32_t piece = fine.patch_of_element[coarse.members[k]];
      if (std::find(pieces[p].begin(), pieces[p].end(), piece) == pieces[p].end()) pieces[p].push_back(piece);
    }
    if (!split[p] && pieces[p].size() == 1) same[p] = pieces[p][0];
  }
  MeasuredRows out;
  out.resize(fine.size());
  fresh.clear();
  pending.clear();
  for (size_t p = 0; p < n; ++p) {
    if (same[p] == UINT32_MAX) {
      fresh.insert(fresh.end(), pieces[p].begin(), pieces[p].end());
      continue;
    }
    const uint32_t to = same[p];
    auto& row = out.rows[to];
    for (auto [q, f] : rows.rows[p]) {
      if (same[q] != UINT32_MAX) row.emplace_back(same[q], f);
      else pending.push_back({to, q, f});
    }
    std::sort(row.begin(), row.end());
    out.escaped[to] = rows.escaped[p];
    out.lost[to] = rows.lost[p];
    out.rays[to] = rows.rays[p];
    out.fates[to] = rows.fates[p];
  }
  std::sort(fresh.begin(), fresh.end());
  return out;
}

// A carried share landing on a split patch goes to its pieces as their own measured rows say they
// see the row's patch back: by reciprocity A_p F_pr = A_r F_rp. Shared by area instead, a floor
// patch would go on seeing the pieces of a ceiling patch that a lamp hides from it, and light
// would pass through the lamp. Pieces whose rays found nothing of p share it by area.
void resolve_pending(const Patches& fine, const std::vector<std::vector<uint32_t>>& pieces,
                     const std::vector<PendingShare>& pending, MeasuredRows& rows) {
  std::vector<uint32_t> touched;
  std::vector<double> weight;
  for (const PendingShare& s : pending) {
    const std::vector<uint32_t>& to = pieces[s.target];
    weight.assign(to.size(), 0.0);
    double total = 0, area = 0;
    for (size_t k = 0; k < to.size(); ++k) {
      area += fine.area[to[k]];
      const auto& row = rows.rows[to[k]];
      auto at = std::lower_bound(row.begin(), row.end(), std::make_pair(s.from, 0.0f),
                                 [](const auto& a, const auto& b) { return a.first < b.first; });
      if (at != row.end() && at->first == s.from) total += weight[k] = double(fine.area[to[k]]) * at->second;
    }
    auto& row = rows.rows[s.from];
    for (size_t k = 0; k < to.size(); ++k) {
      double part = total > 0 ? weight[k] / total : fine.area[to[k]] / area;
      if (part > 0) row.emplace_back(to[k], float(s.share * part));
    }
    touched.push_back(s.from);
  }
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  for (uint32_t p : touched) std::sort(rows.rows[p].begin(), rows.rows[p].end());
}

}  // namespace

std::vector<Rgb> gathered_irradiance(const Patches& patches, const PatchTransport& transport,
                                     const std::vector<Rgb>& exitance) {
  // Rows say where each patch's light lands, so each receiver's share comes by scattering:
  // E_q += B_p A_p F_pq / A_q.
  std::vector<Rgb> irradiance(patches.size());
  for (size_t p = 0; p < patches.size(); ++p)
    for (uint64_t k = transport.row_start[p]; k < transport.row_start[p + 1]; ++k) {
      const uint32_t q = transport.target[k];
      irradiance[q] += exitance[p] * (transport.form_factor[k] * patches.area[p] / patches.area[q]);
    }
  return irradiance;
}

std::vector<uint8_t> patches_to_split(const Elements& e, const Surface& surface, const Patches& patches,
                                      const std::vector<Rgb>& exitance, double tolerance) {
  const size_t n = patches.size();
  std::vector<double> radiosity(n);
  double weighted = 0, area = 0;
  for (size_t p = 0; p < n; ++p) {
    radiosity[p] = double(sum(patches.emission[p] + exitance[p])) / 3.0;
    weighted += radiosity[p] * patches.area[p];
    area += patches.area[p];
  }
  const double dark = area > 0 ? 0.01 * weighted / area : 0;
  std::vector<uint8_t> split(n, 0);
  for (size_t i = 0; i < e.size(); ++i) {
    const uint32_t p = patches.patch_of_element[i];
    if (p == UINT32_MAX) continue;
    const uint32_t width = uint32_t(surface.pages[e.page[i]].width);
    for (auto [bit, step] : {std::pair<uint8_t, uint32_t>{kJoinsRight, 1}, {kJoinsDown, width}}) {
      if (!(e.flags[i] & bit)) continue;
      int32_t j = e.element_at[e.page[i]][e.texel[i] + step];
      if (j < 0) continue;
      const uint32_t q = patches.patch_of_element[size_t(j)];
      if (q == UINT32_MAX || q == p) continue;
      const double brighter = std::max(radiosity[p], radiosity[q]);
      if (brighter > dark && std::fabs(radiosity[p] - radiosity[q]) > tolerance * brighter) {
        split[p] |= patches.side[p] > 1;
        split[q] |= patches.side[q] > 1;
      }
    }
  }
  return split;
}

Interreflection solve_interreflection(const Elements& elements, const Surface& surface, const RayTracer& tracer,
                                      const std::vector<Rgb>& direct, const InterreflectionOptions& options,
                                      Progress& progress, const InterreflectionObserver& observer, const Sharing& sharing) {
  const uint64_t seed = options.seed;
  const SubdivisionOptions& subdivision = options.subdivision;
  SoloTeam alone;
  Team& team = sharing.team ? *sharing.team : alone;
  Interreflection out;
  SolveObserver solve_observer{observer.every, [&](const std::vector<Rgb>& exitance, size_t iteration) {
                                 observer.see(out.patches, out.transport, exitance, iteration);
                               }};
  PatchOptions patching = options.patches;
  if (patching.block_size <= 0 && patching.mean_free_path_m <= 0) {
    const double free_path = mean_free_path(elements, surface, tracer, seed);
    if (std::isfinite(free_path)) patching.mean_free_path_m = free_path;
  }
  out.mean_free_path_m = patching.mean_free_path_m;
  out.patches = build_patches(elements, surface, patching);
  std::vector<Rgb> patch_direct;
  std::vector<double> power;
  first_bounce(elements, out.patches, direct, patch_direct, power);
  MeasuredRows rows;
  rows.resize(out.patches.size());
  std::vector<uint32_t> which = all_patches(out.patches.size());
  std::vector<std::vector<uint32_t>> pieces;
  std::vector<PendingShare> pending;
  for (int round = 0;; ++round) {
    const std::string suffix = round == 0 ? "" : ", round " + std::to_string(round + 1);
    auto start = std::chrono::steady_clock::now();
    measure_shared(elements, out.patches, surface, tracer, options.form_factors, power, which, seed, "form factors" + suffix,
                   team, sharing, progress, rows);
    if (round == 0 && sharing.stop_after == StopAfter::FormFactors) throw StoppedEarly("form factors");
    // Only another round reads the measured rows again: the last hands them over to be freed.
    const bool last_round = subdivision.tolerance <= 0 || round >= subdivision.max_rounds;
    if (team.first()) {
      resolve_pending(out.patches, pieces, pending, rows);
      out.transport = balanced_transport(out.patches, last_round ? std::move(rows) : MeasuredRows(rows));
    }
    out.form_factor_seconds += seconds_since(start);
    start = std::chrono::steady_clock::now();
    std::vector<uint8_t> split;
    if (team.first()) {
      SolveSaving saving{sharing.store, "radiosity" + suffix, sharing.resume, sharing.solve_save_seconds};
      out.solution = solve_radiosity(out.patches, out.transport, patch_direct, options.solve, progress, solve_observer, saving);
      if (!last_round) split = patches_to_split(elements, surface, out.patches, out.solution.exitance, subdivision.tolerance);
    }
    share_solution(team, out.solution, split);
    out.solve_seconds += seconds_since(start);
    out.rounds.push_back({out.patches.size(), 0});
    if (last_round) break;

    out.rounds.back().split = size_t(std::count(split.begin(), split.end(), uint8_t(1)));
    if (out.rounds.back().split == 0) break;
    Patches finer = split_patches(elements, surface, out.patches, split);
    rows = carry_rows(out.patches, finer, split, rows, which, pieces, pending);
    out.patches = std::move(finer);
    first_bounce(elements, out.patches, direct, patch_direct, power);
  }
  return out;
}

}  // namespace radbake
