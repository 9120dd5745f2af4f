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
};

/// The Pioneer P2-AT: 16 sonars at the mounts of docs/p2at.md, limits as MobileSim models them.
/// Other Pioneers: find_robot_model() in robot_models.h.
RobotGeometry p2at_geometry();

}  // namespace cogmap::mapper
