#pragma once
/// Reading validation shared by every updater: a reading that fails is counted by reason in
/// RejectedReadings and never touches the grid.

#include "cogmap/mapper/grid/grid_updater.h"

namespace cogmap::mapper {

/// True when `reading` may be integrated for a robot with `sonar_count` transducers and
/// maximum range `max_range_m`; otherwise counts the first failed check in `rejected`.
/// Order of checks: unknown sonar, not finite, non-positive, beyond max range.
bool accept_reading(const SonarReading& reading, int sonar_count, double max_range_m,
                    RejectedReadings& rejected);

}  // namespace cogmap::mapper
