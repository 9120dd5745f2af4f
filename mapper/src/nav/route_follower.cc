// The route follower: waypoints in the world frame, steered through VFH (thesis §2.2.3).

#include <cmath>
#include <optional>
#include <utility>

#include "cogmap/mapper/nav/controller.h"
#include "nav/nav_core.h"

namespace cogmap::mapper::nav {
namespace {

CoreOptions core_options(const RouteOptions& o) {
  return {o.speed_mps, o.max_turn_rate_radps, o.stuck_time_s, o.vfh, o.memory, o.safety,
          o.recovery};
}

class RouteFollower final : public Controller {
 public:
  RouteFollower(const RouteOptions& options, std::vector<Point2> waypoints)
      : options_(options), waypoints_(std::move(waypoints)), core_(core_options(options)) {}

  VelocityCommand step(const NavInput& input) override {
    if (input.frame == nullptr) return core_.stop(NavMode::kIdle);
    advance(input.pose.translation());
    if (done()) return core_.stop(NavMode::kDone);
    // What lies beyond the waypoint (plus the robot's clearance) need not block the way there:
    // a waypoint near a wall must stay reachable.
    const double goal_range_m =
        (waypoints_[index_] - input.pose.translation()).norm() + options_.vfh.safety_radius_m;
    core_.sense(input, goal_range_m);
    if (core_.check_stuck(input) && ++attempts_ > options_.recovery.max_attempts) {
      // This waypoint has defeated every recovery: give it up and try the next one.
      ++index_;
      attempts_ = 0;
      leg_start_ = input.pose.translation();  // the next leg starts where it gave up
      ++core_.trace().skipped_waypoints;
      advance(input.pose.translation());
      if (done()) return core_.stop(NavMode::kDone);
    }
    core_.trace().waypoint_index = index_;
    const Point2 to_goal = waypoints_[index_] - input.pose.translation();
    const double target_rad = std::atan2(to_goal.y(), to_goal.x());
    if (const auto cmd = core_.recover(input, target_rad)) return *cmd;
    return core_.drive_toward(input, target_rad);
  }

  bool done() const override { return index_ >= waypoints_.size(); }
  const NavTrace& trace() const override { return core_.trace(); }

 private:
  void advance(const Point2& position) {
    if (!leg_start_) leg_start_ = position;
    while (!done() && reached(position)) {
      leg_start_ = waypoints_[index_];
      ++index_;
      attempts_ = 0;
    }
    core_.trace().waypoint_index = index_;
  }

  /// Within the tolerance, or across the line through the waypoint perpendicular to the leg
  /// (from the previous waypoint, or the start) and within pass_half_width_m of the waypoint.
  bool reached(const Point2& position) const {
    const Point2 to_robot = position - waypoints_[index_];
    if (to_robot.norm() < options_.waypoint_tolerance_m) return true;
    const Point2 leg = waypoints_[index_] - *leg_start_;
    const double length = leg.norm();
    if (options_.pass_half_width_m <= 0.0 || length < 1e-9) return false;
    const Point2 along = leg / length;
    const double ahead = to_robot.dot(along);  // > 0: beyond the perpendicular line
    const double lateral = std::abs(along.x() * to_robot.y() - along.y() * to_robot.x());
    return ahead >= 0.0 && lateral <= options_.pass_half_width_m;
  }

  RouteOptions options_;
  std::vector<Point2> waypoints_;
  std::size_t index_ = 0;
  int attempts_ = 0;                 // recoveries spent on the current waypoint
  std::optional<Point2> leg_start_;  // where the current leg began (previous waypoint or start)
  NavCore core_;
};

}  // namespace

std::unique_ptr<Controller> make_route_follower(const RouteOptions& options,
                                                std::vector<Point2> waypoints_world) {
  return std::make_unique<RouteFollower>(options, std::move(waypoints_world));
}

}  // namespace cogmap::mapper::nav
