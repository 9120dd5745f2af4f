#include "nav/recovery.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cogmap::mapper::nav {

void StuckRecovery::rearm(double time_s, const Pose2& pose) {
  armed_ = true;
  anchor_time_s_ = time_s;
  anchor_ = pose;
  stall_since_s_.reset();
}

bool StuckRecovery::detect(double time_s, const Pose2& pose, bool stalled, bool commanded_motion) {
  if (active()) return false;
  // Standing still on purpose is not being stuck: the clock starts with commanded motion.
  if (!armed_ || !commanded_motion) {
    rearm(time_s, pose);
    return false;
  }
  const double moved = (pose.translation() - anchor_.translation()).norm();
  const double turned = std::abs(wrap_angle_rad(pose.theta_rad - anchor_.theta_rad));
  if (moved >= options_.stuck_distance_m || turned >= deg_to_rad(options_.stuck_rotation_deg)) {
    anchor_time_s_ = time_s;
    anchor_ = pose;
  }
  if (stalled) {
    if (!stall_since_s_) stall_since_s_ = time_s;
  } else {
    stall_since_s_.reset();
  }
  const bool no_progress = time_s - anchor_time_s_ >= stuck_time_s_;
  const bool stalled_long = stall_since_s_ && time_s - *stall_since_s_ >= options_.stall_time_s;
  return no_progress || stalled_long;
}

void StuckRecovery::start(double time_s, const Pose2& pose) {
  phase_ = NavMode::kBackOff;
  phase_start_s_ = time_s;
  phase_start_pose_ = pose;
}

std::optional<VelocityCommand> StuckRecovery::command(double time_s, const Pose2& pose,
                                                      double rear_clearance_m, double freest_rad,
                                                      double max_turn_radps) {
  if (phase_ == NavMode::kBackOff) {
    const double speed = std::max(1e-3, options_.backoff_speed_mps);
    // Give up reversing after twice the nominal time: the robot may be stuck backwards too.
    const double timeout_s = 2.0 * options_.backoff_distance_m / speed;
    const double reversed = (pose.translation() - phase_start_pose_.translation()).norm();
    if (reversed < options_.backoff_distance_m && time_s - phase_start_s_ < timeout_s &&
        rear_clearance_m > options_.rear_stop_clearance_m) {
      return VelocityCommand{-speed, 0.0};
    }
    phase_ = NavMode::kTurn;
    phase_start_s_ = time_s;
    turn_to_rad_ = freest_rad;
  }
  if (phase_ == NavMode::kTurn) {
    const double error = wrap_angle_rad(turn_to_rad_ - pose.theta_rad);
    if (std::abs(error) > deg_to_rad(options_.turn_done_deg) &&
        time_s - phase_start_s_ < options_.turn_time_s) {
      return VelocityCommand{0.0, std::copysign(max_turn_radps, error)};
    }
    phase_ = NavMode::kIdle;
    rearm(time_s, pose);
  }
  return std::nullopt;
}

}  // namespace cogmap::mapper::nav
