#pragma once
/// Stall flags as the P2-AT reports them (bit 0 of the SIP's stall bytes, per side): a side is
/// stalled when its wheels are driven but the body side barely moves, for long enough or while
/// the body is pushing against something.

#include "cogmap/sim/skid_steer.h"

namespace cogmap::sim {

/// Thresholds. Defaults: the thresholds the task fixes (docs/simulator.md "Stall").
struct StallOptions {
  double speed_fraction = 0.25;  ///< "barely moves": below this fraction of the expected speed
  double persist_s = 0.3;        ///< how long slow motion lasts before it is a stall, seconds
  double min_wheel_mps = 0.01;   ///< commanded wheel speeds below this count as stopped
  double track_m = 0.394;        ///< physical track that maps a twist to side speeds, metres
};

/// Per-side stall state, updated once per physics step.
class StallDetector {
 public:
  explicit StallDetector(const StallOptions& options = {}) : options_(options) {}

  /// wheels: commanded wheel speeds; expected: the twist the floor allows; actual: the twist the
  /// body achieved; in_contact: the body touches a wall or obstacle.
  void update(const WheelSpeeds& wheels, const BodyTwist& expected, const BodyTwist& actual,
              bool in_contact, double dt_s);

  bool left() const { return left_.stalled; }    ///< left side stalled
  bool right() const { return right_.stalled; }  ///< right side stalled

 private:
  struct Side {
    double slow_s = 0.0;
    bool stalled = false;
  };
  void update_side(Side& side, double wheel_mps, double expected_mps, double actual_mps,
                   bool in_contact, double dt_s) const;

  StallOptions options_;
  Side left_;
  Side right_;
};

}  // namespace cogmap::sim
