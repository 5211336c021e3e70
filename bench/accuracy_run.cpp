// One run of the accuracy study (bench/accuracy drives it, one process per run so that the peak
// memory is the run's own): bakes a study scene with radbake's own bake options and prints one
// JSON line with the bake's time, peak memory, and its error against the reference.
//
//   accuracy_run SCENE [radbake bake options] [--reference FILE | --write-reference FILE]
//                [--contact-distance METRES] [--dump-texels CSV] [--cornell-regions]
//
// SCENE is furnace, emitter-over-floor or point-light-over-floor (built here, with closed-form
// irradiance per texel) or a glTF file, whose reference is a bake written earlier with
// --write-reference (the same density and page size give the same texels): a path-traced one
// (--method pathtrace) also writes its texels' standard errors, and runs against it then report
// their error with the reference's noise taken out. --dump-texels writes each compared texel's
// element index, position, normal, area, instance (the report's surface), lux and reference lux
// (and its noise) for looking at regions;
// --cornell-regions adds the Cornell box's contact regions (tests/support/cornell_regions.h).
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "baker/direct/direct_light.h"
#include "baker/finish/lightmap_difference.h"
#include "baker/pipeline/bake.h"
#include "baker/surface/back_faces.h"
#include "baker/surface/material_sampler.h"
#include "baker/surface/ray_tracer.h"
#include "baker/surface/sampling.h"
#include "baker/surface/surface.h"
#include "cli/command_line.h"
#include "io/gltf/gltf_loader.h"
#include "support/cornell_regions.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

struct StudyScene {
  Scene scene;
  // Closed-form irradiance (lux) at a sample point with its normal; empty when there is none.
  std::function<Rgb(Vec3 position, Vec3 normal)> exact;
};

// A closed 1 m box, every face emitting 100 cd/m2 with reflectance 0.8: irradiance
// pi * 100 / (1 - 0.8) lux everywhere (every direction sees the same radiosity).
StudyScene furnace() {
  StudyScene s;
  const float luminance = 100, rho = 0.8f;
  int m = test::add_material(s.scene, {rho, rho, rho}, {1, 1, 1}, luminance);
  test::add_box(s.scene, {0, 0, 0}, {1, 1, 1}, true, m);
  const float e = kExitancePerEmissiveUnit * luminance / (1 - rho);
  s.exact = [e](Vec3, Vec3) { return Rgb{e, e, e}; };
  return s;
}

// A 1 m square of luminance 1000 cd/m2 one metre above a black 4 m floor, facing it: the parallel
// plates case; irradiance pi L F(point -> square) by Lambert's contour integral.
StudyScene emitter_over_floor() {
  StudyScene s;
  int black = test::add_material(s.scene, {0, 0, 0});
  const float luminance = 1000;
  int lamp = test::add_material(s.scene, {0, 0, 0}, {1, 1, 1}, luminance);
  test::add_quad(s.scene, {-2, 0, 2}, {4, 0, 0}, {0, 0, -4}, black);
  test::add_quad(s.scene, {-0.5f, 1, -0.5f}, {1, 0, 0}, {0, 0, 1}, lamp);
  s.exact = [luminance](Vec3 x, Vec3 n) {
    if (n.y < 0.5f) return Rgb{};  // the lamp's own texels: the black floor sends nothing back
    const Vec3 square[4] = {{-0.5f, 1, -0.5f}, {0.5f, 1, -0.5f}, {0.5f, 1, 0.5f}, {-0.5f, 1, 0.5f}};
    float e = float(kExitancePerEmissiveUnit * luminance * polygon_form_factor(x, n, square, 4));
    return Rgb{e, e, e};
  };
  return s;
}

// A 1000 cd point light 1 m above a black 4 m floor: E = I h / d^3.
StudyScene point_light_over_floor() {
  StudyScene s;
  int black = test::add_material(s.scene, {0, 0, 0});
  test::add_quad(s.scene, {-2, 0, 2}, {4, 0, 0}, {0, 0, -4}, black);
  Light bulb;
  bulb.intensity = 1000;
  bulb.position = {0, 1, 0};
  s.scene.lights.push_back(bulb);
  s.exact = [](Vec3 x, Vec3) {
    Vec3 d = Vec3{0, 1, 0} - x;
    float r = length(d), e = 1000 * d.y / (r * r * r);
    return Rgb{e, e, e};
  };
  return s;
}

StudyScene study_scene(const std::string& name) {
  if (name == "furnace") return furnace();
  if (name == "emitter-over-floor") return emitter_over_floor();
  if (name == "point-light-over-floor") return point_light_over_floor();
  StudyScene s;
  s.scene = load_gltf(name).scene;
  return s;
}

// User and system CPU time of this process so far, seconds: a bake's cost over all its threads.
double cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

size_t peak_memory_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return size_t(usage.ru_maxrss) * 1024;
}

// A reference's values per element, as --write-reference wrote them: irradiance, and beside it
// (".noise") a path-traced reference's standard errors.
template <typename T>
void write_per_texel(const std::string& path, const std::vector<T>& values) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(values.data()), std::streamsize(values.size() * sizeof(T)));
}

template <typename T>
std::vector<T> read_per_texel(const std::string& path, size_t count) {
  std::ifstream in(path, std::ios::binary);
  std::vector<T> values(count);
  in.read(reinterpret_cast<char*>(values.data()), std::streamsize(count * sizeof(T)));
  if (!in || in.peek() != EOF) throw std::runtime_error(path + " is not a reference for these texels");
  return values;
}

// Contact texels: those with another surface within `distance` metres above them (a block's foot,
// the floor beside it, the corners of walls), found with 64 rays over each texel's hemisphere.
// Where a lightmapper's near-field errors are.
std::vector<uint8_t> contact_texels(const Scene& scene, const Atlas& atlas, const Elements& e, float distance) {
  const Surface surface = build_surface(scene, atlas);
  const RayTracer tracer(surface);
  std::vector<uint8_t> contact(e.size(), 0);
  constexpr uint32_t kRays = 64;
  for (size_t i = 0; i < e.size(); ++i) {
    if (!e.valid(i)) continue;
    const Vec3 ng = surface.normal[e.triangle[i]], origin = e.position[i] + ng * e.offset[i];
    for (uint32_t k = 0; k < kRays && !contact[i]; ++k)
      contact[i] = tracer.occluded(origin, hemisphere_direction(e.normal[i], ng, cmj_sample(k, kRays, 1)), 0.0f, distance);
  }
  return contact;
}

int run(int argc, char** argv) {
  if (argc < 2) throw std::runtime_error("usage: accuracy_run SCENE [bake options] [--reference F | --write-reference F]");
  std::vector<std::string> args = {"bake", argv[1], "-o", "unused"};
  std::string reference, write_reference, dump_texels;
  float contact_distance = 0.02f;
  bool cornell_regions = false;
  for (int i = 2; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--cornell-regions") {
      cornell_regions = true;
      continue;
    }
    if (a == "--contact-distance" && i + 1 < argc) {
      contact_distance = std::stof(argv[++i]);
      continue;
    }
    if (a == "--dump-texels" && i + 1 < argc) {
      dump_texels = argv[++i];
      continue;
    }
    if ((a == "--reference" || a == "--write-reference") && i + 1 < argc) (a == "--reference" ? reference : write_reference) = argv[++i];
    else args.push_back(a);
  }
  CommandLine cl = parse_command_line(args);
  StudyScene study = study_scene(argv[1]);
  add_back_faces(study.scene);
  Atlas atlas = ensure_lightmap_uvs(mesh_views(study.scene), cl.bake.atlas);

  auto start = std::chrono::steady_clock::now();
  const double cpu_start = cpu_seconds();
  BakeOptions options = cl.bake.bake;
  options.sky = daylight_sky(cl.bake.daylight).light;
  BakeResult result = bake(study.scene, atlas, options);
  const double cpu = cpu_seconds() - cpu_start;
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const Elements& e = result.elements;
  if (!write_reference.empty()) {
    write_per_texel(write_reference, result.irradiance);
    if (!result.standard_error.empty()) write_per_texel(write_reference + ".noise", result.standard_error);
  }
  std::vector<Rgb> exact;
  std::vector<float> reference_noise;
  if (!reference.empty()) {
    exact = read_per_texel<Rgb>(reference, e.size());
    if (std::ifstream(reference + ".noise")) reference_noise = read_per_texel<float>(reference + ".noise", e.size());
  }
  else if (study.exact) {
    exact.resize(e.size());
    for (size_t i = 0; i < e.size(); ++i) exact[i] = study.exact(e.position[i], e.normal[i]);
  }
  double solve_seconds = 0;
  for (const StageTime& t : result.report.stage_times)
    if (t.stage == "radiosity") solve_seconds = t.seconds;
  double total = 0;
  for (size_t i = 0; i < e.size(); ++i)
    if (e.valid(i)) total += sum(result.irradiance[i]) / 3.0;
  nlohmann::ordered_json line = {{"scene", argv[1]}, {"seconds", seconds}, {"cpu_seconds", cpu}, {"solve_seconds", solve_seconds}, {"peak_memory_bytes", peak_memory_bytes()},
                                 {"texels", result.report.valid_elements}, {"patches", result.report.patches},
                                 {"rays", result.report.rays}, {"energy_error", result.report.balance.relative_error},
                                 {"mean_lux", total / double(std::max<size_t>(1, result.report.valid_elements))}};
  if (!exact.empty()) {
    // Undilated pages: texels no element covers are black in both and not compared.
    const Surface surface = build_surface(study.scene, atlas);
    LightmapDifference d = compare_lightmaps(compose_pages(e, exact, surface.pages, false),
                                             compose_pages(e, result.irradiance, surface.pages, false), {});
    line["rmse"] = d.all.rmse;
    line["p99"] = d.all.p99;
    line["reference_mean_lux"] = d.all.reference_level;
    const std::vector<uint8_t> contact = contact_texels(study.scene, atlas, e, contact_distance);
    double contact_sum = 0, contact_reference = 0, contact_squared = 0, contact_noise = 0;
    size_t contact_count = 0;
    for (size_t i = 0; i < e.size(); ++i) {
      if (!contact[i]) continue;
      const double a = sum(exact[i]) / 3.0, b = sum(result.irradiance[i]) / 3.0;
      contact_sum += b;
      contact_reference += a;
      contact_squared += (b - a) * (b - a);
      if (!reference_noise.empty()) contact_noise += double(reference_noise[i]) * reference_noise[i];
      ++contact_count;
    }
    if (contact_count > 0) {
      const double level = contact_reference / double(contact_count);
      line["contact_texels"] = contact_count;
      line["contact_bias"] = contact_sum / contact_reference - 1;
      line["contact_rmse_noise_removed"] =
          std::sqrt(std::max(0.0, contact_squared - contact_noise) / double(contact_count)) / level;
    }
    if (cornell_regions) {
      line["regions"] = nlohmann::json::array();
      for (const test::RegionBias& r : test::cornell_region_biases(e, result.irradiance, exact, reference_noise))
        line["regions"].push_back({{"region", r.name}, {"texels", r.texels}, {"bias", r.bias}, {"noise", r.noise}});
    }
    if (!dump_texels.empty()) {
      std::ofstream out(dump_texels);
      out << "element,x,y,z,nx,ny,nz,area_m2,instance,lux,reference_lux,reference_noise_lux\n";
      for (size_t i = 0; i < e.size(); ++i)
        if (e.valid(i))
          out << i << ',' << e.position[i].x << ',' << e.position[i].y << ',' << e.position[i].z << ',' << e.normal[i].x << ','
              << e.normal[i].y << ',' << e.normal[i].z << ',' << e.area[i] << ',' << surface.instance[e.triangle[i]]
              << ',' << sum(result.irradiance[i]) / 3 << ','
              << sum(exact[i]) / 3 << ',' << (reference_noise.empty() ? 0.0f : reference_noise[i]) << '\n';
    }
    if (!reference_noise.empty()) {
      // The reference's own noise adds to the squared error of every texel in expectation (it is
      // independent of the bake's): taken out, what is left is the bake's error against the
      // exact answer. Texels are those the comparison took (valid elements).
      double squared = 0;
      size_t n = 0;
      for (size_t i = 0; i < e.size(); ++i)
        if (e.valid(i)) squared += double(reference_noise[i]) * reference_noise[i], ++n;
      const double noise = n ? std::sqrt(squared / double(n)) / d.all.reference_level : 0;
      line["reference_noise"] = noise;
      line["rmse_noise_removed"] = std::sqrt(std::max(0.0, d.all.rmse * d.all.rmse - noise * noise));
    }
  }
  std::printf("%s\n", line.dump().c_str());
  return 0;
}

}  // namespace
}  // namespace radbake

int main(int argc, char** argv) {
  try {
    return radbake::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "accuracy_run: error: %s\n", e.what());
    return 2;
  }
}
