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

/// One robot model.
struct RobotModel {
  std::string name;         ///< cogmap's name: "p2at", "p3dx", ...
  std::string aria_params;  ///< the ARIA parameter file the facts come from, e.g. "p3dx.p"
  RobotGeometry geometry;   ///< with the drive and the odometry's track
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
