#include "nav/nav_core.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "nav/side_walls.h"
#include "nav/spin_guard.h"
#include "nav/steering.h"

namespace cogmap::mapper::nav {
namespace {

constexpr double kMotionEpsilon = 1e-3;  // |v| in m/s or |w| in rad/s that counts as moving

}  // namespace

NavCore::NavCore(const CoreOptions& options)
    : options_(options),
      memory_(options.memory),
      field_(options.vfh, options.memory),
      vfh_(options.vfh),
      recovery_(options.stuck_time_s, options.recovery),
      turn_backs_(options.vfh) {}

bool NavCore::sense(const NavInput& input, double goal_range_m) {
  if (input.frame == nullptr) return false;
  robot_ = input.robot ? *input.robot : RobotGeometry{};
  // Never command more than the robot can do.
  speed_mps_ = std::clamp(options_.speed_mps, 0.0, robot_.max_speed_mps);
  max_turn_radps_ = std::clamp(options_.max_turn_rate_radps, 0.0, robot_.max_turn_rate_radps);
  heading_rad_ = input.pose.theta_rad;
  memory_.add_frame(*input.frame, input.pose, robot_);
  field_.build(input.pose.translation(), input.grid, memory_);
  goal_range_m_ = goal_range_m;
  vfh_.build(field_.points(), goal_range_m_);
  trace_.density = vfh_.density();
  trace_.blocked = vfh_.blocked_mask();
  trace_.front_clearance_m =
      clearance_m(field_.points(), input.pose.theta_rad,
                  deg_to_rad(options_.safety.front_half_angle_deg), robot_.length_m);
  return true;
}

bool NavCore::check_stuck(const NavInput& input) {
  const SensorFrame& f = *input.frame;
  if (!recovery_.detect(f.time_s, input.pose, f.stall_left || f.stall_right, moving_)) {
    return false;
  }
  // Whatever stopped the robot is where it was heading; remember it, the sonar may never see
  // it (a low step, glass, a chair leg), so the recovery's turn and VFH steer around it.
  memory_.add_contact(input.pose, robot_, f.time_s, last_forward_);
  field_.build(input.pose.translation(), input.grid, memory_);
  vfh_.build(field_.points(), goal_range_m_);
  recovery_.start(f.time_s, input.pose);
  ++trace_.recoveries;
  return true;
}

std::optional<VelocityCommand> NavCore::recover(const NavInput& input, double prefer_rad) {
  if (!recovery_.active()) return std::nullopt;
  const double rear =
      clearance_m(field_.points(), input.pose.theta_rad + std::numbers::pi,
                  deg_to_rad(options_.safety.front_half_angle_deg), robot_.length_m);
  const double freest = vfh_.sector_center_rad(vfh_.freest_sector(prefer_rad));
  const auto cmd =
      recovery_.command(input.frame->time_s, input.pose, rear, freest, max_turn_radps_);
  if (cmd) {
    trace_.mode = recovery_.phase();
    trace_.target_rad = prefer_rad;
    trace_.direction_rad = freest;
    trace_.has_direction = true;
    return sent(*cmd);
  }
  return std::nullopt;
}

VelocityCommand NavCore::drive_toward(const NavInput& input, double target_rad) {
  trace_.target_rad = wrap_angle_rad(target_rad);
  const std::optional<double> previous = trace_.mode == NavMode::kDrive && trace_.has_direction
                                             ? std::optional<double>(trace_.direction_rad)
                                             : std::nullopt;
  const double now_s = input.frame != nullptr ? input.frame->time_s : 0.0;
  const VfhChoice choice = vfh_.select(target_rad, input.pose.theta_rad, previous,
                                       turn_backs_.holding(now_s, target_rad));
  if (choice.found && previous) {
    turn_backs_.record(now_s, target_rad, *previous, choice.direction_rad);
  }
  trace_.has_direction = choice.found;
  if (!choice.found) {
    // Boxed in: turn on the spot toward the least dense sector, hoping one opens.
    const double freest = vfh_.sector_center_rad(vfh_.freest_sector(target_rad));
    trace_.direction_rad = freest;
    trace_.mode = NavMode::kBlocked;
    const double error = wrap_angle_rad(freest - input.pose.theta_rad);
    return sent({0.0, std::copysign(max_turn_radps_, error)});
  }
  trace_.direction_rad = choice.direction_rad;
  trace_.mode = NavMode::kDrive;
  return sent(steer(choice.direction_rad - input.pose.theta_rad, trace_.front_clearance_m,
                    speed_mps_, max_turn_radps_, options_.safety));
}

VelocityCommand NavCore::drive_direct(const NavInput& input, double target_rad, double speed_mps,
                                      NavMode mode, const DoorBand* door_band) {
  trace_.target_rad = wrap_angle_rad(target_rad);
  trace_.direction_rad = trace_.target_rad;
  trace_.has_direction = true;
  trace_.mode = mode;
  const double speed = std::min(speed_mps, speed_mps_);
  const double error = target_rad - input.pose.theta_rad;
  if (mode != NavMode::kDoorCross) {
    return sent(steer(error, trace_.front_clearance_m, speed, max_turn_radps_, options_.safety));
  }
  // The lane the body sweeps, with the VFH margin beyond its half-width: in a doorway the
  // jambs sit inside the ±30° cone but beside the lane.
  const double half_lane =
      0.5 * robot_.width_m + (options_.vfh.safety_radius_m - 0.5 * robot_.width_m) * 0.5;
  // A wall closed in on at a grazing angle is silent ahead of the body: its line through the
  // side echoes stops the crossing where it enters the lane (side_walls.h).
  const SideWallOptions& walls = options_.cross_side_walls;
  const double side_wall_m = lane_clearance_m(
      side_wall_points(field_.points(), input.pose.theta_rad, 0.5 * robot_.length_m,
                       0.5 * robot_.width_m, walls),
      input.pose.theta_rad, 0.5 * robot_.width_m + walls.lane_margin_m, robot_.length_m);
  const double lane =
      std::min(side_wall_m, lane_clearance_m(field_.points(), input.pose.theta_rad, half_lane,
                                             robot_.length_m, door_band));
  const VelocityCommand outside = steer(error, lane, speed, max_turn_radps_, options_.safety);
  if (door_band == nullptr) return sent(outside);
  // What lies in the door's band is the jambs (and their smear): the body passes between
  // them, so it may close in on them to the crossing's own, shorter, stop distance.
  const double in_band = std::min(
      side_wall_m,
      lane_clearance_m(field_.points(), input.pose.theta_rad, half_lane, robot_.length_m, nullptr));
  SafetyOptions safety = options_.safety;
  safety.stop_clearance_m = options_.cross_stop_clearance_m;
  safety.slow_clearance_m = options_.cross_slow_clearance_m;
  const VelocityCommand inside = steer(error, in_band, speed, max_turn_radps_, safety);
  return sent(std::abs(inside.v_mps) < std::abs(outside.v_mps) ? inside : outside);
}

VelocityCommand NavCore::spin_guarded(const VelocityCommand& cmd) const {
  const SafetyOptions& s = options_.safety;
  if (s.spin_guard_deg <= 0.0 || std::abs(cmd.v_mps) > s.spin_max_speed_mps ||
      std::abs(cmd.w_radps) <= kMotionEpsilon) {
    return cmd;
  }
  const auto strike = spin_strike(field_.points(), heading_rad_, cmd.w_radps > 0.0 ? 1 : -1, robot_,
                                  s.spin_guard_margin_m, deg_to_rad(s.spin_guard_deg));
  if (!strike) return cmd;
  // Away from the point along the axis: back from one ahead of the centre, on from one behind.
  const double away_rad = strike->x() >= 0.0 ? heading_rad_ + std::numbers::pi : heading_rad_;
  const double half_lane = 0.5 * robot_.width_m + s.spin_guard_margin_m;
  const double free_m = lane_clearance_m(field_.points(), away_rad, half_lane, robot_.length_m);
  if (free_m > s.spin_escape_clearance_m) {
    return {strike->x() >= 0.0 ? -s.spin_escape_mps : s.spin_escape_mps, 0.0};
  }
  // No room to move away: the long way round, if that turn strikes nothing; boxed in both
  // ways, the turn as asked is all there is.
  const int other = cmd.w_radps > 0.0 ? -1 : 1;
  if (!spin_strike(field_.points(), heading_rad_, other, robot_, s.spin_guard_margin_m,
                   deg_to_rad(s.spin_guard_deg))) {
    return {cmd.v_mps, -cmd.w_radps};
  }
  return cmd;
}

VelocityCommand NavCore::arc_guarded(const VelocityCommand& cmd) const {
  const SafetyOptions& s = options_.safety;
  if (s.arc_guard_s <= 0.0 || std::abs(cmd.v_mps) <= s.spin_max_speed_mps ||
      !arc_strikes(field_.points(), heading_rad_, cmd.v_mps, cmd.w_radps, robot_,
                   s.spin_guard_margin_m, s.arc_guard_s)) {
    return cmd;
  }
  // The turn alone, which the spin guard checks in turn (and moves away from the point first
  // when the turn itself would strike it).
  return {0.0, cmd.w_radps};
}

VelocityCommand NavCore::sent(const VelocityCommand& requested) {
  const VelocityCommand cmd = spin_guarded(arc_guarded(requested));
  moving_ = std::abs(cmd.v_mps) > kMotionEpsilon || std::abs(cmd.w_radps) > kMotionEpsilon;
  if (std::abs(cmd.v_mps) > kMotionEpsilon) last_forward_ = cmd.v_mps > 0.0;
  return cmd;
}

VelocityCommand NavCore::stop(NavMode mode) {
  trace_.mode = mode;
  return sent({});
}

}  // namespace cogmap::mapper::nav
