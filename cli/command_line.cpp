#include "cli/command_line.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "baker/pipeline/quality_presets.h"
#include "base/errors.h"

// The field a row sets, for a const target (the echo) and a mutable one (the parser) alike.
#define FIELD(path) [](auto& c) -> auto& { return c.path; }

namespace radbake {
namespace {

// ---- Rows of more than one command ----

// What a scene file may make radbake read and hold; `bake` and `uv` share them.
OptionGroup<LoadOptions> reading_group() {
  using L = LoadOptions;
  Option<L> memory = row<L>("--max-memory", "SIZE|auto",
      "refuse a scene whose bake is estimated to need more memory; SIZE in bytes or with K, M, G (x1024)");
  memory.default_note = "half the physical memory";
  memory.set = [](L& l, const std::string& v) {
    if (v == "auto") {
      l.max_memory_bytes = 0;
      return;
    }
    const std::string units = "KMGT";
    const size_t unit = v.empty() ? std::string::npos : units.find(char(std::toupper(static_cast<unsigned char>(v.back()))));
    const double scale = unit == std::string::npos ? 1 : std::pow(1024.0, double(unit + 1));
    const std::string digits = unit == std::string::npos ? v : v.substr(0, v.size() - 1);
    l.max_memory_bytes = uint64_t(parse_number("--max-memory", digits, 1, 1e15 / scale) * scale);
  };
  memory.echo = [](const L& l) { return l.max_memory_bytes ? std::to_string(l.max_memory_bytes) : std::string("auto"); };
  Option<L> triangles = number<L>("--max-triangles", "N", 1, double(1L << 40), "triangles", FIELD(max_triangles),
                                  "refuse a scene with more triangles after instancing");
  triangles.echo = [](const L& l) { return std::to_string(l.max_triangles); };
  return {"reading options (bake and uv):",
          {flag<L>("--allow-external-files", true, FIELD(allow_external_files),
                   "read images and buffers whose URIs lead out of the scene's folder (absolute paths, ../, links); "
                   "refused by default"),
           memory, triangles}};
}

// The atlas options `bake` and `uv` share.
OptionGroup<AtlasOptions> atlas_group() {
  using A = AtlasOptions;
  Option<A> density = number_or_auto<A>("--density", "N|auto", 1e-6, 1e9, "texels/m", FIELD(texel_density),
                                        "lightmap texels per metre");
  density.default_note =
      "about --texels texels over the scene's surface, fewer if they do not fit one page; report.json says which";
  Option<A> texels = number<A>("--texels", "N", 16, double(1L << 32), "texels", FIELD(automatic_texels),
                               "the automatic density's budget, texels over the whole surface");
  texels.default_note = "a few seconds at the default preset on 2 cores";
  Option<A> page = number<A>("--max-page-size", "N", 16, 16384, "texels", FIELD(max_page_size),
                             "texels per page side; generated pages are powers of two, at most the largest power of "
                             "two not above N");
  Option<A> uvs = choice<A>("--lightmap-uvs", "WHAT",
                            std::vector<std::pair<std::string, InputUvPolicy>>{{"keep-valid", InputUvPolicy::KeepValid},
                                                                               {"keep", InputUvPolicy::KeepAll},
                                                                               {"generate", InputUvPolicy::Generate}},
                            FIELD(input_uvs),
                            "keep-valid: use the scene's TEXCOORD_1 where valid, generate elsewhere; keep: use it even "
                            "where invalid; generate: always generate");
  uvs.default_note = "what was invalid is reported";
  return {"lightmap UV options (bake and uv):",
          {density, texels, page,
           flag<A>("--any-page-size", true, FIELD(any_page_size),
                   "generated pages as tight as their charts (sides a multiple of 4, up to --max-page-size) instead "
                   "of powers of two"),
           number<A>("--padding", "N", 0, 64, "texels", FIELD(padding), "empty texels between charts"),
           flag<A>("--fit-page", true, FIELD(fit_one_page),
                   "with --density: lower it until everything fits one page (reported); without, a scene too large "
                   "for one page gets more pages"),
           flag<A>("--no-rotate", false, FIELD(rotate_charts),
                   "keep charts upright (no turning to their tightest box or by 90 degrees)"),
           uvs,
           number<A>("--chart-angle", "DEG", 1, 89, "degrees", FIELD(max_chart_normal_deviation),
                     "faces of one chart stay within this cone of normals")}};
}

// ---- bake and merge ----

using B = BakeCommand;

template <class T>
Option<B> run_option(Option<T> o) {
  o.affects = Affects::Run;
  return o;
}

// --pages K/N and --texel-range K/N: a slice of the final gather.
Option<B> slice_option(const char* name, GatherSlice::By by, const char* help) {
  Option<B> o;
  o.name = name;
  o.value = "K/N";
  o.help = help;
  o.affects = Affects::Run;
  o.show_default = false;
  o.set = [name = std::string(name), by](B& b, const std::string& v) {
    int k = 0, n = 0;
    char extra = 0;
    if (std::sscanf(v.c_str(), "%d/%d%c", &k, &n, &extra) != 2 || n < 1 || n > 100000 || k < 1 || k > n)
      throw UsageError("option " + name + " needs K/N with 1 <= K <= N (slice K of N)" + got(v));
    if (b.bake.sharing.slice.by != GatherSlice::By::Everything) throw UsageError("give one of --pages and --texel-range");
    b.bake.sharing.slice = {by, k - 1, n};
  };
  o.echo = [by](const B& b) {
    const GatherSlice& s = b.bake.sharing.slice;
    return s.by == by ? std::to_string(s.index + 1) + "/" + std::to_string(s.count) : std::string("none");
  };
  return o;
}

OptionGroup<B> bake_group() {
  Option<B> quality = row<B>("--quality", "NAME",
      "draft | preview | production | reference: ray counts, tolerance and patch size together "
      "(docs/accuracy.md has each preset's measured error and time); options given as well override it");
  quality.first = true;
  quality.set = [](B& b, const std::string& v) {
    const std::vector<std::string> presets = quality_preset_names();
    if (std::find(presets.begin(), presets.end(), v) == presets.end())
      throw UsageError("option --quality must be " + one_of(presets) + got(v));
    b.quality = v;
    apply_quality_preset(v, b.bake);
  };
  quality.echo = [](const B& b) { return b.quality; };

  Option<B> hemicube = number<B>("--hemicube-resolution", "N", 2, 4096, "pixels", FIELD(bake.form_factors.hemicube_resolution),
                                 "hemicube: pixels per side of the top face, even");
  hemicube.set = [set = hemicube.set](B& b, const std::string& v) {
    if (parse_integer("--hemicube-resolution", v, 2, 4096) % 2)
      throw UsageError("option --hemicube-resolution must be even" + got(v));
    set(b, v);
  };
  Option<B> patch_size = number<B>("--patch-size", "N", 0, 16384, "texels", FIELD(bake.patches.block_size),
                                   "patch side in texels, a power of two, 0 = auto");
  patch_size.set = [](B& b, const std::string& v) {
    const long size = parse_integer("--patch-size", v, 0, 16384);
    if (size & (size - 1)) throw UsageError("option --patch-size must be 0 (auto) or a power of two up to 16384" + got(v));
    b.bake.patches.block_size = int(size);
  };
  patch_size.echo = [](const B& b) {
    return b.bake.patches.block_size > 0 ? echo_number(b.bake.patches.block_size) : std::string("auto");
  };
  Option<B> glazing = number<B>("--glazing-transmittance", "X", 0, 1, "", FIELD(bake.glazing.transmittance),
                                "visible transmittance of glazing along its normal (KHR_materials_transmission, read as "
                                "a thin pane: the factor is the share of light meeting the glazing; obliquely it passes "
                                "less, as a clear pane of the material's KHR_materials_ior), for materials without "
                                "extras.visible_transmittance of their own");
  glazing.echo = [](const B& b) {
    return b.bake.glazing.transmittance >= 0 ? echo_number(b.bake.glazing.transmittance) : std::string("clear pane");
  };
  glazing.default_note = "0.92 for glass; double glazing is about 0.8, solar control 0.4-0.7";
  Option<B> glazing_model = choice<B>(
      "--glazing-model", "NAME",
      std::vector<std::pair<std::string, GlazingModel>>{{"fresnel-absorbing", GlazingModel::FresnelAbsorbing},
                                                         {"fresnel", GlazingModel::Fresnel},
                                                         {"cie171", GlazingModel::Cie171}},
      FIELD(bake.glazing.model),
      "how glazing passes less light obliquely: fresnel-absorbing (Fresnel faces and absorption in the glass, as "
      "Radiance's glass: a pane of low transmittance falls faster), fresnel (the faces alone, scaled), cie171 (CIE "
      "171's 6 mm clear glass, scaled); docs/daylight.md");
  Option<B> emission = number<B>("--emission-scale", "X", 1e-6, 1e9, "", FIELD(bake.emission_scale),
                                 "multiply glTF emission before reading it as cd/m2; 683 for Blender's exporter, which "
                                 "converts lamps to candela but not emission");
  Option<B> output = run_option(text<B>("--output", "DIR", FIELD(output),
                                        "output folder (required); replaced only if it is an earlier radbake output "
                                        "holding nothing but the files it wrote; one bake at a time per folder"));
  output.alias = "-o";
  Option<B> threads = run_option(number<B>("--threads", "N", 0, 1024, "threads", FIELD(bake.threads),
                                           "worker threads, 0 = all cores"));
  Option<B> preview = run_option(number<B>("--preview-every", "N", 0, double(1L << 40), "", FIELD(bake.preview_every),
                                           "write the solve's progressive estimate every N shots (or sweeps) as PNG "
                                           "pages into OUTDIR/preview/, 0 = none"));
  return {
      "bake options:",
      {output, quality,
       choice<B>("--method", "NAME",
                 std::vector<std::pair<std::string, Method>>{{"radiosity", Method::Radiosity}, {"pathtrace", Method::PathTrace}},
                 FIELD(bake.method),
                 "radiosity | pathtrace: the baker, or unbiased Monte Carlo path tracing per texel with no patches, the "
                 "independent reference (slow; its noise estimate is printed and in report.json)"),
       number<B>("--samples", "N", 2, 1 << 24, "paths", FIELD(bake.path_trace.samples),
                 "pathtrace: paths per texel; noise falls as 1/sqrt(N)"),
       number<B>("--tolerance", "X", 1e-9, 1, "", FIELD(bake.solve.tolerance),
                 "stop when no patch has more than X of its own light unshot"),
       choice<B>("--solver", "NAME",
                 std::vector<std::pair<std::string, Solver>>{
                     {"shooting", Solver::Shooting}, {"gauss-seidel", Solver::GaussSeidel}, {"jacobi", Solver::Jacobi}},
                 FIELD(bake.solve.solver), "shooting | gauss-seidel | jacobi: how the radiosity equation is solved"),
       threads,
       number<B>("--seed", "N", 0, double(1L << 53), "", FIELD(bake.seed), "random seed; same seed, same output"),
       number<B>("--gather-rays", "N", 1, 1 << 20, "rays", FIELD(bake.gather.rays),
                 "hemisphere rays per texel for indirect light"),
       run_option(number<B>("--max-rays", "N", 1, 1e18, "rays", FIELD(max_rays),
                 "refuse a bake whose form factors, gather, path tracing, probes, sensors or hours are estimated to "
                 "cast more rays in one stage (the default is about an hour on 2 cores)")),
       flag<B>("--no-near-field", false, FIELD(bake.gather.near_field),
               "gather rays landing within three widths of the struck patch take the patch's mean like the others, not "
               "the struck texel's own light (for measuring what the near field does; docs/accuracy.md)"),
       number<B>("--gather-filter", "N", 0, 16, "texels", FIELD(bake.gather.filter.radius),
                 "average each texel's gathered light with its neighbours up to N texels away on the same surface, "
                 "closing in where other surfaces are near; 0 = off"),
       number<B>("--gather-filter-validity", "X", 0.01, 100, "", FIELD(bake.gather.filter.validity),
                 "the filter's reach near other surfaces: neighbours within X times the harmonic mean distance of what "
                 "the gather rays struck"),
       choice<B>("--form-factors", "METHOD",
                 std::vector<std::pair<std::string, FormFactorMethod>>{{"raycast", FormFactorMethod::RayCast},
                                                                       {"hemicube", FormFactorMethod::Hemicube}},
                 FIELD(bake.form_factors.method), "raycast | hemicube: how form factors between patches are measured"),
       number<B>("--patch-rays", "N", 16, 1 << 24, "rays", FIELD(bake.form_factors.rays_per_patch),
                 "raycast: rays per patch for form factors"),
       hemicube,
       number<B>("--subdivide", "X", 0, 10, "", FIELD(bake.subdivision.tolerance),
                 "adaptive subdivision: split neighbouring patches whose radiosity differs by more than X (e.g. 0.2 = "
                 "20%), re-solve, repeat; 0 = off"),
       number<B>("--subdivide-rounds", "N", 1, 12, "rounds", FIELD(bake.subdivision.max_rounds),
                 "at most N split-and-solve rounds"),
       preview,
       number<B>("--area-light-rays", "N", 1, 1 << 16, "rays", FIELD(bake.direct.area_light_rays),
                 "shadow rays per texel per emitting triangle, a quarter of them (at least 16) first and the rest only "
                 "where those disagree"),
       number<B>("--light-rays", "N", 1, 1 << 16, "rays", FIELD(bake.direct.punctual_rays),
                 "shadow rays per texel per punctual light"),
       patch_size, emission, glazing, glazing_model,
       flag<B>("--no-ambient", false, FIELD(bake.solve.ambient_term), "leave out the ambient estimate of the light still unshot"),
       flag<B>("--direct-only", true, FIELD(bake.plan.direct_only), "direct light only: no light between surfaces"),
       flag<B>("--simulate-everything", true, FIELD(bake.plan.simulate_everything),
               "skip nothing the effect plan would skip (one colour channel, no shadow rays in a convex room, culled "
               "lights...): the reference the planned bake is checked against"),
       run_option(flag<B>("--debug-dumps", true, FIELD(debug_dumps),
                          "also write OUTDIR/debug/*.exr: light by source, material, normals, sample flags and patch "
                          "layout, undilated")),
       run_option(flag<B>("--quiet", true, FIELD(quiet), "no progress and no warnings on stderr"))}};
}

// What is written besides the lightmap: the stored quantity, the PNG pages, the display file, the
// engine file's COLOR_0, directional pages and probes.
OptionGroup<B> output_group() {
  Option<B> png = number_or_auto<B>("--png-scale", "X|auto", 1e-30, 1e30, "", FIELD(png_scale),
                                    "value (lux or lm/m2) that the PNG encodes as white");
  Option<B> detail = number_or_auto<B>("--display-detail", "N|auto", 1, 4, "", FIELD(display.detail),
                                       "pre-lit texels per lightmap texel along a side, 1, 2 or 4, so base colour "
                                       "textures keep their detail");
  detail.range.clear();
  detail.default_note = "what the textures hold, up to 4, pages up to 4096";
  detail.set = [](B& b, const std::string& v) {
    if (v == "auto") b.display.detail = 0;
    else if (v == "1" || v == "2" || v == "4") b.display.detail = std::stoi(v);
    else throw UsageError("option --display-detail must be 1, 2, 4 or auto" + got(v));
  };
  Option<B> exposure = number_or_auto<B>("--exposure", "X|auto", 1e-30, 1e30, "per cd/m2", FIELD(display.exposure.exposure),
                                         "display value per cd/m2 for the display file and the three.js plugin");
  exposure.default_note = "the median lit surface shows at --key, unless more than 2% of the lit area would clip";
  Option<B> color_0 = choice<B>("--color-0", "WHAT",
                                std::vector<std::pair<std::string, Color0>>{
                                    {"source", Color0::Source}, {"light", Color0::Light}, {"prelit", Color0::Prelit}},
                                FIELD(color_0),
                                "what the engine file's COLOR_0 holds: source (the input's own, a base colour "
                                "multiplier) | light (baked light / color_0_intensity) | prelit (exposed display colour "
                                "of a white surface)");
  color_0.default_note = "the baked light is always in _BAKED_LIGHT";
  Option<B> probes = row<B>("--probes", "SPACING",
      "auto | none | metres: L2 spherical-harmonic light probes on a grid in the scene's empty space (auto: 8 "
      "along its longest side), for objects that move through it: NAME_probes.json and extras.radbake.probes");
  probes.set = [](B& b, const std::string& v) {
    b.bake.probes.enabled = v != "none";
    b.bake.probes.spacing = v == "auto" || v == "none" ? 0.0f : float(parse_number("--probes", v, 1e-3, 1e6));
  };
  probes.echo = [](const B& b) {
    const ProbeOptions& p = b.bake.probes;
    return !p.enabled ? std::string("none") : p.spacing > 0 ? echo_number(p.spacing) : std::string("auto");
  };
  return {"output options (bake): what is written, and how viewers show it",
          {choice<B>("--store", "WHAT",
                     std::vector<std::pair<std::string, StoredQuantity>>{{"irradiance", StoredQuantity::Irradiance},
                                                                          {"radiosity", StoredQuantity::Radiosity}},
                     FIELD(bake.store), "irradiance (lux) | radiosity (lm/m2) per texel and vertex"),
           png,
           choice<B>("--display", "WHAT",
                     std::vector<std::pair<std::string, DisplayMode>>{
                         {"page", DisplayMode::Page}, {"vertex", DisplayMode::Vertex}, {"none", DisplayMode::None}},
                     FIELD(display.mode),
                     "the display file NAME_display.glb, for any glTF viewer: page (pre-lit pages on unlit materials) "
                     "| vertex (base colour x pre-lit COLOR_0) | none"),
           detail,
           number<B>("--vertex-refine", "N", 0, 100000000, "triangles", FIELD(display.vertex_refine_triangles),
                     "with --display vertex: split triangles where the baked light varies (shadow edges, gradients) up "
                     "to N triangles in all, so vertex light keeps the shadows; report.json gives the RMS difference "
                     "from the lightmap against triangle count; 0: the mesh as it is"),
           exposure,
           number<B>("--key", "X", 1e-6, 1, "", FIELD(display.exposure.key),
                     "display value (linear) of the log-mean luminance"),
           color_0,
           choice<B>("--directional", "MODE",
                     std::vector<std::pair<std::string, Directional>>{{"none", Directional::None},
                                                                      {"sh", Directional::SphericalHarmonics},
                                                                      {"dominant", Directional::Dominant}},
                     FIELD(bake.directional),
                     "none | sh: also pages of L1 spherical harmonics of the irradiance "
                     "(NAME_sh_c0/c1x/c1y/c1z_N.exr and packed .png), so normal maps show under baked light | "
                     "dominant: a page of the light's dominant direction (Unity's directional mode); see the glTF's "
                     "extras.radbake.directional"),
           probes,
           number<B>("--probe-rays", "N", 16, 1 << 20, "rays", FIELD(bake.probes.rays),
                     "sphere rays per probe for the light surfaces reflect")}};
}

OptionGroup<B> distribution_group() {
  Option<B> stop = run_option(choice<B>("--stop-after", "STAGE",
                                        std::vector<std::pair<std::string, StopAfter>>{
                                            {"direct-light", StopAfter::DirectLight},
                                            {"form-factors", StopAfter::FormFactors},
                                            {"radiosity", StopAfter::Radiosity}},
                                        FIELD(bake.sharing.stop_after),
                                        "direct-light | form-factors | radiosity: stop there with DIR saved (then bake "
                                        "slices that share the solve)"));
  return {"distributed bakes (docs/distributed.md): under `mpirun -np N radbake bake ...` (or srun) the\n"
          "processes share the work and the first writes the output, the same bytes as one process",
          {run_option(text<B>("--checkpoint", "DIR", FIELD(checkpoint),
                              "save each stage's results in DIR as the bake goes (the solve every --checkpoint-every "
                              "seconds), so a stopped bake can resume")),
           run_option(flag<B>("--resume", true, FIELD(bake.sharing.resume),
                              "take back what DIR holds and go on from there; refused when DIR was saved by a bake of "
                              "another scene or other options")),
           run_option(number<B>("--checkpoint-every", "S", 0, 1e7, "s", FIELD(bake.sharing.solve_save_seconds),
                                "within the radiosity solve, save at most every S seconds")),
           stop,
           slice_option("--pages", GatherSlice::By::Pages,
                        "bake slice K of N of the final gather, whole pages, into DIR (needs --checkpoint; writes no "
                        "output); `radbake merge` joins the slices"),
           slice_option("--texel-range", GatherSlice::By::Texels,
                        "the same in runs of texels, so one large page is split too")}};
}

Option<B> noted(Option<B> o, const char* note) {
  o.default_note = note;
  return o;
}

// The site's options: each sets one field of the site as typed; finish_site() checks they come
// as a set. Echoed from the site the bake uses, "none" without one.
template <class Field>
Option<B> site_number(const char* name, const char* value, double lo, double hi, const char* unit, bool SiteInput::*given,
                      Field field, const char* help) {
  Option<B> o = number<B>(name, value, lo, hi, unit, [field](auto& b) -> auto& { return field(b.site_input.site); }, help);
  o.show_default = false;
  if (given) o.set = [set = o.set, given](B& b, const std::string& v) {
    set(b, v);
    b.site_input.*given = true;
  };
  o.echo = [field](const B& b) { return b.daylight.site ? echo_number(field(*b.daylight.site)) : std::string("none"); };
  return o;
}

OptionGroup<B> daylight_group() {
  using D = DaylightOptions;
  Option<B> sky = row<B>("--sky", "NAME",
      "none | uniform | cie-overcast (the traditional CIE overcast sky, for daylight factors) | cie-1 .. cie-15 "
      "(the CIE standard general skies, ISO 15469: 1-6 overcast, 7-10 intermediate, 11-15 clear) | cie-clear "
      "(= cie-12) | perez (the Perez all-weather sky and its sun from an hour of weather: --direct-normal, "
      "--diffuse-horizontal, a site and time)");
  sky.set = [](B& b, const std::string& v) {
    D& d = b.daylight;
    if (v == "none") d.sky = SkyKind::None;
    else if (v == "uniform") d.sky = SkyKind::Uniform;
    else if (v == "cie-overcast") d.sky = SkyKind::CieOvercast;
    else if (v == "perez") d.sky = SkyKind::Perez;
    else if (v == "cie-clear") {
      d.sky = SkyKind::CieGeneral;
      d.cie_type = 12;
    } else if (const char* type = v.rfind("cie-", 0) == 0 ? v.c_str() + 4 : nullptr;
               type && std::string(type) == std::to_string(std::atoi(type)) && std::atoi(type) >= 1 && std::atoi(type) <= 15) {
      d.sky = SkyKind::CieGeneral;
      d.cie_type = std::atoi(type);
    } else {
      throw UsageError("option --sky must be none, uniform, cie-overcast, cie-clear, cie-1 .. cie-15 or perez" + got(v));
    }
  };
  sky.echo = [](const B& b) {
    const D& d = b.daylight;
    return d.sky == SkyKind::None          ? std::string("none")
           : d.sky == SkyKind::Uniform     ? std::string("uniform")
           : d.sky == SkyKind::CieOvercast ? std::string("cie-overcast")
           : d.sky == SkyKind::Perez       ? std::string("perez")
                                           : "cie-" + echo_number(d.cie_type);
  };
  Option<B> sun = optional_number<B>("--sun-illuminance", "LUX", 0, 2e5, "lux", FIELD(daylight.sun_illuminance),
                                     "the sun's direct normal illuminance (skies cie-7 .. cie-15 have a sun and need it: "
                                     "0 for none); the sun is a 0.53 degree disc, so shadow edges are soft");
  sun.echo = [](const B& b) { return echo_number(b.daylight.sun_illuminance.value_or(0)); };
  sun.default_note = "default none";
  auto weather_irradiance = [](const char* name, double D::*field, const char* help) {
    Option<B> o = number<B>(name, "W/M2", 0, 1500, "W/m2", [field](auto& b) -> auto& { return b.daylight.*field; }, help);
    o.echo = [field](const B& b) {
      return b.daylight.*field >= 0 ? echo_number(b.daylight.*field) : std::string("none");
    };
    o.show_default = false;
    return o;
  };
  Option<B> dew = optional_number<B>("--dew-point", "C", -90, 60, "C", FIELD(daylight.dew_point),
                                     "perez: the dew point, for the luminous efficacy");
  dew.echo = [](const B& b) {
    return b.daylight.dew_point ? echo_number(*b.daylight.dew_point) : std::string("none (2 cm of precipitable water)");
  };
  dew.default_note = "default: 2 cm of precipitable water";
  Option<B> sun_position = row<B>("--sun-position", "Z,A",
      "the sun's zenith angle and azimuth in degrees instead of a site and time (azimuth from north, "
      "eastward: east 90, south 180)");
  sun_position.show_default = false;
  sun_position.set = [](B& b, const std::string& v) {
    const std::vector<double> za = parse_numbers("--sun-position", v, 2, -360, 360);
    if (za[0] < 0 || za[0] > 180) throw UsageError("option --sun-position: the zenith angle must be 0..180 degrees" + got(v));
    b.daylight.sun = SunPosition{za[0], za[1]};
  };
  sun_position.echo = [](const B& b) {
    const auto& s = b.daylight.sun;
    return s ? echo_number(s->zenith) + "," + echo_number(s->azimuth) : std::string("none");
  };
  Option<B> date = row<B>("--date", "YYYY-MM-DD",
      "local date");
  date.show_default = false;
  date.set = [](B& b, const std::string& v) {
    int year = 0, month = 0, day = 0, used = 0;
    if (std::sscanf(v.c_str(), "%4d-%2d-%2d%n", &year, &month, &day, &used) != 3 || size_t(used) != v.size() ||
        month < 1 || month > 12 || day < 1 || day > 31 || year < 1 || year > 9999)
      throw UsageError("option --date needs YYYY-MM-DD" + got(v));
    SiteAndTime& s = b.site_input.site;
    s.year = year, s.month = month, s.day = day;
    b.site_input.date = true;
  };
  date.echo = [](const B& b) {
    if (!b.daylight.site) return std::string("none");
    char text[16];
    std::snprintf(text, sizeof text, "%04d-%02d-%02d", b.daylight.site->year, b.daylight.site->month, b.daylight.site->day);
    return std::string(text);
  };
  Option<B> time = row<B>("--time", "HH:MM[:SS]",
      "local clock time");
  time.show_default = false;
  time.set = [](B& b, const std::string& v) {
    int hour = 0, minute = 0, used = 0;
    double second = 0;
    const int fields = std::sscanf(v.c_str(), "%2d:%2d%n:%lf%n", &hour, &minute, &used, &second, &used);
    if (fields < 2 || size_t(used) != v.size() || hour > 24 || minute > 59 || second < 0 || second >= 60 || hour < 0 ||
        minute < 0)
      throw UsageError("option --time needs HH:MM or HH:MM:SS, local clock time" + got(v));
    SiteAndTime& s = b.site_input.site;
    s.hour = hour, s.minute = minute, s.second = second;
    b.site_input.time = true;
  };
  time.echo = [](const B& b) {
    const auto& s = b.daylight.site;
    return s ? echo_number(s->hour) + ":" + echo_number(s->minute) + ":" + echo_number(s->second) : std::string("none");
  };
  Option<B> utc = site_number("--utc-offset", "H", -12, 14, "h", &SiteInput::utc_offset, FIELD(utc_offset),
                              "local time minus UTC in hours");
  utc.default_note = "default: the longitude's nominal zone, round(longitude / 15): daylight saving is yours to add";
  Option<B> north = row<B>("--north", "DEG|X,Y,Z",
      "which way north is in the scene: a direction along the ground, or an angle from -Z turned toward +X "
      "(seen from above, clockwise)");
  north.default_note = "north is -Z, east +X, with glTF's +Y up";
  north.set = [](B& b, const std::string& v) {
    if (v.find(',') == std::string::npos) {
      // Rounded so that whole quarter turns give exact axes (cos 90 degrees is 6e-17, not 0).
      const double turn = parse_number("--north", v, -360, 360) * M_PI / 180;
      auto rounded = [](double x) { return float(std::round(x * 1e9) / 1e9) + 0.0f; };  // + 0: no -0
      b.daylight.north = {rounded(std::sin(turn)), 0, rounded(-std::cos(turn))};
    } else {
      const std::vector<double> n = parse_numbers("--north", v, 3, -1e6, 1e6);
      b.daylight.north = {float(n[0]), float(n[1]), float(n[2])};
    }
  };
  north.echo = [](const B& b) {
    const Vec3 n = b.daylight.north;
    return echo_number(n.x) + "," + echo_number(n.y) + "," + echo_number(n.z);
  };
  return {"daylight options (bake): a sky and a sun lighting the scene, besides its own lights",
          {sky,
           number<B>("--sky-illuminance", "LUX", 1e-6, 1e6, "lux", FIELD(daylight.sky_illuminance),
                     "the sky's illuminance on an open horizontal plane, sun excluded"),
           sun,
           weather_irradiance("--direct-normal", &D::direct_normal_irradiance,
                              "perez: the hour's direct normal irradiance (a weather file's DNI)"),
           weather_irradiance("--diffuse-horizontal", &D::diffuse_horizontal_irradiance,
                              "perez: the hour's diffuse horizontal irradiance (DHI)"),
           dew,
           site_number("--latitude", "DEG", -90, 90, "degrees", &SiteInput::latitude, FIELD(latitude),
                       "site, north positive; with --longitude, --date and --time it places the sun"),
           site_number("--longitude", "DEG", -180, 180, "degrees", &SiteInput::longitude, FIELD(longitude),
                       "site, east positive (NREL SPA's conventions)"),
           date, time, utc,
           noted(site_number("--elevation", "M", -500, 9000, "m", nullptr, FIELD(elevation), "site elevation"),
                 "default 0"),
           noted(site_number("--pressure", "MBAR", 300, 1100, "mbar", nullptr, FIELD(pressure),
                             "air pressure, for the refraction near the horizon"),
                 "default 1013.25"),
           noted(site_number("--temperature", "C", -90, 60, "C", nullptr, FIELD(temperature),
                             "air temperature, for the refraction near the horizon"),
                 "default 15"),
           sun_position, north,
           number<B>("--ground-reflectance", "X", 0, 1, "", FIELD(daylight.ground_reflectance),
                     "the ground beyond the scene, below the horizon"),
           number<B>("--sky-rays", "N", 1, 1 << 20, "rays", FIELD(daylight.sky_rays), "sky rays per texel"),
           number<B>("--sun-rays", "N", 1, 1 << 16, "rays", FIELD(daylight.sun_rays),
                     "shadow rays per texel to the sun's disc")}};
}

OptionGroup<B> analysis_group() {
  Option<B> over = row<B>("--work-plane-over", "NAMES",
      "the floors, by node name (comma-separated parts of names)");
  over.default_note = "default: every surface facing up; in each storey the lowest under each point";
  over.show_default = false;
  over.set = [](B& b, const std::string& v) {
    std::vector<std::string>& names = b.bake.work_plane.over;
    names.clear();
    std::stringstream parts(v);
    for (std::string name; std::getline(parts, name, ',');)
      if (!name.empty()) names.push_back(name);
    if (names.empty()) throw UsageError("option --work-plane-over needs names" + got(v));
  };
  over.echo = [](const B& b) {
    std::string names;
    for (const std::string& n : b.bake.work_plane.over) names += (names.empty() ? "" : ",") + n;
    return names.empty() ? std::string("none") : names;
  };
  Option<B> colour = row<B>("--false-colour", "SCALE",
      "linear | log: NAME_false_colour_N.png, each page in false colour with a legend in lux (log: three "
      "decades)");
  colour.show_default = false;
  colour.set = [](B& b, const std::string& v) {
    if (v == "linear") b.analysis.scale.logarithmic = false;
    else if (v == "log") b.analysis.scale.logarithmic = true;
    else throw UsageError("option --false-colour must be linear or log" + got(v));
    b.analysis.false_colour_pages = true;
  };
  colour.echo = [](const B& b) {
    return !b.analysis.false_colour_pages ? std::string("none") : b.analysis.scale.logarithmic ? "log" : "linear";
  };
  Option<B> colour_max = number_or_auto<B>("--false-colour-max", "X|auto", 1e-9, 1e12, "", FIELD(analysis.scale.max),
                                           "the value at the top of the false-colour scales");
  colour_max.default_note = "the 99th percentile, rounded up to 1, 2, 2.5 or 5 x 10^k";
  Option<B> view = row<B>("--view", "X,Y,Z:DX,DY,DZ",
      "an eye at X,Y,Z looking along DX,DY,DZ (up stays +Y), repeatable: view_N.exr (a 180-degree fisheye of "
      "luminance, cd/m2, sky and sun included), view_N.png (false colour) and, in report.json, its vertical "
      "illuminance and daylight glare probability DGP (Wienold) with the glare sources (docs/annual.md)");
  view.show_default = false;
  view.set = [](B& b, const std::string& v) {
    float n[6];
    char tail = 0;
    if (std::sscanf(v.c_str(), "%f,%f,%f:%f,%f,%f%c", &n[0], &n[1], &n[2], &n[3], &n[4], &n[5], &tail) != 6 ||
        !std::all_of(n, n + 6, [](float x) { return std::isfinite(x); }))
      throw UsageError("option --view must be X,Y,Z:DX,DY,DZ (the eye and where it looks, metres)" + got(v));
    const Vec3 direction{n[3], n[4], n[5]};
    if (!(length(direction) > 0)) throw UsageError("option --view needs a direction to look in" + got(v));
    b.bake.views.push_back({{n[0], n[1], n[2]}, normalize(direction), {0, 1, 0}});
  };
  view.echo = [](const B& b) {
    std::string eyes;
    for (const EyeView& e : b.bake.views) {
      const Vec3 p = e.position, d = e.direction;
      eyes += (eyes.empty() ? "" : " ") + echo_number(p.x) + "," + echo_number(p.y) + "," + echo_number(p.z) + ":" +
              echo_number(d.x) + "," + echo_number(d.y) + "," + echo_number(d.z);
    }
    return eyes.empty() ? std::string("none") : eyes;
  };
  return {"analysis options (bake): readings where there is no surface, what an eye sees, false colour",
          {flag<B>("--work-plane", true, FIELD(bake.work_plane.enabled),
                   "a grid of sensors over the enclosed floors, facing up: OUTDIR/sensors.csv, a heat map per storey "
                   "(work_plane.png, or work_plane_storey_N.png; seen from above, -Z up, +X right, rooms numbered), "
                   "work_plane_rooms.csv, and min, mean, max and uniformity (min / mean) per storey and room in "
                   "report.json and on stderr"),
           number<B>("--work-plane-height", "M", 0, 1000, "m", FIELD(bake.work_plane.height),
                     "its height over the floors: 0.8 for desks, 0 for circulation"),
           number<B>("--work-plane-spacing", "M", 0.001, 1000, "m", FIELD(bake.work_plane.spacing),
                     "between the grid's points, along x and z"),
           over,
           flag<B>("--work-plane-outdoors", true, FIELD(bake.work_plane.outdoors),
                   "measure floors open to the sky or without walls round them too (terrain, roofs, balconies, a "
                   "plaza); by default a point needs something above it and walls round it"),
           text<B>("--sensors", "FILE.csv", FIELD(sensor_file),
                   "points to measure at too: a line each, x,y,z or x,y,z,nx,ny,nz (metres; the meter faces +Y, up, "
                   "unless given); # comments, blank lines and one header line before the first point are skipped"),
           number<B>("--sensor-rays", "N", 8, 1 << 24, "rays", FIELD(bake.sensor.rays),
                     "rays per sensor (and work-plane point) for the light surfaces send, in 8 batches whose spread "
                     "gives each reading's standard error"),
           number<B>("--sensor-sky-rays", "N", 8, 1 << 24, "rays", FIELD(bake.sensor.sky_rays),
                     "rays per sensor (and work-plane point) for the sky and the ground, apart from the texels' "
                     "--sky-rays, in 8 batches likewise; with --method pathtrace, whole paths per sensor (the "
                     "reference)"),
           flag<B>("--daylight-factor", true, FIELD(daylight_factor),
                   "under an overcast sky without a sun (cie-overcast, uniform, cie-1 .. cie-6): each sensor's and "
                   "texel's illuminance over the unobstructed sky's horizontal illuminance, in percent: a column of "
                   "sensors.csv, work_plane_daylight_factor.png and NAME_daylight_factor_N.png pages"),
           colour, colour_max, view,
           number<B>("--view-size", "N", 16, 4096, "pixels", FIELD(bake.view.size), "fisheye pixels per side")}};
}

OptionGroup<B> annual_group() {
  Option<B> occupied = row<B>("--occupied", "FROM-TO",
      "occupied hours, local standard time");
  occupied.default_note = "IES LM-83";
  occupied.set = [](B& b, const std::string& v) {
    const size_t dash = v.find('-');
    if (dash == std::string::npos) throw UsageError("option --occupied must be FROM-TO in hours, as 8-18" + got(v));
    b.occupied_from = int(parse_integer("--occupied", v.substr(0, dash), 0, 23));
    b.occupied_to = int(parse_integer("--occupied", v.substr(dash + 1), 1, 24));
    if (b.occupied_to <= b.occupied_from) throw UsageError("option --occupied must end after it starts" + got(v));
  };
  occupied.echo = [](const B& b) { return echo_number(b.occupied_from) + "-" + echo_number(b.occupied_to); };
  return {"annual options (bake): a year of daylight at the sensors by daylight coefficients (docs/annual.md)",
          {text<B>("--weather", "FILE.epw", FIELD(weather_file),
                   "an EnergyPlus weather file: its site and every hour's Perez sky and sun (samples/weather has "
                   "synthetic years); needs --sensors, --work-plane or --view, takes no --sky or site. Writes "
                   "annual_illuminance.f32 (float32, by hour, sensor by sensor), annual_sensors.csv (DA, UDI bins, sun "
                   "hours), work-plane maps and, in report.json, sDA300/50%, ASE1000/250h, UDI; with --view, each "
                   "eye's hourly DGP (annual_dgp.f32) and the shares of occupied hours over 0.35, 0.40 and 0.45"),
           occupied,
           number<B>("--da-threshold", "LUX", 1, 1e6, "lux", FIELD(metrics.da_threshold),
                     "daylight autonomy's illuminance"),
           number<B>("--sky-subdivision", "M", 1, 4, "", FIELD(sky_subdivision),
                     "the sky patches the surfaces' light is solved for: 1, Tregenza's 145; 2 or 4, Reinhart's 577 or "
                     "2305 (finer, slower)")}};
}

// The site and moment come as a set: a sun position needs all four of latitude, longitude, date
// and time; the UTC offset defaults to the nominal zone of the longitude (no daylight saving).
void finish_site(DaylightOptions& d, SiteInput& in) {
  const int given = in.latitude + in.longitude + in.date + in.time;
  if (given == 0) return;
  if (given < 4)
    throw UsageError(std::string("a site and time needs --latitude, --longitude, --date and --time; missing") +
                     (in.latitude ? "" : " --latitude") + (in.longitude ? "" : " --longitude") +
                     (in.date ? "" : " --date") + (in.time ? "" : " --time"));
  if (!in.utc_offset) in.site.utc_offset = std::round(in.site.longitude / 15);
  d.site = in.site;
}

BakeCommand default_bake() {
  BakeCommand b;
  apply_quality_preset(b.quality, b.bake);
  return b;
}

// Each command's parse returns false when -h or --help asked for the help instead.
bool parse_bake(const std::vector<std::string>& args, bool merge, BakeCommand& b) {
  b = default_bake();
  b.merge = merge;
  if (!parse_options(args, bake_options(), b, [&](const std::string& arg) {
        if (!b.input.empty()) throw UsageError("unexpected argument '" + clipped(arg) + "' (one scene per bake)");
        b.input = arg;
      }))
    return false;
  if (b.input.empty()) throw UsageError("missing input scene (radbake bake SCENE.gltf -o OUTDIR)");
  const bool sliced = b.bake.sharing.slice.by != GatherSlice::By::Everything;
  const bool stops = b.bake.sharing.stop_after != StopAfter::Nothing;
  if (b.output.empty() && !sliced && !stops) throw UsageError("missing -o OUTDIR");
  BakeRun run;
  run.year = !b.weather_file.empty();
  run.sensors = !b.sensor_file.empty();
  run.daylight_factor = b.daylight_factor;
  run.checkpoint = !b.checkpoint.empty();
  run.merge = b.merge;
  // A year takes its site from the weather file: a site given beside it, whole or not, is for
  // validate() to refuse. Otherwise the four options make one site, or none.
  if (run.year && b.site_input.given()) b.daylight.site = b.site_input.site;
  else finish_site(b.daylight, b.site_input);
  validate(b.bake, b.daylight, run);
  if (!b.output.empty() && (sliced || stops))
    throw UsageError("a slice or a stopped bake writes only its checkpoint: leave out -o (radbake merge writes the output)");
  if (b.merge) b.bake.sharing.resume = true;
  b.effective = echo_options(bake_options(), b);
  const Affects result = Affects::Result;
  b.result_options = echo_options(bake_options(), b, &result);
  return true;
}

// ---- uv, diff, view ----

OptionGroup<UvCommand> uv_group() {
  using U = UvCommand;
  Option<U> stats = row<U>("--stats", "",
      "print what the atlas is worth (what `uv` always does)");  // statistics are what `uv` prints; the flag is accepted for clarity
  stats.set = [](U&, const std::string&) {};
  stats.echo = [](const U&) { return std::string("yes"); };
  stats.show_default = false;
  Option<U> json = flag<U>("--json", true, FIELD(json), "machine-readable statistics on stdout");
  Option<U> evaluate = number<U>("--evaluate-texcoord", "N", 0, 7, "", FIELD(evaluate_texcoord),
                                 "measure the scene's own TEXCOORD_N as one page of --max-page-size instead of "
                                 "unwrapping (for comparing UVs made elsewhere)");
  evaluate.show_default = false;
  return {"uv options:", {stats, json, evaluate}};
}

bool parse_uv(const std::vector<std::string>& args, UvCommand& u) {
  if (!parse_options(args, uv_options(), u, [&](const std::string& arg) {
        if (!u.input.empty()) throw UsageError("unexpected argument '" + clipped(arg) + "' (one scene at a time)");
        u.input = arg;
      }))
    return false;
  if (u.input.empty()) throw UsageError("missing input scene (radbake uv SCENE.gltf --stats)");
  return true;
}

// A percentage on the command line, a fraction in the options structs.
template <class Field>
Option<DiffCommand> percent(const char* name, double lo, Field field, const char* help) {
  Option<DiffCommand> o;
  o.name = name;
  o.value = "PCT";
  o.help = help;
  o.set = [name = std::string(name), lo, field](DiffCommand& d, const std::string& v) {
    field(d) = parse_number(name, v, lo, 1e6) / 100;
  };
  o.echo = [field](const DiffCommand& d) {
    if constexpr (std::is_same_v<std::remove_cv_t<std::remove_reference_t<decltype(field(d))>>, double>)
      return echo_number(100 * field(d));
    else
      return field(d) ? echo_number(100 * *field(d)) : std::string("none");
  };
  return o;
}

bool parse_diff(const std::vector<std::string>& args, DiffCommand& d) {
  if (!parse_options(args, diff_options(), d, [&](const std::string& arg) {
        if (d.reference.empty()) d.reference = arg;
        else if (d.candidate.empty()) d.candidate = arg;
        else throw UsageError("unexpected argument '" + clipped(arg) + "' (radbake diff compares two bakes)");
      }))
    return false;
  if (d.candidate.empty()) throw UsageError("missing bakes to compare (radbake diff A B)");
  return true;
}

bool parse_view(const std::vector<std::string>& args, ViewCommand& v) {
  if (!parse_options(args, view_options(), v, [&](const std::string& arg) {
        if (v.folders.size() == 2)
          throw UsageError("unexpected argument '" + clipped(arg) + "' (radbake view shows one bake, or two to compare)");
        v.folders.push_back(arg);
      }))
    return false;
  if (v.folders.empty()) throw UsageError("missing output folder (radbake view OUTDIR [OUTDIR_B])");
  return true;
}

}  // namespace

const OptionTable<BakeCommand>& bake_options() {
  static const OptionTable<BakeCommand> table = {
      lifted(reading_group(), &BakeCommand::load), lifted(atlas_group(), &BakeCommand::atlas),
      bake_group(), output_group(), daylight_group(), analysis_group(), annual_group(), distribution_group()};
  return table;
}

const OptionTable<UvCommand>& uv_options() {
  static const OptionTable<UvCommand> table = {lifted(reading_group(), &UvCommand::load),
                                               lifted(atlas_group(), &UvCommand::atlas), uv_group()};
  return table;
}

const OptionTable<DiffCommand>& diff_options() {
  using D = DiffCommand;
  Option<D> error = optional_number<D>("--max-error", "X", 0, 1e30, "", FIELD(limits.max_error),
                                       "fail when a texel's error exceeds X (lux, or lm/m2)");
  error.range.clear();
  auto limit = [](const char* name, std::optional<double> DifferenceLimits::*field, const char* help) {
    Option<D> o = percent(name, 0, [field](auto& d) -> auto& { return d.limits.*field; }, help);
    o.show_default = false;
    return o;
  };
  static const OptionTable<DiffCommand> table = {
      {"diff options:",
       {flag<D>("--json", true, FIELD(json), "machine-readable statistics on stdout"),
        limit("--max-rmse", &DifferenceLimits::rmse, "fail when the relative RMSE exceeds PCT percent"),
        limit("--max-p50", &DifferenceLimits::p50,
              "fail when the median relative error exceeds PCT percent (the statistic least moved by noise, most by a "
              "change of overall light)"),
        limit("--max-p95", &DifferenceLimits::p95, "fail when the 95th percentile relative error exceeds PCT percent"),
        limit("--max-p99", &DifferenceLimits::p99, "fail when the 99th percentile relative error exceeds PCT percent"),
        error,
        percent("--relative-floor", 1e-6, FIELD(difference.relative_floor),
                "percent of the reference level that relative errors are taken against at least"),
        text<D>("--diff-images", "DIR", FIELD(image_folder),
                "write DIR/PAGE_diff.png per page of B: white where B equals A, towards red where B is brighter and "
                "blue where darker, full colour at --image-scale; black where not compared"),
        percent("--image-scale", 1e-6, FIELD(difference.image_scale), "relative difference shown at full colour")}}};
  return table;
}

const OptionTable<ViewCommand>& view_options() {
  using V = ViewCommand;
  Option<V> port = number<V>("--port", "N", 1, 65535, "", FIELD(port), "the port");
  port.default_note = "default: a free one; the address is printed";
  port.show_default = false;
  static const OptionTable<ViewCommand> table = {
      {"view options: a page on 127.0.0.1 showing OUTDIR's bake in three.js (and OUTDIR_B's beside it);\n"
       "it serves the page, three.js and the two folders' files, nothing else",
       {port, flag<V>("--no-open", false, FIELD(open), "do not open the page in the browser")}}};
  return table;
}

std::string usage_text() {
  std::string text = R"(usage: radbake bake SCENE.gltf|SCENE.glb -o OUTDIR [options]
       radbake merge SCENE.gltf|SCENE.glb -o OUTDIR --checkpoint DIR [the slices' options]
       radbake uv SCENE.gltf|SCENE.glb --stats [--json] [lightmap UV options]
       radbake diff A B [--json] [--max-rmse PCT] [--max-p50|p95|p99 PCT] [--max-error X]
                    [--diff-images DIR]
       radbake view OUTDIR [OUTDIR_B] [--port N] [--no-open]
       radbake --help | --version

Bakes diffuse global illumination (radiosity with colour bleeding) into lightmaps.
OUTDIR receives NAME.gltf with lightmap UVs (TEXCOORD_1), baked COLOR_0 and MOZ_lightmap
materials, the lightmap pages as NAME_lightmap_N.exr (linear) and .png (sRGB), and report.json.

`radbake uv` unwraps without baking and prints what the atlas is worth: pages, density, charts,
utilisation counted two ways (texels a triangle touches, and texels whose centre a triangle
covers), L2 stretch (Sander et al. 2001; 1 = none), seam length, overlapping texels, flipped
triangles, padding violations, time. With --evaluate-texcoord N it measures the scene's own
TEXCOORD_N as one page of --max-page-size instead (for comparing UVs made elsewhere).

`radbake diff` compares two bakes of one scene, A the reference: each an EXR page or an output
folder, whose NAME_lightmap_N.exr pages are matched by N. Per page and over all pages it prints
the texels compared, the relative RMSE, the largest texel error (in the bake's unit: lux, or lm/m2
for radiosity) and the 50th, 95th and 99th percentiles of the relative texel error, where
  - a texel is compared unless it is zero in both bakes (unused page space, unlit surfaces);
  - its value is the mean of its R, G, B and its error the mean of |B - A| over R, G, B;
  - its relative error is error / max(A, floor), floor = --relative-floor x the reference level,
    the mean of A over the compared texels, so dark texels are not divided by almost nothing;
  - relative RMSE = RMS of the errors / the reference level; percentiles are by nearest rank.
Thresholds apply to the all-pages numbers.

Every option of `bake` is listed with the value in effect in report.json's "options".
)";
  text += options_help(bake_options(), default_bake());
  const OptionTable<UvCommand> uv_own = {uv_options().back()};
  text += options_help(uv_own, UvCommand{});
  text += options_help(view_options(), ViewCommand{});
  text += options_help(diff_options(), DiffCommand{});
  text += R"(
  -h, --help              this text
  --version               print the version

exit status: 0 done, 2 bad input or usage, 1 anything else, 130/143 ended by SIGINT/SIGTERM
(nothing is left behind);
diff: 0 when every threshold holds, 1 when one is exceeded (named on stderr), 2 bad input or usage
)";
  return text;
}

CommandLine parse_command_line(const std::vector<std::string>& args) {
  CommandLine cl;
  if (args.empty()) throw UsageError("missing command (try radbake --help)");
  if (args[0] == "-h" || args[0] == "--help" || args[0] == "help") return cl;
  if (args[0] == "--version") {
    cl.action = Action::Version;
    return cl;
  }
  bool parsed = false;
  if (args[0] == "uv") {
    cl.action = Action::Uv;
    parsed = parse_uv(args, cl.uv);
  } else if (args[0] == "diff") {
    cl.action = Action::Diff;
    parsed = parse_diff(args, cl.diff);
  } else if (args[0] == "view") {
    cl.action = Action::View;
    parsed = parse_view(args, cl.view);
  } else if (args[0] == "bake" || args[0] == "merge") {
    cl.action = args[0] == "merge" ? Action::Merge : Action::Bake;
    parsed = parse_bake(args, cl.action == Action::Merge, cl.bake);
  } else {
    throw UsageError("unknown command '" + clipped(args[0]) + "' (try radbake --help)");
  }
  if (!parsed) cl.action = Action::Help;
  return cl;
}

}  // namespace radbake

#undef FIELD
