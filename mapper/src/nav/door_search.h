#pragma once
/// The door search: when the wall between the robot and its waypoint has no opening where the
/// sonar looked (the probe stalled), sweep along the wall at a standoff and listen with the
/// side transducers, which meet the wall square-on. A door shows there as readings that pass
/// beyond the wall line between two stretches of echoes from it; its centre is the middle of
/// the two stretches' inner ends (the beam's smear narrows the gap equally on both sides).
/// Everything is in the estimate frame; only the sonar readings and the remembered echoes are
/// read (no map, no truth).

#include <optional>
#include <vector>

#include "cogmap/mapper/nav/controller.h"
#include "cogmap/mapper/nav/vfh.h"
#include "nav/door_passage.h"

namespace cogmap::mapper::nav {

/// A straight wall: a point on it, its unit direction, and the unit normal from the robot's
/// side toward the wall.
struct WallLine {
  Point2 point_m{0.0, 0.0};
  Point2 along{1.0, 0.0};
  Point2 normal{0.0, 1.0};
};

/// The wall that blocks the way from robot_m toward goal_m: the orthogonal fit of the
/// remembered echoes (offsets from robot_m) within 1 m of the first one on the way (within
/// radius_m of the line, up to max_m). nullopt when nothing blocks, too few points describe it,
/// or they do not lie on a line (rms distance above max_rms_m).
std::optional<WallLine> blocking_wall(const std::vector<ObstaclePoint>& obstacles,
                                      const Point2& robot_m, const Point2& goal_m, double radius_m,
                                      double max_m, double max_rms_m);

/// What the transducers have heard of one wall, as positions along it.
class WallProfile {
 public:
  explicit WallProfile(const WallLine& wall) : wall_(wall) {}
  /// One reading from a transducer at `origin_m` looking along unit `dir`: an echo within
  /// band_m of the wall line marks the wall where it lies; a reading that passes beyond the
  /// line by more than band_m (or no echo) marks where its axis crosses the line as open.
  /// Readings meeting the wall more than max_incidence_rad off its normal are ignored, as are
  /// echoes from something nearer than the wall.
  void add(const Point2& origin_m, const Point2& dir, double range_m, bool echo, double band_m,
           double max_incidence_rad);
  /// The gap between two marked stretches of wall whose width (between their inner ends) is in
  /// [min_width_m, max_width_m], with open readings inside and none of its stretches longer
  /// than max_unseen_m without one; the one whose centre is nearest `prefer_s_m` (position
  /// along the wall). nullopt when there is none.
  std::optional<Opening> gap(double min_width_m, double max_width_m, double max_unseen_m,
                             double prefer_s_m) const;
  /// Refits the wall to the echoes that marked it, once there are at least min_points over
  /// min_extent_m lying within max_rms_m of a line (square-on echoes place the wall better
  /// than the oblique front view it was started from). Keeps the direction's and the
  /// normal's sense.
  void refit(std::size_t min_points, double min_extent_m, double max_rms_m);
  /// Position of `p` along the wall.
  double s_of(const Point2& p) const { return (p - wall_.point_m).dot(wall_.along); }
  const WallLine& wall() const { return wall_; }

 private:
  WallLine wall_;
  std::vector<Point2> wall_at_;  // where an echo marked the wall
  std::vector<Point2> open_at_;  // where a reading passed the wall line
};

/// The sweep's state machine: started at a wall, it steers along it (toward the waypoint's
/// side first, then back past the start to the other side); at the first gap it hears it
/// drives to the point approach_m in front of the gap's centre and hands the gap over there
/// (the door passage's own approach accepts 0.34 m of lateral error, too much for a 0.9 m
/// door entered from the side).
class DoorSearch {
 public:
  explicit DoorSearch(const DoorOptions& options) : options_(options) {}
  /// Starts a sweep along the wall blocking the way from pose toward goal_m. False (and
  /// nothing started) when goal_m lies beyond search_max_goal_m, when no straight wall blocks
  /// the way to it, or when neither goal_m nor `then_m` (the waypoint after it, counted only
  /// within search_max_goal_m too) lies search_min_beyond_m beyond the wall: the route does not
  /// cross that wall here (a corridor's corner point the estimate's drift puts behind the end
  /// wall, its next leg tens of metres long).
  /// `lane_m`: how near the line to the goal an echo must lie to block it (VFH's safety radius).
  /// `max_goal_m`: the goal's distance limit, search_max_goal_m unless the caller widens it.
  bool start(const std::vector<ObstaclePoint>& obstacles, const Pose2& pose, const Point2& goal_m,
             const std::optional<Point2>& then_m, double lane_m, double time_s, double max_goal_m);
  bool active() const { return profile_.has_value() || heard_.has_value(); }
  /// A gap has been heard and the robot is on its way to (or turning at) its approach point.
  bool gap_heard() const { return heard_.has_value(); }
  void stop() {
    profile_.reset();
    heard_.reset();
  }

  struct Step {
    std::optional<Opening> found;  ///< a gap, and the robot is in front of it: pass through it
    std::optional<Point2> aim;     ///< otherwise the point to steer to; neither = sweep over
  };
  /// Per cycle while active: records the readings of `frame`, then returns the approach point
  /// of a gap found so far (the gap itself once the robot is there), or the next point on the
  /// standoff line. A remembered echo in the body's lane ahead that is not the swept wall (a
  /// corner, furniture; offsets from the robot in `obstacles`) turns the sweep around.
  Step step(const SensorFrame& frame, const std::vector<ObstaclePoint>& obstacles,
            const RobotGeometry& robot, const Pose2& pose, double time_s);
  std::size_t started() const { return started_; }
  std::size_t found() const { return found_; }

 private:
  DoorOptions options_;
  std::optional<WallProfile> profile_;
  std::optional<Opening> heard_;  // the gap, while the robot drives to its approach point
  bool at_approach_ = false;      // ...and has reached it (now turning to face the gap)
  Point2 start_m_{0.0, 0.0};      // where the sweep began
  Point2 goal_m_{0.0, 0.0};       // the waypoint
  double direction_ = 1.0;        // +1 / -1 along the wall
  int legs_ = 0;                  // turns of direction so far (the sweep ends after the second)
  double start_time_s_ = 0.0;
  std::size_t started_ = 0;
  std::size_t found_ = 0;
};

}  // namespace cogmap::mapper::nav
