#pragma once
/// Test support: frames on a 100 ms clock and an ideal unicycle to close the loop.

#include <cmath>
#include <cstring>
#include <vector>

#include "cogmap/mapper/nav/controller.h"
#include "cogmap/mapper/seam/geometry.h"

namespace cogmap::mapper::nav::testing {

inline constexpr double kCycleS = 0.1;  ///< the seam's 100 ms cycle

/// Frame `i` of a run: time i·0.1 s, no sonar unless given.
inline SensorFrame frame_at(int i, std::vector<SonarReading> sonar = {}) {
  SensorFrame f;
  f.time_s = i * kCycleS;
  f.sonar = std::move(sonar);
  return f;
}

/// Moves `pose` by `cmd` for one cycle (exact arc integration, no slip).
inline Pose2 integrate(const Pose2& pose, const VelocityCommand& cmd) {
  const double dtheta = cmd.w_radps * kCycleS;
  const double ds = cmd.v_mps * kCycleS;
  const double mid = pose.theta_rad + 0.5 * dtheta;
  return {pose.x_m + ds * std::cos(mid), pose.y_m + ds * std::sin(mid),
          wrap_angle_rad(pose.theta_rad + dtheta)};
}

/// A frame at `time_s` holding `sonar`.
inline SensorFrame frame(double time_s, std::vector<SonarReading> sonar) {
  SensorFrame f;
  f.time_s = time_s;
  f.sonar = std::move(sonar);
  return f;
}

/// The point `range_m` from the origin along `bearing_rad`.
inline Point2 at(double bearing_rad, double range_m) {
  return range_m * Point2(std::cos(bearing_rad), std::sin(bearing_rad));
}

/// Equal to the last bit (a bit-for-bit comparison of two computations).
inline bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

inline constexpr double kHalfLength = 0.313;  ///< P2-AT: 0.626 m long

}  // namespace cogmap::mapper::nav::testing
