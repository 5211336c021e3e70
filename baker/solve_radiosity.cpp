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

// Residual of the current estimate: what each patch would still change by, as power.
double residual_power(const Patches& patches, const Incoming& in, const std::vector<Rgb>& direct,
                      const std::vector<Rgb>& b) {
  double total = 0;
  for (size_t q = 0; q < patches.size(); ++q) {
    Rgb h = direct[q];
    for (uint64_t k = in.start[q]; k < in.start[q + 1]; ++k) h += b[in.source[k]] * in.weight[k];
    Rgb r = patches.reflectance[q] * h - b[q];
    total += (std::fabs(double(r.x)) + std::fabs(double(r.y)) + std::fabs(double(r.z))) / 3.0 * patches.area[q];
  }
  return total;
}

// Cohen et al. 1988: the unshot light, spread evenly and bounced by the mean reflectance.
Rgb ambient_exitance(const Patches& patches, const std::vector<Rgb>& unshot) {
  double area = 0;
  Rgb unshot_power{}, reflected{}, ambient{};
  for (size_t p = 0; p < patches.size(); ++p) {
    area += patches.area[p];
    unshot_power += unshot[p] * patches.area[p];
    reflected += patches.reflectance[p] * patches.area[p];
  }
  if (area <= 0) return ambient;
  for (int c = 0; c < 3; ++c) {
    double rho = std::min(double(reflected[c]) / area, 0.999);
    ambient[c] = float(unshot_power[c] / area / (1.0 - rho));
  }
  return ambient;
}

// Shows the estimate so far to the observer, ambient term included when it is on.
void show(const Patches& patches, const SolveOptions& options, const SolveObserver& observer,
          const RadiositySolution& s, const std::vector<Rgb>& unshot) {
  if (observer.every == 0 || s.iterations % observer.every != 0) return;
  std::vector<Rgb> estimate = s.exitance;
  if (options.ambient_term) {
    Rgb ambient = ambient_exitance(patches, unshot);
    for (size_t p = 0; p < estimate.size(); ++p) estimate[p] += patches.reflectance[p] * ambient;
  }
  observer.see(estimate, s.iterations);
}

void shoot(const Patches& patches, const PatchTransport& t, const std::vector<Rgb>& direct,
           const SolveOptions& options, const SolveObserver& observer, Progress& progress, RadiositySolution& s,
           std::vector<Rgb>& unshot) {
  const size_t n = patches.size();
  // Max-heap of unshot power with lazy deletion: an entry is stale when its power is outdated.
  using Entry = std::pair<double, uint32_t>;
  std::priority_queue<Entry> heap;
  std::vector<double> power(n);
  double total_unshot = 0;
  for (size_t p = 0; p < n; ++p) {
    unshot[p] = s.exitance[p] = patches.reflectance[p] * direct[p];
    power[p] = mean_power(unshot[p], patches.area[p]);
    total_unshot += power[p];
    heap.push({power[p], uint32_t(p)});
  }
  const double target = options.tolerance * s.input_power;
  size_t next_report = 0;
  while (total_unshot > target && !heap.empty() && s.iterations < options.max_iterations) {
    auto [pw, p] = heap.top();
    heap.pop();
    if (pw != power[p]) continue;
    Rgb shot = unshot[p] * patches.area[p];  // power leaving p, lm per channel
    unshot[p] = {};
    total_unshot -= power[p];
    power[p] = 0;
    for (uint64_t k = t.row_start[p]; k < t.row_start[p + 1]; ++k) {
      uint32_t q = t.target[k];
      Rgb gain = patches.reflectance[q] * shot * (t.form_factor[k] / patches.area[q]);
      s.exitance[q] += gain;
      unshot[q] += gain;
      double added = mean_power(gain, patches.area[q]);
      power[q] += added;
      total_unshot += added;
      heap.push({power[q], q});
    }
    ++s.iterations;
    show(patches, options, observer, s, unshot);
    // Now and then: recompute the sum, so floating-point drift stays out of the stopping test,
    // and drop stale heap entries, so the heap stays linear in the patch count.
    if (s.iterations % 4096 == 0 || heap.size() > 8 * n + 1024) {
      total_unshot = 0;
      heap = {};
      for (size_t q = 0; q < n; ++q) {
        total_unshot += power[q];
        if (power[q] > 0) heap.push({power[q], uint32_t(q)});
      }
    }
    if (s.iterations >= next_report) {
      progress.advance(0);
      next_report = s.iterations + 1024;
    }
  }
  s.unshot_power = 0;
  for (double v : power) s.unshot_power += v;
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

void gather(const Patches& patches, const PatchTransport& t, const std::vector<Rgb>& direct,
            const SolveOptions& options, const SolveObserver& observer, Progress& progress, RadiositySolution& s,
            std::vector<Rgb>& unshot) {
  const size_t n = patches.size();
  Incoming in = transpose(patches, t);
  std::vector<Rgb>& b = s.exitance;
  for (size_t q = 0; q < n; ++q) b[q] = {};
  std::vector<Rgb> next(n);
  const double target = options.tolerance * s.input_power;
  s.unshot_power = residual_power(patches, in, direct, b);
  while (s.unshot_power > target && s.iterations < options.max_iterations) {
    for (size_t q = 0; q < n; ++q) {
      Rgb h = direct[q];
      for (uint64_t k = in.start[q]; k < in.start[q + 1]; ++k) h += b[in.source[k]] * in.weight[k];
      // Gauss-Seidel uses each new value at once; Jacobi only after the sweep.
      (options.solver == Solver::GaussSeidel ? b : next)[q] = patches.reflectance[q] * h;
    }
    if (options.solver == Solver::Jacobi) b.swap(next);
    ++s.iterations;
    s.unshot_power = residual_power(patches, in, direct, b);
    if (observer.every > 0 && s.iterations % observer.every == 0) {
      residual_per_patch(patches, in, direct, b, unshot);
      show(patches, options, observer, s, unshot);
    }
    progress.advance(0);
  }
  residual_per_patch(patches, in, direct, b, unshot);
}

}  // namespace

RadiositySolution solve_radiosity(const Patches& patches, const PatchTransport& transport,
                                  const std::vector<Rgb>& direct, const SolveOptions& options, Progress& progress,
                                  const SolveObserver& observer) {
  const size_t n = patches.size();
  RadiositySolution s;
  s.exitance.assign(n, Rgb{});
  for (size_t p = 0; p < n; ++p) s.input_power += mean_power(direct[p], patches.area[p]);
  std::vector<Rgb> unshot(n);
  progress.begin("radiosity", 1);
  if (options.solver == Solver::Shooting) shoot(patches, transport, direct, options, observer, progress, s, unshot);
  else gather(patches, transport, direct, options, observer, progress, s, unshot);
  s.relative_unshot = s.input_power > 0 ? s.unshot_power / s.input_power : 0;
  s.converged = s.unshot_power <= options.tolerance * s.input_power;

  if (options.ambient_term && n > 0) {
    s.ambient = ambient_exitance(patches, unshot);
    for (size_t p = 0; p < n; ++p) s.exitance[p] += patches.reflectance[p] * s.ambient;
  }
  progress.end();
  return s;
}

}  // namespace radbake
