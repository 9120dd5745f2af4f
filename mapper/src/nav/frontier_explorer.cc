// The frontier explorer: keeps its own map of what the sonar has swept from close by, drives
// to the cheapest frontier of it through the route follower (VFH, the door behaviour,
// recoveries), gives up goals it cannot reach, and stops when no reachable frontier is left.

#include "nav/frontier_explorer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "nav/explore_budget.h"
#include "nav/explore_map.h"
#include "nav/explore_reopen.h"
#include "nav/frontier_planner.h"
#include "nav/route_follower.h"

namespace cogmap::mapper::nav {
namespace {

RouteOptions route_options(const ExploreOptions& o) {
  RouteOptions r;
  r.speed_mps = o.speed_mps;
  r.waypoint_tolerance_m = o.waypoint_tolerance_m;
  r.max_turn_rate_radps = o.max_turn_rate_radps;
  r.vfh = o.vfh;
  r.stuck_time_s = o.stuck_time_s;
  r.memory = o.memory;
  r.safety = o.safety;
  r.recovery = o.recovery;
  r.door = o.door;
  r.give_up_s = o.give_up_s;
  r.progress_m = o.progress_m;
  return r;
}

class FrontierExplorer final : public Controller {
 public:
  explicit FrontierExplorer(const ExploreOptions& options)
      : options_(options),
        map_(options.map),
        follower_(make_reroutable_route_follower(route_options(options))),
        budget_(options.time_budget_s, options.distance_budget_m) {}

  VelocityCommand step(const NavInput& input) override {
    // No frame, or no usable estimate: stand still (and do not call the exploration done).
    if (input.frame == nullptr || !input.pose.translation().allFinite() ||
        !std::isfinite(input.pose.theta_rad)) {
      return stopped(NavMode::kIdle);
    }
    const RobotGeometry& robot = input.robot ? *input.robot : default_robot_;
    map_.add_frame(*input.frame, input.pose, robot);
    if (finished_) return stopped(NavMode::kExploreDone);
    const double now = input.frame->time_s;
    const Point2 here = input.pose.translation();
    if (budget_.spent(now, input.frame->odometry.translation())) return finish(false);
    if (edge_active_) {
      if (const auto cmd = edge_step(input)) return *cmd;
    }
    // A position the map cannot hold (beyond max_span_m): stand, decide nothing.
    if (!map_.inside(map_.cell_of(here))) return stopped(NavMode::kIdle);
    const std::size_t ring = std::max<std::size_t>(robot.sonars.size(), 1);
    track_progress(here, now);
    // A waypoint given up, or a recovery (the robot got stuck: a pocket behind furniture, a
    // gap narrower than the sensed one): this goal is not worth a second try.
    const NavTrace& followed = follower_->trace();
    const bool failed = followed.skipped_waypoints > skipped_seen_ ||
                        followed.recoveries > recoveries_seen_ ||
                        (goal_ && now - progress_s_ > options_.give_up_s);
    skipped_seen_ = followed.skipped_waypoints;
    recoveries_seen_ = followed.recoveries;
    if (goal_ && follower_->done() && !failed) {
      // Arrived: hold still for a couple of sonar cycles (the ring looks all round; turning
      // to face the frontier costs heading, 1-2 % of every turn on a skid-steer base).
      // The frontier is judged on what the ring heard while holding: at least one pulse of
      // every transducer, or three holds' time if the sonar is silent.
      if (!arrived_s_) {
        arrived_s_ = now;
        arrived_readings_ = map_.readings();
      }
      const bool heard = map_.readings() >= arrived_readings_ + ring;
      if (now - *arrived_s_ < options_.look_hold_s ||
          (!heard && now - *arrived_s_ < 3.0 * options_.look_hold_s)) {
        return stopped(NavMode::kLook);
      }
    }
    if (goal_ && (failed || follower_->done())) {
      // Looked at from near (its frontier should be gone; if the sonar still cannot see it
      // from there it never will), or not reachable after all: not this frontier again.
      // A doorway looked at leaves open what the look began to reveal beyond it: the far
      // side's first free cells are new frontier (seen through the gap, past the jambs'
      // echoes), and banning them with the rest would give up the room behind the door.
      if (failed) {
        banned_.push_back({target_, std::nullopt});
      } else if (map_.frontier(map_.cell_of(target_))) {
        banned_.push_back(
            {target_, target_in_doorway_ ? std::optional<Point2>(here) : std::nullopt});
      }
      goal_.reset();
      arrived_s_.reset();
    }
    // The goal is kept while its frontier cell is one: re-choosing every cycle swings the
    // robot between nearly equal goals, and every turn costs heading.
    // (A goal planned through reopened cells is kept until it is reached or fails: its
    // frontier may be one only on the reopened copy.)
    if (goal_ && !goal_reopened_ && !map_.frontier(map_.cell_of(target_))) goal_.reset();
    if (path_blocked_long_enough(here, now, robot)) {
      // A new plan over the map as it is now, the goal not given up (no ban: the same
      // frontier may have another way in). With none, the blocked path is still the best
      // bet (the door behaviour may find the way through what the map shows shut), so it is
      // followed on and checked again blocked_path_s later; ending the exploration here ended
      // runs in their start room.
      if (auto plan = plan_over_free_cells(input.pose)) {
        arrived_s_.reset();
        follow(*plan, here, now);
      } else {
        blocked_since_s_ = now;
      }
    }
    if (!goal_) {
      goal_reopened_ = false;
      auto plan = plan_over_free_cells(input.pose);
      if (!plan && map_.readings() >= ring) {
        plan = plan_through_reopened(input);
        goal_reopened_ = plan.has_value();
      }
      if (!plan) {
        // Nothing left to explore, unless the sonar has not yet been heard round once (a
        // real robot's sonar starts a moment after its motors): then wait, and decide later.
        if (map_.readings() < ring) return stopped(NavMode::kIdle);
        if (walk_start_room_edge(now)) {
          if (const auto cmd = edge_step(input)) return *cmd;
          return stopped(NavMode::kIdle);  // a door passed this very cycle: plan next cycle
        }
        return finish(true);
      }
      follow(*plan, here, now);
    }
    const VelocityCommand cmd = follower_->step(input);
    trace_ = follower_->trace();
    trace_.door_passages += edge_passages_;
    trace_.exploration_complete = false;
    return cmd;
  }

  bool done() const override { return finished_; }
  const NavTrace& trace() const override { return trace_; }

  std::optional<ExploreMapImage> explore_map() const override {
    return explore_map_image(map_, banned_, options_.ban_radius_m);
  }

 private:
  /// The plan to the cheapest frontier over seen free cells, else over the trail as well
  /// (ExploreOptions::plan_over_trail).
  std::optional<FrontierPlan> plan_over_free_cells(const Pose2& pose) const {
    auto plan = plan_to_frontier(map_, pose, banned_, options_.ban_radius_m, options_.frontier);
    if (!plan && options_.plan_over_trail) {
      FrontierOptions over_trail = options_.frontier;
      over_trail.trail_passable = true;
      plan = plan_to_frontier(map_, pose, banned_, options_.ban_radius_m, over_trail);
    }
    return plan;
  }

  /// Makes `plan` the goal and hands its waypoints to the route follower.
  void follow(const FrontierPlan& plan, const Point2& here, double now) {
    progress_s_ = now;
    goal_ = plan.goal;
    target_ = plan.frontier;
    target_in_doorway_ = plan.frontier_in_doorway;
    best_m_ = std::numeric_limits<double>::infinity();
    legs_.assign(1, here);
    legs_.insert(legs_.end(), plan.waypoints.begin(), plan.waypoints.end());
    blocked_since_s_.reset();
    follower_->set_waypoints(plan.waypoints);
  }

  /// ExploreOptions::blocked_path_s: true once the rest of the planned path has crossed an
  /// obstacle cell for that long. A path planned over cells the beams swept free runs into a
  /// wall they had swept through, heard since from near; followed on, it ends only at the
  /// give-up clock (give_up_s, 45 s). A doorway's jambs heard obliquely from afar paint its
  /// middle for a moment and the beams through it from near clear it again: hence the wait.
  /// Plans through reopened cells (the last look) are not checked: their cells are obstacles
  /// on the map by definition.
  bool path_blocked_long_enough(const Point2& here, double now, const RobotGeometry& robot) {
    if (options_.blocked_path_s <= 0.0 || !goal_ || goal_reopened_ ||
        !path_blocked(map_, legs_, follower_->trace().waypoint_index, here, 0.5 * robot.length_m)) {
      blocked_since_s_.reset();
      return false;
    }
    if (!blocked_since_s_) blocked_since_s_ = now;
    return now - *blocked_since_s_ >= options_.blocked_path_s;
  }

  /// The give-up clock restarts when the robot comes progress_m nearer its goal or the map
  /// gains progress_cells newly seen cells (travelling back through known rooms to a far
  /// frontier makes progress of the first kind, exploring of the second). Nearer along the
  /// planned path (ExploreOptions::progress_along_path): a way round a wall or through the
  /// rooms between first leads away from the goal as the crow flies.
  void track_progress(const Point2& here, double now) {
    const std::size_t seen = map_.seen_count();
    if (seen >= seen_at_progress_ + static_cast<std::size_t>(options_.progress_cells)) {
      seen_at_progress_ = seen;
      progress_s_ = now;
    }
    if (goal_) {
      const double d = options_.progress_along_path
                           ? remaining_path_m(legs_, follower_->trace().waypoint_index, here)
                           : (*goal_ - here).norm();
      if (d < best_m_ - options_.progress_m) {
        best_m_ = d;
        progress_s_ = now;
      }
    }
  }

  /// The last look before stopping (FrontierOptions::reopen_echo_himm): a plan on a copy of
  /// the explore map whose obstacle cells the current room's grid shows swept and silent are
  /// free. At most reopen_plans in an exploration.
  std::optional<FrontierPlan> plan_through_reopened(const NavInput& input) {
    const FrontierOptions& o = options_.frontier;
    if (input.grid == nullptr || o.reopen_echo_himm < 0.0 || reopen_plans_ >= o.reopen_plans) {
      return std::nullopt;
    }
    ExploreMap reopened = map_;
    if (reopen_swept_cells(reopened, *input.grid, o.reopen_echo_himm) == 0) return std::nullopt;
    auto plan = plan_to_frontier(reopened, input.pose, banned_, options_.ban_radius_m, o);
    if (plan) ++reopen_plans_;
    return plan;
  }

  /// The start room's edge walk (ExploreOptions::start_room_edge_s): begins when no frontier
  /// is left while no door has been passed, and resumes when a door it passed led to no new
  /// frontier (a gap between furniture), until its time is up. True when it walks on.
  bool walk_start_room_edge(double now) {
    if (edge_) {
      if (edge_over_ || now - edge_start_s_ > options_.start_room_edge_s) return false;
      edge_active_ = true;
      return true;
    }
    if (options_.start_room_edge_s <= 0.0 || follower_->trace().door_passages > 0) return false;
    ExploreOptions edge = options_;
    edge.strategy = ExploreStrategy::kEdge;
    edge.time_budget_s = 0.0;  // this explorer's budget still applies
    edge.distance_budget_m = 0.0;
    edge_ = make_edge_explorer(edge);
    edge_start_s_ = now;
    edge_active_ = true;
    return true;
  }

  /// One cycle of the edge walk: its command, or nullopt when a door has just been passed (the
  /// frontiers take over again) or the walk is over (round the room, or out of time): then
  /// the frontiers are planned once more, since the walk's beams may have opened a doorway
  /// the map had painted shut, and only with none reachable does the exploration end.
  std::optional<VelocityCommand> edge_step(const NavInput& input) {
    const VelocityCommand cmd = edge_->step(input);
    const NavTrace& walked = edge_->trace();
    if (walked.door_passages > edge_passages_) {
      edge_passages_ = walked.door_passages;
      edge_active_ = false;
      goal_.reset();
      return std::nullopt;
    }
    if (edge_->done() || input.frame->time_s - edge_start_s_ > options_.start_room_edge_s) {
      edge_active_ = false;
      edge_over_ = true;
      goal_.reset();
      return std::nullopt;
    }
    trace_ = walked;
    trace_.exploration_complete = false;
    return cmd;
  }

  VelocityCommand finish(bool complete) {
    finished_ = true;
    trace_.exploration_complete = complete;
    return stopped(NavMode::kExploreDone);
  }

  VelocityCommand stopped(NavMode mode) {
    trace_.mode = mode;
    return {};
  }

  ExploreOptions options_;
  ExploreMap map_;
  std::unique_ptr<ReroutableFollower> follower_;
  RobotGeometry default_robot_;
  NavTrace trace_;
  bool finished_ = false;
  ExploreBudget budget_;
  std::vector<Point2> legs_;               // the plan's start, then its waypoints
  std::optional<double> blocked_since_s_;  // the rest of the path crosses an obstacle since
  std::optional<Point2> goal_;             // where the robot drives to see...
  Point2 target_{0.0, 0.0};                // ...this frontier cell,
  bool target_in_doorway_ = false;         // which lies in a doorway (a look bans only this side)
  bool goal_reopened_ = false;             // planned through cells the room grid reopened
  int reopen_plans_ = 0;                   // such plans made so far
  std::unique_ptr<Controller> edge_;       // the start room's edge walk, once begun
  bool edge_active_ = false;               // ...walking now (not between its doors' frontiers)
  bool edge_over_ = false;                 // ...round the room or out of time: never again
  double edge_start_s_ = 0.0;
  std::size_t edge_passages_ = 0;  // doors it passed
  double progress_s_ = 0.0;        // when the give-up clock last restarted
  double best_m_ = std::numeric_limits<double>::infinity();  // nearest to the goal so far
  std::size_t seen_at_progress_ = 0;
  std::size_t skipped_seen_ = 0;
  std::size_t recoveries_seen_ = 0;
  std::vector<BannedFrontier> banned_;  // frontier cells given up or looked at in vain
  std::optional<double> arrived_s_;     // arrived at the goal: holding still since...
  std::size_t arrived_readings_ = 0;    // ...with this many readings integrated
};

}  // namespace

std::unique_ptr<Controller> make_frontier_explorer(const ExploreOptions& options) {
  return std::make_unique<FrontierExplorer>(options);
}

}  // namespace cogmap::mapper::nav
