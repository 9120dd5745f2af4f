#pragma once
/// Per-transducer statistics of a sonar recording (docs/sonar-model.md "Holding a recording
/// against the simulator"): how often each transducer fires and answers, and the spread of its
/// ranges, counted while the robot moves. `cogmap sonar-stats` prints them; the simulator's
/// calibration test holds a simulated run against a real Pioneer's figures with them.

#include <iosfwd>
#include <string>
#include <vector>

#include "cogmap/mapper/seam/robot.h"
#include "cogmap/mapper/seam/robot_geometry.h"
#include "cogmap/mapper/seam/sensor_frame.h"

namespace cogmap::experiments {

/// What counts.
struct SonarStatsOptions {
  /// Frames count only while the odometry moves at least this fast, m/s (a robot standing still
  /// hears the same wall over and over).
  double min_speed_mps = 0.1;
  /// A reading is an echo when the robot says so and its range is below this, metres (the real
  /// table counts echoes under 4.9 m: a max-range reading is silence).
  double max_echo_range_m = 4.9;
};

/// One transducer's figures.
struct TransducerStats {
  int index = 0;
  double bearing_deg = 0.0;                      ///< mount heading, robot frame, CCW
  long firings = 0;                              ///< readings while moving
  long echoes = 0;                               ///< of which echoes under max_echo_range_m
  double echo_fraction = 0.0;                    ///< echoes / firings (0 when no firing)
  double p10_m = 0.0, p50_m = 0.0, p90_m = 0.0;  ///< range quantiles of the echoes
  double firings_per_100ms = 0.0;                ///< firings per 100 ms of moving time
};

/// The whole recording's figures.
struct SonarStats {
  std::vector<TransducerStats> transducers;  ///< one per mount of the geometry, in index order
  double moving_time_s = 0.0;                ///< time the robot moved (sum of frame intervals)
  long moving_frames = 0;
  double readings_per_frame = 0.0;  ///< new readings per cycle while moving, all transducers
  double median_speed_mps = 0.0;    ///< of the moving frames
};

/// Accumulates frames; call add() for every frame in time order, then result().
class SonarStatsCollector {
 public:
  SonarStatsCollector(const mapper::RobotGeometry& geometry, SonarStatsOptions options = {});
  void add(const mapper::SensorFrame& frame);
  SonarStats result() const;

 private:
  mapper::RobotGeometry geometry_;
  SonarStatsOptions options_;
  bool have_previous_ = false;
  mapper::SensorFrame previous_;
  double moving_time_s_ = 0.0;
  long moving_frames_ = 0, moving_readings_ = 0;
  std::vector<long> firings_, echoes_;
  std::vector<std::vector<double>> ranges_;
  std::vector<double> speeds_;
};

/// Reads every frame of `robot` (until next_frame() is empty) into statistics.
SonarStats collect_sonar_stats(mapper::Robot& robot, const SonarStatsOptions& options = {});

/// A fixed-width text table, one row per transducer.
void write_sonar_stats_text(std::ostream& out, const SonarStats& stats);

/// CSV: index,bearing_deg,firings,echoes,echo_fraction,p10_m,p50_m,p90_m,firings_per_100ms.
void write_sonar_stats_csv(std::ostream& out, const SonarStats& stats);

/// Two recordings side by side, matched by bearing (first: `a`, second: `b`), with the echo
/// fraction difference and the p50 ratio b / a.
void write_sonar_stats_comparison(std::ostream& out, const SonarStats& a, const SonarStats& b,
                                  const std::string& name_a, const std::string& name_b);

}  // namespace cogmap::experiments
