#pragma once
/// The per-cycle machinery the route follower and the explorer share: sensing (memory,
/// obstacle field, polar histogram), stuck detection and recovery, and driving toward a goal
/// direction through VFH with the front safety check. The behaviours only choose the goal.

#include <limits>
#include <optional>

#include "cogmap/mapper/nav/controller.h"
#include "cogmap/mapper/nav/vfh.h"
#include "nav/obstacle_field.h"
#include "nav/obstacle_memory.h"
#include "nav/recovery.h"
#include "nav/steering.h"
#include "nav/turn_backs.h"

namespace cogmap::mapper::nav {

/// The options both behaviours have, gathered from RouteOptions or ExploreOptions.
struct CoreOptions {
  double speed_mps = 0.5;
  double max_turn_rate_radps = 1.0;
  double stuck_time_s = 4.0;
  VfhOptions vfh;
  MemoryOptions memory;
  SafetyOptions safety;
  RecoveryOptions recovery;
  double cross_stop_clearance_m = 0.25;  ///< DoorOptions: the crossing's front check on the
  double cross_slow_clearance_m = 0.6;   ///< points in the door's band
  SideWallOptions cross_side_walls;      ///< DoorOptions: grazing walls while crossing
};

/// The shared options of a behaviour's options (RouteOptions, ExploreOptions: same names).
template <typename BehaviourOptions>
CoreOptions core_options_of(const BehaviourOptions& o) {
  return {o.speed_mps,
          o.max_turn_rate_radps,
          o.stuck_time_s,
          o.vfh,
          o.memory,
          o.safety,
          o.recovery,
          o.door.cross_stop_clearance_m,
          o.door.cross_slow_clearance_m,
          o.door.cross_side_walls};
}

class NavCore {
 public:
  explicit NavCore(const CoreOptions& options);

  /// Remembers this frame's echoes, collects the obstacles and builds the polar histogram
  /// from those within `goal_range_m`. False (and a zero command is due) without a frame.
  bool sense(const NavInput& input, double goal_range_m = std::numeric_limits<double>::infinity());

  /// Stuck detection for this cycle; when stuck, records a contact and starts the recovery.
  /// Returns true when a recovery started this cycle.
  bool check_stuck(const NavInput& input);

  /// The recovery command while one runs, turning toward the freest sector nearest
  /// `prefer_rad` (world); nullopt otherwise.
  std::optional<VelocityCommand> recover(const NavInput& input, double prefer_rad);

  /// Drives toward the world direction `target_rad` through VFH and the front safety check,
  /// holding its way after repeated turn-backs (nav/turn_backs.h).
  VelocityCommand drive_toward(const NavInput& input, double target_rad);

  /// Steers straight at the world direction `target_rad` at up to `speed_mps`, without VFH
  /// (the door behaviour's crossing), keeping the front safety check. For kDoorCross the
  /// check looks at the body's lane only, and the points within `door_band` (if given) stop
  /// the robot only at the crossing's shorter distances (DoorOptions::cross_stop_clearance_m).
  VelocityCommand drive_direct(const NavInput& input, double target_rad, double speed_mps,
                               NavMode mode, const DoorBand* door_band = nullptr);

  /// Records the command about to be sent (stuck detection needs it) and returns it.
  VelocityCommand sent(const VelocityCommand& cmd);

  /// A turn on the spot that would strike a sensed point (spin_strike) becomes a move away
  /// from it along the axis, when that lane is clear; any other command is returned as is.
  VelocityCommand spin_guarded(const VelocityCommand& cmd) const;

  /// Moving on an arc that would bring a sensed point inside the body within
  /// SafetyOptions::arc_guard_s (arc_strikes): the turn alone, for spin_guarded to check; any
  /// other command is returned as is.
  VelocityCommand arc_guarded(const VelocityCommand& cmd) const;

  /// A zero command in mode `mode` (also clears the motion flag).
  VelocityCommand stop(NavMode mode);

  const Vfh& vfh() const { return vfh_; }
  const ObstacleField& field() const { return field_; }
  const RobotGeometry& robot() const { return robot_; }
  NavTrace& trace() { return trace_; }
  const NavTrace& trace() const { return trace_; }
  double speed_mps() const { return speed_mps_; }
  double max_turn_radps() const { return max_turn_radps_; }

 private:
  CoreOptions options_;
  ObstacleMemory memory_;
  ObstacleField field_;
  Vfh vfh_;
  StuckRecovery recovery_;
  TurnBacks turn_backs_;
  RobotGeometry robot_;
  double speed_mps_ = 0.0;
  double max_turn_radps_ = 0.0;
  double goal_range_m_ = 0.0;  // obstacles beyond the goal do not block
  double heading_rad_ = 0.0;   // the estimate's heading at the last sense()
  bool moving_ = false;        // the last command moved the robot
  bool last_forward_ = true;   // the last translation was forward
  NavTrace trace_;
};

}  // namespace cogmap::mapper::nav
