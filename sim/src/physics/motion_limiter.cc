#include "cogmap/sim/motion_limiter.h"

#include <algorithm>
#include <cmath>

namespace cogmap::sim {

namespace {

// One axis: accelerate when growing away from zero in the same direction, otherwise decelerate
// (a reversal first brakes through zero at the deceleration limit).
double ramp(double current, double target, double accel, double decel, double dt_s) {
  const bool speeding_up = current * target >= 0.0 && std::abs(target) > std::abs(current);
  const double max_change = (speeding_up ? accel : decel) * dt_s;
  return current + std::clamp(target - current, -max_change, max_change);
}

}  // namespace

MotionLimits MotionLimits::from_geometry(const mapper::RobotGeometry& geometry) {
  MotionLimits limits;
  limits.max_speed_mps = geometry.max_speed_mps;
  limits.max_turn_rate_radps = geometry.max_turn_rate_radps;
  limits.accel_mps2 = geometry.max_accel_mps2;
  limits.decel_mps2 = geometry.max_decel_mps2;
  return limits;
}

mapper::VelocityCommand MotionLimiter::clamp(const mapper::VelocityCommand& cmd) const {
  return {std::clamp(cmd.v_mps, -limits_.max_speed_mps, limits_.max_speed_mps),
          std::clamp(cmd.w_radps, -limits_.max_turn_rate_radps, limits_.max_turn_rate_radps)};
}

const mapper::VelocityCommand& MotionLimiter::step(const mapper::VelocityCommand& target,
                                                   double dt_s) {
  const mapper::VelocityCommand goal = clamp(target);
  current_.v_mps = ramp(current_.v_mps, goal.v_mps, limits_.accel_mps2, limits_.decel_mps2, dt_s);
  current_.w_radps = ramp(current_.w_radps, goal.w_radps, limits_.rot_accel_radps2,
                          limits_.rot_decel_radps2, dt_s);
  return current_;
}

}  // namespace cogmap::sim
