#pragma once
/// Turns the P2OS's wrapping 15-bit position and 12-bit heading counters into a continuous
/// odometry pose, and keeps that pose continuous across reconnections (the robot restarts its
/// counters at zero after a reset).

#include <cstdint>
#include <optional>

#include "cogmap/hw/p2os_sip.h"
#include "cogmap/mapper/seam/pose2.h"

namespace cogmap::hw {

/// Raw SIP counters -> continuous odometry pose (metres, radians); one per connection chain.
class OdometryUnwrapper {
 public:
  explicit OdometryUnwrapper(p2os::ConversionFactors factors = {}) : factors_(factors) {}

  /// Changes the conversion (after a handshake names the subclass).
  void set_factors(const p2os::ConversionFactors& factors) { factors_ = factors; }

  /// Feeds one SIP's raw position; returns the continuous pose (metres, radians) in the
  /// odometry frame of the first connection.
  mapper::Pose2 update(std::uint16_t x_raw, std::uint16_t y_raw, std::int16_t th_raw);

  /// The robot's counters restart (reset, reconnection): the next update() is anchored so the
  /// returned pose continues from the last one instead of jumping.
  void rebase();

  /// Reconnected after silence without a reset packet: the counters probably continued (the
  /// robot's watchdog stopped it), so motion during the gap is kept; but if the next pose is
  /// farther than `max_distance_m` from the last one, the controller was power-cycled and the
  /// pose is rebased instead.
  void rebase_if_implausible(double max_distance_m);

  /// The last pose returned (identity before the first update).
  const mapper::Pose2& pose() const { return pose_; }

  /// Difference of two wrapping 15-bit counters per P2AT.md: beyond ±0x1000 the counter
  /// wrapped, so ±0x8000 is added (real motion is never discarded).
  static std::int32_t position_delta(std::uint16_t now, std::uint16_t last);
  /// Difference of two 12-bit heading counters, in [-2048, 2047].
  static std::int32_t heading_delta(std::int16_t now, std::int16_t last);

 private:
  p2os::ConversionFactors factors_;
  bool have_last_ = false;
  std::uint16_t last_x_ = 0, last_y_ = 0;
  std::int16_t last_th_ = 0;
  // Accumulated counts since the current anchor (doubles: exact for any realistic count).
  double x_units_ = 0.0, y_units_ = 0.0, th_units_ = 0.0;
  mapper::Pose2 anchor_;  // odometry pose of this connection's counter origin
  mapper::Pose2 pose_;
  bool rebase_pending_ = false;
  double plausible_m_ = -1.0;  // >= 0: check the next update against this distance
};

}  // namespace cogmap::hw
