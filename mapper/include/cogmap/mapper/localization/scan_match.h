#pragma once
/// Heading and position kept consistent with the echoes of the last minute (ours; the thesis
/// corrects only between ASRs, §3.1.9). Every metre or half radian the echoes heard since the
/// last match (the *window*) are matched against a small occupancy grid built from the echoes
/// before them (the *memory*, HIMM increments and decrements along each beam); the rigid move of
/// the window about the robot that best fits them, weighed against odometry's drift since the
/// last match, turns and shifts the estimate. Drift then grows only as fast as the matches
/// leave it, not as fast as a room's turns make it, and the room grid is drawn in one frame.
/// docs/algorithms.md, "Echoes matched against the last minute", has the measurements.

#include <cstddef>
#include <deque>
#include <vector>

#include "cogmap/mapper/seam/pose2.h"
#include "cogmap/mapper/seam/robot_geometry.h"
#include "cogmap/mapper/seam/sensor_frame.h"

namespace cogmap::mapper {

/// Options of ScanMatcher (experiment keys `mapper.scan_match*`).
struct ScanMatchOptions {
  /// Off by default (the thesis corrects the heading only between ASRs).
  bool enabled = false;
  /// A match is due after this much travel of the estimate...
  double interval_m = 1.0;
  /// ... or this much turning (a skid-steer's heading drifts with its turns: ~1.5 % of each).
  double interval_rad = 0.5;
  /// ... but not before the window holds this many echoes (about 2 s of the ring near walls:
  /// turning on the spot, half a radian is half a second and 20-30 echoes, too few to measure).
  std::size_t min_window_echoes = 100;
  /// Echoes farther than this are not used (the grid window w: beyond it a 30° beam spans more
  /// than 1.6 m and its point on the axis says little about where the echo came from).
  double max_range_m = 3.0;
  /// Readings kept as memory (the ring fires ~50 a second: about a minute).
  std::size_t memory_readings = 3000;
  /// Cell of the memory grid (metres): the thesis's 10 cm.
  double cell_m = 0.1;
  /// A memory cell is a wall from this HIMM value (+3 a hit, −1 a beam through): two hits
  /// that no later beam crossed.
  double occupied_value = 6.0;
  /// sd of a window echo about the wall it came from (one cell and the sonar's 1 % range noise).
  double sigma_m = 0.1;
  /// Likelihood of an echo nowhere near a memory wall, relative to one on it: a phantom, a
  /// surface heard for the first time, a wall met obliquely whose echo sits on the beam axis.
  double outlier_weight = 0.1;
  /// Echoes of one transducer off one surface err together (the same beam geometry): this many
  /// echoes count as one independent measurement in the likelihood.
  double correlated_echoes = 3.0;
  /// Fewer window echoes than this within 2 sd of a memory wall: nothing is measured.
  std::size_t min_matched = 30;
  /// Whether the match turns the estimate (false: it only shifts it) ...
  bool rotation = true;
  /// ... and whether it shifts it (false: it only turns it; exploring, the shift doubles the
  /// contacts, docs/algorithms.md).
  bool shift = true;
  /// Search half-widths (4 prior sd, clamped to these) and steps.
  double max_rotation_rad = 0.105;    ///< 6°
  double rotation_step_rad = 0.0035;  ///< 0.2°
  double max_shift_m = 0.2;
  double shift_step_m = 0.04;
  /// A direction of the shift whose posterior variance stays above this share of the prior's
  /// is not measured (the length of a corridor): its part of the shift is not applied.
  double degenerate_ratio = 0.5;
  /// Odometry's distance error per metre driven (the shift's prior grows by it).
  double shift_drift_per_m = 0.02;
};

/// What one match measured (estimate frame).
struct ScanMatchFix {
  bool measured = false;           ///< false: too few echoes near memory walls, nothing applied
  double rotation_rad = 0.0;       ///< posterior mean, about `pivot`
  Point2 shift_m{0.0, 0.0};        ///< posterior mean, after the rotation
  Point2 pivot{0.0, 0.0};          ///< the robot's position at the match
  double rotation_var_rad2 = 0.0;  ///< posterior variance (prior when nothing was measured)
  double shift_var_m2 = 0.0;       ///< the same for each axis of the shift
  std::size_t window_echoes = 0;   ///< echoes in the window
  std::size_t matched_echoes = 0;  ///< of which near a memory wall (at the prior's mean)
  int degenerate_axes = 0;         ///< directions of the shift the echoes left unmeasured (0-2)

  /// The move that takes the estimate (and the window's echoes) onto the memory.
  Pose2 transform() const;
};

/// Keeps the memory and the window, and matches them.
class ScanMatcher {
 public:
  ScanMatcher(const ScanMatchOptions& options, const RobotGeometry& robot);

  /// One reading taken at `pose` (estimate frame) of room `room_id`.
  void add(const Pose2& pose, const SonarReading& reading, int room_id);
  /// The robot moved to `pose`, turning `turned_rad`: true when a match is due.
  bool visit(const Pose2& pose, double turned_rad);
  /// Matches the window against the memory with the prior variances (rad², m² per axis) of the
  /// estimate's error since the memory was drawn; the window then joins the memory, moved by
  /// the fix when one was measured (apply the same move to the estimate).
  ScanMatchFix match(const Pose2& pose, double rotation_prior_var_rad2, double shift_prior_var_m2);
  /// Room `room_id` was moved by `move` (its EM correction): its readings in memory follow.
  void move_room(int room_id, const Pose2& move);
  /// The estimate was shifted (a doorway passed again): every reading follows, as every one was
  /// drawn with the error the shift removes.
  void shift_all(const Point2& shift);

  double travelled_m() const { return travelled_m_; }
  double turned_rad() const { return turned_rad_; }
  std::size_t memory_size() const { return memory_.size(); }

 private:
  struct Echo {
    Point2 origin;  ///< transducer position
    Point2 point;   ///< where the echo lies on the beam axis
    int room_id;
  };

  ScanMatchOptions options_;
  std::vector<Pose2> mounts_;  ///< transducer poses on the robot
  std::deque<Echo> memory_;
  std::vector<Echo> window_;
  Point2 last_position_{0.0, 0.0};
  bool has_position_ = false;
  double travelled_m_ = 0.0;
  double turned_rad_ = 0.0;
};

}  // namespace cogmap::mapper
