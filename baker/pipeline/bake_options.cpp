#include "baker/pipeline/bake_options.h"

#include <string>

#include "base/errors.h"

namespace radbake {

void validate(const BakeOptions& options, const DaylightOptions& daylight, const BakeRun& run) {
  const Sharing& sharing = options.sharing;
  const bool sliced = sharing.slice.by != GatherSlice::By::Everything;
  const bool stops = sharing.stop_after != StopAfter::Nothing;
  const bool merges = run.merge || sharing.merge_slices > 0;
  if ((sliced || stops || sharing.resume || merges) && !run.checkpoint && !sharing.store)
    throw InputError(std::string(merges   ? "radbake merge"
                                 : sliced ? "--pages and --texel-range"
                                 : stops  ? "--stop-after"
                                          : "--resume") +
                     " needs --checkpoint DIR");
  if (sliced && stops) throw InputError("a slice stops after its part of the final gather: leave out --stop-after");
  if (merges && (sliced || stops))
    throw InputError("radbake merge joins slices: leave out --pages, --texel-range and --stop-after");
  if (options.directional != Directional::None &&
      (options.store != StoredQuantity::Irradiance || options.method != Method::Radiosity))
    throw InputError("directional lightmaps are of the radiosity bake's irradiance: --method radiosity, --store irradiance");
  if (options.plan.direct_only && options.plan.simulate_everything)
    throw InputError("--direct-only and --simulate-everything contradict each other");
  if (run.year) {
    if (daylight.sky != SkyKind::None) throw InputError("--weather gives every hour its sky: leave out --sky");
    if (daylight.site) throw InputError("--weather gives the site: leave out --latitude, --longitude, --date and --time");
    if (!run.sensors && options.sensors.empty() && !options.work_plane.enabled && options.views.empty())
      throw InputError("--weather needs --sensors, --work-plane or --view: the year's results are per sensor or eye");
    if (options.method != Method::Radiosity) throw InputError("--weather needs --method radiosity");
    if (run.daylight_factor) throw InputError("--daylight-factor is for one overcast sky, not a year of weather");
  }
  if (daylight.site && daylight.sun)
    throw InputError("--sun-position and a site and time both say where the sun is: give one");
  if (run.daylight_factor && options.store != StoredQuantity::Irradiance)
    throw InputError("--daylight-factor needs --store irradiance: it is the ratio of illuminances");
}

InterreflectionOptions interreflection_options(const BakeOptions& options) {
  return {options.patches, options.form_factors, options.subdivision, options.solve, options.seed};
}

}  // namespace radbake
