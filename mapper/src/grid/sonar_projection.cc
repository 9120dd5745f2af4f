#include "grid/sonar_projection.h"

#include <cmath>

namespace cogmap::mapper {

SonarProjector::SonarProjector(const RobotGeometry& robot) {
  mounts_.reserve(robot.sonars.size());
  for (const SonarMount& m : robot.sonars) {
    mounts_.push_back({m.x_m, m.y_m, std::cos(m.heading_rad), std::sin(m.heading_rad)});
  }
}

SonarBeam SonarProjector::beam(const Pose2& pose, int index) {
  // Exact comparison on purpose: the cache is only a shortcut for the very same heading.
  if (pose.theta_rad != last_theta_rad_) {
    last_theta_rad_ = pose.theta_rad;
    cos_h_ = std::cos(pose.theta_rad);
    sin_h_ = std::sin(pose.theta_rad);
  }
  const Mount& m = mounts_[static_cast<std::size_t>(index)];
  SonarBeam b;
  b.origin = {pose.x_m + m.x_m * cos_h_ - m.y_m * sin_h_,   // Eq. 3.4 + x_0
              pose.y_m + m.x_m * sin_h_ + m.y_m * cos_h_};  // Eq. 3.5 + y_0 (3.7 has -)
  b.cos_h = cos_h_ * m.cos_sh - sin_h_ * m.sin_sh;          // cos(h + sh_i)
  b.sin_h = sin_h_ * m.cos_sh + cos_h_ * m.sin_sh;          // sin(h + sh_i)
  return b;
}

}  // namespace cogmap::mapper
