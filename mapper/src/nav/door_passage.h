#pragma once
/// The door behaviour: find an opening in the sensed obstacles between the robot and its goal,
/// drive to a point on the opening's axis in front of it, then cross along the axis.
/// States (printable, NavMode names): idle -> door_align -> door_cross -> idle.
/// Everything is in the estimate frame; only the obstacle field is read (no map, no truth).

#include <optional>
#include <vector>

#include "cogmap/mapper/nav/controller.h"
#include "cogmap/mapper/nav/vfh.h"
#include "nav/path_obstacles.h"

namespace cogmap::mapper::nav {

/// A sensed opening: its centre and the unit normal pointing away from the robot's side.
struct Opening {
  Point2 center_m{0.0, 0.0};  ///< estimate frame
  Point2 normal{1.0, 0.0};    ///< unit, from the robot's side through the opening
  double width_m = 0.0;       ///< between the two jamb points
};

/// The opening between `robot_m` and `goal_m` (estimate frame) in `obstacles` (offsets from
/// robot_m): pairs of nearest-per-bin points whose distance is within [min_width, max_width]
/// and with nothing between them in bearing nearer than depth_m beyond their line; of those,
/// the one whose centre lies nearest the goal line (within max_offset_m) and which the goal is
/// beyond (or within approach_m of). nullopt when there is none.
/// Openings whose centre lies within track_m of one of `excluded` (estimate frame) are skipped.
/// A gap that is a pocket (something sensed within beyond_clear_m beyond it, in the body's
/// lane) is no opening; when the goal itself lies in such a pocket, `goal_in_pocket` (if
/// given) is set: the body cannot get there and turn.
std::optional<Opening> find_opening(const std::vector<ObstaclePoint>& obstacles,
                                    const Point2& robot_m, const Point2& goal_m,
                                    const DoorOptions& options,
                                    const std::vector<Point2>& excluded = {},
                                    bool* goal_in_pocket = nullptr);

/// The state machine. step() returns the point to steer to; while crossing (mode()
/// kDoorCross) the caller steers straight at it without VFH: the jambs may sit inside VFH's
/// enlargement when the gap is sensed narrow.
class DoorPassage {
 public:
  explicit DoorPassage(const DoorOptions& options) : options_(options) {}

  /// Starts a passage through `opening` at time_s. `refine` = false keeps the opening as
  /// given until the crossing (the door search heard it square-on, which the front
  /// transducers' re-detection would only smear).
  void start(const Opening& opening, double time_s, bool refine = true);

  /// Offers this cycle's detection (or none); starts the passage once the same opening (within
  /// track_m) has been detected without a break for confirm_s. Returns active().
  bool offer(const std::optional<Opening>& opening, double time_s);
  bool active() const { return mode_ != NavMode::kIdle; }
  NavMode mode() const { return mode_; }

  /// Per cycle while active: re-detects the opening near the locked one (before the crossing),
  /// advances the state machine and returns the point to steer to (estimate frame), or
  /// nullopt when the passage just ended (crossed, closed, timed out or lost; see crossed()).
  std::optional<Point2> step(const std::vector<ObstaclePoint>& obstacles, const Pose2& pose,
                             const Point2& goal_m, double time_s);

  /// The opening, excluding those found closed or abandoned in the last rejected_keep_s.
  std::optional<Opening> find(const std::vector<ObstaclePoint>& obstacles, const Point2& robot_m,
                              const Point2& goal_m, double time_s);
  /// True when the last find() saw the goal inside a pocket (find_opening).
  bool goal_in_pocket() const { return goal_in_pocket_; }

  /// Passages completed so far.
  std::size_t crossed() const { return crossed_; }
  /// Passages abandoned (closed, timed out or lost) so far.
  std::size_t abandoned() const { return abandoned_; }
  const Opening& opening() const { return opening_; }

 private:
  DoorOptions options_;
  NavMode mode_ = NavMode::kIdle;
  Opening opening_;
  double start_s_ = 0.0;
  double seen_s_ = 0.0;
  bool refine_ = true;       // re-detect the opening while aligning
  double best_along_ = 0.0;  // crossing: farthest along the axis so far, and when
  double progress_s_ = 0.0;
  std::size_t crossed_ = 0;
  std::size_t abandoned_ = 0;
  std::optional<Opening> candidate_;  // detected, not yet confirmed
  bool goal_in_pocket_ = false;       // the last find() saw the goal in a pocket
  double candidate_since_s_ = 0.0;
  std::vector<std::pair<Point2, double>> rejected_;  // opening centre, when it is forgotten

  void reject(double time_s);
  /// While crossing: moves the opening's centre toward the middle of the jambs now sensed.
  void recenter(const std::vector<ObstaclePoint>& obstacles, const Point2& robot_m);
};

}  // namespace cogmap::mapper::nav
