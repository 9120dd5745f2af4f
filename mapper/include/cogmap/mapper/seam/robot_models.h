#pragma once
/// The Pioneer family the mapper knows by name: sonar mounts, body and limits of each model,
/// from ARIA's published robot parameter files (params/<model>.p) and the AMRISim/MobileSim
/// robot models. Pure data; `robot.model` in an experiment, `--robot` for replay and the P2OS
/// driver's SYNC2 subclass all look models up here.

#include <string>
#include <string_view>
#include <vector>

#include "cogmap/mapper/seam/robot_geometry.h"

namespace cogmap::mapper {

/// How the wheels turn the body.
enum class DriveKind {
  kSkidSteer,     ///< four wheels, turning skids (P2-AT, P3-AT): effective track > physical
  kDifferential,  ///< two driven wheels and a caster (P3-DX, P2-DX, PeopleBot)
};

/// One robot model.
struct RobotModel {
  std::string name;         ///< cogmap's name: "p2at", "p3dx", ...
  std::string aria_params;  ///< the ARIA parameter file the facts come from, e.g. "p3dx.p"
  DriveKind drive = DriveKind::kSkidSteer;
  /// The track odometry integrates with, metres: 2 / DiffConvFactor (ARIA's ratio of turn rate
  /// to wheel speed, per mm), e.g. 0.0034 -> 0.588 m for the P2-AT.
  double odometry_track_m = 0.588;
  RobotGeometry geometry;
};

/// Every model, in a fixed order: p2at, p2at8, p3at, p3dx, p2dx, p2de, peoplebot.
const std::vector<RobotModel>& robot_models();

/// The model called `name`, or one of the ARIA subclass names a robot reports in its SYNC2
/// reply that share its geometry (p2at8+, p3at-sh, p3dx-sh, p2d8, p2d8+, peoplebot-sh);
/// case-insensitive. nullptr when unknown.
const RobotModel* find_robot_model(std::string_view name);

/// "p2at, p2at8, p3at, p3dx, p2dx, p2de, peoplebot": for error messages that list the choices.
std::string robot_model_names();

}  // namespace cogmap::mapper
