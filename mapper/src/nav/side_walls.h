#pragma once
/// Walls met at a grazing angle. The calibrated sonar hears a wall only within 40-60° of its
/// normal (docs/sonar-model.md), so a wall the robot closes in on at a shallow angle is silent
/// to the transducers that look ahead and heard only by the side ones, beside the body. The
/// door crossing's lane check (NavCore::drive_direct) would then find the lane clear until a
/// corner touches the wall. A straight line through the side echoes beside the body, carried
/// on ahead, is where that wall goes (DoorOptions::cross_side_walls, off by default).

#include <vector>

#include "cogmap/mapper/nav/nav_options.h"
#include "cogmap/mapper/nav/vfh.h"

namespace cogmap::mapper::nav {

/// Points (offsets from the robot's centre, like `obstacles`) along each side's wall line
/// ahead of the echoes it was fitted to, every `SideWallOptions::step_m`, up to `ahead_m`
/// ahead of the centre. A side's line is fitted (total least squares) to the points beside the
/// body on that side: from `half_length_m` + reach behind the centre to as far ahead, between
/// `half_width_m` and `half_width_m` + reach out; it counts only with at least `min_points`
/// points spanning `min_span_m`, a residual rms of at most `max_rms_m`, and a direction within
/// `max_angle_deg` of the heading (a wall across the way, such as a doorway's, is the front
/// transducers' to hear). Empty when the check is off (`enabled` false, or `reach_m` not
/// positive).
std::vector<ObstaclePoint> side_wall_points(const std::vector<ObstaclePoint>& obstacles,
                                            double heading_rad, double half_length_m,
                                            double half_width_m, const SideWallOptions& options);

}  // namespace cogmap::mapper::nav
