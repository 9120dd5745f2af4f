#pragma once
// The streams of a bag turned into frames: odometry interpolated at each sonar message's stamp,
// and only the transducer values that changed since the last message as new readings.

#include "cogmap/hw/bag_import.h"
#include "cogmap/mapper/seam/robot_geometry.h"
#include "ros_bag_reader.h"

namespace cogmap::hw::bag {

/// A range within this much of the maximum is a sonar that heard no echo. ARIA reports "no echo"
/// as 5000 mm; the analysis of the public RosAria P3-DX corridor recording (docs/sonar-model.md
/// "Calibration") counts an echo as a reading under 4.9 m, and the same threshold here keeps a
/// replay consistent with it.
inline constexpr double kNoEchoMarginM = 0.1;
/// Odometry samples farther apart than this do not interpolate: the reading is rejected.
inline constexpr double kMaxOdometryGapS = 0.5;

/// Fills `out.frames` (time_s from the earliest stamp of either stream) and the reading counts
/// of `stats`. Throws std::runtime_error "topic T, message K: ..." for a stamp that is zero or
/// earlier than the one before on the same topic, a non-finite value, more transducers than
/// `geometry` has, or an odometry sample or frame that fails the checks every log gets
/// (log_checks.h: |x|, |y| within LogLimits::max_coordinate_m, no jump beyond what
/// `geometry.max_speed_mps` allows); and "...: nothing to map" when no sonar message has a
/// pose (the two topics' stamps never overlap, or every message falls in an odometry gap).
void build_frames(const Streams& streams, const StreamRequest& request,
                  const mapper::RobotGeometry& geometry, ImportedLog& out, BagImportStats& stats);

}  // namespace cogmap::hw::bag
