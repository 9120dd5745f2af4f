#pragma once
/// Turn-backs that repeat. When the way to the target is blocked, VFH steers along the
/// obstacle; when that valley closes (a desk, a corner, the wall beside a door the drifted
/// estimate misplaces) the only valley left is often the way back, and a metre later the
/// first one opens again. Each turn-back is a turn of 120-180° on the spot, and a skid-steer
/// base loses 2-3 % of every spin in heading: on generated routes such limit cycles ran for
/// minutes and carried 30-60° of odometry error (docs/algorithms.md, "Turn-backs held").
/// After VfhOptions::turn_back_limit turn-backs within turn_back_window_s toward one target,
/// the robot holds its way for turn_back_hold_s: Vfh::select then charges a candidate more
/// than 90° from last cycle's direction turn_back_cost_rad, so VFH follows the obstacle
/// round, as a Bug algorithm walks a boundary, and turns back only where nothing else is free.

#include <deque>

#include "cogmap/mapper/nav/nav_options.h"

namespace cogmap::mapper::nav {

/// A choice of `to_rad` after `from_rad` turns back: more than 90° from it.
bool turns_back(double from_rad, double to_rad);

class TurnBacks {
 public:
  explicit TurnBacks(const VfhOptions& options) : options_(options) {}

  /// The direction chosen at `time_s` toward `target_rad`, after `previous_rad` chosen the
  /// cycle before. A target that has swung more than turn_back_target_deg from the one the
  /// turn-backs were counted against (a new waypoint or goal) starts the count afresh.
  void record(double time_s, double target_rad, double previous_rad, double direction_rad);

  /// Whether the robot holds its way at `time_s` for a target at `target_rad`.
  bool holding(double time_s, double target_rad) const;

 private:
  bool same_target(double target_rad) const;

  VfhOptions options_;
  double target_rad_ = 0.0;
  bool has_target_ = false;
  std::deque<double> turn_back_times_s_;  // within turn_back_window_s of the latest
  double hold_until_s_ = -1.0;
};

}  // namespace cogmap::mapper::nav
