#include "cli/command_line.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <sstream>

#include "baker/errors.h"

namespace radbake {
namespace {

std::string number_text(double v) {
  char text[32];
  std::snprintf(text, sizeof text, v == std::floor(v) && std::fabs(v) < 1e16 ? "%.0f" : "%g", v);
  return text;
}

// `text` as the user typed it, for a message naming the option.
std::string got(const std::string& text) { return ", got '" + clipped(text) + "'"; }

double parse_number(const std::string& option, const std::string& text, double lo, double hi) {
  // strtod, not stod: a value too large for a double is out of range (HUGE_VAL), not "no number".
  char* end = nullptr;
  const double v = text.empty() ? NAN : std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || std::isnan(v)) throw UsageError("option " + option + " needs a number" + got(text));
  if (v < lo || v > hi)
    throw UsageError("option " + option + " must be between " + number_text(lo) + " and " + number_text(hi) + got(text));
  return v;
}

long parse_integer(const std::string& option, const std::string& text, long lo, long hi) {
  double v = parse_number(option, text, double(lo), double(hi));
  if (v != std::floor(v)) throw UsageError("option " + option + " needs a whole number" + got(text));
  return long(v);
}

// Percent on the command line, a fraction in the options structs.
double parse_percent(const std::string& option, const std::string& text, double lo) {
  return parse_number(option, text, lo, 1e6) / 100;
}

}  // namespace

void apply_quality_preset(const std::string& name, BakeOptions& bake) {
  struct Preset {
    const char* name;
    uint32_t gather_rays, patch_rays;
    int area_light_rays, light_rays;
    double tolerance;
    int patch_size;     // 0: auto
    int gather_filter;  // texels each side
  };
  // Chosen from the accuracy-versus-time front measured in docs/accuracy.md (./dev accuracy):
  // on the Cornell box at a 256 page, against the path tracer, about 2%, 1%, 0.6% and 0.4%.
  static const Preset presets[] = {
      {"draft", 32, 512, 16, 1, 1e-2, 0, 3},
      {"preview", 64, 1024, 64, 4, 1e-3, 0, 3},
      {"production", 256, 1024, 128, 16, 1e-4, 4, 2},
      {"reference", 1024, 4096, 512, 64, 1e-5, 2, 2},
  };
  for (const Preset& p : presets)
    if (name == p.name) {
      bake.gather_rays = p.gather_rays;
      bake.gather_filter.radius = p.gather_filter;
      bake.form_factors.rays_per_patch = p.patch_rays;
      bake.direct.area_light_rays = p.area_light_rays;
      bake.direct.punctual_rays = p.light_rays;
      bake.solve.tolerance = p.tolerance;
      bake.patches.block_size = p.patch_size;
      return;
    }
  throw UsageError("option --quality must be draft, preview, production or reference" + got(name));
}

const char* usage_text() {
  return R"(usage: radbake bake SCENE.gltf|SCENE.glb -o OUTDIR [options]
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

reading options (bake and uv):
  --allow-external-files  read images and buffers whose URIs lead out of the scene's folder
                          (absolute paths, ../, links); refused by default
  --max-memory SIZE|auto  refuse a scene whose bake is estimated to need more memory; SIZE in
                          bytes or with K, M, G (x1024) (default auto: half the physical memory)
  --max-triangles N       refuse a scene with more triangles after instancing (default 20000000)

lightmap UV options (bake and uv):
  --density N|auto        lightmap texels per metre (default auto: about --texels texels over the
                          scene's surface, fewer if they do not fit one page; report.json says
                          which)
  --texels N              the automatic density's budget, texels over the whole surface
                          (default 50000: a few seconds at the default preset on 2 cores)
  --max-page-size N       texels per page side, 16..16384 (default 1024); generated pages are
                          powers of two, at most the largest power of two not above N
  --any-page-size         generated pages as tight as their charts (sides a multiple of 4, up to
                          --max-page-size) instead of powers of two
  --padding N             empty texels between charts, 0..64 (default 2)
  --fit-page              with --density: lower it until everything fits one page (reported);
                          without, a scene too large for one page gets more pages
  --no-rotate             keep charts upright (no turning to their tightest box or by 90 degrees)
  --lightmap-uvs WHAT     keep-valid: use the scene's TEXCOORD_1 where valid, generate elsewhere;
                          keep: use it even where invalid; generate: always generate
                          (default keep-valid; what was invalid is reported)
  --chart-angle DEG       faces of one chart stay within this cone of normals, 1..89 (default 50)

bake options:
  -o, --output DIR        output folder (required); replaced only if it is an earlier radbake output
                          holding nothing but the files it wrote; one bake at a time per folder
  --quality NAME          draft | preview | production | reference: ray counts, tolerance and
                          patch size together (default preview; docs/accuracy.md has each
                          preset's measured error and time); options given as well override it
  --method NAME           radiosity | pathtrace: the baker, or unbiased Monte Carlo path tracing
                          per texel with no patches, the independent reference (slow; its noise
                          estimate is printed and in report.json) (default radiosity)
  --samples N             pathtrace: paths per texel, 2..16777216; noise falls as 1/sqrt(N)
                          (default 1024)
  --tolerance X           stop when unshot light <= X of the light brought in (default 0.001)
  --solver NAME           shooting | gauss-seidel | jacobi (default shooting)
  --threads N             worker threads, 0 = all cores (default 0)
  --seed N                random seed; same seed, same output (default 1)
  --store WHAT            irradiance (lux) | radiosity (lm/m2) per texel and vertex (default irradiance)
  --gather-rays N         hemisphere rays per texel for indirect light, 1..1048576 (default 64)
  --no-near-field         gather rays landing within three widths of the struck patch take
                          the patch's mean like the others, not the struck texel's own light (for
                          measuring what the near field does; docs/accuracy.md)
  --gather-filter N       average each texel's gathered light with its neighbours up to N texels
                          away on the same surface, closing in where other surfaces are near;
                          0..16, 0 = off (default 3)
  --gather-filter-validity X
                          the filter's reach near other surfaces: neighbours within X times the
                          harmonic mean distance of what the gather rays struck (default 1)
  --form-factors METHOD   raycast | hemicube: how form factors between patches are measured
                          (default raycast)
  --patch-rays N          raycast: rays per patch for form factors (default 1024)
  --hemicube-resolution N hemicube: pixels per side of the top face, even, 2..4096 (default 64)
  --subdivide X           adaptive subdivision: split neighbouring patches whose radiosity differs
                          by more than X (e.g. 0.2 = 20%), re-solve, repeat (default 0 = off)
  --subdivide-rounds N    at most N split-and-solve rounds, 1..12 (default 4)
  --preview-every N       write the solve's progressive estimate every N shots (or sweeps) as
                          PNG pages into OUTDIR/preview/ (default 0 = none)
  --area-light-rays N     shadow rays per texel per emitting triangle, a quarter of them (at least
                          16) first and the rest only where those disagree (default 64)
  --light-rays N          shadow rays per texel per punctual light (default 4)
  --patch-size N          patch side in texels, a power of two up to 16384, 0 = auto (default 0)
  --png-scale X|auto      value (lux or lm/m2) that the PNG encodes as white (default auto)
  --display WHAT          the display file NAME_display.glb, for any glTF viewer: page (pre-lit
                          pages on unlit materials) | vertex (base colour x pre-lit COLOR_0) |
                          none (default page)
  --display-detail N|auto pre-lit texels per lightmap texel along a side, 1, 2 or 4, so base
                          colour textures keep their detail (default auto: what the textures
                          hold, up to 4, pages up to 4096)
  --vertex-refine N       with --display vertex: split triangles where the baked light varies
                          (shadow edges, gradients) up to N triangles in all, so vertex light
                          keeps the shadows; report.json gives the RMS difference from the
                          lightmap against triangle count (default 0: the mesh as it is)
  --exposure X|auto       display value per cd/m2 for the display file and the three.js plugin
                          (default auto: the log-mean luminance shows at --key)
  --key X                 display value (linear, 0..1) of the log-mean luminance (default 0.18)
  --color-0 WHAT          what the engine file's COLOR_0 holds: source (the input's own, a base
                          colour multiplier) | light (baked light / color_0_intensity) | prelit
                          (exposed display colour of a white surface) (default source; the
                          baked light is always in _BAKED_LIGHT)
  --emission-scale X      multiply glTF emission before reading it as cd/m2, 1e-6..1e9 (default 1;
                          683 for Blender's exporter, which converts lamps to candela but not
                          emission)
  --glazing-transmittance X
                          visible transmittance of glazing along its normal (KHR_materials_
                          transmission, read as a thin pane: the factor is the share of light
                          meeting the glazing; obliquely it passes less, as a clear pane of the
                          material's KHR_materials_ior), 0..1, for materials without
                          extras.visible_transmittance of their own (default: a clear pane's,
                          0.92 for glass; double glazing is about 0.8, solar control 0.4-0.7)
  --no-ambient            leave out the ambient estimate of the light still unshot
  --direct-only           direct light only: no light between surfaces
  --simulate-everything   skip nothing the effect plan would skip (one colour channel, no
                          shadow rays in a convex room, culled lights...): the reference the
                          planned bake is checked against
  --directional MODE      none | sh: also pages of L1 spherical harmonics of the irradiance
                          (NAME_sh_c0/c1x/c1y/c1z_N.exr and packed .png), so normal maps show
                          under baked light | dominant: a page of the light's dominant direction
                          (Unity's directional mode); see the glTF's extras.radbake.directional
  --probes SPACING        auto | none | metres: L2 spherical-harmonic light probes on a grid in
                          the scene's empty space (auto: 8 along its longest side), for objects
                          that move through it: NAME_probes.json and extras.radbake.probes
  --probe-rays N          sphere rays per probe for the light surfaces reflect (default 4096)
  --debug-dumps           also write OUTDIR/debug/*.exr: light by source, material, normals,
                          sample flags and patch layout, undilated
  --quiet                 no progress and no warnings on stderr

distributed bakes (docs/distributed.md): under `mpirun -np N radbake bake ...` (or srun) the
processes share the work and the first writes the output, the same bytes as one process
  --checkpoint DIR        save each stage's results in DIR as the bake goes (the solve every
                          --checkpoint-every seconds), so a stopped bake can resume
  --resume                take back what DIR holds and go on from there; refused when DIR was
                          saved by a bake of another scene or other options
  --checkpoint-every S    within the radiosity solve, save at most every S seconds (default 60)
  --stop-after STAGE      direct-light | form-factors | radiosity: stop there with DIR saved
                          (then bake slices that share the solve)
  --pages K/N             bake slice K of N of the final gather, whole pages, into DIR (needs
                          --checkpoint; writes no output); `radbake merge` joins the slices
  --texel-range K/N       the same in runs of texels, so one large page is split too

daylight options (bake): a sky and a sun lighting the scene, besides its own lights
  --sky NAME              none | uniform | cie-overcast (the traditional CIE overcast sky, for
                          daylight factors) | cie-1 .. cie-15 (the CIE standard general skies,
                          ISO 15469: 1-6 overcast, 7-10 intermediate, 11-15 clear) | cie-clear
                          (= cie-12) | perez (the Perez all-weather sky and its sun from an hour
                          of weather: --direct-normal, --diffuse-horizontal, a site and time)
                          (default none)
  --sky-illuminance LUX   the sky's illuminance on an open horizontal plane, sun excluded
                          (default 10000)
  --sun-illuminance LUX   the sun's direct normal illuminance, lux (default none; skies cie-7 ..
                          cie-15 have a sun and need it: 0 for none); the sun is a 0.53 degree
                          disc, so shadow edges are soft
  --direct-normal W/M2    perez: the hour's direct normal irradiance (a weather file's DNI)
  --diffuse-horizontal W/M2
                          perez: the hour's diffuse horizontal irradiance (DHI)
  --dew-point C           perez: the dew point, for the luminous efficacy (default: 2 cm of
                          precipitable water)
  --latitude DEG          site, north positive; with --longitude, --date and --time it places
  --longitude DEG         the sun (NREL SPA's conventions: east positive)
  --date YYYY-MM-DD       local date
  --time HH:MM[:SS]       local clock time
  --utc-offset H          local time minus UTC in hours, -12..14 (default the longitude's nominal
                          zone, round(longitude / 15): daylight saving is yours to add)
  --elevation M           site elevation (default 0)
  --pressure MBAR         air pressure (default 1013.25) and temperature (default 15 C), for
  --temperature C         the refraction near the horizon
  --sun-position Z,A      the sun's zenith angle and azimuth in degrees instead of a site and time
                          (azimuth from north, eastward: east 90, south 180)
  --north DEG|X,Y,Z       which way north is in the scene: a direction along the ground, or an
                          angle from -Z turned toward +X (seen from above, clockwise) (default
                          0,0,-1: north is -Z, east +X, with glTF's +Y up)
  --ground-reflectance X  the ground beyond the scene, below the horizon, 0..1 (default 0.2)
  --sky-rays N            sky rays per texel (default 256)
  --sun-rays N            shadow rays per texel to the sun's disc (default 32)

analysis options (bake): illuminance where there is no surface, and images to read it from
  --work-plane            a grid of sensors over the floors, facing up: OUTDIR/sensors.csv and the
                          heat map work_plane.png (seen from above, -Z up, +X right), min, mean,
                          max and uniformity (min / mean) in report.json and on stderr
  --work-plane-height M   its height over the floors (default 0.8, desks; 0 for circulation)
  --work-plane-spacing M  between the grid's points, along x and z (default 0.5)
  --work-plane-over NAMES the floors, by node name (comma-separated parts of names) (default:
                          under each point, the lowest surface facing up)
  --sensors FILE.csv      points to measure at too: a line each, x,y,z or x,y,z,nx,ny,nz (metres;
                          the meter faces +Y, up, unless given); a header line and # comments
                          are skipped
  --sensor-rays N         rays per sensor for the light surfaces send (default 1024)
  --daylight-factor       under an overcast sky without a sun (cie-overcast, uniform, cie-1 ..
                          cie-6): each sensor's and texel's illuminance over the unobstructed sky's
                          horizontal illuminance, in percent: a column of sensors.csv,
                          work_plane_daylight_factor.png and NAME_daylight_factor_N.png pages
  --false-colour SCALE    linear | log: NAME_false_colour_N.png, each page in false colour with a
                          legend in lux (log: three decades)
  --false-colour-max X|auto
                          the value at the top of the false-colour scales (default auto: the 99th
                          percentile, rounded up to 1, 2, 2.5 or 5 x 10^k)

glare options (bake): what an eye sees of the bake, and how much it glares
  --view X,Y,Z:DX,DY,DZ   an eye at X,Y,Z looking along DX,DY,DZ (up stays +Y), repeatable:
                          view_N.exr (a 180-degree fisheye of luminance, cd/m2, sky and sun
                          included), view_N.png (false colour) and, in report.json, its vertical
                          illuminance and daylight glare probability DGP (Wienold) with the glare
                          sources (docs/annual.md)
  --view-size N           fisheye pixels per side (default 512)

annual options (bake): a year of daylight at the sensors by daylight coefficients (docs/annual.md)
  --weather FILE.epw      an EnergyPlus weather file: its site and every hour's Perez sky and sun
                          (samples/weather has synthetic years); needs --sensors, --work-plane or
                          --view, takes no --sky or site. Writes annual_illuminance.f32 (float32, by
                          hour, sensor by sensor), annual_sensors.csv (DA, UDI bins, sun hours),
                          work-plane maps and, in report.json, sDA300/50%, ASE1000/250h, UDI;
                          with --view, each eye's hourly DGP (annual_dgp.f32) and the shares of
                          occupied hours over 0.35, 0.40 and 0.45
  --occupied FROM-TO      occupied hours, local standard time (default 8-18, IES LM-83)
  --da-threshold LUX      daylight autonomy's illuminance (default 300)
  --sky-subdivision M     the sky patches the surfaces' light is solved for: 1, Tregenza's 145
                          (default); 2 or 4, Reinhart's 577 or 2305 (finer, slower)

view options: a page on 127.0.0.1 showing OUTDIR's bake in three.js (and OUTDIR_B's beside it);
it serves the page, three.js and the two folders' files, nothing else
  --port N                the port (default: a free one; the address is printed)
  --no-open               do not open the page in the browser

diff options:
  --json                  machine-readable statistics on stdout
  --max-rmse PCT          fail when the relative RMSE exceeds PCT percent
  --max-p50 PCT           fail when the median relative error exceeds PCT percent (the
                          statistic least moved by noise, most by a change of overall light)
  --max-p95 PCT           fail when the 95th percentile relative error exceeds PCT percent
  --max-p99 PCT           fail when the 99th percentile relative error exceeds PCT percent
  --max-error X           fail when a texel's error exceeds X (lux, or lm/m2)
  --relative-floor PCT    percent of the reference level that relative errors are taken
                          against at least (default 10)
  --diff-images DIR       write DIR/PAGE_diff.png per page of B: white where B equals A, towards
                          red where B is brighter and blue where darker, full colour at
                          --image-scale; black where not compared
  --image-scale PCT       relative difference shown at full colour (default 10)

  -h, --help              this text
  --version               print the version

exit status: 0 done, 2 bad input or usage, 1 anything else, 130/143 ended by SIGINT/SIGTERM
(nothing is left behind);
diff: 0 when every threshold holds, 1 when one is exceeded (named on stderr), 2 bad input or usage
)";
}

namespace {

using Setter = std::function<void(const std::string&)>;
using Flag = std::function<void()>;

// The atlas options `bake` and `uv` share.
void atlas_options(AtlasOptions& a, std::map<std::string, Setter>& with_value, std::map<std::string, Flag>& flags) {
  with_value["--density"] = [&](const std::string& v) {
    a.texel_density = v == "auto" ? 0.0f : float(parse_number("--density", v, 1e-6, 1e9));
  };
  with_value["--texels"] = [&](const std::string& v) { a.automatic_texels = size_t(parse_integer("--texels", v, 16, 1L << 32)); };
  with_value["--max-page-size"] = [&](const std::string& v) { a.max_page_size = int(parse_integer("--max-page-size", v, 16, 16384)); };
  with_value["--padding"] = [&](const std::string& v) { a.padding = int(parse_integer("--padding", v, 0, 64)); };
  with_value["--lightmap-uvs"] = [&](const std::string& v) {
    if (v == "keep-valid") a.input_uvs = InputUvPolicy::KeepValid;
    else if (v == "keep") a.input_uvs = InputUvPolicy::KeepAll;
    else if (v == "generate") a.input_uvs = InputUvPolicy::Generate;
    else throw UsageError("option --lightmap-uvs must be keep-valid, keep or generate" + got(v));
  };
  with_value["--chart-angle"] = [&](const std::string& v) { a.max_chart_normal_deviation = float(parse_number("--chart-angle", v, 1, 89)); };
  flags["--no-rotate"] = [&] { a.rotate_charts = false; };
  flags["--fit-page"] = [&] { a.fit_one_page = true; };
  flags["--any-page-size"] = [&] { a.any_page_size = true; };
}

// What a scene file may make radbake read and hold; `bake` and `uv` share them.
void load_options(LoadOptions& l, std::map<std::string, Setter>& with_value, std::map<std::string, Flag>& flags) {
  flags["--allow-external-files"] = [&] { l.allow_external_files = true; };
  with_value["--max-triangles"] = [&](const std::string& v) {
    l.max_triangles = uint64_t(parse_integer("--max-triangles", v, 1, 1L << 40));
  };
  with_value["--max-memory"] = [&](const std::string& v) {
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
}

// "a,b,c" as numbers, for the options that take a direction or a pair of angles.
std::vector<double> parse_numbers(const std::string& option, const std::string& text, size_t count, double lo,
                                  double hi) {
  std::vector<double> values;
  size_t start = 0;
  for (size_t k = 0; k < count; ++k) {
    const size_t comma = k + 1 < count ? text.find(',', start) : text.size();
    if (comma == std::string::npos)
      throw UsageError("option " + option + " needs " + std::to_string(count) + " numbers separated by commas" + got(text));
    values.push_back(parse_number(option, text.substr(start, comma - start), lo, hi));
    start = comma + 1;
  }
  return values;
}

// The site and moment as typed; made into a SiteAndTime once every option is read.
struct SiteInput {
  bool latitude = false, longitude = false, date = false, time = false, utc_offset = false;
  SiteAndTime site;
  bool given() const { return latitude || longitude || date || time || utc_offset; }
};

void daylight_options(DaylightOptions& d, SiteInput& in, std::map<std::string, Setter>& with_value) {
  with_value["--sky"] = [&](const std::string& v) {
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
  with_value["--sky-illuminance"] = [&](const std::string& v) { d.sky_illuminance = parse_number("--sky-illuminance", v, 1e-6, 1e6); };
  with_value["--sun-illuminance"] = [&](const std::string& v) { d.sun_illuminance = parse_number("--sun-illuminance", v, 0, 2e5); };
  with_value["--direct-normal"] = [&](const std::string& v) { d.direct_normal_irradiance = parse_number("--direct-normal", v, 0, 1500); };
  with_value["--diffuse-horizontal"] = [&](const std::string& v) { d.diffuse_horizontal_irradiance = parse_number("--diffuse-horizontal", v, 0, 1500); };
  with_value["--dew-point"] = [&](const std::string& v) { d.dew_point = parse_number("--dew-point", v, -90, 60); };
  with_value["--sun-position"] = [&](const std::string& v) {
    const std::vector<double> za = parse_numbers("--sun-position", v, 2, -360, 360);
    if (za[0] < 0 || za[0] > 180) throw UsageError("option --sun-position: the zenith angle must be 0..180 degrees" + got(v));
    d.sun = SunPosition{za[0], za[1]};
  };
  with_value["--latitude"] = [&](const std::string& v) { in.site.latitude = parse_number("--latitude", v, -90, 90); in.latitude = true; };
  with_value["--longitude"] = [&](const std::string& v) { in.site.longitude = parse_number("--longitude", v, -180, 180); in.longitude = true; };
  with_value["--elevation"] = [&](const std::string& v) { in.site.elevation = parse_number("--elevation", v, -500, 9000); };
  with_value["--pressure"] = [&](const std::string& v) { in.site.pressure = parse_number("--pressure", v, 300, 1100); };
  with_value["--temperature"] = [&](const std::string& v) { in.site.temperature = parse_number("--temperature", v, -90, 60); };
  with_value["--utc-offset"] = [&](const std::string& v) { in.site.utc_offset = parse_number("--utc-offset", v, -12, 14); in.utc_offset = true; };
  with_value["--date"] = [&](const std::string& v) {
    int year = 0, month = 0, day = 0, used = 0;
    if (std::sscanf(v.c_str(), "%4d-%2d-%2d%n", &year, &month, &day, &used) != 3 || size_t(used) != v.size() ||
        month < 1 || month > 12 || day < 1 || day > 31 || year < 1 || year > 9999)
      throw UsageError("option --date needs YYYY-MM-DD" + got(v));
    in.site.year = year;
    in.site.month = month;
    in.site.day = day;
    in.date = true;
  };
  with_value["--time"] = [&](const std::string& v) {
    int hour = 0, minute = 0, used = 0;
    double second = 0;
    const int fields = std::sscanf(v.c_str(), "%2d:%2d%n:%lf%n", &hour, &minute, &used, &second, &used);
    if (fields < 2 || size_t(used) != v.size() || hour > 24 || minute > 59 || second < 0 || second >= 60 || hour < 0 ||
        minute < 0)
      throw UsageError("option --time needs HH:MM or HH:MM:SS, local clock time" + got(v));
    in.site.hour = hour;
    in.site.minute = minute;
    in.site.second = second;
    in.time = true;
  };
  with_value["--north"] = [&](const std::string& v) {
    if (v.find(',') == std::string::npos) {
      // Rounded so that whole quarter turns give exact axes (cos 90 degrees is 6e-17, not 0).
      const double turn = parse_number("--north", v, -360, 360) * M_PI / 180;
      auto rounded = [](double x) { return float(std::round(x * 1e9) / 1e9) + 0.0f; };  // + 0: no -0
      d.north = {rounded(std::sin(turn)), 0, rounded(-std::cos(turn))};
    } else {
      const std::vector<double> n = parse_numbers("--north", v, 3, -1e6, 1e6);
      d.north = {float(n[0]), float(n[1]), float(n[2])};
    }
  };
  with_value["--ground-reflectance"] = [&](const std::string& v) { d.ground_reflectance = parse_number("--ground-reflectance", v, 0, 1); };
  with_value["--sky-rays"] = [&](const std::string& v) { d.sky_rays = uint32_t(parse_integer("--sky-rays", v, 1, 1 << 20)); };
  with_value["--sun-rays"] = [&](const std::string& v) { d.sun_rays = uint32_t(parse_integer("--sun-rays", v, 1, 1 << 16)); };
}

// The site's options come as a set: a sun position needs all four of latitude, longitude, date
// and time; the UTC offset defaults to the nominal zone of the longitude (no daylight saving).
void finish_site(DaylightOptions& d, SiteInput& in) {
  const int given = in.latitude + in.longitude + in.date + in.time;
  if (given == 0) return;
  if (given < 4)
    throw UsageError(std::string("a site and time needs --latitude, --longitude, --date and --time; missing") +
                     (in.latitude ? "" : " --latitude") + (in.longitude ? "" : " --longitude") +
                     (in.date ? "" : " --date") + (in.time ? "" : " --time"));
  if (d.sun) throw UsageError("--sun-position and a site and time both say where the sun is: give one");
  if (!in.utc_offset) in.site.utc_offset = std::round(in.site.longitude / 15);
  d.site = in.site;
}

// Reads `args` from position 1: options from the two tables, positional arguments to `positional`.
void parse_options(const std::vector<std::string>& args, const std::map<std::string, Setter>& with_value,
                   const std::map<std::string, Flag>& flags, const std::function<void(const std::string&)>& positional,
                   bool& help) {
  for (size_t i = 1; i < args.size(); ++i) {
    std::string arg = args[i];
    if (arg == "-h" || arg == "--help") {
      help = true;
      return;
    }
    if (auto flag = flags.find(arg); flag != flags.end()) {
      flag->second();
      continue;
    }
    if (arg.empty() || arg[0] != '-') {
      positional(arg);
      continue;
    }
    std::string value;
    bool inline_value = false;
    if (arg == "-o") arg = "--output";
    if (size_t eq = arg.find('='); arg.rfind("--", 0) == 0 && eq != std::string::npos) {
      value = arg.substr(eq + 1);
      arg = arg.substr(0, eq);
      inline_value = true;
    }
    auto setter = with_value.find(arg);
    if (setter == with_value.end()) throw UsageError("unknown option " + clipped(arg) + " (see radbake --help)");
    if (!inline_value) {
      if (i + 1 >= args.size()) throw UsageError("option " + arg + " needs a value");
      value = args[++i];
    }
    setter->second(value);
  }
}

void parse_uv(const std::vector<std::string>& args, CommandLine& cl) {
  UvCommand& u = cl.uv;
  std::map<std::string, Setter> with_value;
  std::map<std::string, Flag> flags;
  atlas_options(u.atlas, with_value, flags);
  load_options(u.load, with_value, flags);
  with_value["--evaluate-texcoord"] = [&](const std::string& v) { u.evaluate_texcoord = int(parse_integer("--evaluate-texcoord", v, 0, 7)); };
  flags["--stats"] = [] {};  // statistics are what `uv` prints; the flag is accepted for clarity
  flags["--json"] = [&] { u.json = true; };
  bool help = false;
  parse_options(args, with_value, flags, [&](const std::string& arg) {
    if (!u.input.empty()) throw UsageError("unexpected argument '" + clipped(arg) + "' (one scene at a time)");
    u.input = arg;
  }, help);
  if (help) {
    cl.action = Action::Help;
    return;
  }
  if (u.input.empty()) throw UsageError("missing input scene (radbake uv SCENE.gltf --stats)");
}

void parse_diff(const std::vector<std::string>& args, CommandLine& cl) {
  DiffCommand& d = cl.diff;
  std::map<std::string, Setter> with_value = {
      {"--max-rmse", [&](const std::string& v) { d.limits.rmse = parse_percent("--max-rmse", v, 0); }},
      {"--max-p50", [&](const std::string& v) { d.limits.p50 = parse_percent("--max-p50", v, 0); }},
      {"--max-p95", [&](const std::string& v) { d.limits.p95 = parse_percent("--max-p95", v, 0); }},
      {"--max-p99", [&](const std::string& v) { d.limits.p99 = parse_percent("--max-p99", v, 0); }},
      {"--max-error", [&](const std::string& v) { d.limits.max_error = parse_number("--max-error", v, 0, 1e30); }},
      {"--relative-floor",
       [&](const std::string& v) { d.difference.relative_floor = parse_percent("--relative-floor", v, 1e-6); }},
      {"--image-scale",
       [&](const std::string& v) { d.difference.image_scale = parse_percent("--image-scale", v, 1e-6); }},
      {"--diff-images", [&](const std::string& v) { d.image_folder = v; }},
  };
  std::map<std::string, Flag> flags = {{"--json", [&] { d.json = true; }}};
  bool help = false;
  parse_options(args, with_value, flags, [&](const std::string& arg) {
    if (d.reference.empty()) d.reference = arg;
    else if (d.candidate.empty()) d.candidate = arg;
    else throw UsageError("unexpected argument '" + clipped(arg) + "' (radbake diff compares two bakes)");
  }, help);
  if (help) {
    cl.action = Action::Help;
    return;
  }
  if (d.candidate.empty()) throw UsageError("missing bakes to compare (radbake diff A B)");
}

void parse_view(const std::vector<std::string>& args, CommandLine& cl) {
  ViewCommand& v = cl.view;
  std::map<std::string, Setter> with_value = {
      {"--port", [&](const std::string& text) { v.port = int(parse_integer("--port", text, 1, 65535)); }},
  };
  std::map<std::string, Flag> flags = {{"--no-open", [&] { v.open = false; }}};
  bool help = false;
  parse_options(args, with_value, flags, [&](const std::string& arg) {
    if (v.folders.size() == 2) throw UsageError("unexpected argument '" + clipped(arg) + "' (radbake view shows one bake, or two to compare)");
    v.folders.push_back(arg);
  }, help);
  if (help) {
    cl.action = Action::Help;
    return;
  }
  if (v.folders.empty()) throw UsageError("missing output folder (radbake view OUTDIR [OUTDIR_B])");
}

}  // namespace

CommandLine parse_command_line(const std::vector<std::string>& args) {
  CommandLine cl;
  if (args.empty()) throw UsageError("missing command (try radbake --help)");
  if (args[0] == "-h" || args[0] == "--help" || args[0] == "help") return cl;
  if (args[0] == "--version") {
    cl.action = Action::Version;
    return cl;
  }
  if (args[0] == "uv") {
    cl.action = Action::Uv;
    parse_uv(args, cl);
    return cl;
  }
  if (args[0] == "diff") {
    cl.action = Action::Diff;
    parse_diff(args, cl);
    return cl;
  }
  if (args[0] == "view") {
    cl.action = Action::View;
    parse_view(args, cl);
    return cl;
  }
  if (args[0] != "bake" && args[0] != "merge")
    throw UsageError("unknown command '" + clipped(args[0]) + "' (try radbake --help)");
  cl.action = args[0] == "merge" ? Action::Merge : Action::Bake;
  BakeCommand& b = cl.bake;
  b.merge = cl.action == Action::Merge;
  auto slice = [&](const std::string& option, GatherSlice::By by, const std::string& v) {
    int k = 0, n = 0;
    char extra = 0;
    if (std::sscanf(v.c_str(), "%d/%d%c", &k, &n, &extra) != 2 || n < 1 || n > 100000 || k < 1 || k > n)
      throw UsageError("option " + option + " needs K/N with 1 <= K <= N (slice K of N)" + got(v));
    if (b.bake.sharing.slice.by != GatherSlice::By::Everything) throw UsageError("give one of --pages and --texel-range");
    b.bake.sharing.slice = {by, k - 1, n};
  };

  std::map<std::string, Setter> with_value = {
      {"--output", [&](const std::string& v) { b.output = v; }},
      {"--method", [&](const std::string& v) {
         if (v == "radiosity") b.bake.method = Method::Radiosity;
         else if (v == "pathtrace") b.bake.method = Method::PathTrace;
         else throw UsageError("option --method must be radiosity or pathtrace" + got(v));
       }},
      {"--samples", [&](const std::string& v) { b.bake.path_trace.samples = uint32_t(parse_integer("--samples", v, 2, 1 << 24)); }},
      {"--tolerance", [&](const std::string& v) { b.bake.solve.tolerance = parse_number("--tolerance", v, 1e-9, 1); }},
      {"--solver", [&](const std::string& v) {
         if (v == "shooting") b.bake.solve.solver = Solver::Shooting;
         else if (v == "gauss-seidel") b.bake.solve.solver = Solver::GaussSeidel;
         else if (v == "jacobi") b.bake.solve.solver = Solver::Jacobi;
         else throw UsageError("option --solver must be shooting, gauss-seidel or jacobi" + got(v));
       }},
      {"--threads", [&](const std::string& v) { b.bake.threads = int(parse_integer("--threads", v, 0, 1024)); }},
      {"--seed", [&](const std::string& v) { b.bake.seed = uint64_t(parse_integer("--seed", v, 0, 1L << 53)); }},
      {"--store", [&](const std::string& v) {
         if (v == "irradiance") b.bake.store = StoredQuantity::Irradiance;
         else if (v == "radiosity") b.bake.store = StoredQuantity::Radiosity;
         else throw UsageError("option --store must be irradiance or radiosity" + got(v));
       }},
      {"--gather-rays", [&](const std::string& v) { b.bake.gather_rays = uint32_t(parse_integer("--gather-rays", v, 1, 1 << 20)); }},
      {"--gather-filter", [&](const std::string& v) { b.bake.gather_filter.radius = int(parse_integer("--gather-filter", v, 0, 16)); }},
      {"--gather-filter-validity", [&](const std::string& v) { b.bake.gather_filter.validity = float(parse_number("--gather-filter-validity", v, 0.01, 100)); }},
      {"--patch-rays", [&](const std::string& v) { b.bake.form_factors.rays_per_patch = uint32_t(parse_integer("--patch-rays", v, 16, 1 << 24)); }},
      {"--form-factors", [&](const std::string& v) {
         if (v == "raycast") b.bake.form_factors.method = FormFactorMethod::RayCast;
         else if (v == "hemicube") b.bake.form_factors.method = FormFactorMethod::Hemicube;
         else throw UsageError("option --form-factors must be raycast or hemicube" + got(v));
       }},
      {"--hemicube-resolution", [&](const std::string& v) {
         long r = parse_integer("--hemicube-resolution", v, 2, 4096);
         if (r % 2) throw UsageError("option --hemicube-resolution must be even" + got(v));
         b.bake.form_factors.hemicube_resolution = int(r);
       }},
      {"--subdivide", [&](const std::string& v) { b.bake.subdivision.tolerance = parse_number("--subdivide", v, 0, 10); }},
      {"--subdivide-rounds", [&](const std::string& v) { b.bake.subdivision.max_rounds = int(parse_integer("--subdivide-rounds", v, 1, 12)); }},
      {"--preview-every", [&](const std::string& v) { b.bake.preview_every = size_t(parse_integer("--preview-every", v, 0, 1L << 40)); }},
      {"--quality", [](const std::string&) {}},  // applied before the others, below
      {"--area-light-rays", [&](const std::string& v) { b.bake.direct.area_light_rays = int(parse_integer("--area-light-rays", v, 1, 1 << 16)); }},
      {"--light-rays", [&](const std::string& v) { b.bake.direct.punctual_rays = int(parse_integer("--light-rays", v, 1, 1 << 16)); }},
      {"--patch-size", [&](const std::string& v) {
         long size = parse_integer("--patch-size", v, 0, 16384);
         if (size & (size - 1)) throw UsageError("option --patch-size must be 0 (auto) or a power of two up to 16384" + got(v));
         b.bake.patches.block_size = int(size);
       }},
      {"--sensors", [&](const std::string& v) { b.sensor_file = v; }},
      {"--weather", [&](const std::string& v) { b.weather_file = v; }},
      {"--directional", [&](const std::string& v) {
         if (v == "none") b.bake.directional = Directional::None;
         else if (v == "sh") b.bake.directional = Directional::SphericalHarmonics;
         else if (v == "dominant") b.bake.directional = Directional::Dominant;
         else throw UsageError("option --directional must be none, sh or dominant" + got(v));
       }},
      {"--probes", [&](const std::string& v) {
         b.bake.probes.enabled = v != "none";
         b.bake.probes.spacing = v == "auto" || v == "none" ? 0.0f : float(parse_number("--probes", v, 1e-3, 1e6));
       }},
      {"--probe-rays", [&](const std::string& v) { b.bake.probes.rays = uint32_t(parse_integer("--probe-rays", v, 16, 1 << 20)); }},
      {"--checkpoint", [&](const std::string& v) { b.checkpoint = v; }},
      {"--checkpoint-every", [&](const std::string& v) {
         b.bake.sharing.solve_save_seconds = parse_number("--checkpoint-every", v, 0, 1e7);
       }},
      {"--stop-after", [&](const std::string& v) {
         if (v == "direct-light") b.bake.sharing.stop_after = StopAfter::DirectLight;
         else if (v == "form-factors") b.bake.sharing.stop_after = StopAfter::FormFactors;
         else if (v == "radiosity") b.bake.sharing.stop_after = StopAfter::Radiosity;
         else throw UsageError("option --stop-after must be direct-light, form-factors or radiosity" + got(v));
       }},
      {"--pages", [&](const std::string& v) { slice("--pages", GatherSlice::By::Pages, v); }},
      {"--texel-range", [&](const std::string& v) { slice("--texel-range", GatherSlice::By::Texels, v); }},
      {"--view", [&](const std::string& v) {
         float n[6];
         char tail = 0;
         if (std::sscanf(v.c_str(), "%f,%f,%f:%f,%f,%f%c", &n[0], &n[1], &n[2], &n[3], &n[4], &n[5], &tail) != 6 ||
             !std::all_of(n, n + 6, [](float x) { return std::isfinite(x); }))
           throw UsageError("option --view must be X,Y,Z:DX,DY,DZ (the eye and where it looks, metres)" + got(v));
         const Vec3 direction{n[3], n[4], n[5]};
         if (!(length(direction) > 0)) throw UsageError("option --view needs a direction to look in" + got(v));
         b.bake.views.push_back({{n[0], n[1], n[2]}, normalize(direction), {0, 1, 0}});
       }},
      {"--view-size", [&](const std::string& v) { b.bake.view.size = int(parse_integer("--view-size", v, 16, 4096)); }},
      {"--occupied", [&](const std::string& v) {
         const size_t dash = v.find('-');
         if (dash == std::string::npos) throw UsageError("option --occupied must be FROM-TO in hours, as 8-18" + got(v));
         b.occupied_from = int(parse_integer("--occupied", v.substr(0, dash), 0, 23));
         b.occupied_to = int(parse_integer("--occupied", v.substr(dash + 1), 1, 24));
         if (b.occupied_to <= b.occupied_from) throw UsageError("option --occupied must end after it starts" + got(v));
       }},
      {"--da-threshold", [&](const std::string& v) { b.metrics.da_threshold = parse_number("--da-threshold", v, 1, 1e6); }},
      {"--sky-subdivision", [&](const std::string& v) { b.sky_subdivision = int(parse_integer("--sky-subdivision", v, 1, 4)); }},
      {"--sensor-rays", [&](const std::string& v) { b.bake.sensor.rays = uint32_t(parse_integer("--sensor-rays", v, 1, 1 << 24)); }},
      {"--work-plane-height", [&](const std::string& v) {
         b.bake.work_plane.height = parse_number("--work-plane-height", v, 0, 1000);
       }},
      {"--work-plane-spacing", [&](const std::string& v) { b.bake.work_plane.spacing = parse_number("--work-plane-spacing", v, 0.001, 1000); }},
      {"--work-plane-over", [&](const std::string& v) {
         b.bake.work_plane.over.clear();
         std::stringstream names(v);
         for (std::string name; std::getline(names, name, ',');)
           if (!name.empty()) b.bake.work_plane.over.push_back(name);
         if (b.bake.work_plane.over.empty()) throw UsageError("option --work-plane-over needs names" + got(v));
       }},
      {"--false-colour", [&](const std::string& v) {
         if (v == "linear") b.analysis.scale.logarithmic = false;
         else if (v == "log") b.analysis.scale.logarithmic = true;
         else throw UsageError("option --false-colour must be linear or log" + got(v));
         b.analysis.false_colour_pages = true;
       }},
      {"--false-colour-max", [&](const std::string& v) {
         b.analysis.scale.max = v == "auto" ? 0.0 : parse_number("--false-colour-max", v, 1e-9, 1e12);
       }},
      {"--glazing-transmittance", [&](const std::string& v) { b.bake.glazing_transmittance = float(parse_number("--glazing-transmittance", v, 0, 1)); }},
      {"--emission-scale", [&](const std::string& v) { b.bake.emission_scale = float(parse_number("--emission-scale", v, 1e-6, 1e9)); }},
      {"--png-scale", [&](const std::string& v) { b.png_scale = v == "auto" ? 0.0f : float(parse_number("--png-scale", v, 1e-30, 1e30)); }},
      {"--display", [&](const std::string& v) {
         if (v == "page") b.display = DisplayMode::Page;
         else if (v == "vertex") b.display = DisplayMode::Vertex;
         else if (v == "none") b.display = DisplayMode::None;
         else throw UsageError("option --display must be page, vertex or none" + got(v));
       }},
      {"--display-detail", [&](const std::string& v) {
         if (v == "auto") b.display_detail = 0;
         else if (v == "1" || v == "2" || v == "4") b.display_detail = std::stoi(v);
         else throw UsageError("option --display-detail must be 1, 2, 4 or auto" + got(v));
       }},
      {"--exposure", [&](const std::string& v) { b.exposure.exposure = v == "auto" ? 0.0f : float(parse_number("--exposure", v, 1e-30, 1e30)); }},
      {"--vertex-refine", [&](const std::string& v) { b.vertex_refine_triangles = size_t(parse_integer("--vertex-refine", v, 0, 100000000)); }},
      {"--key", [&](const std::string& v) { b.exposure.key = float(parse_number("--key", v, 1e-6, 1)); }},
      {"--color-0", [&](const std::string& v) {
         if (v == "source") b.color_0 = Color0::Source;
         else if (v == "light") b.color_0 = Color0::Light;
         else if (v == "prelit") b.color_0 = Color0::Prelit;
         else throw UsageError("option --color-0 must be source, light or prelit" + got(v));
       }},
  };
  std::map<std::string, Flag> flags = {
      {"--quiet", [&] { b.quiet = true; }},
      {"--debug-dumps", [&] { b.debug_dumps = true; }},
      {"--no-ambient", [&] { b.bake.solve.ambient_term = false; }},
      {"--direct-only", [&] { b.bake.plan.direct_only = true; }},
      {"--no-near-field", [&] { b.bake.near_field = false; }},
      {"--simulate-everything", [&] { b.bake.plan.simulate_everything = true; }},
      {"--daylight-factor", [&] { b.daylight_factor = true; }},
      {"--work-plane", [&] { b.bake.work_plane.enabled = true; }},
      {"--resume", [&] { b.bake.sharing.resume = true; }},
  };
  atlas_options(b.atlas, with_value, flags);
  load_options(b.load, with_value, flags);
  SiteInput site;
  daylight_options(b.daylight, site, with_value);
  // The preset (preview unless one is named) goes first wherever it stands, so options given with
  // it override it.
  std::string quality = "preview";
  for (size_t i = 1; i + 1 < args.size(); ++i)
    if (args[i] == "--quality") quality = args[i + 1];
  apply_quality_preset(quality, b.bake);
  bool help = false;
  parse_options(args, with_value, flags, [&](const std::string& arg) {
    if (!b.input.empty()) throw UsageError("unexpected argument '" + clipped(arg) + "' (one scene per bake)");
    b.input = arg;
  }, help);
  if (help) {
    cl.action = Action::Help;
    return cl;
  }
  if (b.input.empty()) throw UsageError("missing input scene (radbake bake SCENE.gltf -o OUTDIR)");
  const bool sliced = b.bake.sharing.slice.by != GatherSlice::By::Everything;
  const bool stops = b.bake.sharing.stop_after != StopAfter::Nothing;
  if (b.output.empty() && !sliced && !stops) throw UsageError("missing -o OUTDIR");
  if ((sliced || stops || b.bake.sharing.resume || b.merge) && b.checkpoint.empty())
    throw UsageError(std::string(b.merge ? "radbake merge" : sliced ? "--pages and --texel-range" : stops ? "--stop-after" : "--resume") +
                     " needs --checkpoint DIR");
  if (sliced && stops) throw UsageError("a slice stops after its part of the final gather: leave out --stop-after");
  if (b.merge && (sliced || stops)) throw UsageError("radbake merge joins slices: leave out --pages, --texel-range and --stop-after");
  if (!b.output.empty() && (sliced || stops))
    throw UsageError("a slice or a stopped bake writes only its checkpoint: leave out -o (radbake merge writes the output)");
  if (b.merge) b.bake.sharing.resume = true;
  if (b.bake.directional != Directional::None &&
      (b.bake.store != StoredQuantity::Irradiance || b.bake.method != Method::Radiosity))
    throw UsageError("directional lightmaps are of the radiosity bake's irradiance: --method radiosity, --store irradiance");
  if (b.bake.plan.direct_only && b.bake.plan.simulate_everything)
    throw UsageError("--direct-only and --simulate-everything contradict each other");
  if (!b.weather_file.empty()) {
    if (b.daylight.sky != SkyKind::None) throw UsageError("--weather gives every hour its sky: leave out --sky");
    if (site.given()) throw UsageError("--weather gives the site: leave out --latitude, --longitude, --date and --time");
    if (b.sensor_file.empty() && !b.bake.work_plane.enabled && b.bake.views.empty())
      throw UsageError("--weather needs --sensors, --work-plane or --view: the year's results are per sensor or eye");
    if (b.bake.method != Method::Radiosity) throw UsageError("--weather needs --method radiosity");
    if (b.daylight_factor) throw UsageError("--daylight-factor is for one overcast sky, not a year of weather");
  }
  finish_site(b.daylight, site);
  if (b.daylight_factor && b.bake.store != StoredQuantity::Irradiance)
    throw UsageError("--daylight-factor needs --store irradiance: it is the ratio of illuminances");

  // The report lists every option with the value the bake used, read back from the structs so
  // the listing cannot drift from the defaults.
  auto number = [](double v) {
    std::ostringstream out;
    out << v;
    return out.str();
  };
  const char* solver_names[] = {"shooting", "gauss-seidel", "jacobi"};
  b.effective = {
      {"density", b.atlas.texel_density > 0 ? number(b.atlas.texel_density) : "auto"},
      {"texels", number(double(b.atlas.automatic_texels))},
      {"max-page-size", number(b.atlas.max_page_size)},
      {"padding", number(b.atlas.padding)},
      {"method", b.bake.method == Method::Radiosity ? "radiosity" : "pathtrace"},
      {"samples", number(b.bake.path_trace.samples)},
      {"tolerance", number(b.bake.solve.tolerance)},
      {"solver", solver_names[int(b.bake.solve.solver)]},
      {"threads", number(b.bake.threads)},
      {"seed", number(double(b.bake.seed))},
      {"store", b.bake.store == StoredQuantity::Irradiance ? "irradiance" : "radiosity"},
      {"gather-rays", number(b.bake.gather_rays)},
      {"gather-filter", number(b.bake.gather_filter.radius)},
      {"gather-filter-validity", number(b.bake.gather_filter.validity)},
      {"quality", quality},
      {"form-factors", b.bake.form_factors.method == FormFactorMethod::RayCast ? "raycast" : "hemicube"},
      {"patch-rays", number(b.bake.form_factors.rays_per_patch)},
      {"hemicube-resolution", number(b.bake.form_factors.hemicube_resolution)},
      {"subdivide", number(b.bake.subdivision.tolerance)},
      {"subdivide-rounds", number(b.bake.subdivision.max_rounds)},
      {"preview-every", number(double(b.bake.preview_every))},
      {"area-light-rays", number(b.bake.direct.area_light_rays)},
      {"light-rays", number(b.bake.direct.punctual_rays)},
      {"patch-size", b.bake.patches.block_size > 0 ? number(b.bake.patches.block_size) : "auto"},
      {"png-scale", b.png_scale > 0 ? number(b.png_scale) : "auto"},
      {"display", b.display == DisplayMode::Page ? "page" : b.display == DisplayMode::Vertex ? "vertex" : "none"},
      {"display-detail", b.display_detail > 0 ? number(b.display_detail) : "auto"},
      {"exposure", b.exposure.exposure > 0 ? number(b.exposure.exposure) : "auto"},
      {"key", number(b.exposure.key)},
      {"vertex-refine", number(double(b.vertex_refine_triangles))},
      {"color-0", b.color_0 == Color0::Source ? "source" : b.color_0 == Color0::Light ? "light" : "prelit"},
      {"emission-scale", number(b.bake.emission_scale)},
      {"sensors", b.sensor_file.empty() ? "none" : b.sensor_file},
      {"sensor-rays", number(b.bake.sensor.rays)},
      {"work-plane", b.bake.work_plane.enabled ? "yes" : "no"},
      {"work-plane-height", number(b.bake.work_plane.height)},
      {"work-plane-spacing", number(b.bake.work_plane.spacing)},
      {"daylight-factor", b.daylight_factor ? "yes" : "no"},
      {"weather", b.weather_file.empty() ? "none" : b.weather_file},
      {"occupied", number(b.occupied_from) + "-" + number(b.occupied_to)},
      {"da-threshold", number(b.metrics.da_threshold)},
      {"sky-subdivision", number(b.sky_subdivision)},
      {"false-colour", !b.analysis.false_colour_pages ? "none" : b.analysis.scale.logarithmic ? "log" : "linear"},
      {"false-colour-max", b.analysis.scale.max > 0 ? number(b.analysis.scale.max) : "auto"},
      {"glazing-transmittance", b.bake.glazing_transmittance >= 0 ? number(b.bake.glazing_transmittance) : "clear pane"},
      {"ambient", b.bake.solve.ambient_term ? "yes" : "no"},
      {"direct-only", b.bake.plan.direct_only ? "yes" : "no"},
      {"near-field", b.bake.near_field ? "yes" : "no"},
      {"probes", !b.bake.probes.enabled ? "none" : b.bake.probes.spacing > 0 ? number(b.bake.probes.spacing) : "auto"},
      {"probe-rays", number(b.bake.probes.rays)},
      {"directional", b.bake.directional == Directional::None ? "none"
                      : b.bake.directional == Directional::Dominant ? "dominant" : "sh"},
      {"simulate-everything", b.bake.plan.simulate_everything ? "yes" : "no"},
      {"rotate-charts", b.atlas.rotate_charts ? "yes" : "no"},
      {"fit-page", b.atlas.fit_one_page ? "yes" : "no"},
      {"any-page-size", b.atlas.any_page_size ? "yes" : "no"},
      {"lightmap-uvs", b.atlas.input_uvs == InputUvPolicy::KeepValid ? "keep-valid"
                       : b.atlas.input_uvs == InputUvPolicy::KeepAll ? "keep" : "generate"},
      {"chart-angle", number(b.atlas.max_chart_normal_deviation)},
      {"allow-external-files", b.load.allow_external_files ? "yes" : "no"},
      {"max-memory", b.load.max_memory_bytes ? std::to_string(b.load.max_memory_bytes) : "auto"},
      {"max-triangles", std::to_string(b.load.max_triangles)},
  };
  const DaylightOptions& d = b.daylight;
  if (d.sky != SkyKind::None) {
    b.effective.insert(b.effective.end(), {
        {"sky", d.sky == SkyKind::Uniform       ? "uniform"
                : d.sky == SkyKind::CieOvercast ? "cie-overcast"
                : d.sky == SkyKind::Perez       ? "perez"
                                                : "cie-" + number(d.cie_type)},
        {"sky-illuminance", number(d.sky_illuminance)},
        {"sun-illuminance", number(d.sun_illuminance.value_or(0))},
        {"north", number(d.north.x) + "," + number(d.north.y) + "," + number(d.north.z)},
        {"ground-reflectance", number(d.ground_reflectance)},
        {"sky-rays", number(d.sky_rays)},
        {"sun-rays", number(d.sun_rays)},
    });
    if (d.sun) b.effective.push_back({"sun-position", number(d.sun->zenith) + "," + number(d.sun->azimuth)});
    if (d.sky == SkyKind::Perez) {
      b.effective.push_back({"direct-normal", number(d.direct_normal_irradiance)});
      b.effective.push_back({"diffuse-horizontal", number(d.diffuse_horizontal_irradiance)});
      b.effective.push_back({"dew-point", d.dew_point ? number(*d.dew_point) : "none (2 cm of precipitable water)"});
    }
    if (d.site) {
      char date[16];
      std::snprintf(date, sizeof date, "%04d-%02d-%02d", d.site->year, d.site->month, d.site->day);
      b.effective.insert(b.effective.end(), {
          {"latitude", number(d.site->latitude)}, {"longitude", number(d.site->longitude)},
          {"elevation", number(d.site->elevation)}, {"utc-offset", number(d.site->utc_offset)},
          {"date", date}, {"time", number(d.site->hour) + ":" + number(d.site->minute) + ":" + number(d.site->second)},
          {"pressure", number(d.site->pressure)}, {"temperature", number(d.site->temperature)},
      });
    }
  }
  return cl;
}

}  // namespace radbake
