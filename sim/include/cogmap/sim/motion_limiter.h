#pragma once
/// The P2-AT firmware's speed and acceleration limits: a command is clamped to the top speeds,
/// and the velocity the wheels are asked for ramps towards it at the accel/decel limits.

#include "cogmap/mapper/seam/robot_geometry.h"
#include "cogmap/mapper/seam/velocity_command.h"

namespace cogmap::sim {

/// Limits. Defaults: MobileSim's P2-AT model (docs/p2at.md) for translation; rotation ramps at
/// ARIA's default RotAccel/RotDecel of 100 deg/s² (an assumption until measured).
struct MotionLimits {
  double max_speed_mps = 0.75;
  double max_turn_rate_radps = 1.74;
  double accel_mps2 = 0.3;          ///< speeding up
  double decel_mps2 = 0.6;          ///< slowing down (and through zero on reversal)
  double rot_accel_radps2 = 1.745;  ///< turning faster
  double rot_decel_radps2 = 1.745;  ///< turning slower

  /// The speed limits of a robot geometry, rotational ramps at their defaults.
  static MotionLimits from_geometry(const mapper::RobotGeometry& geometry);
};

/// Ramps the velocity towards the last command, one step at a time.
class MotionLimiter {
 public:
  explicit MotionLimiter(const MotionLimits& limits = {}) : limits_(limits) {}

  /// Clamps a command to the top speeds (what Robot::command accepts).
  mapper::VelocityCommand clamp(const mapper::VelocityCommand& cmd) const;

  /// Moves the current velocity towards clamp(target) for dt_s seconds; returns it.
  const mapper::VelocityCommand& step(const mapper::VelocityCommand& target, double dt_s);

  /// The velocity after the last step.
  const mapper::VelocityCommand& current() const { return current_; }

 private:
  MotionLimits limits_;
  mapper::VelocityCommand current_;
};

}  // namespace cogmap::sim
