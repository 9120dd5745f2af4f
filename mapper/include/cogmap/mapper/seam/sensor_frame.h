#pragma once
/// What a robot reports every cycle (100 ms): odometry, the sonars fired since the last
/// frame, stall flags and, in simulation only, the true pose (for metrics; the mapper never
/// reads it).

#include <cstdint>
#include <optional>
#include <vector>

#include "cogmap/mapper/seam/pose2.h"

namespace cogmap::mapper {

/// One sonar ping.
struct SonarReading {
  int index = 0;         ///< transducer number, 0-based, into RobotGeometry::sonars
  double range_m = 0.0;  ///< measured range, metres (max range when no echo came back)
  bool echo = true;      ///< false when the pulse never came back (range_m is then max range)
  double time_s = 0.0;   ///< when this transducer fired, seconds (same clock as the frame)
};

/// One control cycle of sensor data.
struct SensorFrame {
  double time_s = 0.0;              ///< seconds since the run started
  Pose2 odometry;                   ///< encoder-integrated pose in the robot's odometry frame
  std::vector<SonarReading> sonar;  ///< transducers fired since the previous frame
  bool stall_left = false;          ///< left wheels stalled (motor current limit)
  bool stall_right = false;         ///< right wheels stalled
  std::optional<Pose2> true_pose;   ///< ground truth in the world frame, simulation only
};

}  // namespace cogmap::mapper
