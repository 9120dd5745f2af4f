#pragma once
/// Where a sonar reading lies in the world (thesis Eqs. 3.4-3.7, Fig. A.1): the transducer's
/// position from the robot pose and the mount, and points along the transducer's heading.

#include <vector>

#include "cogmap/mapper/seam/pose2.h"
#include "cogmap/mapper/seam/robot_geometry.h"

namespace cogmap::mapper {

/// One transducer's beam in the world frame: its origin and unit heading (cos h_i, sin h_i).
struct SonarBeam {
  Point2 origin{0.0, 0.0};  ///< transducer position, world frame, metres
  double cos_h = 1.0;       ///< cos of the global heading h_i = h + sh_i
  double sin_h = 0.0;       ///< sin of the global heading h_i = h + sh_i

  /// The point `range_m` along the beam axis from the transducer, world frame.
  Point2 at(double range_m) const {
    return {origin.x() + range_m * cos_h, origin.y() + range_m * sin_h};
  }
};

/// Projects readings for one robot. The mount trig is cached at construction and the robot
/// heading's trig for the last pose seen, so a reading costs no trig call inside one frame
/// (every reading of a frame shares the pose); h_i's trig is composed by the angle-sum
/// identities instead of a cos/sin call per reading.
class SonarProjector {
 public:
  /// Caches the mounts of `robot.sonars`.
  explicit SonarProjector(const RobotGeometry& robot);

  /// Number of transducers; readings with an index outside [0, count) are unknown.
  int count() const { return static_cast<int>(mounts_.size()); }

  /// The beam of transducer `index` (must be < count()) with the robot at `pose`.
  /// Eqs. 3.4-3.5: offset = R(h) (sox_i, soy_i); the origin adds the pose (x_0, y_0) as Eq. 3.6
  /// does. Eq. 3.7 (and Figs. A.1-A.3) print sox_i sin h - soy_i cos h, a sign typo against its
  /// own Eq. 3.5; the rigid transform sox_i sin h + soy_i cos h is used here.
  SonarBeam beam(const Pose2& pose, int index);

 private:
  struct Mount {
    double x_m, y_m, cos_sh, sin_sh;
  };
  std::vector<Mount> mounts_;
  double last_theta_rad_ = 0.0;
  double cos_h_ = 1.0;
  double sin_h_ = 0.0;
};

}  // namespace cogmap::mapper
