#pragma once
/// Decides when the robot leaves one ASR and enters the next: the doorway state machine of
/// thesis Fig. 3.4 (obstacles close on both sides), or a new ASR every fixed distance (§3.1.2).
/// docs/algorithms.md reconstructs the figure and lists every interpretation.

#include <memory>
#include <optional>

#include "cogmap/mapper/seam/robot_geometry.h"
#include "cogmap/mapper/seam/sensor_frame.h"

namespace cogmap::mapper {

/// Which boundary detector a run uses (experiment key `mapper.asr_boundary`).
enum class BoundaryKind { kDoorway, kDistance };

/// Options of the doorway state machine (thesis Fig. 3.4; the thesis gives no numbers, these
/// are ours and documented in docs/algorithms.md).
struct DoorwayOptions {
  double close_side_m = 0.8;       ///< an echo closer than this (metres) on a side is L or R
  double min_room_travel_m = 1.5;  ///< path length (m) in a room before a new exit counts
  int confirm_frames = 2;          ///< consecutive frames a condition must hold (debounce)
  double max_reading_age_s = 1.0;  ///< older side readings are unknown (a sonar fires ~0.5 s)
  double side_heading_tolerance_rad = 0.35;  ///< a mount within ~20° of ±90° is a side sonar
  /// The robot must leave the access point at least this far past the gap centre along the
  /// direction it crossed in (metres): turning on the spot next to a jamb, or backing out of a
  /// door, makes both sides close and then free without passing anything. 0.2 m is less than
  /// half the body length (0.313 m), which a robot driving through has always covered.
  double min_exit_advance_m = 0.2;
};

/// Options of the fixed-distance cut (thesis §3.1.2, used for hallways).
struct DistanceOptions {
  double asr_distance_m = 4.5;  ///< a new ASR every 4.5 m of travel, thesis §3.1.2
};

/// The robot crossed from one ASR into the next.
struct BoundaryEvent {
  double time_s = 0.0;           ///< frame time at which the crossing was confirmed, seconds
  Point2 exit_center{0.0, 0.0};  ///< centre of the gap, estimate frame, metres
  double exit_width_m = 0.0;     ///< measured gap width, metres (0 for distance cuts)
  double heading_rad = 0.0;      ///< direction of travel through the exit, estimate frame
};

/// A boundary detector consumes every frame and says when a room ends.
class AsrBoundaryDetector {
 public:
  virtual ~AsrBoundaryDetector() = default;
  /// Feeds one frame with the robot's estimated pose; returns an event when a boundary is crossed.
  virtual std::optional<BoundaryEvent> update(const SensorFrame& frame, const Pose2& pose) = 0;
  /// Forgets all state (a new run).
  virtual void reset() = 0;
};

/// The doorway state machine of Fig. 3.4; side sonars are the mounts of `robot` whose heading
/// lies within `side_heading_tolerance_rad` of +90° (left) or −90° (right).
std::unique_ptr<AsrBoundaryDetector> make_doorway_detector(const DoorwayOptions& options,
                                                           const RobotGeometry& robot);
/// A cut every `asr_distance_m` of estimate-pose path length.
std::unique_ptr<AsrBoundaryDetector> make_distance_detector(const DistanceOptions& options);

}  // namespace cogmap::mapper
