#pragma once
/// Stuck detection and the back-off-and-turn recovery shared by the route follower and the
/// explorer. The pose is the mapper's estimate; encoders keep counting when wheels slip in
/// place only in the real world's worst cases, and the stall flags cover those.

#include <optional>

#include "cogmap/mapper/nav/controller.h"

namespace cogmap::mapper::nav {

class StuckRecovery {
 public:
  StuckRecovery(double stuck_time_s, const RecoveryOptions& options)
      : stuck_time_s_(stuck_time_s), options_(options) {}

  /// Feeds one cycle. `commanded_motion` says whether the previous command moved the robot.
  /// Returns true when the robot is stuck: no progress of stuck_distance_m (nor a turn of
  /// stuck_rotation_deg) for stuck_time_s while commanding motion, or stall flags held for
  /// stall_time_s. Never true while a recovery is running.
  bool detect(double time_s, const Pose2& pose, bool stalled, bool commanded_motion);

  /// Starts backing off from `pose`.
  void start(double time_s, const Pose2& pose);

  /// The recovery command this cycle, or nullopt when no recovery runs (or it just ended, in
  /// which case normal control resumes this very cycle). `rear_clearance_m` is the room
  /// behind the bumper; `freest_rad` the world direction to turn to, read once when the turn
  /// starts.
  std::optional<VelocityCommand> command(double time_s, const Pose2& pose, double rear_clearance_m,
                                         double freest_rad, double max_turn_radps);

  bool active() const { return phase_ != NavMode::kIdle; }
  /// kIdle, kBackOff or kTurn.
  NavMode phase() const { return phase_; }

 private:
  void rearm(double time_s, const Pose2& pose);

  double stuck_time_s_;
  RecoveryOptions options_;
  NavMode phase_ = NavMode::kIdle;
  bool armed_ = false;
  double anchor_time_s_ = 0.0;
  Pose2 anchor_;
  std::optional<double> stall_since_s_;
  double phase_start_s_ = 0.0;
  Pose2 phase_start_pose_;
  double turn_to_rad_ = 0.0;
};

}  // namespace cogmap::mapper::nav
