#pragma once
/// The physical description of a robot that the mapper needs: sonar mounts, sonar range and
/// beam, body footprint and motion limits.

#include <vector>

namespace cogmap::mapper {

/// Where one transducer sits on the body, robot frame (x forward, y left, CCW heading).
struct SonarMount {
  double x_m = 0.0;          ///< sox_i, thesis Table A.1
  double y_m = 0.0;          ///< soy_i, thesis Table A.1
  double heading_rad = 0.0;  ///< sh_i, thesis Table A.1 (converted to CCW)
};

/// How the wheels turn the body.
enum class DriveKind {
  kSkidSteer,     ///< four wheels, turning skids (P2-AT, P3-AT): effective track > physical
  kDifferential,  ///< two driven wheels and a caster (P3-DX, P2-DX, PeopleBot)
};

struct RobotGeometry {
  std::vector<SonarMount> sonars;
  double sonar_min_range_m = 0.1;        ///< closer echoes are not measurable
  double sonar_max_range_m = 5.0;        ///< R, thesis Table 2.1; readings beyond are rejected
  double sonar_beam_width_rad = 0.5236;  ///< β, thesis Table 2.1 (30°)
  double length_m = 0.626;               ///< footprint along x
  double width_m = 0.505;                ///< footprint along y
  double max_speed_mps = 0.75;
  double max_turn_rate_radps = 1.74;
  double max_accel_mps2 = 0.3;
  double max_decel_mps2 = 0.6;
  /// The mapper re-integrates a skid-steer's odometry for its arcs (OdometryCalibration); a
  /// differential drive's wheels roll, so its odometry is taken as reported.
  DriveKind drive = DriveKind::kSkidSteer;
  /// The track odometry integrates with, metres: 2 / DiffConvFactor (ARIA's ratio of turn rate
  /// to wheel speed, per mm), e.g. 0.0034 -> 0.588 m for the P2-AT.
  double odometry_track_m = 0.588;
};

/// The Pioneer P2-AT: 16 sonars at the mounts of docs/p2at.md, limits as MobileSim models them.
/// Other Pioneers: find_robot_model() in robot_models.h.
RobotGeometry p2at_geometry();

}  // namespace cogmap::mapper
