// The edge explorer (ExploreStrategy::kEdge; docs/algorithms.md, "Exploration"): right-hand
// edge following on the sonar's obstacle field, with the door behaviour at the edge's ends,
// closing when the robot is back where it first took the edge.

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "nav/door_passage.h"
#include "nav/explore_budget.h"
#include "nav/frontier_explorer.h"
#include "nav/nav_constants.h"
#include "nav/nav_core.h"

namespace cogmap::mapper::nav {
namespace {

/// The sides as the side transducers see them now (robot frame, from the centre line), and
/// the body's lane ahead from the obstacle field. The field's echoes linger for seconds and
/// the grid's smear fills a doorway, so the sides are read from each transducer's last pulse.
struct Sides {
  double right_m = kInf;         // nearer of the two right-side transducers
  double right_front_m = kInf;   // the foremost right-side transducer
  double right_rear_m = kInf;    // the rearmost
  double mount_spacing_m = 0.0;  // between those two, along the body
  double left_m = kInf;
  double ahead_m = kInf;  // in the body's lane, from the bumper
};

/// Each transducer's last reading: range (infinity without an echo) and when.
struct LastPulse {
  double range_m = kInf;
  double time_s = -kInf;
};

Sides sense_sides(const std::vector<LastPulse>& pulses, const RobotGeometry& robot,
                  const std::vector<ObstaclePoint>& points, const Pose2& pose, double now,
                  double max_age_s) {
  Sides s;
  const double side_window = 25.0 * std::numbers::pi / 180.0;
  double front_x = -kInf, rear_x = kInf;
  for (std::size_t i = 0; i < robot.sonars.size() && i < pulses.size(); ++i) {
    const SonarMount& m = robot.sonars[i];
    if (now - pulses[i].time_s > max_age_s) continue;
    const double to_right = std::abs(wrap_angle_rad(m.heading_rad + 0.5 * std::numbers::pi));
    const double to_left = std::abs(wrap_angle_rad(m.heading_rad - 0.5 * std::numbers::pi));
    const double lateral = pulses[i].range_m * std::cos(std::min(to_right, to_left));
    if (to_right < side_window) {
      const double d = lateral + std::abs(m.y_m);
      s.right_m = std::min(s.right_m, d);
      if (m.x_m > front_x) {
        front_x = m.x_m;
        s.right_front_m = d;
      }
      if (m.x_m < rear_x) {
        rear_x = m.x_m;
        s.right_rear_m = d;
      }
    } else if (to_left < side_window) {
      s.left_m = std::min(s.left_m, lateral + std::abs(m.y_m));
    }
  }
  s.mount_spacing_m = std::isfinite(front_x) && std::isfinite(rear_x) ? front_x - rear_x : 0.0;
  const double c = std::cos(pose.theta_rad), sn = std::sin(pose.theta_rad);
  const double half_length = 0.5 * robot.length_m, half_width = 0.5 * robot.width_m;
  for (const ObstaclePoint& p : points) {
    const double x = c * p.offset_m.x() + sn * p.offset_m.y();
    const double y = -sn * p.offset_m.x() + c * p.offset_m.y();
    if (x > half_length - 0.05 && std::abs(y) < half_width + 0.05) {
      s.ahead_m = std::min(s.ahead_m, x - half_length);
    }
  }
  return s;
}

/// The last sensed point on the right (estimate frame): where the edge ended.
std::optional<Point2> right_end(const std::vector<ObstaclePoint>& points, const Pose2& pose,
                                double half_width_m, double lost_m) {
  const double c = std::cos(pose.theta_rad), sn = std::sin(pose.theta_rad);
  std::optional<Point2> end;
  double foremost = -kInf;
  for (const ObstaclePoint& p : points) {
    const double x = c * p.offset_m.x() + sn * p.offset_m.y();
    const double y = -sn * p.offset_m.x() + c * p.offset_m.y();
    if (y > -half_width_m || y < -lost_m || x < -1.0 || x > 0.5) continue;
    if (x > foremost) {
      foremost = x;
      end = pose.translation() + p.offset_m;
    }
  }
  return end;
}

class EdgeExplorer final : public Controller {
 public:
  explicit EdgeExplorer(const ExploreOptions& options)
      : options_(options),
        core_(core_options_of(options)),
        door_(options.door),
        budget_(options.time_budget_s, options.distance_budget_m) {}

  VelocityCommand step(const NavInput& input) override {
    // No frame, or no usable estimate: stand still (and do not call the exploration done).
    if (!input.pose.translation().allFinite() || !std::isfinite(input.pose.theta_rad) ||
        !core_.sense(input)) {
      return core_.stop(NavMode::kIdle);
    }
    if (finished_) return core_.stop(NavMode::kExploreDone);
    const double now = input.frame->time_s;
    if (budget_.spent(now, input.frame->odometry.translation())) return finish(false);
    // Turning is counted every cycle, recoveries and doorways included.
    track_turn(input.pose.theta_rad);
    core_.check_stuck(input);
    if (const auto cmd = core_.recover(input, input.pose.theta_rad + 0.5 * kPi)) return *cmd;
    if (door_.active()) {
      if (const auto cmd = door_step(input)) return *cmd;
      state_ = State::kAcquire;  // crossed (or given up): find the edge on the right again
      turned_rad_ = 0.0;
    }
    const EdgeOptions& e = options_.edge;
    remember_pulses(*input.frame);
    const Sides sides = sides_now(input);
    if (sides.right_m < e.lost_m) {
      edge_end_ =
          right_end(core_.field().points(), input.pose, 0.5 * core_.robot().width_m, e.lost_m);
    }
    if (const auto cmd = seek_or_acquire(input, sides)) return *cmd;
    if (state_ == State::kCross) return cross(input, sides);
    const bool turning_to_gap =
        state_ == State::kEndOfEdge &&
        (input.pose.translation() - end_pose_.translation()).norm() >= e.end_advance_m;
    if (const auto cmd = corner(sides, turning_to_gap)) return *cmd;
    if (const auto cmd = along_edge(input, sides, turning_to_gap)) return *cmd;
    return end_of_edge(input);
  }

  bool done() const override { return finished_; }
  const NavTrace& trace() const override { return core_.trace(); }

 private:
  enum class State { kSeek, kFollow, kEndOfEdge, kCross, kPivot, kAcquire, kCorner };

  /// kSeek: straight ahead until something is near enough to follow. kAcquire (after a
  /// doorway): bear right until the edge is back. nullopt once following begins.
  std::optional<VelocityCommand> seek_or_acquire(const NavInput& input, const Sides& sides) {
    const EdgeOptions& e = options_.edge;
    if (state_ == State::kSeek) {
      if (sides.ahead_m >= e.follow_m && sides.right_m >= e.follow_m + 0.2) {
        return core_.drive_toward(input, seek_heading_rad(input.pose));
      }
      begin_follow();
    } else if (state_ == State::kAcquire) {
      if (sides.right_m >= e.follow_m + 0.3 && sides.ahead_m >= e.corner_clearance_m &&
          turned_rad_ <= 1.5 * kPi) {
        return arc_right(sides, 1.0);
      }
      begin_follow();
    }
    return std::nullopt;
  }

  /// kCross: through the gap along cross_rad_, then find the edge on the right again. The
  /// obstacle memory still holds what the side transducer painted into the gap: the
  /// crossing's own lane check (drive_direct) stops the body, not the corner rule.
  VelocityCommand cross(const NavInput& input, const Sides& sides) {
    const EdgeOptions& e = options_.edge;
    const double now = input.frame->time_s;
    if ((input.pose.translation() - cross_from_).norm() < e.cross_m &&
        now - cross_s_ < e.cross_timeout_s) {
      // Keep to the middle of the gap while the side transducers see both jambs.
      double rad = cross_rad_;
      if (sides.left_m < 1.0 && sides.right_m < 1.0) {
        rad += std::clamp(0.8 * (sides.left_m - sides.right_m), -0.3, 0.3);
      }
      return core_.drive_direct(input, rad, options_.door.speed_mps, NavMode::kDoorCross);
    }
    ++crossings_;
    core_.trace().door_passages = door_.crossed() + crossings_;
    state_ = State::kAcquire;
    turned_rad_ = 0.0;
    return arc_right(sides, 1.0);
  }

  /// An inner corner (or something in the way): turn left on the spot until the way ahead is
  /// clear by a margin (without it, following's pull to the right brings the corner back at
  /// once and the robot dithers on the spot). nullopt when there is no corner to turn.
  std::optional<VelocityCommand> corner(const Sides& sides, bool turning_to_gap) {
    const EdgeOptions& e = options_.edge;
    if (sides.ahead_m < e.corner_clearance_m && !turning_to_gap && state_ != State::kCorner) {
      state_ = State::kCorner;
      turned_rad_ = 0.0;
    }
    if (state_ != State::kCorner) return std::nullopt;
    if ((sides.ahead_m < e.corner_clearance_m + e.corner_margin_m ||
         -turned_rad_ < e.corner_min_turn_rad) &&
        -turned_rad_ < kPi) {
      core_.trace().mode = NavMode::kEdgeCorner;
      // Creep forward while there is room: an arc slips less than a turn on the spot.
      const double v = sides.ahead_m > e.corner_creep_from_m ? e.corner_creep_mps : 0.0;
      return core_.sent({v, 0.6 * core_.max_turn_radps()});
    }
    begin_follow();
    return std::nullopt;
  }

  /// Following, while the foremost right transducer still hears the edge (the rear one hears
  /// the wall before a doorway until the robot is halfway past); closes the tour when back
  /// where it began. nullopt when the edge has ended.
  std::optional<VelocityCommand> along_edge(const NavInput& input, const Sides& sides,
                                            bool turning_to_gap) {
    const EdgeOptions& e = options_.edge;
    if (sides.right_front_m >= e.lost_m || turning_to_gap) return std::nullopt;
    if (state_ != State::kFollow && (state_ != State::kPivot || turned_rad_ > 0.25 * kPi)) {
      begin_follow();
    }
    if (state_ != State::kFollow) return std::nullopt;
    if (steady(sides)) {
      if (!loop_start_) {
        loop_start_ = input.pose;
        loop_start_m_ = budget_.travelled_m();
      } else if (loop_closed(input.pose)) {
        return finish(true);
      }
    }
    return follow(sides);
  }

  /// The edge has ended on the right: a doorway, or the end of a wall. A doorway shows to the
  /// side transducer as the edge ending; the forward transducers see through it head-on. So:
  /// on to about the doorway's middle, face it, look, and cross; else round the end (pivot).
  VelocityCommand end_of_edge(const NavInput& input) {
    const EdgeOptions& e = options_.edge;
    const double now = input.frame->time_s;
    const Point2 here = input.pose.translation();
    if (state_ == State::kFollow) {
      state_ = State::kEndOfEdge;
      end_s_ = now;
      end_pose_ = input.pose;
      turned_rad_ = 0.0;
      facing_s_.reset();
    }
    if (state_ != State::kEndOfEdge) return pivot(input);
    const double advanced = (here - end_pose_.translation()).norm();
    const double face_rad = end_pose_.theta_rad - 0.5 * kPi;
    if (advanced < e.end_advance_m && now - end_s_ < 3.0) {
      return core_.drive_direct(input, end_pose_.theta_rad, e.pivot_speed_mps,
                                NavMode::kEdgeFollow);
    }
    const double error = wrap_angle_rad(face_rad - input.pose.theta_rad);
    if (!facing_s_) {
      if (std::abs(error) > 10.0 * kPi / 180.0 && now - end_s_ < 6.0) {
        core_.trace().mode = NavMode::kEdgePivot;
        return core_.sent(
            {0.0, std::clamp(1.5 * error, -core_.max_turn_radps(), core_.max_turn_radps())});
      }
      facing_s_ = now;
    }
    if (const auto cmd = look_for_door(input, face_rad)) return *cmd;
    const auto ahead = front_pulses_since(*facing_s_);
    // A jamb at a beam's edge answers one of the forward pair (a 1 m door spans ±30° at
    // 0.9 m); a wall answers both.
    if (ahead && ahead->farthest_m > e.gap_clear_m) {
      state_ = State::kCross;
      cross_from_ = here;
      cross_s_ = now;
      cross_rad_ = face_rad;
      // Lean away from the jamb that answered.
      if (ahead->left_m < e.gap_clear_m) cross_rad_ -= e.cross_lean_rad;
      if (ahead->right_m < e.gap_clear_m) cross_rad_ += e.cross_lean_rad;
      return core_.drive_direct(input, cross_rad_, options_.door.speed_mps, NavMode::kDoorCross);
    }
    if (now - *facing_s_ < e.door_search_s) return core_.stop(NavMode::kEdgePivot);
    state_ = State::kPivot;
    turned_rad_ = 0.5 * kPi;  // the face turn counts toward the pivot
    return pivot(input);
  }

  void remember_pulses(const SensorFrame& frame) {
    const RobotGeometry& robot = core_.robot();
    pulses_.resize(robot.sonars.size());
    for (const SonarReading& r : frame.sonar) {
      if (r.index < 0 || static_cast<std::size_t>(r.index) >= pulses_.size()) continue;
      if (!std::isfinite(r.range_m) || r.range_m < robot.sonar_min_range_m) continue;
      const bool echo = r.echo && r.range_m <= robot.sonar_max_range_m;
      pulses_[static_cast<std::size_t>(r.index)] = {echo ? r.range_m : kInf, frame.time_s};
    }
  }

  Sides sides_now(const NavInput& input) const {
    // A ring cycle is ~0.4 s; older pulses describe a place the robot has left.
    return sense_sides(pulses_, core_.robot(), core_.field().points(), input.pose,
                       input.frame->time_s, 1.0);
  }

  /// The shortest range the forward transducers (within 20° of straight ahead) have heard
  /// since `since_s`, infinity for no echo; nullopt until each has fired since. Their last
  /// pulses, not the obstacle memory: the memory still holds echoes the side transducer
  /// painted into the gap while it passed.
  struct FrontPulses {
    double farthest_m = 0.0;  // the gap is open when one of them hears nothing near
    double left_m = kInf;     // the left-of-centre and right-of-centre ones
    double right_m = kInf;
  };
  std::optional<FrontPulses> front_pulses_since(double since_s) const {
    const RobotGeometry& robot = core_.robot();
    FrontPulses f;
    bool any = false;
    for (std::size_t i = 0; i < pulses_.size() && i < robot.sonars.size(); ++i) {
      const double h = wrap_angle_rad(robot.sonars[i].heading_rad);
      if (std::abs(h) > 20.0 * kPi / 180.0) continue;
      if (pulses_[i].time_s < since_s) return std::nullopt;
      f.farthest_m = std::max(f.farthest_m, pulses_[i].range_m);
      (h > 0.0 ? f.left_m : f.right_m) =
          std::min(h > 0.0 ? f.left_m : f.right_m, pulses_[i].range_m);
      any = true;
    }
    return any ? std::optional<FrontPulses>(f) : std::nullopt;
  }

  void begin_follow() {
    state_ = State::kFollow;
    follow_from_m_ = budget_.travelled_m();
  }

  /// Steady following: in kFollow for a while, at about follow_m. Only here is the tour's
  /// start taken, and only here is it found again (a corner or a doorway is no place to
  /// compare poses: the robot turns there).
  bool steady(const Sides& s) const {
    return state_ == State::kFollow && budget_.travelled_m() - follow_from_m_ > 1.0 &&
           std::abs(s.right_front_m - options_.edge.follow_m) < 0.25;
  }

  bool loop_closed(const Pose2& pose) const {
    const EdgeOptions& e = options_.edge;
    if (!loop_start_ || budget_.travelled_m() - loop_start_m_ < e.min_loop_m) return false;
    if ((pose.translation() - loop_start_->translation()).norm() > e.close_m) return false;
    return std::abs(wrap_angle_rad(pose.theta_rad - loop_start_->theta_rad)) <
           e.close_heading_deg * kPi / 180.0;
  }

  void track_turn(double theta_rad) {
    if (last_theta_) turned_rad_ -= wrap_angle_rad(theta_rad - *last_theta_);  // right = +
    last_theta_ = theta_rad;
  }

  double seek_heading_rad(const Pose2& pose) {
    if (!seek_rad_) seek_rad_ = pose.theta_rad;
    return *seek_rad_;
  }

  /// Keeps the edge on the right at follow_m (or midway in a passage narrower than twice it).
  VelocityCommand follow(const Sides& s) {
    const EdgeOptions& e = options_.edge;
    double ref = e.follow_m;
    if (s.left_m < e.lost_m) ref = std::min(ref, 0.5 * (s.left_m + s.right_m));
    double w = -e.lateral_gain * (s.right_m - ref);
    if (std::isfinite(s.right_front_m) && std::isfinite(s.right_rear_m) &&
        s.mount_spacing_m > 0.1 && std::abs(s.right_front_m - s.right_rear_m) < 0.5) {
      // The edge's angle to the heading (positive: it falls away ahead, turn right).
      w -= e.angle_gain * std::atan2(s.right_front_m - s.right_rear_m, s.mount_spacing_m);
    }
    const double w_max = core_.max_turn_radps();
    w = std::clamp(w, -0.8 * w_max, 0.8 * w_max);
    const double slow = std::clamp((s.ahead_m - e.corner_clearance_m) / 0.8, 0.3, 1.0);
    const double v = core_.speed_mps() * slow * std::clamp(1.0 - std::abs(w) / w_max, 0.3, 1.0);
    core_.trace().mode = NavMode::kEdgeFollow;
    return core_.sent({v, w});
  }

  /// Bears right on an arc of `radius_m` (searching for the edge).
  VelocityCommand arc_right(const Sides& s, double radius_m) {
    const double v = options_.edge.pivot_speed_mps *
                     std::clamp((s.ahead_m - options_.edge.corner_clearance_m) / 0.5, 0.0, 1.0);
    core_.trace().mode = NavMode::kEdgePivot;
    return core_.sent({v, -std::max(v, 0.1) / radius_m});
  }

  /// Circles clockwise around the edge's last sensed end at pivot_radius_m.
  VelocityCommand pivot(const NavInput& input) {
    const EdgeOptions& e = options_.edge;
    const Point2 here = input.pose.translation();
    if (turned_rad_ > 2.5 * kPi) {
      // Round and round with nothing heard on the right (glass, a low obstacle, an end point
      // that was a ghost): set off straight ahead for the next edge instead.
      state_ = State::kSeek;
      seek_rad_ = input.pose.theta_rad;
      return core_.stop(NavMode::kEdgePivot);
    }
    if (!edge_end_ || turned_rad_ > 1.75 * kPi) {
      return arc_right(sides_now(input), 1.0);
    }
    Point2 r = here - *edge_end_;
    const double dist = std::max(r.norm(), 1e-6);
    r /= dist;
    const Point2 tangent(r.y(), -r.x());  // clockwise around the end
    const Point2 dir = tangent - 1.5 * (dist - e.pivot_radius_m) * r;
    return core_.drive_direct(input, std::atan2(dir.y(), dir.x()), e.pivot_speed_mps,
                              NavMode::kEdgePivot);
  }

  /// At the end of the edge: a doorway to the right, sensed by the door behaviour, is crossed.
  std::optional<VelocityCommand> look_for_door(const NavInput& input, double face_rad) {
    if (!options_.door.enabled) return std::nullopt;
    const double now = input.frame->time_s;
    // Straight through the gap, 2 m on.
    door_goal_ = input.pose.translation() + 2.0 * Point2(std::cos(face_rad), std::sin(face_rad));
    const auto& points = core_.field().points();
    const auto found = door_.find(points, input.pose.translation(), door_goal_, now);
    if (!door_.offer(found, now)) {
      return std::nullopt;
    }
    return door_step(input);
  }

  std::optional<VelocityCommand> door_step(const NavInput& input) {
    const auto aim =
        door_.step(core_.field().points(), input.pose, door_goal_, input.frame->time_s);
    core_.trace().door_passages = door_.crossed() + crossings_;
    if (!aim) return std::nullopt;
    const Point2 d = *aim - input.pose.translation();
    const double rad = std::atan2(d.y(), d.x());
    const bool crossing = door_.mode() == NavMode::kDoorCross;
    return core_.drive_direct(input, rad,
                              crossing ? options_.door.speed_mps : options_.edge.pivot_speed_mps,
                              door_.mode());
  }

  VelocityCommand finish(bool complete) {
    finished_ = true;
    core_.trace().exploration_complete = complete;
    return core_.stop(NavMode::kExploreDone);
  }

  ExploreOptions options_;
  NavCore core_;
  DoorPassage door_;
  State state_ = State::kSeek;
  bool finished_ = false;
  ExploreBudget budget_;
  std::optional<Pose2> loop_start_;  // where the edge was first taken
  double loop_start_m_ = 0.0;
  double follow_from_m_ = 0.0;  // travel when following last began
  std::optional<double> seek_rad_;
  std::optional<double> last_theta_;
  double turned_rad_ = 0.0;  // clockwise turning since the state began
  std::optional<Point2> edge_end_;
  double end_s_ = 0.0;
  Pose2 end_pose_;
  Point2 door_goal_{0.0, 0.0};
  std::optional<double> facing_s_;  // end of edge: facing the gap since
  Point2 cross_from_{0.0, 0.0};     // crossing the gap: from here, along cross_rad_
  double cross_rad_ = 0.0;
  double cross_s_ = 0.0;
  std::size_t crossings_ = 0;
  std::vector<LastPulse> pulses_;
};

}  // namespace

std::unique_ptr<Controller> make_edge_explorer(const ExploreOptions& options) {
  return std::make_unique<EdgeExplorer>(options);
}

}  // namespace cogmap::mapper::nav
