#include "baker/transport/solve_radiosity.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "baker/sharing/byte_stream.h"
#include "base/errors.h"

namespace radbake {
namespace {

// The solve runs on Rgb, or on float when the plan found one channel enough; these make both read
// the same. Means are taken in double, so a grey Rgb and its float give bit-identical solves.
constexpr int channels(float) { return 1; }
constexpr int channels(Rgb) { return 3; }
float& channel(float& v, int) { return v; }
float& channel(Rgb& v, int c) { return v[c]; }
double mean(float v) { return v; }
double mean(Rgb v) { return (double(v.x) + v.y + v.z) / 3.0; }
double mean_abs(float v) { return std::fabs(double(v)); }
double mean_abs(Rgb v) { return (std::fabs(double(v.x)) + std::fabs(double(v.y)) + std::fabs(double(v.z))) / 3.0; }
float non_negative(float v) { return std::max(0.0f, v); }
Rgb non_negative(Rgb v) { return {non_negative(v.x), non_negative(v.y), non_negative(v.z)}; }

template <typename V>
double mean_power(V exitance, float area) { return mean(exitance) * area; }

// What the templates below read of the patches: area, reflectance and direct light in V.
template <typename V>
struct Problem {
  const Patches& patches;
  const PatchTransport& transport;
  const Enclosures& enclosures;
  std::vector<V> reflectance, direct;
  size_t size() const { return patches.size(); }
  float area(size_t p) const { return patches.area[p]; }
};

// What patch q would change by if it gathered now: rho_q (D_q + sum_p F_qp B_p) - B_q.
template <typename V>
V residual(const Problem<V>& pb, const IncomingRows& in, const std::vector<V>& b, size_t q) {
  V h = pb.direct[q];
  for (uint64_t k = in.start[q]; k < in.start[q + 1]; ++k) h += b[in.source[k]] * in.weight[k];
  return pb.reflectance[q] * h - b[q];
}

// A patch is open while more than the tolerance of its own light is still to come: unshot (or
// residual) exitance above tolerance times its exitance so far. Held per patch, not per enclosure:
// a room lit through a window shares its enclosure with the sunlit ground outside, whose input
// dwarfs the room's; held to that input, the room stopped with 4-6% of its light unshot, which
// the ambient term spread over the ground (bench/window_room at preview). Per patch, what is still
// to arrive anywhere is about the tolerance over (1 - rho) of what is there.
template <typename V>
bool open_patch(V still_to_come, V exitance, double tolerance) {
  return mean_abs(still_to_come) > tolerance * mean(exitance);
}

// Residual of the current estimate: what each patch would still change by. Returns the total
// power; `open` is the number of open patches.
template <typename V>
double residual_power(const Problem<V>& pb, const IncomingRows& in, const std::vector<V>& b, double tolerance,
                      size_t& open) {
  double total = 0;
  open = 0;
  for (size_t q = 0; q < pb.size(); ++q) {
    const V r = residual(pb, in, b, q);
    total += mean_abs(r) * pb.area(q);
    open += open_patch(r, b[q], tolerance);
  }
  return total;
}

// Cohen et al. 1988: the unshot light, spread evenly and bounced by the mean reflectance, per
// enclosure: light left unshot in one room cannot reach another.
template <typename V>
std::vector<V> ambient_exitance(const Problem<V>& pb, const std::vector<V>& unshot) {
  struct Sums {
    double area = 0, unshot_power[3] = {}, reflected[3] = {};
  };
  std::vector<Sums> sums(pb.enclosures.count);
  for (size_t p = 0; p < pb.size(); ++p) {
    Sums& e = sums[pb.enclosures.of_patch[p]];
    e.area += pb.area(p);
    V u = unshot[p], rho = pb.reflectance[p];
    for (int c = 0; c < channels(V{}); ++c) {
      e.unshot_power[c] += double(channel(u, c)) * pb.area(p);
      e.reflected[c] += double(channel(rho, c)) * pb.area(p);
    }
  }
  std::vector<V> ambient(pb.enclosures.count);
  for (size_t e = 0; e < ambient.size(); ++e) {
    if (sums[e].area <= 0) continue;
    for (int c = 0; c < channels(V{}); ++c) {
      double rho = std::min(sums[e].reflected[c] / sums[e].area, 0.999);
      channel(ambient[e], c) = float(sums[e].unshot_power[c] / sums[e].area / (1.0 - rho));
    }
  }
  return ambient;
}

// Adds the ambient term to `exitance`: each patch reflects its enclosure's ambient light.
template <typename V>
void add_ambient(const Problem<V>& pb, const std::vector<V>& ambient, std::vector<V>& exitance) {
  for (size_t p = 0; p < exitance.size(); ++p) exitance[p] += pb.reflectance[p] * ambient[pb.enclosures.of_patch[p]];
}

// Values in the caller's Rgb: one channel scales the light colour.
Rgb as_rgb(Rgb v, Rgb) { return v; }
Rgb as_rgb(float v, Rgb colour) { return colour * v; }
template <typename V>
std::vector<Rgb> as_rgb(const std::vector<V>& v, Rgb colour) {
  std::vector<Rgb> out(v.size());
  for (size_t p = 0; p < v.size(); ++p) out[p] = as_rgb(v[p], colour);
  return out;
}

// Shows the estimate so far to the observer, ambient term included when it is on.
template <typename V>
void show(const Problem<V>& pb, const SolveOptions& options, const SolveObserver& observer, size_t iteration,
          const std::vector<V>& exitance, const std::vector<V>& unshot) {
  if (observer.every == 0 || iteration % observer.every != 0) return;
  std::vector<V> estimate = exitance;
  if (options.ambient_term) add_ambient(pb, ambient_exitance(pb, unshot), estimate);
  observer.see(as_rgb(estimate, options.one_channel_colour), iteration);
}

struct Outcome {
  size_t iterations = 0;
  double unshot_power = 0;
  bool converged = false;  // every patch within the tolerance
};

// Saves the solver's state when it is time (SolveSaving), and gives back a saved one.
class SolveSaver {
 public:
  SolveSaver(const SolveSaving& s, int channels) : saving_(s), channels_(channels), last_(Clock::now()) {}

  std::optional<Bytes> saved() const {
    if (!saving_.store || !saving_.resume) return std::nullopt;
    std::optional<Bytes> state = saving_.store->load(saving_.key);
    if (state) {
      ByteReader in(*state);
      if (in.get<int32_t>() != channels_) throw InputError("the checkpoint's " + saving_.key + " solved other channels");
      state->erase(state->begin(), state->begin() + sizeof(int32_t));
    }
    return state;
  }
  bool due() const {
    return saving_.store && std::chrono::duration<double>(Clock::now() - last_).count() >= saving_.every_seconds;
  }
  template <typename Write>
  void save(const Write& write) {
    if (!saving_.store) return;
    ByteWriter out;
    out.put(int32_t(channels_));
    write(out);
    saving_.store->save(saving_.key, out.bytes());
    last_ = Clock::now();
  }

 private:
  using Clock = std::chrono::steady_clock;
  const SolveSaving& saving_;
  int channels_;
  Clock::time_point last_;
};

struct HeapEntry {
  double key;
  uint32_t patch;
  bool operator<(const HeapEntry& o) const { return key < o.key || (key == o.key && patch < o.patch); }
};

template <typename V>
Outcome shoot(const Problem<V>& pb, const std::vector<double>& input, const SolveOptions& options,
              const SolveObserver& observer, Progress& progress, SolveSaver& saver, std::vector<V>& exitance,
              std::vector<V>& unshot) {
  const size_t n = pb.size();
  const PatchTransport& t = pb.transport;
  const Enclosures& enclosures = pb.enclosures;
  // Max-heap of unshot power relative to the power brought into the patch's enclosure, with lazy
  // deletion: an entry is stale when its power is outdated.
  std::vector<HeapEntry> heap;
  auto push = [&](double key, uint32_t p) {
    heap.push_back({key, p});
    std::push_heap(heap.begin(), heap.end());
  };
  std::vector<double> power(n);
  auto relative = [&](uint32_t p) { return power[p] / input[enclosures.of_patch[p]]; };
  auto open = [&](uint32_t p) { return open_patch(unshot[p], exitance[p], options.tolerance); };
  auto count_open = [&] {
    size_t count = 0;
    for (size_t q = 0; q < n; ++q) count += open(uint32_t(q));
    return count;
  };
  Outcome out;
  size_t open_count = 0;
  auto write_state = [&](ByteWriter& w) {
    w.put(uint64_t(out.iterations));
    w.put(uint64_t(open_count));
    w.put_vector(exitance);
    w.put_vector(unshot);
    w.put_vector(power);
    w.put_vector(heap);
  };
  if (std::optional<Bytes> state = saver.saved()) {
    ByteReader in(*state);
    out.iterations = size_t(in.get<uint64_t>());
    open_count = size_t(in.get<uint64_t>());
    exitance = in.get_vector<V>();
    unshot = in.get_vector<V>();
    power = in.get_vector<double>();
    heap = in.get_vector<HeapEntry>();
    if (exitance.size() != n || unshot.size() != n || power.size() != n ||
        std::any_of(heap.begin(), heap.end(), [&](const HeapEntry& h) { return h.patch >= n; }))
      throw InputError("the checkpoint's radiosity solve is for other patches");
  } else {
    for (size_t p = 0; p < n; ++p) {
      unshot[p] = exitance[p] = pb.reflectance[p] * pb.direct[p];
      power[p] = mean_power(unshot[p], pb.area(p));
      if (power[p] > 0) push(relative(uint32_t(p)), uint32_t(p));
    }
    open_count = count_open();
  }
  size_t next_report = 0;
  while (open_count > 0 && !heap.empty() && out.iterations < options.max_iterations) {
    const HeapEntry top = heap.front();
    std::pop_heap(heap.begin(), heap.end());
    heap.pop_back();
    const uint32_t p = top.patch;
    if (top.key != relative(p) || !open(p)) continue;  // stale, or done until it receives more
    V shot = unshot[p] * pb.area(p);  // power leaving p, lm per channel
    unshot[p] = {};
    power[p] = 0;
    --open_count;
    for (uint64_t k = t.row_start[p]; k < t.row_start[p + 1]; ++k) {
      uint32_t q = t.target[k];  // in p's enclosure, by definition
      const bool was_open = open(q);
      V gain = pb.reflectance[q] * shot * (t.form_factor[k] / pb.area(q));
      exitance[q] += gain;
      unshot[q] += gain;
      power[q] += mean_power(gain, pb.area(q));
      open_count = open_count + open(q) - was_open;
      push(relative(q), q);
    }
    ++out.iterations;
    show(pb, options, observer, out.iterations, exitance, unshot);
    // Now and then: count the open patches afresh, a check on the count kept shot by shot, and
    // drop stale heap entries, so the heap stays linear in the patch count.
    if (out.iterations % 4096 == 0 || heap.size() > 8 * n + 1024) {
      heap.clear();
      for (size_t q = 0; q < n; ++q)
        if (power[q] > 0) push(relative(uint32_t(q)), uint32_t(q));
      open_count = count_open();
    }
    if (out.iterations >= next_report) {
      progress.advance(0);
      next_report = out.iterations + 1024;
      if (saver.due()) saver.save(write_state);
    }
  }
  saver.save(write_state);
  for (double v : power) out.unshot_power += v;
  out.converged = open_count == 0;
  return out;
}

// The residual per patch: the light each would still shoot, which the ambient term spreads.
template <typename V>
void residual_per_patch(const Problem<V>& pb, const IncomingRows& in, const std::vector<V>& b, std::vector<V>& unshot) {
  for (size_t q = 0; q < pb.size(); ++q) unshot[q] = non_negative(residual(pb, in, b, q));
}

template <typename V>
Outcome gather(const Problem<V>& pb, const SolveOptions& options,
               const SolveObserver& observer, Progress& progress, SolveSaver& saver, std::vector<V>& b,
               std::vector<V>& unshot) {
  const size_t n = pb.size();
  const IncomingRows in = incoming_rows(pb.patches, pb.transport);
  std::vector<V> next(n);
  Outcome out;
  auto write_state = [&](ByteWriter& w) {
    w.put(uint64_t(out.iterations));
    w.put_vector(b);
  };
  if (std::optional<Bytes> state = saver.saved()) {
    ByteReader r(*state);
    out.iterations = size_t(r.get<uint64_t>());
    b = r.get_vector<V>();
    if (b.size() != n) throw InputError("the checkpoint's radiosity solve is for other patches");
  }
  size_t open_count = 0;
  out.unshot_power = residual_power(pb, in, b, options.tolerance, open_count);
  while (open_count > 0 && out.iterations < options.max_iterations) {
    for (size_t q = 0; q < n; ++q) {
      V h = pb.direct[q];
      for (uint64_t k = in.start[q]; k < in.start[q + 1]; ++k) h += b[in.source[k]] * in.weight[k];
      // Gauss-Seidel uses each new value at once; Jacobi only after the sweep.
      (options.solver == Solver::GaussSeidel ? b : next)[q] = pb.reflectance[q] * h;
    }
    if (options.solver == Solver::Jacobi) b.swap(next);
    ++out.iterations;
    out.unshot_power = residual_power(pb, in, b, options.tolerance, open_count);
    if (observer.every > 0 && out.iterations % observer.every == 0) {
      residual_per_patch(pb, in, b, unshot);
      show(pb, options, observer, out.iterations, b, unshot);
    }
    progress.advance(0);
    if (saver.due()) saver.save(write_state);
  }
  saver.save(write_state);
  residual_per_patch(pb, in, b, unshot);
  out.converged = open_count == 0;
  return out;
}

// Powers are in V's own units until the end, where `colour` turns them into lm (mean of RGB).
template <typename V>
void solve(const Problem<V>& pb, const SolveOptions& options, Progress& progress, const SolveObserver& observer,
           const SolveSaving& saving, RadiositySolution& s) {
  const size_t n = pb.size();
  std::vector<double> input(pb.enclosures.count, 0.0);  // per enclosure
  double input_power = 0;
  for (size_t p = 0; p < n; ++p) {
    double power = mean_power(pb.direct[p], pb.area(p));
    input[pb.enclosures.of_patch[p]] += power;
    input_power += power;
  }
  std::vector<V> exitance(n), unshot(n);
  SolveSaver saver(saving, channels(V{}));
  Outcome out = options.solver == Solver::Shooting
                    ? shoot(pb, input, options, observer, progress, saver, exitance, unshot)
                    : gather(pb, options, observer, progress, saver, exitance, unshot);
  const Rgb colour = options.one_channel_colour;
  const double to_lumens = channels(V{}) == 1 ? mean(colour) : 1.0;
  s.iterations = out.iterations;
  s.channels = channels(V{});
  s.input_power = input_power * to_lumens;
  s.unshot_power = out.unshot_power * to_lumens;
  s.relative_unshot = input_power > 0 ? out.unshot_power / input_power : 0;
  s.converged = out.converged;
  if (options.ambient_term && n > 0) {
    const std::vector<V> ambient = ambient_exitance(pb, unshot);
    add_ambient(pb, ambient, exitance);
    double area = 0;  // the report's ambient: the enclosures' area-weighted mean
    V weighted{};
    for (size_t p = 0; p < n; ++p) {
      area += pb.area(p);
      weighted += ambient[pb.enclosures.of_patch[p]] * pb.area(p);
    }
    if (area > 0) s.ambient = as_rgb(weighted / float(area), colour);
  }
  s.exitance = as_rgb(exitance, colour);
}

}  // namespace

RadiositySolution solve_radiosity(const Patches& patches, const PatchTransport& transport,
                                  const std::vector<Rgb>& direct, const SolveOptions& options, Progress& progress,
                                  const SolveObserver& observer, const SolveSaving& saving) {
  const size_t n = patches.size();
  const Enclosures enclosures = find_enclosures(transport);
  RadiositySolution s;
  progress.begin("radiosity", 1);
  const Rgb colour = options.one_channel_colour;
  if (max_component(colour) > 0) {
    // Grey reflectance and light of one colour: every channel is the colour times one solve. The
    // light is read in the colour's largest channel, where the colour is exactly 1.
    int c = colour.x == 1 ? 0 : (colour.y == 1 ? 1 : 2);
    Problem<float> pb{patches, transport, enclosures, std::vector<float>(n), std::vector<float>(n)};
    for (size_t p = 0; p < n; ++p) {
      pb.reflectance[p] = patches.reflectance[p].x;
      pb.direct[p] = direct[p][c];
    }
    solve(pb, options, progress, observer, saving, s);
  } else {
    solve(Problem<Rgb>{patches, transport, enclosures, patches.reflectance, direct}, options, progress, observer, saving, s);
  }
  progress.end();
  return s;
}

}  // namespace radbake
