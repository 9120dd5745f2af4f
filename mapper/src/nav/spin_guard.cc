#include "nav/spin_guard.h"

#include <cmath>

namespace cogmap::mapper::nav {

std::optional<Point2> spin_strike(const std::vector<ObstaclePoint>& obstacles, double heading_rad,
                                  int turn_sign, const RobotGeometry& robot, double margin_m,
                                  double sweep_rad) {
  const double hl = 0.5 * robot.length_m + margin_m;
  const double hw = 0.5 * robot.width_m + margin_m;
  const double reach_sq = hl * hl + hw * hw;
  const auto inside = [&](const Point2& p) {
    return std::abs(p.x()) <= hl && std::abs(p.y()) <= hw;
  };
  const double c = std::cos(heading_rad), s = std::sin(heading_rad);
  // 1° steps: a corner 0.40 m out moves 7 mm a step, finer than the 0.1 m cells of the points.
  const double step = M_PI / 180.0;
  std::optional<Point2> first;
  double first_angle = sweep_rad + step;
  for (const ObstaclePoint& o : obstacles) {
    if (o.offset_m.squaredNorm() > reach_sq) continue;  // beyond every corner
    const Point2 p(c * o.offset_m.x() + s * o.offset_m.y(),
                   -s * o.offset_m.x() + c * o.offset_m.y());
    if (inside(p)) continue;
    // Turning the body by +a turns the point by -a in the body's frame.
    for (double a = step; a <= sweep_rad + 1e-12 && a < first_angle; a += step) {
      const double ca = std::cos(-turn_sign * a), sa = std::sin(-turn_sign * a);
      if (inside(Point2(ca * p.x() - sa * p.y(), sa * p.x() + ca * p.y()))) {
        first = p;
        first_angle = a;
        break;
      }
    }
  }
  return first;
}

}  // namespace cogmap::mapper::nav
