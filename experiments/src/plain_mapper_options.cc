#include "cogmap/experiments/plain_mapper_options.h"

namespace cogmap::experiments {

mapper::MapperOptions plain_mapper_options(const mapper::MapperOptions& map) {
  const mapper::MapperOptions library;
  mapper::MapperOptions plain = map;
  plain.scan_match = library.scan_match;
  plain.glimpse = library.glimpse;
  plain.odometry_calibration = library.odometry_calibration;
  plain.translation.moves_estimate = library.translation.moves_estimate;
  plain.localizer.echo_refit = library.localizer.echo_refit;
  plain.localizer.measurement_sd_rad_m = library.localizer.measurement_sd_rad_m;
  return plain;
}

bool has_map_only_refinements(const mapper::MapperOptions& map) {
  const mapper::MapperOptions library;
  return map.scan_match.enabled || map.glimpse.enabled ||
         map.odometry_calibration.curvature_gain != library.odometry_calibration.curvature_gain ||
         map.translation.moves_estimate != library.translation.moves_estimate ||
         map.localizer.echo_refit.band_m != library.localizer.echo_refit.band_m ||
         map.localizer.measurement_sd_rad_m != library.localizer.measurement_sd_rad_m;
}

}  // namespace cogmap::experiments
