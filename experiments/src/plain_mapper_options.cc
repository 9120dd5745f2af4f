#include "cogmap/experiments/plain_mapper_options.h"

namespace cogmap::experiments {

mapper::MapperOptions plain_mapper_options(const mapper::MapperOptions& map) {
  const mapper::MapperOptions library;
  mapper::MapperOptions plain = map;
  plain.scan_match = library.scan_match;
  plain.glimpse = library.glimpse;
  plain.odometry_calibration = library.odometry_calibration;
  plain.translation.moves_estimate = library.translation.moves_estimate;
  return plain;
}

}  // namespace cogmap::experiments
