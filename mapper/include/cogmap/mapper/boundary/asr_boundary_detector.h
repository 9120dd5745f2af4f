#pragma once
/// Decides when the robot leaves one ASR and enters the next: the doorway state machine of
/// thesis Fig. 3.4 (obstacles close on both sides), or a new ASR every fixed distance (§3.1.2).

#include <memory>
#include <optional>

#include "cogmap/mapper/seam/robot_geometry.h"
#include "cogmap/mapper/seam/sensor_frame.h"

namespace cogmap::mapper {

enum class BoundaryKind { kDoorway, kDistance };

struct DoorwayOptions {
  double close_side_m = 0.8;       ///< an obstacle this close to a side counts as L or R
  double min_room_travel_m = 1.5;  ///< distance travelled in a room before a new exit counts
  int confirm_frames = 2;          ///< consecutive frames a state must hold (debounce)
};

struct DistanceOptions {
  double asr_distance_m = 4.5;  ///< a new ASR every 4.5 m, thesis §3.1.2
};

/// The robot crossed from one ASR into the next.
struct BoundaryEvent {
  double time_s = 0.0;
  Point2 exit_center{0.0, 0.0};  ///< estimate frame, metres
  double exit_width_m = 0.0;     ///< measured gap width (0 for distance cuts)
  double heading_rad = 0.0;      ///< direction of travel through the exit, estimate frame
};

class AsrBoundaryDetector {
 public:
  virtual ~AsrBoundaryDetector() = default;
  /// Feeds one frame with the robot's estimated pose; returns an event when a boundary is crossed.
  virtual std::optional<BoundaryEvent> update(const SensorFrame& frame, const Pose2& pose) = 0;
  /// Forgets all state (a new run).
  virtual void reset() = 0;
};

std::unique_ptr<AsrBoundaryDetector> make_doorway_detector(const DoorwayOptions& options,
                                                           const RobotGeometry& robot);
std::unique_ptr<AsrBoundaryDetector> make_distance_detector(const DistanceOptions& options);

}  // namespace cogmap::mapper
