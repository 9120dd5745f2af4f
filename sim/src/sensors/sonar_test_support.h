#pragma once
/// Scene builders shared by the sonar tests: exact synthetic geometry around one transducer.

#include <cmath>

#include "cogmap/mapper/seam/robot_geometry.h"
#include "cogmap/sim/sonar_model.h"

namespace cogmap::sim::testing {

/// Where transducer `index` sits and points when the robot is at `pose` (world frame).
struct TransducerFrame {
  mapper::Point2 origin;
  double axis_rad = 0.0;
  mapper::Point2 along(double distance_m, double offset_rad = 0.0) const {
    return origin + distance_m * mapper::Point2(std::cos(axis_rad + offset_rad),
                                                std::sin(axis_rad + offset_rad));
  }
};

inline TransducerFrame transducer_frame(const mapper::RobotGeometry& g, const mapper::Pose2& pose,
                                        int index) {
  const mapper::SonarMount& m = g.sonars[static_cast<std::size_t>(index)];
  return {pose.transform(mapper::Point2(m.x_m, m.y_m)), pose.theta_rad + m.heading_rad};
}

/// A segment through `center` along heading `heading_rad`, `half_length_m` each way.
inline mapper::Segment segment_through(const mapper::Point2& center, double heading_rad,
                                       double half_length_m) {
  const mapper::Point2 d(std::cos(heading_rad), std::sin(heading_rad));
  return {center - half_length_m * d, center + half_length_m * d};
}

/// Options with neither noise nor dropouts, so readings equal the geometric echo.
inline SonarModelOptions noiseless_sonar_options() {
  SonarModelOptions o;
  o.range_noise_fraction = 0.0;
  o.range_noise_floor_m = 0.0;
  o.dropout_probability = 0.0;
  return o;
}

}  // namespace cogmap::sim::testing
