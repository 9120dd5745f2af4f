#pragma once
/// Turning on the spot sweeps the body's corners through a disc of radius
/// hypot(length, width)/2 (0.40 m for the P2-AT): an obstacle beside a corner that the front
/// check never looks at is struck by the turn itself. Most contacts of the generated-building
/// runs began that way (docs/algorithms.md, "Turning on the spot").

#include <optional>
#include <vector>

#include "cogmap/mapper/nav/vfh.h"
#include "cogmap/mapper/seam/robot_geometry.h"

namespace cogmap::mapper::nav {

/// The first obstacle point (offsets from the robot centre, world axes) that turning on the
/// spot from `heading_rad` in direction `turn_sign` (+1 CCW, -1 CW) brings inside the body
/// outline grown by `margin_m`, within `sweep_rad` of turning; its position in the robot
/// frame (x forward, y left) at the start of the turn. Points already inside the grown outline
/// are skipped (a contact or smear the turn cannot avoid). nullopt when the sweep is clear.
std::optional<Point2> spin_strike(const std::vector<ObstaclePoint>& obstacles, double heading_rad,
                                  int turn_sign, const RobotGeometry& robot, double margin_m,
                                  double sweep_rad);

/// Driving on an arc swings the corners out too (a turn toward a point beside the front corner
/// strikes it while the cone ahead sees nothing): true when driving (v_mps, w_radps) for
/// horizon_s from heading_rad brings an obstacle point (offsets from the robot centre, world
/// axes) inside the body outline grown by margin_m. Points already inside are skipped, as in
/// spin_strike. The body is placed every 0.02 m of travel or 1° of turn along the arc.
bool arc_strikes(const std::vector<ObstaclePoint>& obstacles, double heading_rad, double v_mps,
                 double w_radps, const RobotGeometry& robot, double margin_m, double horizon_s);

}  // namespace cogmap::mapper::nav
