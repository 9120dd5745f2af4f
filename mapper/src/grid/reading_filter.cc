#include "grid/reading_filter.h"

#include <cmath>

namespace cogmap::mapper {

bool accept_reading(const SonarReading& reading, int sonar_count, double max_range_m,
                    RejectedReadings& rejected) {
  if (reading.index < 0 || reading.index >= sonar_count) {
    ++rejected.unknown_sonar;
    return false;
  }
  if (!std::isfinite(reading.range_m)) {
    ++rejected.not_finite;
    return false;
  }
  if (reading.range_m <= 0.0) {
    ++rejected.non_positive;
    return false;
  }
  if (reading.range_m > max_range_m) {
    ++rejected.beyond_max;
    return false;
  }
  return true;
}

}  // namespace cogmap::mapper
