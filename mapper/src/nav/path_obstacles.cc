// Geometric tests of the sensed obstacles against the straight way to a goal, shared by the
// door behaviour and the route follower.
#include "nav/path_obstacles.h"

#include <algorithm>
#include <cmath>

#include "cogmap/mapper/asr/stages.h"

namespace cogmap::mapper::nav {

bool line_blocked(const std::vector<ObstaclePoint>& obstacles, const Point2& robot_m,
                  const Point2& goal_m, double radius_m, double from_m, double max_m) {
  const Point2 d = goal_m - robot_m;
  const double len = d.norm();
  if (len < 1e-6) return false;
  const Point2 u = d / len;
  const double reach = std::min(len + radius_m, max_m);  // a goal in a wall is blocked too
  for (const ObstaclePoint& p : obstacles) {
    const double along = p.offset_m.dot(u);
    if (along < from_m || along > reach) continue;
    if (std::abs(cross(u, p.offset_m)) < radius_m) return true;
  }
  return false;
}

bool wall_across(const std::vector<ObstaclePoint>& obstacles, const Point2& robot_m,
                 const Point2& goal_m, double radius_m, double max_m) {
  const Point2 d = goal_m - robot_m;
  const double len = d.norm();
  if (len < 1e-6) return false;
  const Point2 u = d / len;
  const double reach = std::min(len + radius_m, max_m);
  bool left = false, right = false;
  for (const ObstaclePoint& p : obstacles) {
    const double along = p.offset_m.dot(u);
    if (along < 0.1 || along > reach) continue;
    const double lateral = cross(u, p.offset_m);
    if (std::abs(lateral) >= radius_m) continue;
    if (std::abs(lateral) < 0.05) return true;  // on the line itself (half a 10 cm cell)
    (lateral > 0.0 ? left : right) = true;
    if (left && right) return true;
  }
  return false;
}

std::vector<Point2> blocking_structure(const std::vector<ObstaclePoint>& obstacles,
                                       const Point2& robot_m, const Point2& goal_m, double radius_m,
                                       double max_m) {
  const Point2 d = goal_m - robot_m;
  const double len = d.norm();
  if (len < 1e-6) return {};
  const Point2 u = d / len;
  const double reach = std::min(len + radius_m, max_m);
  // The first obstacle on the way...
  std::optional<Point2> first;
  for (const ObstaclePoint& p : obstacles) {
    const double along = p.offset_m.dot(u);
    if (along < 0.1 || along > reach || std::abs(cross(u, p.offset_m)) >= radius_m) continue;
    if (!first || along < first->dot(u)) first = p.offset_m;
  }
  if (!first) return {};
  // ...and the structure it belongs to: every point within 1 m of it (the ±10° and ±30°
  // transducers' axes meet a wall 1.5 m ahead 0.27 and 0.87 m off the line).
  std::vector<Point2> near;
  for (const ObstaclePoint& p : obstacles) {
    if ((p.offset_m - *first).norm() <= 1.0) near.push_back(p.offset_m);
  }
  return near;
}

std::optional<double> blocking_wall_angle_rad(const std::vector<ObstaclePoint>& obstacles,
                                              const Point2& robot_m, const Point2& goal_m,
                                              double radius_m, double max_m) {
  const std::vector<Point2> near = blocking_structure(obstacles, robot_m, goal_m, radius_m, max_m);
  if (near.empty()) return std::nullopt;
  const LineFit fit = fit_line(near);  // the ASR stage's orthogonal fit (§3.1.8)
  if (!fit.valid) return std::nullopt;
  const Point2 u = (goal_m - robot_m).normalized();
  return std::acos(
      std::min(1.0, std::abs(fit.direction.dot(u))));  // 0: along the line, π/2: across
}

}  // namespace cogmap::mapper::nav
