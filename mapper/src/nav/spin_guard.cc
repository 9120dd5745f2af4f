#include "nav/spin_guard.h"

#include <cmath>
#include <numbers>

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
  // Turning the body by +a turns a point by -a in the body's frame; the step rotations are the
  // same for every point, so they are computed once.
  const double step = std::numbers::pi / 180.0;
  struct Turn {
    double angle, cos_a, sin_a;
  };
  std::vector<Turn> turns;
  for (double a = step; a <= sweep_rad + 1e-12; a += step) {
    turns.push_back({a, std::cos(-turn_sign * a), std::sin(-turn_sign * a)});
  }
  std::optional<Point2> first;
  double first_angle = sweep_rad + step;
  for (const ObstaclePoint& o : obstacles) {
    if (o.offset_m.squaredNorm() > reach_sq) continue;  // beyond every corner
    const Point2 p(c * o.offset_m.x() + s * o.offset_m.y(),
                   -s * o.offset_m.x() + c * o.offset_m.y());
    if (inside(p)) continue;
    for (const Turn& t : turns) {
      if (t.angle >= first_angle) break;  // an earlier point strikes sooner
      if (inside(Point2(t.cos_a * p.x() - t.sin_a * p.y(), t.sin_a * p.x() + t.cos_a * p.y()))) {
        first = p;
        first_angle = t.angle;
        break;
      }
    }
  }
  return first;
}

}  // namespace cogmap::mapper::nav
