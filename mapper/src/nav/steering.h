#pragma once
/// Heading control and the front safety check: turning a chosen world direction into a
/// velocity command the P2-AT can follow.

#include <vector>

#include "cogmap/mapper/nav/controller.h"
#include "cogmap/mapper/nav/vfh.h"

namespace cogmap::mapper::nav {

/// Distance from the robot's bumper (half `length_m` ahead of the centre along `heading_rad`)
/// to the nearest obstacle whose bearing is within `half_angle_rad` of `heading_rad`, metres;
/// +infinity when there is none. Negative when an obstacle is inside the body outline.
double clearance_m(const std::vector<ObstaclePoint>& obstacles, double heading_rad,
                   double half_angle_rad, double length_m);

/// Distance from the bumper to the nearest obstacle ahead inside the lane the body sweeps
/// driving straight along `heading_rad` (|lateral| ≤ half_width_m), metres; +infinity when
/// the lane is clear. Used in doorways, where the jambs sit inside the ±30° cone but beside
/// the lane.
/// A band about a door line (points whose distance from the line through `center_offset_m`
/// with unit normal `normal` is at most `half_depth_m`; offsets from the robot, like the
/// obstacles') that the lane check skips while crossing: the opening was sensed there, so
/// what lies in it is the sonar's smear of the jambs, not something in the way.
struct DoorBand {
  Point2 center_offset_m{0.0, 0.0};
  Point2 normal{1.0, 0.0};
  double half_depth_m = 0.0;
};
double lane_clearance_m(const std::vector<ObstaclePoint>& obstacles, double heading_rad,
                        double half_width_m, double length_m, const DoorBand* skip = nullptr);

/// w = k·error clipped to `max_turn_radps`; errors beyond turn_in_place_deg turn on the spot;
/// otherwise v = speed·(1 - |error|/turn_in_place)·proximity, where proximity falls linearly
/// from 1 at slow_clearance_m to 0 at stop_clearance_m of `front_clearance_m`. Below the stop
/// clearance the robot turns in place at no less than a third of the turn limit.
VelocityCommand steer(double heading_error_rad, double front_clearance_m, double speed_mps,
                      double max_turn_radps, const SafetyOptions& options);

}  // namespace cogmap::mapper::nav
