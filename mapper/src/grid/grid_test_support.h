#pragma once
/// Shared fixtures of the grid tests: small robots with known mounts and grid comparisons.

#include <cstddef>
#include <numbers>

#include "cogmap/mapper/grid/grid_updater.h"

namespace cogmap::mapper::testing {

inline constexpr double kPi = std::numbers::pi;

/// A robot at the centre of cell (60, 60) of the default grid (10 cm cells, origin (-6, -6)).
inline constexpr Pose2 kRobot{0.05, 0.05, 0.0};

/// One transducer at the robot centre looking forward: the beam starts at the pose itself.
inline RobotGeometry single_forward_sonar() {
  RobotGeometry r;
  r.sonars = {{0.0, 0.0, 0.0}};
  r.sonar_max_range_m = 5.0;
  r.sonar_beam_width_rad = kPi / 6.0;  // 30°
  return r;
}

/// Number of cells whose values differ between two grids of the same geometry.
inline std::size_t cells_differing(const HistogramGrid& a, const HistogramGrid& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.geometry().cell_count(); ++i) n += a.data()[i] != b.data()[i];
  return n;
}

/// A reading with an echo.
inline SonarReading echo(int index, double range_m) { return {index, range_m, true, 0.0}; }

}  // namespace cogmap::mapper::testing
