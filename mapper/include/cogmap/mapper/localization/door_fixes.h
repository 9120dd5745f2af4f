#pragma once
/// Our extension beyond §3.1.9 (which corrects the heading only): a position fix from doorways
/// passed again. The doorway state machine (§3.1.2, Fig. 3.4) places each exit between the side
/// sonars' echoes off the door frame, so a door the robot passes a second time is measured
/// twice; the difference is the position drift of the estimate since the first passage, and
/// moving the estimate back towards the first passage makes the robot agree with the rooms it
/// mapped then. docs/algorithms.md, "Position fixes at doorways passed again".

#include <optional>
#include <vector>

#include "cogmap/mapper/seam/geometry.h"

namespace cogmap::mapper {

/// Defaults measured on generated buildings (docs/algorithms.md, "Position fixes at doorways
/// passed again"); the thesis has no such fix.
struct DoorFixOptions {
  /// On (default): the estimate takes the fix. Off: EM's rotation only, as the thesis.
  bool enabled = true;
  /// A passage further than this from every door passed before is a new door. It bounds the
  /// drift a fix can undo (1 of 199 re-passages measured had drifted further).
  double match_radius_m = 0.8;
  /// The next door passed before must be at least this many times further than the match, so
  /// that a passage halfway between two known doors is no fix for either.
  double ambiguity_ratio = 2.0;
  /// Gaps wider than this are no fix: the side echoes place a wide opening's centre poorly
  /// (two passages disagree by 0.32 m rms at 1.6 m, 0.13 m at 0.9-1.2 m).
  double max_width_m = 1.3;
  /// Widths measured at the two passages differ by at most this (the same door frame).
  double max_width_difference_m = 0.3;
  /// The two passages' headings, as axes (a door is passed both ways), differ by at most this.
  double max_axis_difference_deg = 45.0;
  /// How well one passage places the door's centre, sd per axis (with noise-free encoders,
  /// passages of the same door scatter this much about their mean).
  double door_sd_m = 0.09;
  /// How fast the estimate's position drifts, sd per axis per metre travelled (fitted to the
  /// shifts that would have put re-passed doors back where they were first measured).
  double drift_sd_per_m = 0.016;
};

/// One passage through a doorway, in the corrected estimate frame at the time it was passed.
struct DoorPassage {
  Point2 center{0.0, 0.0};   ///< the gap's centre between the side echoes
  double width_m = 0.0;      ///< the gap's width
  double heading_rad = 0.0;  ///< direction of travel through it
  double travel_m = 0.0;     ///< the estimate's path length when it was passed
};

/// The doors passed so far, each where it was first measured.
class DoorMemory {
 public:
  explicit DoorMemory(const DoorFixOptions& options) : options_(options) {}

  /// The shift to add to the estimate for `passage`: towards where the door it passes again
  /// was first measured, by the Kalman gain of the drift since that door was last passed
  /// against two passages' scatter. None for a door not passed before (remembered from now
  /// on), a passage too near two known doors to say which, or too wide to place.
  std::optional<Point2> pass(const DoorPassage& passage);

  const std::vector<DoorPassage>& doors() const { return doors_; }

 private:
  DoorFixOptions options_;
  std::vector<DoorPassage> doors_;
};

}  // namespace cogmap::mapper
