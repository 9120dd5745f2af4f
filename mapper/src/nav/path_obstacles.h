#pragma once
/// Geometric tests of the sensed obstacles (offsets from the robot, estimate frame) against the
/// straight way from the robot to a goal: is it blocked, is a wall across it, at what angle.

#include <optional>
#include <vector>

#include "cogmap/mapper/nav/vfh.h"

namespace cogmap::mapper::nav {

/// True when a sensed obstacle lies within `radius_m` of the segment from robot_m toward
/// goal_m, between `from_m` along it and `max_m` (or radius_m beyond the goal, if nearer).
bool line_blocked(const std::vector<ObstaclePoint>& obstacles, const Point2& robot_m,
                  const Point2& goal_m, double radius_m, double from_m, double max_m);

/// True when sensed obstacles lie within `radius_m` of the segment from robot_m toward
/// goal_m (out to max_m) on both sides of it, or on it: something across the way, not beside.
bool wall_across(const std::vector<ObstaclePoint>& obstacles, const Point2& robot_m,
                 const Point2& goal_m, double radius_m, double max_m);

/// The structure of the first obstacle within `radius_m` of the line from robot_m toward goal_m
/// (from 0.1 m out to max_m, or radius_m beyond the goal): every obstacle point within 1 m of
/// that one, as offsets from robot_m. Empty when nothing blocks.
std::vector<Point2> blocking_structure(const std::vector<ObstaclePoint>& obstacles,
                                       const Point2& robot_m, const Point2& goal_m, double radius_m,
                                       double max_m);

/// The angle between the line from robot_m toward goal_m and the structure of the first
/// obstacle within `radius_m` of it (up to max_m): the principal direction of the obstacle
/// points within 1 m of that one. π/2 for a wall square across the way, near 0 for a wall
/// the line runs along. nullopt when nothing blocks or too few points describe it.
std::optional<double> blocking_wall_angle_rad(const std::vector<ObstaclePoint>& obstacles,
                                              const Point2& robot_m, const Point2& goal_m,
                                              double radius_m, double max_m);

}  // namespace cogmap::mapper::nav
