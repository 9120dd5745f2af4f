#pragma once
/// The seam: simulator, real P2-AT and log replay all implement Robot, and the mapper and
/// navigation see nothing else.

#include <optional>

#include "cogmap/mapper/seam/robot_geometry.h"
#include "cogmap/mapper/seam/sensor_frame.h"
#include "cogmap/mapper/seam/velocity_command.h"

namespace cogmap::mapper {

class Robot {
 public:
  virtual ~Robot() = default;

  /// The robot's physical description; constant for the robot's lifetime.
  virtual const RobotGeometry& geometry() const = 0;

  /// Blocks until the next cycle and returns its data; empty at end of log or on disconnect.
  virtual std::optional<SensorFrame> next_frame() = 0;

  /// Sets the motion command that holds until the next command (clamped to the limits).
  virtual void command(const VelocityCommand& cmd) = 0;

  /// Stops the robot (zero velocity); further frames may still arrive.
  virtual void stop() = 0;
};

}  // namespace cogmap::mapper
