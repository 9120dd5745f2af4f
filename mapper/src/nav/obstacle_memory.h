#pragma once
/// Short-term obstacle memory: the sonar echoes of the last few seconds as points in the
/// estimate (world) frame, plus "contacts" where the robot got stuck on something the sonar
/// never saw. The room grid is reset at every doorway; this memory is what keeps the robot
/// from steering into the door frame it just passed.

#include <vector>

#include "cogmap/mapper/nav/controller.h"

namespace cogmap::mapper::nav {

class ObstacleMemory {
 public:
  /// One remembered obstacle point.
  struct Hit {
    Point2 world_m{0.0, 0.0};  ///< estimate frame, metres
    double expires_s = 0.0;    ///< forgotten once the frame time reaches this
    bool contact = false;      ///< a stuck contact, not a sonar echo
  };

  explicit ObstacleMemory(const MemoryOptions& options) : options_(options) {}

  /// Forgets expired hits, then adds this frame's echoes, placed with `pose` (the estimate at
  /// the frame; the few-ms offset of each ping is ignored). Invalid readings are skipped.
  void add_frame(const SensorFrame& frame, const Pose2& pose, const RobotGeometry& robot);

  /// Remembers three points just beyond the bumper on the side the robot was moving
  /// (`forward`), for contact_keep_s: a stuck robot is touching something there.
  void add_contact(const Pose2& pose, const RobotGeometry& robot, double time_s, bool forward);

  /// Hits still remembered, oldest first.
  const std::vector<Hit>& hits() const { return hits_; }

  /// True when at least one sonar echo (not a contact) is remembered: the sonar is live.
  bool has_echoes() const;

 private:
  void push(const Point2& world_m, double expires_s, bool contact);
  /// A beam of this frame: remembered echoes in its core, short of its reading, are gone.
  struct ClearingBeam {
    Point2 origin;  ///< the transducer, estimate frame
    Point2 axis;    ///< unit vector along the beam
    double free_m;  ///< free up to here along the axis
  };
  /// This frame's clearing beams into beams_ (none when clearing is off).
  void collect_clearing_beams(const SensorFrame& frame, const Pose2& pose,
                              const RobotGeometry& robot);

  MemoryOptions options_;
  std::vector<Hit> hits_;            // a vector: filtered whole every frame, appended at the back
  std::vector<ClearingBeam> beams_;  ///< reused from frame to frame
};

}  // namespace cogmap::mapper::nav
