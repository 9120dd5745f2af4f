#pragma once
/// Turns the wheels made while the body was held: a skid-steer wedged between two obstacles
/// can spin its wheels on the spot while the body stays put, and the encoders count a turn
/// that never happened (the simulated P2-AT, wedged in a 0.78 m gap, counted 153° in 2.7 s;
/// docs/algorithms.md, "Turns made while held").
///
/// The sonar ring tells: when the odometry has turned the robot by min_turn_deg or more
/// without moving it, each transducer looks in a new direction (a ping's fan is ±20°), so
/// its range should change; if nearly every transducer reads what it read before the turn,
/// the body did not turn. Then the turn since the first such unchanged reading is taken out
/// of the odometry the mapper uses, and so is every further turn until a transducer reads
/// something new. A robot spinning in the exact centre of a round room (or of a square one,
/// by exactly 90°) looks the same; none of the measured runs did. One with no echo within
/// max_range_m, or moving, is never judged.

#include <cstddef>
#include <deque>
#include <optional>
#include <vector>

#include "cogmap/mapper/seam/pose2.h"
#include "cogmap/mapper/seam/sensor_frame.h"

namespace cogmap::mapper {

struct HeldTurnOptions {
  bool enabled = true;
  double min_turn_deg = 40.0;  ///< a ping's fan is ±20°: after this turn it sees elsewhere
  double max_shift_m = 0.05;   ///< ...and the odometry moved the robot no more than this
  double max_range_m = 2.0;    ///< only echoes this near (noise 1 % of range + 1 cm)
  double same_m = 0.04;        ///< a range within this of the one before is unchanged
  double window_s = 3.0;       ///< readings and comparisons this recent are counted
  int recent_comparisons = 6;  ///< of the latest this many comparisons (~1 s of a wedged
  int recent_same = 5;         ///< spin), at least this many unchanged: held
};

/// Feeds on the odometry and the sonar frame by frame and returns the odometry with the
/// turns made while held taken out.
class HeldTurnFilter {
 public:
  explicit HeldTurnFilter(const HeldTurnOptions& options = {}) : options_(options) {}

  /// The odometry for `odometry` (as reported, or recalibrated) at `frame`'s readings.
  Pose2 update(const Pose2& odometry, const SensorFrame& frame);

  bool held() const { return held_; }
  /// Turn taken out so far, radians (Σ |removed turn|).
  double removed_abs_rad() const { return removed_abs_rad_; }
  /// Times a held body was detected.
  std::size_t detections() const { return detections_; }

 private:
  struct Reading {
    double range_m = 0.0;
    double turn_rad = 0.0;  // cumulative odometry turn when it was taken
    Point2 at{0.0, 0.0};    // odometry position then
    double time_s = 0.0;
  };
  struct Comparison {
    double time_s = 0.0;
    bool same = false;
    double since_turn_rad = 0.0;  // cumulative turn at the earlier reading
  };
  void compare(const SonarReading& r, const Point2& at);

  HeldTurnOptions options_;
  std::optional<Pose2> last_in_;
  Pose2 offset_;  // output = offset_ ∘ input
  bool has_offset_ = false;
  double turn_rad_ = 0.0;  // cumulative (unwrapped) turn of the input
  std::vector<std::optional<Reading>> last_reading_;
  std::deque<Comparison> comparisons_;
  bool held_ = false;
  double removed_abs_rad_ = 0.0;
  std::size_t detections_ = 0;
};

}  // namespace cogmap::mapper
