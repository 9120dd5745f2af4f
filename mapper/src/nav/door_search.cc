#include "nav/door_search.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cogmap/mapper/asr/stages.h"
#include "nav/path_obstacles.h"

namespace cogmap::mapper::nav {
namespace {

// Root mean square distance of `points` from the fitted line.
double rms_distance_m(const LineFit& fit, const std::vector<Point2>& points) {
  double sum_sq = 0.0;
  for (const Point2& p : points) {
    const double off = cross(fit.direction, p - fit.point);
    sum_sq += off * off;
  }
  return std::sqrt(sum_sq / static_cast<double>(points.size()));
}

// The sweep refits its wall once this many square-on echoes span this much of it (a third of
// a second of side readings at the sweep speed, over more than the body's length).
constexpr std::size_t kRefitPoints = 6;
constexpr double kRefitExtentM = 0.8;
// A corner is sensed in the body's lane no nearer the wall than this beyond the robot's centre.
constexpr double kCornerSideM = 0.1;
// Facing the gap this nearly (the crossing's pure pursuit removes the rest).
constexpr double kFacedRad = 15.0 * std::numbers::pi / 180.0;

}  // namespace

std::optional<WallLine> blocking_wall(const std::vector<ObstaclePoint>& obstacles,
                                      const Point2& robot_m, const Point2& goal_m, double radius_m,
                                      double max_m, double max_rms_m) {
  const std::vector<Point2> near = blocking_structure(obstacles, robot_m, goal_m, radius_m, max_m);
  if (near.size() < 3) return std::nullopt;
  const LineFit fit = fit_line(near);
  if (!fit.valid || rms_distance_m(fit, near) > max_rms_m) return std::nullopt;
  WallLine wall;
  wall.point_m = robot_m + fit.point;
  wall.along = fit.direction;
  wall.normal = Point2(-fit.direction.y(), fit.direction.x());
  if (wall.normal.dot(fit.point) < 0.0) wall.normal = -wall.normal;  // robot -> wall
  return wall;
}

void WallProfile::add(const Point2& origin_m, const Point2& dir, double range_m, bool echo,
                      double band_m, double max_incidence_rad) {
  const double cos_incidence = dir.dot(wall_.normal);
  if (cos_incidence < std::cos(max_incidence_rad)) return;  // oblique, or facing away
  const double to_wall_m = (wall_.point_m - origin_m).dot(wall_.normal);
  if (to_wall_m <= 0.0) return;  // the transducer is beyond the line
  const double t_wall = to_wall_m / cos_incidence;
  if (echo && range_m < t_wall - band_m) return;  // something in front of the wall
  if (echo && range_m <= t_wall + band_m) {
    wall_at_.push_back(origin_m + range_m * dir);
    return;
  }
  if (range_m <= t_wall + band_m) return;  // a short maximum range says nothing of the wall
  open_at_.push_back(origin_m + t_wall * dir);
}

void WallProfile::refit(std::size_t min_points, double min_extent_m, double max_rms_m) {
  if (wall_at_.size() < min_points) return;
  double lo = 0.0, hi = 0.0;
  for (std::size_t i = 0; i < wall_at_.size(); ++i) {
    const double s = s_of(wall_at_[i]);
    lo = i == 0 ? s : std::min(lo, s);
    hi = i == 0 ? s : std::max(hi, s);
  }
  if (hi - lo < min_extent_m) return;
  const LineFit fit = fit_line(wall_at_);
  if (!fit.valid || rms_distance_m(fit, wall_at_) > max_rms_m) return;
  const Point2 along = fit.direction.dot(wall_.along) >= 0.0 ? fit.direction : -fit.direction;
  Point2 normal(-along.y(), along.x());
  if (normal.dot(wall_.normal) < 0.0) normal = -normal;
  // Keep the origin of s where it was (its projection onto the new line).
  wall_.point_m = fit.point + (wall_.point_m - fit.point).dot(along) * along;
  wall_.along = along;
  wall_.normal = normal;
}

std::optional<Opening> WallProfile::gap(double min_width_m, double max_width_m, double max_unseen_m,
                                        double prefer_s_m) const {
  std::vector<double> walls, opens;
  for (const Point2& p : wall_at_) walls.push_back(s_of(p));
  for (const Point2& p : open_at_) opens.push_back(s_of(p));
  std::sort(walls.begin(), walls.end());
  std::sort(opens.begin(), opens.end());
  std::optional<Opening> best;
  double best_cost = 0.0;
  for (std::size_t i = 0; i + 1 < walls.size(); ++i) {
    const double a = walls[i], b = walls[i + 1];
    const double width = b - a;
    if (width < min_width_m || width > max_width_m) continue;
    // Readings through it, none of its stretches unseen: not one lost echo, not an unvisited
    // part of the wall.
    auto it = std::upper_bound(opens.begin(), opens.end(), a);
    int through = 0;
    double last = a;
    bool seen = true;
    for (; it != opens.end() && *it < b; ++it) {
      if (*it - last > max_unseen_m) seen = false;
      last = *it;
      ++through;
    }
    if (!seen || through < 2 || b - last > max_unseen_m) continue;
    const double center_s = 0.5 * (a + b);
    const double cost = std::abs(center_s - prefer_s_m);
    if (!best || cost < best_cost) {
      best_cost = cost;
      best = Opening{wall_.point_m + center_s * wall_.along, wall_.normal, width};
    }
  }
  return best;
}

bool DoorSearch::start(const std::vector<ObstaclePoint>& obstacles, const Pose2& pose,
                       const Point2& goal_m, const std::optional<Point2>& then_m, double lane_m,
                       double time_s, double max_goal_m) {
  const Point2 here = pose.translation();
  if ((goal_m - here).norm() > max_goal_m) return false;
  const auto wall = blocking_wall(obstacles, here, goal_m, lane_m, options_.probe_range_m,
                                  options_.search_max_rms_m);
  if (!wall) return false;
  const auto beyond = [&](const Point2& p) { return (p - wall->point_m).dot(wall->normal); };
  double farthest = beyond(goal_m);
  if (then_m && (*then_m - here).norm() <= max_goal_m) {
    farthest = std::max(farthest, beyond(*then_m));
  }
  if (farthest < options_.search_min_beyond_m) return false;
  profile_.emplace(*wall);
  start_m_ = here;
  goal_m_ = goal_m;
  // Toward the waypoint's foot on the wall first: a door-centre waypoint the estimate has
  // moved lies beside its door, a room-centre waypoint faces the middle of the wall.
  direction_ = profile_->s_of(goal_m) >= profile_->s_of(here) ? 1.0 : -1.0;
  legs_ = 0;
  start_time_s_ = time_s;
  ++started_;
  return true;
}

DoorSearch::Step DoorSearch::step(const SensorFrame& frame,
                                  const std::vector<ObstaclePoint>& obstacles,
                                  const RobotGeometry& robot, const Pose2& pose, double time_s) {
  Step out;
  if (heard_) {
    // To the approach point, then face the gap: the passage's crossing calls a door that
    // makes no headway for closed_after_s closed, and a turn on the spot makes none.
    const Point2 approach = heard_->center_m - options_.approach_m * heard_->normal;
    const Point2 facing(std::cos(pose.theta_rad), std::sin(pose.theta_rad));
    if (!at_approach_ &&
        (approach - pose.translation()).norm() < options_.search_approach_tolerance_m) {
      at_approach_ = true;
    }
    const bool faced = facing.dot(heard_->normal) >= std::cos(kFacedRad);
    if ((at_approach_ && faced) || time_s - start_time_s_ > options_.search_timeout_s) {
      out.found = heard_;
      heard_.reset();
    } else {
      out.aim = at_approach_ ? pose.translation() + heard_->normal : approach;
    }
    return out;
  }
  if (!profile_) return out;
  const double max_incidence = options_.search_max_incidence_deg * std::numbers::pi / 180.0;
  for (const SonarReading& r : frame.sonar) {
    if (r.index < 0 || r.index >= static_cast<int>(robot.sonars.size())) continue;
    if (!std::isfinite(r.range_m)) continue;
    const SonarMount& m = robot.sonars[static_cast<std::size_t>(r.index)];
    const Point2 origin = pose.transform(Point2(m.x_m, m.y_m));
    const double heading = pose.theta_rad + m.heading_rad;
    profile_->add(origin, Point2(std::cos(heading), std::sin(heading)), r.range_m, r.echo,
                  options_.search_band_m, max_incidence);
  }
  profile_->refit(kRefitPoints, kRefitExtentM, options_.search_max_rms_m);
  const double start_s = profile_->s_of(start_m_);
  const double goal_s = profile_->s_of(goal_m_);
  if (auto g = profile_->gap(options_.search_min_gap_m, options_.max_width_m,
                             options_.search_max_unseen_m, goal_s)) {
    ++found_;
    profile_.reset();
    heard_ = g;
    at_approach_ = false;
    out.aim = g->center_m - options_.approach_m * g->normal;
    return out;
  }
  if (time_s - start_time_s_ > options_.search_timeout_s) {
    profile_.reset();
    return out;
  }
  const WallLine& wall = profile_->wall();
  const Point2 here = pose.translation();
  const double s = profile_->s_of(here);
  // The first leg runs past the waypoint's foot (if that is further than the span), the
  // second back past the start by the span.
  const double first_end =
      start_s +
      direction_ * std::min(std::max(options_.search_span_m, direction_ * (goal_s - start_s) +
                                                                 options_.search_beyond_goal_m),
                            options_.search_max_span_m);
  const double end_s = legs_ == 0 ? first_end : start_s + direction_ * options_.search_span_m;
  // Something ahead in the half of the body's lane away from the wall: a corner (a wall across
  // the lane fills all of it). The half toward the wall is left out: there the oblique
  // transducers paint a jamb's end face, and that is where a door is, not where it ends.
  const Point2 ahead = direction_ * wall.along;
  const double half_lane = 0.5 * robot.width_m + 0.1;
  const double reach = 0.5 * robot.length_m + options_.search_turn_clearance_m;
  bool cornered = false;
  for (const ObstaclePoint& p : obstacles) {
    const double a = p.offset_m.dot(ahead);
    if (a <= 0.0 || a > reach || std::abs(cross(ahead, p.offset_m)) > half_lane) continue;
    if (p.offset_m.dot(wall.normal) > kCornerSideM) continue;  // on the wall's side
    cornered = true;
    break;
  }
  if (direction_ * (s - end_s) >= 0.0 || cornered) {
    if (++legs_ >= 2) {
      profile_.reset();
      return out;
    }
    direction_ = -direction_;
  }
  out.aim = wall.point_m + (s + direction_ * options_.search_lookahead_m) * wall.along -
            options_.search_standoff_m * wall.normal;
  return out;
}

}  // namespace cogmap::mapper::nav
