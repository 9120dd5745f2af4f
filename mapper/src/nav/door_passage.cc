#include "nav/door_passage.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "cogmap/mapper/asr/stages.h"
#include "nav/nav_constants.h"

namespace cogmap::mapper::nav {
namespace {

/// The opening's normal from the wall it sits in: the two jamb points alone (0.9-1.2 m
/// apart, one often on the wall's near face and one on its far face, each with range noise)
/// tilt it by 5-15°, and a tilted axis leads the crossing into a jamb. The wall points within
/// wall_fit_m beyond either jamb and near the jamb line give a baseline 2-3 times longer;
/// their principal direction replaces the jamb line when at least 4 points support it.
Point2 wall_normal(const std::vector<std::optional<Point2>>& scan, const Point2& center,
                   const Point2& jamb_normal, double width_m, const DoorOptions& o) {
  const Point2 along(-jamb_normal.y(), jamb_normal.x());
  std::vector<Point2> wall;
  for (const auto& q : scan) {
    if (!q) continue;
    const Point2 rel = *q - center;
    const double lateral = std::abs(rel.dot(along));
    if (std::abs(rel.dot(jamb_normal)) > o.depth_m) continue;
    if (lateral < 0.5 * width_m - 0.05 || lateral > 0.5 * width_m + o.wall_fit_m) continue;
    wall.push_back(rel);
  }
  if (o.wall_fit_m <= 0.0 || wall.size() < 4) return jamb_normal;
  const LineFit fit = fit_line(wall);  // the ASR stage's orthogonal fit (§3.1.8)
  if (!fit.valid) return jamb_normal;
  Point2 n(-fit.direction.y(), fit.direction.x());
  if (n.dot(jamb_normal) < 0.0) n = -n;
  // A fit far from the jamb line is some other structure (a corner): keep the jambs' word.
  return n.dot(jamb_normal) > std::cos(o.max_axis_angle_deg * kPi / 180.0 / 2.0) ? n : jamb_normal;
}

/// What lies beyond an opening, in the lane the body sweeps along its axis (half-width
/// beyond_lane_m) between depth_m (points nearer the jamb line are the wall and its smear,
/// judged by the caller) and beyond_clear_m beyond its line: how many scan points, and how far
/// across the lane they spread.
struct Beyond {
  int points = 0;
  double span_m = 0.0;
};

Beyond lane_beyond(const std::vector<std::optional<Point2>>& scan, const Point2& center,
                   const Point2& normal, const DoorOptions& o) {
  Beyond b;
  if (o.beyond_clear_m <= o.depth_m) return b;  // no pocket check (routes)
  const Point2 side(-normal.y(), normal.x());
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const std::optional<Point2>& q : scan) {
    if (!q) continue;
    const Point2 d = *q - center;
    const double along = normal.dot(d), across = side.dot(d);
    if (along < o.depth_m || along >= o.beyond_clear_m || std::abs(across) >= o.beyond_lane_m) {
      continue;
    }
    ++b.points;
    lo = std::min(lo, across);
    hi = std::max(hi, across);
  }
  if (b.points > 0) b.span_m = hi - lo;
  return b;
}

}  // namespace

std::optional<Opening> find_opening(const std::vector<ObstaclePoint>& obstacles,
                                    const Point2& robot_m, const Point2& goal_m,
                                    const DoorOptions& o, const std::vector<Point2>& excluded,
                                    bool* goal_in_pocket) {
  if (goal_in_pocket) *goal_in_pocket = false;
  const Point2 to_goal = goal_m - robot_m;
  const double goal_dist = to_goal.norm();
  if (goal_dist < 1e-6) return std::nullopt;
  const Point2 g = to_goal / goal_dist;
  const double goal_rad = std::atan2(g.y(), g.x());
  // Polar scan relative to the goal direction over the front half plane: the nearest point
  // per bin (a laser-like scan), so a wall hides what lies behind it.
  const int bins = std::max(4, static_cast<int>(std::lround(180.0 / o.bin_deg)));
  const double bin_rad = kPi / bins;
  std::vector<std::optional<Point2>> scan(static_cast<std::size_t>(bins));
  for (const ObstaclePoint& p : obstacles) {
    const double d = p.offset_m.norm();
    if (d < 0.1 || d > o.search_range_m) continue;
    const double rel = wrap_angle_rad(std::atan2(p.offset_m.y(), p.offset_m.x()) - goal_rad);
    if (std::abs(rel) >= 0.5 * kPi) continue;
    const int b =
        std::clamp(static_cast<int>(std::floor((rel + 0.5 * kPi) / bin_rad)), 0, bins - 1);
    auto& slot = scan[static_cast<std::size_t>(b)];
    if (!slot || d < slot->norm()) slot = p.offset_m;
  }
  // A jamb is the end of a wall: another scan point continues the wall within jamb_support_m
  // on its far side from the opening. A lone echo is no jamb (sparse early sonar would
  // otherwise show "openings" between any two points).
  const auto supported = [&](const Point2& jamb, const Point2& other) {
    const Point2 out = (jamb - other).normalized();
    for (const auto& q : scan) {
      if (!q) continue;
      const Point2 d = *q - jamb;
      const double n = d.norm();
      if (n > 0.02 && n <= o.jamb_support_m && d.dot(out) > 0.5 * n) return true;
    }
    return false;
  };
  const Point2 goal_off = to_goal;
  std::optional<Opening> best;
  double best_cost = std::numeric_limits<double>::infinity();
  for (int i = 0; i < bins; ++i) {
    if (!scan[i]) continue;
    const Point2 a = *scan[i];
    for (int j = i + 1; j < bins; ++j) {
      if (!scan[j]) continue;
      const Point2 b = *scan[j];
      const double width = (b - a).norm();
      if (width > o.max_width_m || width < o.min_width_m) continue;
      // The opening's normal, away from the robot (the robot is at the origin).
      const Point2 center = 0.5 * (a + b);
      Point2 n(-(b - a).y() / width, (b - a).x() / width);
      if (n.dot(center) < 0.0) n = -n;
      if (n.dot(center) < 0.2) continue;  // seen edge-on or the robot is in it
      // Crossing it must lead toward the goal: a gap met sideways (two wall ends meeting at
      // a corner, furniture beside the path) is no door on the way.
      if (n.dot(g) < std::cos(o.max_axis_angle_deg * kPi / 180.0)) continue;
      // Nothing between them (in bearing) nearer than depth_m beyond their line.
      bool clear = true;
      for (int k = i + 1; k < j && clear; ++k) {
        if (scan[k] && n.dot(*scan[k] - center) < o.depth_m) clear = false;
      }
      if (!clear || !supported(a, b) || !supported(b, a)) continue;
      // The goal must be beyond the opening (or about in it: a waypoint at a door centre).
      const double goal_beyond = n.dot(goal_off - center);
      if (goal_beyond < -o.approach_m) continue;
      // A goal in the opening (a door-centre waypoint) names the door: only drift separates
      // them, not the length of a wall.
      if (goal_beyond < o.approach_m && (goal_off - center).norm() > o.goal_in_door_m) continue;
      const double offset = std::abs(cross(g, center));  // from the goal line
      if (offset > o.max_offset_m) continue;
      // Seen too far off its axis, a wall's echoes are painted off its line: no door is known.
      const Point2 axis = wall_normal(scan, center, n, width, o);
      if (axis.dot(center.normalized()) < std::cos(o.max_view_incidence_deg * kPi / 180.0)) {
        continue;
      }
      // Something sensed in the body's lane within beyond_clear_m beyond the gap: a pocket
      // (furniture beside a wall), where the crossing could not end with room to turn.
      const Beyond beyond = lane_beyond(scan, center, n, o);
      if (beyond.points > 0) {
        // A goal inside it, closed across at least half the lane (one or two points are no
        // back wall: a beam looking through a doorway at an angle hears the wall beside it
        // and paints that echo on its axis, inside the lane beyond the door), cannot be
        // reached.
        const Point2 side(-n.y(), n.x());
        if (goal_in_pocket && beyond.span_m >= o.beyond_lane_m && goal_beyond >= 0.0 &&
            goal_beyond < o.beyond_clear_m && std::abs(side.dot(goal_off - center)) < 0.5 * width) {
          *goal_in_pocket = true;
        }
        continue;
      }
      const bool known_bad = std::any_of(excluded.begin(), excluded.end(), [&](const Point2& e) {
        return (e - (robot_m + center)).norm() < o.track_m;
      });
      if (known_bad) continue;
      const double cost = offset + 0.1 * center.norm();
      if (cost < best_cost) {
        best_cost = cost;
        best = Opening{robot_m + center, axis, width};
      }
    }
  }
  return best;
}

std::optional<Opening> DoorPassage::find(const std::vector<ObstaclePoint>& obstacles,
                                         const Point2& robot_m, const Point2& goal_m,
                                         double time_s) {
  std::erase_if(rejected_, [&](const auto& r) { return r.second <= time_s; });
  std::vector<Point2> excluded;
  for (const auto& r : rejected_) excluded.push_back(r.first);
  return find_opening(obstacles, robot_m, goal_m, options_, excluded, &goal_in_pocket_);
}

void DoorPassage::reject(double time_s) {
  rejected_.emplace_back(opening_.center_m, time_s + options_.rejected_keep_s);
  mode_ = NavMode::kIdle;
  ++abandoned_;
}

bool DoorPassage::offer(const std::optional<Opening>& opening, double time_s) {
  if (!opening) {
    candidate_.reset();
    return active();
  }
  if (!candidate_ || (opening->center_m - candidate_->center_m).norm() > options_.track_m) {
    candidate_since_s_ = time_s;
  }
  candidate_ = opening;
  if (time_s - candidate_since_s_ >= options_.confirm_s) {
    start(*candidate_, time_s);
    candidate_.reset();
  }
  return active();
}

void DoorPassage::start(const Opening& opening, double time_s, bool refine) {
  opening_ = opening;
  refine_ = refine;
  mode_ = NavMode::kDoorAlign;
  start_s_ = time_s;
  seen_s_ = time_s;
}

void DoorPassage::recenter(const std::vector<ObstaclePoint>& obstacles, const Point2& robot_m) {
  if (options_.recenter_gain <= 0.0) return;
  // The jambs in the door's own frame: points within recenter_band_m of the door line. The
  // nearest one on either side of the locked centre bound the gap actually there.
  const Point2 side(-opening_.normal.y(), opening_.normal.x());
  double left = std::numeric_limits<double>::infinity();
  double right = -std::numeric_limits<double>::infinity();
  for (const ObstaclePoint& o : obstacles) {
    const Point2 rel = robot_m + o.offset_m - opening_.center_m;
    if (std::abs(rel.dot(opening_.normal)) > options_.recenter_band_m) continue;
    const double lateral = rel.dot(side);
    if (std::abs(lateral) > options_.max_width_m) continue;
    if (lateral >= 0.0)
      left = std::min(left, lateral);
    else
      right = std::max(right, lateral);
  }
  // Both jambs seen, and a gap the robot fits through: move the centre toward its middle
  // (low-pass, so one stray echo cannot throw the robot sideways).
  if (!std::isfinite(left) || !std::isfinite(right)) return;
  if (left - right < options_.min_width_m) return;
  opening_.center_m += options_.recenter_gain * 0.5 * (left + right) * side;
}

std::optional<Point2> DoorPassage::step(const std::vector<ObstaclePoint>& obstacles,
                                        const Pose2& pose, const Point2& goal_m, double time_s) {
  if (mode_ == NavMode::kIdle) return std::nullopt;
  const Point2 p = pose.translation();
  // Before the crossing, keep refining the opening from what the sonar now sees of it; in the
  // opening itself the jambs are beside the robot (outside the front half plane): freeze.
  if (mode_ == NavMode::kDoorAlign && !refine_) seen_s_ = time_s;
  if (mode_ == NavMode::kDoorAlign && refine_) {
    // Look through the locked opening (not at the goal, which may be far off to a side).
    const Point2 through = opening_.center_m + 1.5 * opening_.normal;
    (void)goal_m;
    if (const auto o = find(obstacles, p, through, time_s);
        o && (o->center_m - opening_.center_m).norm() < options_.track_m &&
        o->normal.dot(opening_.normal) > std::cos(30.0 * kPi / 180.0)) {
      opening_ = *o;
      seen_s_ = time_s;
    }
  }
  if (mode_ == NavMode::kDoorCross) recenter(obstacles, p);
  const Point2 rel = p - opening_.center_m;
  const double along = rel.dot(opening_.normal);  // < 0 before the opening
  const Point2 side(-opening_.normal.y(), opening_.normal.x());
  const double lateral = rel.dot(side);
  if (along > options_.exit_m) {
    mode_ = NavMode::kIdle;
    ++crossed_;
    return std::nullopt;
  }
  if (time_s - start_s_ > options_.timeout_s ||
      (mode_ == NavMode::kDoorAlign && time_s - seen_s_ > options_.lost_s)) {
    reject(time_s);
    return std::nullopt;
  }
  // Crossing without getting through: the opening is closed (a shut door, or a gap that was
  // only unseen wall), and the front safety check holds the robot in front of it. (An
  // obstacle test on the axis fails: every echo sits on its beam's axis, so the 30° smear of
  // the jambs paints points into a real opening.)
  if (mode_ == NavMode::kDoorCross) {
    if (along > best_along_ + options_.closed_progress_m) {
      best_along_ = along;
      progress_s_ = time_s;
    } else if (time_s - progress_s_ > options_.closed_after_s) {
      reject(time_s);
      return std::nullopt;
    }
  }
  if (mode_ == NavMode::kDoorAlign) {
    // At the approach point, or near the axis and near the opening, or (found late) already
    // at it: the crossing's pursuit removes what lateral error is left.
    const Point2 approach = opening_.center_m - options_.approach_m * opening_.normal;
    const bool at_approach = (p - approach).norm() < 2.0 * options_.align_tolerance_m + 0.1;
    const bool on_axis = std::abs(lateral) < options_.align_tolerance_m;
    const bool close = along > -options_.approach_m - 0.15;
    if ((on_axis && close) || at_approach || along > -0.4) {
      mode_ = NavMode::kDoorCross;
      best_along_ = along;
      progress_s_ = time_s;
    }
  }
  if (mode_ == NavMode::kDoorAlign) {
    return opening_.center_m - options_.approach_m * opening_.normal;
  }
  // Pure pursuit onto the axis: a point lookahead_m ahead of the robot's projection on it.
  return opening_.center_m + (along + options_.lookahead_m) * opening_.normal;
}

}  // namespace cogmap::mapper::nav
