#include "baker/solve_radiosity.h"

#include <algorithm>
#include <cmath>
#include <queue>

namespace radbake {
namespace {

double mean_power(Rgb exitance, float area) { return (double(exitance.x) + exitance.y + exitance.z) / 3.0 * area; }

// Gathering needs, for each receiver q, the sources p with F_pq weighted by A_p / A_q.
struct Incoming {
  std::vector<uint64_t> start;
  std::vector<uint32_t> source;
  std::vector<float> weight;
};

Incoming transpose(const Patches& patches, const PatchTransport& t) {
  const size_t n = patches.size();
  Incoming in;
  in.start.assign(n + 1, 0);
  for (uint32_t q : t.target) ++in.start[q + 1];
  for (size_t q = 0; q < n; ++q) in.start[q + 1] += in.start[q];
  in.source.resize(t.target.size());
  in.weight.resize(t.target.size());
  std::vector<uint64_t> fill(in.start.begin(), in.start.end() - 1);
  for (size_t p = 0; p < n; ++p)
    for (uint64_t k = t.row_start[p]; k < t.row_start[p + 1]; ++k) {
      uint32_t q = t.target[k];
      in.source[fill[q]] = uint32_t(p);
      in.weight[fill[q]++] = t.form_factor[k] * patches.area[p] / patches.area[q];
    }
  return in;
}

// Residual of the current estimate: what each patch would still change by, as power, summed per
// enclosure into `per_enclosure`; returns the total.
double residual_power(const Patches& patches, const Incoming& in, const Enclosures& enclosures,
                      const std::vector<Rgb>& direct, const std::vector<Rgb>& b, std::vector<double>& per_enclosure) {
  per_enclosure.assign(enclosures.count, 0.0);
  double total = 0;
  for (size_t q = 0; q < patches.size(); ++q) {
    Rgb h = direct[q];
    for (uint64_t k = in.start[q]; k < in.start[q + 1]; ++k) h += b[in.source[k]] * in.weight[k];
    Rgb r = patches.reflectance[q] * h - b[q];
    double power = (std::fabs(double(r.x)) + std::fabs(double(r.y)) + std::fabs(double(r.z))) / 3.0 * patches.area[q];
    per_enclosure[enclosures.of_patch[q]] += power;
    total += power;
  }
  return total;
}

// Enclosures whose unshot (or residual) power is still above the tolerance times the power the
// direct light brings into them. Each is held to its own input: a dim room beside a bright one
// is solved as finely as if it were alone.
size_t open_enclosures(const std::vector<double>& unshot, const std::vector<double>& input, double tolerance) {
  size_t open = 0;
  for (size_t e = 0; e < unshot.size(); ++e) open += unshot[e] > tolerance * input[e];
  return open;
}

// Cohen et al. 1988: the unshot light, spread evenly and bounced by the mean reflectance, per
// enclosure: light left unshot in one room cannot reach another.
std::vector<Rgb> ambient_exitance(const Patches& patches, const Enclosures& enclosures, const std::vector<Rgb>& unshot) {
  struct Sums {
    double area = 0, unshot_power[3] = {}, reflected[3] = {};
  };
  std::vector<Sums> sums(enclosures.count);
  for (size_t p = 0; p < patches.size(); ++p) {
    Sums& e = sums[enclosures.of_patch[p]];
    e.area += patches.area[p];
    for (int c = 0; c < 3; ++c) {
      e.unshot_power[c] += double(unshot[p][c]) * patches.area[p];
      e.reflected[c] += double(patches.reflectance[p][c]) * patches.area[p];
    }
  }
  std::vector<Rgb> ambient(enclosures.count);
  for (size_t e = 0; e < enclosures.count; ++e) {
    if (sums[e].area <= 0) continue;
    for (int c = 0; c < 3; ++c) {
      double rho = std::min(sums[e].reflected[c] / sums[e].area, 0.999);
      ambient[e][c] = float(sums[e].unshot_power[c] / sums[e].area / (1.0 - rho));
    }
  }
  return ambient;
}

// Adds the ambient term to `exitance`: each patch reflects its enclosure's ambient light.
void add_ambient(const Patches& patches, const Enclosures& enclosures, const std::vector<Rgb>& ambient,
                 std::vector<Rgb>& exitance) {
  for (size_t p = 0; p < exitance.size(); ++p)
    exitance[p] += patches.reflectance[p] * ambient[enclosures.of_patch[p]];
}

// Shows the estimate so far to the observer, ambient term included when it is on.
void show(const Patches& patches, const Enclosures& enclosures, const SolveOptions& options,
          const SolveObserver& observer, const RadiositySolution& s, const std::vector<Rgb>& unshot) {
  if (observer.every == 0 || s.iterations % observer.every != 0) return;
  std::vector<Rgb> estimate = s.exitance;
  if (options.ambient_term) add_ambient(patches, enclosures, ambient_exitance(patches, enclosures, unshot), estimate);
  observer.see(estimate, s.iterations);
}

void shoot(const Patches& patches, const PatchTransport& t, const Enclosures& enclosures,
           const std::vector<double>& input, const std::vector<Rgb>& direct, const SolveOptions& options,
           const SolveObserver& observer, Progress& progress, RadiositySolution& s, std::vector<Rgb>& unshot) {
  const size_t n = patches.size();
  // Max-heap of unshot power relative to the power brought into the patch's enclosure, with lazy
  // deletion: an entry is stale when its power is outdated.
  using Entry = std::pair<double, uint32_t>;
  std::priority_queue<Entry> heap;
  std::vector<double> power(n), enclosure_unshot(enclosures.count, 0.0);
  auto relative = [&](uint32_t p) { return power[p] / input[enclosures.of_patch[p]]; };
  for (size_t p = 0; p < n; ++p) {
    unshot[p] = s.exitance[p] = patches.reflectance[p] * direct[p];
    power[p] = mean_power(unshot[p], patches.area[p]);
    enclosure_unshot[enclosures.of_patch[p]] += power[p];
    if (power[p] > 0) heap.push({relative(uint32_t(p)), uint32_t(p)});
  }
  auto open = [&](uint32_t e) { return enclosure_unshot[e] > options.tolerance * input[e]; };
  size_t open_count = open_enclosures(enclosure_unshot, input, options.tolerance);
  size_t next_report = 0;
  while (open_count > 0 && !heap.empty() && s.iterations < options.max_iterations) {
    auto [key, p] = heap.top();
    heap.pop();
    const uint32_t e = enclosures.of_patch[p];
    if (key != relative(p) || !open(e)) continue;  // stale, or its enclosure is done
    Rgb shot = unshot[p] * patches.area[p];  // power leaving p, lm per channel
    unshot[p] = {};
    enclosure_unshot[e] -= power[p];
    power[p] = 0;
    for (uint64_t k = t.row_start[p]; k < t.row_start[p + 1]; ++k) {
      uint32_t q = t.target[k];  // in p's enclosure, by definition
      Rgb gain = patches.reflectance[q] * shot * (t.form_factor[k] / patches.area[q]);
      s.exitance[q] += gain;
      unshot[q] += gain;
      double added = mean_power(gain, patches.area[q]);
      power[q] += added;
      enclosure_unshot[e] += added;
      heap.push({relative(q), q});
    }
    open_count -= !open(e);
    ++s.iterations;
    show(patches, enclosures, options, observer, s, unshot);
    // Now and then: recompute the sums, so floating-point drift stays out of the stopping test,
    // and drop stale heap entries, so the heap stays linear in the patch count.
    if (s.iterations % 4096 == 0 || heap.size() > 8 * n + 1024) {
      enclosure_unshot.assign(enclosures.count, 0.0);
      heap = {};
      for (size_t q = 0; q < n; ++q) {
        enclosure_unshot[enclosures.of_patch[q]] += power[q];
        if (power[q] > 0) heap.push({relative(uint32_t(q)), uint32_t(q)});
      }
      open_count = open_enclosures(enclosure_unshot, input, options.tolerance);
    }
    if (s.iterations >= next_report) {
      progress.advance(0);
      next_report = s.iterations + 1024;
    }
  }
  s.unshot_power = 0;
  for (double v : power) s.unshot_power += v;
  s.converged = open_count == 0;
}

// The residual per patch: the light each would still shoot, which the ambient term spreads.
void residual_per_patch(const Patches& patches, const Incoming& in, const std::vector<Rgb>& direct,
                        const std::vector<Rgb>& b, std::vector<Rgb>& unshot) {
  for (size_t q = 0; q < patches.size(); ++q) {
    Rgb h = direct[q];
    for (uint64_t k = in.start[q]; k < in.start[q + 1]; ++k) h += b[in.source[k]] * in.weight[k];
    Rgb r = patches.reflectance[q] * h - b[q];
    unshot[q] = {std::max(0.0f, r.x), std::max(0.0f, r.y), std::max(0.0f, r.z)};
  }
}

void gather(const Patches& patches, const PatchTransport& t, const Enclosures& enclosures,
            const std::vector<double>& input, const std::vector<Rgb>& direct, const SolveOptions& options,
            const SolveObserver& observer, Progress& progress, RadiositySolution& s, std::vector<Rgb>& unshot) {
  const size_t n = patches.size();
  Incoming in = transpose(patches, t);
  std::vector<Rgb>& b = s.exitance;
  for (size_t q = 0; q < n; ++q) b[q] = {};
  std::vector<Rgb> next(n);
  std::vector<double> residual;
  s.unshot_power = residual_power(patches, in, enclosures, direct, b, residual);
  size_t open_count = open_enclosures(residual, input, options.tolerance);
  while (open_count > 0 && s.iterations < options.max_iterations) {
    for (size_t q = 0; q < n; ++q) {
      Rgb h = direct[q];
      for (uint64_t k = in.start[q]; k < in.start[q + 1]; ++k) h += b[in.source[k]] * in.weight[k];
      // Gauss-Seidel uses each new value at once; Jacobi only after the sweep.
      (options.solver == Solver::GaussSeidel ? b : next)[q] = patches.reflectance[q] * h;
    }
    if (options.solver == Solver::Jacobi) b.swap(next);
    ++s.iterations;
    s.unshot_power = residual_power(patches, in, enclosures, direct, b, residual);
    open_count = open_enclosures(residual, input, options.tolerance);
    if (observer.every > 0 && s.iterations % observer.every == 0) {
      residual_per_patch(patches, in, direct, b, unshot);
      show(patches, enclosures, options, observer, s, unshot);
    }
    progress.advance(0);
  }
  residual_per_patch(patches, in, direct, b, unshot);
  s.converged = open_count == 0;
}

}  // namespace

RadiositySolution solve_radiosity(const Patches& patches, const PatchTransport& transport,
                                  const std::vector<Rgb>& direct, const SolveOptions& options, Progress& progress,
                                  const SolveObserver& observer) {
  const size_t n = patches.size();
  const Enclosures enclosures = find_enclosures(transport);
  RadiositySolution s;
  s.exitance.assign(n, Rgb{});
  std::vector<double> input(enclosures.count, 0.0);  // per enclosure
  for (size_t p = 0; p < n; ++p) {
    double power = mean_power(direct[p], patches.area[p]);
    input[enclosures.of_patch[p]] += power;
    s.input_power += power;
  }
  std::vector<Rgb> unshot(n);
  progress.begin("radiosity", 1);
  if (options.solver == Solver::Shooting)
    shoot(patches, transport, enclosures, input, direct, options, observer, progress, s, unshot);
  else
    gather(patches, transport, enclosures, input, direct, options, observer, progress, s, unshot);
  s.relative_unshot = s.input_power > 0 ? s.unshot_power / s.input_power : 0;

  if (options.ambient_term && n > 0) {
    const std::vector<Rgb> ambient = ambient_exitance(patches, enclosures, unshot);
    add_ambient(patches, enclosures, ambient, s.exitance);
    double area = 0, weighted[3] = {};
    for (size_t p = 0; p < n; ++p) {
      area += patches.area[p];
      for (int c = 0; c < 3; ++c) weighted[c] += double(ambient[enclosures.of_patch[p]][c]) * patches.area[p];
    }
    if (area > 0) s.ambient = {float(weighted[0] / area), float(weighted[1] / area), float(weighted[2] / area)};
  }
  progress.end();
  return s;
}

}  // namespace radbake
