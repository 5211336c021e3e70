// What each skip of the effect plan saves: every scene is baked as planned and with that one
// choice undone (the full simulation of it), and the table shows the stage it touches, the time
// (best of three runs), the rays cast and the largest difference between the two results.
//
//   plan_bench [--markdown FILE] [--density N]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "baker/pipeline/bake.h"
#include "support/scene_builders.h"

namespace radbake {
namespace {

struct Skip {
  const char* effect;
  const char* scene_name;
  Scene scene;
  const char* stage;                // the stage whose time the skip changes, as the table names it
  std::vector<std::string> timed;   // the report's stage times that make it up
  std::function<void(EffectPlan&)> undo;
};

struct Run {
  double stage_seconds = 1e30, total_seconds = 1e30;
  uint64_t rays = 0;
  BakeResult result;
};

Run best_of_three(const Scene& scene, const Atlas& atlas, const EffectPlan& plan, const std::vector<std::string>& timed) {
  Run best;
  for (int k = 0; k < 3; ++k) {
    auto start = std::chrono::steady_clock::now();
    BakeResult r = bake(scene, atlas, {}, plan);
    double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    double in_stage = 0;
    for (const StageTime& t : r.report.stage_times)
      if (std::find(timed.begin(), timed.end(), t.stage) != timed.end()) in_stage += t.seconds;
    best.stage_seconds = std::min(best.stage_seconds, in_stage);
    best.total_seconds = std::min(best.total_seconds, total);
    best.rays = r.report.rays;
    best.result = std::move(r);
  }
  return best;
}

double worst_relative_difference(const BakeResult& a, const BakeResult& b) {
  double worst = 0;
  for (size_t i = 0; i < a.irradiance.size(); ++i) {
    if (!a.elements.valid(i)) continue;
    for (int c = 0; c < 3; ++c) {
      double x = a.irradiance[i][c], y = b.irradiance[i][c];
      worst = std::max(worst, std::fabs(x - y) / std::max({std::fabs(x), std::fabs(y), 1e-3}));
    }
  }
  return worst;
}

int run(int argc, char** argv) {
  std::string markdown;
  float density = 32;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--markdown" && i + 1 < argc) markdown = argv[++i];
    else if (a == "--density" && i + 1 < argc) density = std::stof(argv[++i]);
    else throw std::runtime_error("usage: plan_bench [--markdown FILE] [--density N]");
  }
  Skip skips[] = {
      {"interreflection (all black)", "black room with a block", test::lit_room(0, {1, 1, 1}, true),
       "interreflection", {"patches", "form factors", "radiosity", "final gather"},
       [](EffectPlan& p) { p.interreflection = true; }},
      {"two of three colour channels", "grey room with a block", test::lit_room(0.6f, {1, 1, 1}, true), "radiosity",
       {"radiosity"}, [](EffectPlan& p) { p.one_channel = false; }},
      {"texture sampling (no textures)", "grey room with a block", test::lit_room(0.6f, {1, 1, 1}, true), "elements",
       {"elements"}, [](EffectPlan& p) { p.exhaustive = true; }},
      {"shadow rays of lights out of reach", "floor, block, 3 lights", test::floor_with_lights_out_of_reach(),
       "direct light", {"direct light"}, [](EffectPlan& p) {
         std::fill(p.light_traced.begin(), p.light_traced.end(), 1);
         p.exhaustive = true;
       }},
      {"shadow rays (convex enclosure)", "room with a glowing ceiling", test::glowing_ceiling_room(),
       "direct light", {"direct light"}, [](EffectPlan& p) { p.shadow_rays = true; }},
  };
  std::string table =
      "| skipped | scene | stage | stage s planned | stage s full | bake s planned | bake s full | rays planned | "
      "rays full | largest difference |\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (Skip& skip : skips) {
    Atlas atlas = test::unwrap(skip.scene, {density, 1024, 2});
    EffectPlan planned = plan_effects(skip.scene), full = planned;
    skip.undo(full);
    Run a = best_of_three(skip.scene, atlas, planned, skip.timed);
    Run b = best_of_three(skip.scene, atlas, full, skip.timed);
    char row[512];
    std::snprintf(row, sizeof row, "| %s | %s | %s | %.3f | %.3f | %.2f | %.2f | %.3g | %.3g | %.1e |\n", skip.effect,
                  skip.scene_name, skip.stage, a.stage_seconds, b.stage_seconds, a.total_seconds, b.total_seconds,
                  double(a.rays), double(b.rays), worst_relative_difference(a.result, b.result));
    table += row;
    std::fprintf(stderr, "%s", row);
  }
  std::printf("%s", table.c_str());
  if (!markdown.empty()) {
    std::ofstream out(markdown);
    out << "# What the effect plan saves\n\n"
           "Made by `./dev bench` (`build/plan_bench --markdown docs/bench/plan.md`): each scene baked as\n"
           "planned and with that one skip undone, at "
        << density
        << " texels per metre, default bake options. Times are the best of three runs on this machine\n"
           "(2 cores, shared); the largest difference is over every texel and channel, relative, against\n"
           "a floor of 0.001 lux.\n\n"
        << table;
  }
  return 0;
}

}  // namespace
}  // namespace radbake

int main(int argc, char** argv) {
  try {
    return radbake::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "plan_bench: error: %s\n", e.what());
    return 2;
  }
}
