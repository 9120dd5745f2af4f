#pragma once
/// Re-integrates a skid-steer's odometry with a turn-curvature-dependent effective track.
///
/// A skid-steer base skids its wheels sideways to turn, so the track that turns wheel travel
/// into heading is wider than the physical one (kinematic models put the treads' instantaneous
/// centres of rotation outside the wheels, e.g. Mandow et al. 2007 on a Pioneer P3-AT), and
/// how much wider depends on how the robot moves: a spin on the spot skids most, a gentle arc
/// least. The firmware converts with one track, calibrated on spins (ARIA's DiffConvFactor), so on
/// arcs the odometry under- or over-reports every turn by a few per cent. The law assumed here:
///
///     B_eff = B_cal · (1 + g · (s − 1)),   s = |dr − dl| / (|dl| + |dr|)
///
/// with s the spin fraction of a frame's wheel travel (1 on the spot, 0 straight) and g the
/// curvature gain. Each odometry increment's turn is then dθ · B_cal / B_eff. g is the robot's
/// own constant, fitted from its runs by `scripts/fit-odometry-curvature` (EM's room
/// measurements against the odometry's arc turning; docs/algorithms.md, "Odometry recalibrated
/// for arcs"); g = 0 leaves the odometry exactly as reported.

#include <optional>

#include "cogmap/mapper/seam/pose2.h"
#include "cogmap/mapper/seam/robot_geometry.h"

namespace cogmap::mapper {

struct OdometryCalibration {
  /// g of a skid-steer robot (RobotGeometry::drive; a differential drive's wheels roll and its
  /// odometry is taken as reported): the relative change of the effective track from a spin
  /// (s = 1) to straight driving (s = 0). Default 0: the odometry as the robot reports it. The
  /// simulated P2-AT's, fitted by scripts/fit-odometry-curvature on its runs in 160 generated
  /// buildings, is 0.066 ± 0.007 (2 013 rooms; docs/algorithms.md, "Odometry recalibrated for
  /// arcs"); a real robot's is fitted the same way from a few hundred of its rooms.
  double curvature_gain = 0.0;
};

/// The gain the mapper applies on `robot`: the calibration's for a skid-steer, 0 for a
/// differential drive (its wheels roll).
double applied_curvature_gain(const OdometryCalibration& calibration, const RobotGeometry& robot);

/// Spin fraction s of a motion of `forward_m` with a turn of `turn_rad` on a track of
/// `track_m`: the wheels travel forward_m ∓ turn_rad·track_m/2. 0 for no motion at all.
double spin_fraction(double forward_m, double turn_rad, double track_m);

/// Feeds on the odometry poses as the robot reports them and returns them re-integrated.
class OdometryRecalibrator {
 public:
  /// `track_m`: B_cal, the track the odometry converts wheel travel with
  /// (RobotGeometry::odometry_track_m).
  OdometryRecalibrator(double curvature_gain, double track_m)
      : curvature_gain_(curvature_gain), track_m_(track_m) {}

  /// The re-integrated pose for the reported `raw` pose (the first call returns `raw`). With
  /// g = 0 every answer is `raw` itself.
  Pose2 update(const Pose2& raw);

 private:
  double curvature_gain_;
  double track_m_;
  std::optional<Pose2> last_raw_;
  Pose2 pose_;
};

}  // namespace cogmap::mapper
