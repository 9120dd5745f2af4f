// The route follower: waypoints in the world frame, steered through VFH (thesis §2.2.3), with
// the door behaviour where the line to the waypoint is blocked, and a bounded give-up.

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <utility>

#include "cogmap/mapper/nav/controller.h"
#include "nav/door_passage.h"
#include "nav/door_search.h"
#include "nav/nav_core.h"
#include "nav/route_follower.h"

namespace cogmap::mapper::nav {
namespace {

class RouteFollower final : public ReroutableFollower {
 public:
  RouteFollower(const RouteOptions& options, std::vector<Point2> waypoints)
      : options_(options),
        waypoints_(std::move(waypoints)),
        core_(core_options_of(options)),
        door_(options.door),
        search_(options.door) {}

  VelocityCommand step(const NavInput& input) override {
    if (input.frame == nullptr) return core_.stop(NavMode::kIdle);
    const double now = input.frame->time_s;
    const Point2 here = input.pose.translation();
    core_.trace().door_active = false;  // set again below while the door behaviour holds one
    advance(here, now);
    if (done()) return core_.stop(NavMode::kDone);
    // What lies beyond the waypoint (plus the robot's clearance) need not block the way there:
    // a waypoint near a wall must stay reachable.
    const double goal_range_m = (waypoints_[index_] - here).norm() + options_.vfh.safety_radius_m;
    core_.sense(input, goal_range_m);
    if (reached_behind_obstacle(here)) {
      next_waypoint(waypoints_[index_], now, /*given_up=*/false);
      if (done()) return core_.stop(NavMode::kDone);
    }
    const bool stuck = core_.check_stuck(input);
    // Stuck on the way: probing head-on again would drive back into what stopped the robot.
    if (stuck) probe_failed_at_ = here;
    const bool stalled_too_long = now - progress_s_ > options_.give_up_s;
    if ((stuck && ++attempts_ > options_.recovery.max_attempts) || stalled_too_long ||
        goal_in_pocket_) {
      // This waypoint has defeated every recovery, or the robot has not come any nearer for
      // give_up_s, or it lies in a pocket the body cannot turn in (the door behaviour saw it
      // last cycle): give it up, report it, and go on with the next one.
      ++core_.trace().skipped_waypoints;
      next_waypoint(here, now, /*given_up=*/true);
      advance(here, now);
      if (done()) return core_.stop(NavMode::kDone);
    }
    core_.trace().waypoint_index = index_;
    const Point2 goal = waypoints_[index_];
    const Point2 to_goal = goal - here;
    const double target_rad = std::atan2(to_goal.y(), to_goal.x());
    if (const auto cmd = core_.recover(input, target_rad)) return *cmd;
    if (door_.active()) search_.stop();  // the door behaviour has an opening: it leads
    if (const auto cmd = search_step(input)) return *cmd;
    if (const auto cmd = door_step(input, door_goal(here))) return *cmd;
    if (lane_clear(here, goal)) {
      // Nothing sensed in the body's lane to the waypoint: go straight. VFH's enlargement
      // closes a gap the lane shows open (a 0.9 m door leaves 0.14 m of free band to it),
      // and its valley choice then swings the robot from one side to the other.
      return core_.drive_direct(input, target_rad, options_.speed_mps, NavMode::kDirect);
    }
    if (const auto cmd = probe_step(input, goal)) return *cmd;
    // A probe that has just stalled met the wall where the door is not: sweep along it.
    if (const auto cmd = try_search(input, goal)) return *cmd;
    return core_.drive_toward(input, target_rad);
  }

  /// Starts a sweep if one is due (and allowed for this waypoint) and returns its first
  /// command.
  std::optional<VelocityCommand> try_search(const NavInput& input, const Point2& goal) {
    if (!search_due_) return std::nullopt;
    search_due_ = false;
    if (searches_ >= options_.door.search_per_waypoint ||
        !search_.start(core_.field().points(), input.pose, goal, waypoint_after(),
                       options_.vfh.safety_radius_m, input.frame->time_s,
                       max_goal_m(options_.door.search_max_goal_m))) {
      return std::nullopt;
    }
    ++searches_;
    return search_step(input);
  }

  bool done() const override { return index_ >= waypoints_.size(); }
  void set_waypoints(std::vector<Point2> waypoints) override {
    waypoints_ = std::move(waypoints);
    index_ = 0;
    attempts_ = 0;
    leg_start_.reset();  // the next step starts the leg and the give-up clock
    probe_failed_at_.reset();
    probe_since_s_.reset();
    search_.stop();
    search_due_ = false;
    searches_ = 0;
    goal_in_pocket_ = false;
    after_give_up_ = false;
    best_m_ = std::numeric_limits<double>::infinity();
  }
  const NavTrace& trace() const override { return core_.trace(); }

 private:
  /// The point the door behaviour looks toward: the waypoint, or the one after it when the
  /// waypoint is close (a door-centre waypoint the estimate puts in a jamb).
  Point2 door_goal(const Point2& here) const {
    const Point2 w = waypoints_[index_];
    if ((w - here).norm() < options_.blocked_reach_m && index_ + 1 < waypoints_.size()) {
      return waypoints_[index_ + 1];
    }
    return w;
  }

  /// How far a waypoint may lie for the probe and the search (`limit_m`, theirs), widened
  /// right after a waypoint was given up: DoorOptions::probe_max_goal_after_skip_m.
  double max_goal_m(double limit_m) const {
    return after_give_up_ ? std::max(limit_m, options_.door.probe_max_goal_after_skip_m) : limit_m;
  }

  /// The waypoint after the current one, if there is one.
  std::optional<Point2> waypoint_after() const {
    if (index_ + 1 < waypoints_.size()) return waypoints_[index_ + 1];
    return std::nullopt;
  }

  /// The door search's command this cycle while a sweep runs; a gap it hears starts the door
  /// behaviour's passage through it (which steers from this cycle on).
  std::optional<VelocityCommand> search_step(const NavInput& input) {
    if (!search_.active()) return std::nullopt;
    const double now = input.frame->time_s;
    const bool had_gap = search_.gap_heard();
    const auto s =
        search_.step(*input.frame, core_.field().points(), core_.robot(), input.pose, now);
    // A gap heard is progress: the drive to its approach point (up to a few metres back along
    // the wall, then a turn) must not run out the give-up clock the sweep has spent.
    if (!had_gap && search_.gap_heard()) progress_s_ = now;
    if (s.found) {
      // Handed over: the passage gets the whole give_up_s too.
      progress_s_ = now;
      door_.start(*s.found, now, false);
      return door_step(input, door_goal(input.pose.translation()));
    }
    if (!s.aim) {
      probe_failed_at_ = input.pose.translation();  // swept, nothing heard: VFH until rearmed
      return std::nullopt;
    }
    const Point2 d = *s.aim - input.pose.translation();
    return core_.drive_direct(input, std::atan2(d.y(), d.x()), options_.door.speed_mps,
                              NavMode::kDoorSearch);
  }

  /// The door behaviour's command this cycle, if it is (or now becomes) active.
  std::optional<VelocityCommand> door_step(const NavInput& input, const Point2& goal) {
    if (!options_.door.enabled) return std::nullopt;
    const Point2 here = input.pose.translation();
    const std::vector<ObstaclePoint>& points = core_.field().points();
    const double now = input.frame->time_s;
    if (!door_.active()) {
      // Only where the straight line is blocked within the door search range: open space and
      // openings the line already threads are VFH's.
      const bool blocked = line_blocked(points, here, goal, options_.vfh.safety_radius_m, 0.1,
                                        options_.door.search_range_m);
      std::optional<Opening> found = blocked ? door_.find(points, here, goal, now) : std::nullopt;
      // Looking past a close waypoint (door_goal) is for a door-centre waypoint the estimate
      // puts in a jamb: the opening must be that waypoint's door, not the way back out of a
      // room whose centre clutter hides (which then leads back in, and out, until the
      // waypoint is given up).
      if (found && goal != waypoints_[index_] &&
          (found->center_m - waypoints_[index_]).norm() > options_.door.goal_in_door_m) {
        found.reset();
      }
      goal_in_pocket_ = blocked && door_.goal_in_pocket() && options_.door.give_up_goal_in_pocket;
      if (!door_.offer(found, now)) {
        return std::nullopt;
      }
    }
    const auto aim = door_.step(points, input.pose, goal, now);
    core_.trace().door_passages = door_.crossed();
    NavTrace& t = core_.trace();
    t.door_active = aim.has_value();
    t.door_center_m = door_.opening().center_m;
    t.door_normal_rad = std::atan2(door_.opening().normal.y(), door_.opening().normal.x());
    t.door_width_m = door_.opening().width_m;
    if (!aim) return std::nullopt;
    const Point2 d = *aim - here;
    const double rad = std::atan2(d.y(), d.x());
    if (door_.mode() == NavMode::kDoorCross) {
      const DoorBand band{door_.opening().center_m - here, door_.opening().normal,
                          options_.door.recenter_band_m};
      return core_.drive_direct(input, rad, options_.door.speed_mps, NavMode::kDoorCross, &band);
    }
    // The approach point lies in the open space in front of the opening: steer straight at
    // it (VFH's valley choice swings the heading about near a wall and loses the door).
    return core_.drive_direct(input, rad, options_.speed_mps, NavMode::kDoorAlign);
  }

  /// True when no sensed obstacle lies in the lane the body sweeps on the straight line to
  /// `goal` (half the width plus direct_margin_m each side), out to direct_range_m.
  bool lane_clear(const Point2& here, const Point2& goal) const {
    // Only for a waypoint within reach: on a long leg (a corridor) a wall met at a shallow
    // angle does not echo (specular) until it is too near, and VFH's enlargement of what the
    // side transducers see is what keeps the robot off it.
    if ((goal - here).norm() > options_.direct_range_m) return false;
    const double half_lane = 0.5 * core_.robot().width_m + options_.direct_margin_m;
    // From the rear bumper: what lies beside the body counts too (it sweeps past it when
    // the robot turns toward the goal).
    return !line_blocked(core_.field().points(), here, goal, half_lane,
                         -0.5 * core_.robot().length_m, options_.direct_range_m);
  }

  /// Closes in on `goal` head-on at the door speed while a sensed obstacle blocks the line to
  /// it within probe_range_m (DoorOptions: the sonar sees a door open only from near it).
  /// Gives up once it makes no progress for probe_stall_s, until the robot has moved
  /// probe_rearm_m away from where it gave up (the next wall may hold the door).
  std::optional<VelocityCommand> probe_step(const NavInput& input, const Point2& goal) {
    const DoorOptions& o = options_.door;
    if (!o.enabled || o.probe_range_m <= 0.0) return std::nullopt;
    const Point2 here = input.pose.translation();
    if (probe_failed_at_) {
      if ((here - *probe_failed_at_).norm() < o.probe_rearm_m) return std::nullopt;
      probe_failed_at_.reset();
    }
    const double d = (goal - here).norm();
    if (d > max_goal_m(o.probe_max_goal_m)) return std::nullopt;
    const double now = input.frame->time_s;
    // Only a wall across the line: sensed on both sides of it within VFH's radius (or within
    // the body's half-width of the line), and meeting it at probe_min_angle_deg or more. A
    // corner grazing the lane from one side is VFH's to go around; a wall met at a shallow
    // angle is a corridor side the estimate's drift steers into, with no door to see through.
    const auto& points = core_.field().points();
    const auto wall_rad =
        blocking_wall_angle_rad(points, here, goal, options_.vfh.safety_radius_m, o.probe_range_m);
    const bool across = wall_rad && *wall_rad >= o.probe_min_angle_deg * std::numbers::pi / 180.0;
    if (!across ||
        (!wall_across(points, here, goal, options_.vfh.safety_radius_m, o.probe_range_m) &&
         !line_blocked(points, here, goal, 0.5 * core_.robot().width_m, 0.1, o.probe_range_m))) {
      probe_since_s_.reset();
      return std::nullopt;
    }
    const Point2 to_goal = goal - here;
    const double goal_rad = std::atan2(to_goal.y(), to_goal.x());
    // Turning on the spot toward the goal is no failure to close in: the clock starts once
    // the robot faces it.
    const bool turning = std::abs(wrap_angle_rad(goal_rad - input.pose.theta_rad)) >
                         options_.safety.turn_in_place_deg * std::numbers::pi / 180.0;
    if (!probe_since_s_ || turning || d < probe_best_m_ - options_.progress_m) {
      probe_best_m_ = probe_since_s_ ? std::min(probe_best_m_, d) : d;
      probe_since_s_ = now;
    }
    if (now - *probe_since_s_ > o.probe_stall_s) {
      probe_failed_at_ = here;
      probe_since_s_.reset();
      search_due_ = true;
      return std::nullopt;
    }
    return core_.drive_direct(input, goal_rad, o.speed_mps, NavMode::kDoorProbe);
  }

  /// A waypoint a drifted estimate puts inside or behind an obstacle is as reached as it can
  /// be once the robot is within blocked_reach_m and the sensed obstacle is in between.
  bool reached_behind_obstacle(const Point2& here) const {
    const Point2 w = waypoints_[index_];
    const double d = (w - here).norm();
    if (d > options_.blocked_reach_m) return false;
    return line_blocked(core_.field().points(), here, w, 0.5 * options_.vfh.safety_radius_m, 0.0,
                        d + 0.1);
  }

  /// On to the next waypoint; `given_up`: the one left behind was not reached.
  void next_waypoint(const Point2& leg_start, double now, bool given_up) {
    after_give_up_ = given_up;
    leg_start_ = leg_start;
    goal_in_pocket_ = false;  // seen for the waypoint just left
    ++index_;
    attempts_ = 0;
    probe_failed_at_.reset();
    probe_since_s_.reset();
    search_.stop();
    search_due_ = false;
    searches_ = 0;
    best_m_ = std::numeric_limits<double>::infinity();
    progress_s_ = now;
  }

  void advance(const Point2& position, double now) {
    if (!leg_start_) {
      leg_start_ = position;
      progress_s_ = now;
    }
    while (!done() && reached(position)) {
      next_waypoint(waypoints_[index_], now, /*given_up=*/false);
    }
    if (!done()) {
      const double d = (waypoints_[index_] - position).norm();
      if (d < best_m_ - options_.progress_m) {
        best_m_ = d;
        progress_s_ = now;
      }
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
  double best_m_ = std::numeric_limits<double>::infinity();  // nearest to the waypoint so far
  double progress_s_ = 0.0;                // when the robot last came progress_m nearer to it
  std::optional<Point2> probe_failed_at_;  // where the probe last gave up (this waypoint)
  std::optional<double> probe_since_s_;    // probing: when it last came progress_m nearer
  double probe_best_m_ = 0.0;              // ...and how near that was
  bool goal_in_pocket_ = false;            // the door behaviour saw the waypoint in a pocket
  bool after_give_up_ = false;             // the last waypoint left behind was given up
  bool search_due_ = false;                // the probe stalled this cycle: sweep the wall
  int searches_ = 0;                       // sweeps started for the current waypoint
  NavCore core_;
  DoorPassage door_;
  DoorSearch search_;
};

}  // namespace

std::unique_ptr<Controller> make_route_follower(const RouteOptions& options,
                                                std::vector<Point2> waypoints_world) {
  return std::make_unique<RouteFollower>(options, std::move(waypoints_world));
}

std::unique_ptr<ReroutableFollower> make_reroutable_route_follower(const RouteOptions& options) {
  return std::make_unique<RouteFollower>(options, std::vector<Point2>{});
}

}  // namespace cogmap::mapper::nav
