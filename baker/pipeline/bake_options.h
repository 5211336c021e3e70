// What a bake is asked to do: every stage's options with their defaults and units, and the rules
// that combine them (validate), which the command line and bake() both apply.
#pragma once

#include <cstdint>
#include <vector>

#include "baker/direct/direct_light.h"
#include "baker/finish/directional_lightmaps.h"
#include "baker/gather/final_gather.h"
#include "baker/pipeline/plan.h"
#include "baker/readings/light_probes.h"
#include "baker/readings/luminance_view.h"
#include "baker/readings/sensor_points.h"
#include "baker/readings/work_plane.h"
#include "baker/sharing/sharing.h"
#include "baker/surface/elements.h"
#include "baker/surface/glazing.h"
#include "baker/transport/interreflection.h"
#include "baker/transport/patches.h"
#include "baker/transport/path_tracer.h"
#include "baker/transport/solve_radiosity.h"
#include "daylight/daylight_sky.h"
#include "daylight/sky.h"

namespace radbake {

// What a lightmap texel and a COLOR_0 value hold.
enum class StoredQuantity {
  Irradiance,  // lux (lm/m2 arriving): what a light meter lying on the surface reads
  Radiosity,   // lm/m2 leaving: emission plus reflected light
};

// How the light at each texel is computed.
enum class Method {
  Radiosity,  // patches, form factors, the radiosity solve and a final gather: the baker
  PathTrace,  // unbiased Monte Carlo per texel: the independent reference the baker is measured against
};

struct BakeOptions {
  Method method = Method::Radiosity;
  PathTraceOptions path_trace;  // with Method::PathTrace
  PlanOptions plan;
  ElementOptions elements;
  PatchOptions patches;
  DirectLightOptions direct;
  FormFactorOptions form_factors;
  SubdivisionOptions subdivision;
  SolveOptions solve;
  GatherOptions gather;         // the final gather (final_gather.h)
  SkyLight sky;                 // a sky lighting the scene besides its lamps (sky_light.h); radiosity only
  std::vector<Sensor> sensors;  // points in the air to measure illuminance at (sensor_points.h)
  std::vector<EyeView> views;   // eyes to render a fisheye luminance image and its glare for (luminance_view.h)
  ViewOptions view;
  WorkPlaneOptions work_plane;  // and a grid of them over the floors
  SensorOptions sensor;
  uint64_t seed = 1;            // same seed, same input: bit-identical output, whatever the thread count
  int threads = 0;              // 0: all cores
  StoredQuantity store = StoredQuantity::Irradiance;
  float emission_scale = 1;     // multiplies glTF emission before it is read as cd/m2 (see README)
  Glazing glazing;              // KHR_materials_transmission's panes (baker/surface/glazing.h)
  bool keep_direct = false;     // keep BakeResult::direct (for debug dumps); costs 12 bytes per texel
  size_t preview_every = 0;     // with a preview callback: pages of the estimate every N shots or sweeps
  Sharing sharing;              // a team of processes, a checkpoint, a slice of the gather (sharing.h)
  Directional directional = Directional::None;  // pages of where the light comes from (directional_lightmaps.h)
  ProbeOptions probes;          // light probes in the empty space (light_probes.h)
};

// What a run asks of a bake besides its options, for validate(): what the command line knows
// before the files are read and the checkpoint is opened.
struct BakeRun {
  bool year = false;             // a year of weather (--weather) instead of one sky
  bool sensors = false;          // sensors will be read from a file (options.sensors is empty until then)
  bool daylight_factor = false;  // readings over the unobstructed sky's horizontal illuminance
  bool checkpoint = false;       // a checkpoint will hold the stages (Sharing::store is made later)
  bool merge = false;            // the final gather comes from slices in the checkpoint (radbake merge)
};

// Throws InputError, naming the options as the command line spells them, when options contradict
// each other or the run: a slice or a stop without a checkpoint, directional pages of anything but
// the radiosity bake's irradiance, a year with a sky or site of its own, and the like. `daylight`
// is what becomes options.sky (daylight_sky); bake() checks its own options with the defaults.
void validate(const BakeOptions& options, const DaylightOptions& daylight = {}, const BakeRun& run = {});

// The options of the light between surfaces (baker/transport/interreflection.h), as these set them.
InterreflectionOptions interreflection_options(const BakeOptions& options);

}  // namespace radbake
