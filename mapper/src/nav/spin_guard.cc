#include "nav/spin_guard.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cogmap::mapper::nav {
namespace {

/// The body outline grown by a margin, in the body's frame (x forward, y left), and the
/// sensed points brought into that frame.
struct GrownBody {
  double half_length_m, half_width_m, cos_h, sin_h;

  GrownBody(const RobotGeometry& robot, double margin_m, double heading_rad)
      : half_length_m(0.5 * robot.length_m + margin_m),
        half_width_m(0.5 * robot.width_m + margin_m),
        cos_h(std::cos(heading_rad)),
        sin_h(std::sin(heading_rad)) {}

  bool inside(const Point2& p) const {
    return std::abs(p.x()) <= half_length_m && std::abs(p.y()) <= half_width_m;
  }
  /// An offset from the robot centre in world axes, in the body's frame.
  Point2 to_body(const Point2& offset_m) const {
    return {cos_h * offset_m.x() + sin_h * offset_m.y(),
            -sin_h * offset_m.x() + cos_h * offset_m.y()};
  }
  /// Farthest corner from the centre, and its square.
  double corner_m() const { return std::hypot(half_length_m, half_width_m); }
  double corner_sq() const { return half_length_m * half_length_m + half_width_m * half_width_m; }
};

}  // namespace

std::optional<Point2> spin_strike(const std::vector<ObstaclePoint>& obstacles, double heading_rad,
                                  int turn_sign, const RobotGeometry& robot, double margin_m,
                                  double sweep_rad) {
  const GrownBody body(robot, margin_m, heading_rad);
  const double reach_sq = body.corner_sq();
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
    const Point2 p = body.to_body(o.offset_m);
    if (body.inside(p)) continue;
    for (const Turn& t : turns) {
      if (t.angle >= first_angle) break;  // an earlier point strikes sooner
      if (body.inside(
              Point2(t.cos_a * p.x() - t.sin_a * p.y(), t.sin_a * p.x() + t.cos_a * p.y()))) {
        first = p;
        first_angle = t.angle;
        break;
      }
    }
  }
  return first;
}

bool arc_strikes(const std::vector<ObstaclePoint>& obstacles, double heading_rad, double v_mps,
                 double w_radps, const RobotGeometry& robot, double margin_m, double horizon_s) {
  if (!(horizon_s > 0.0) || !std::isfinite(v_mps) || !std::isfinite(w_radps)) return false;
  const GrownBody body(robot, margin_m, heading_rad);
  const double travel_m = std::abs(v_mps) * horizon_s;
  const double turn_rad = std::abs(w_radps) * horizon_s;
  const double reach_m = body.corner_m() + travel_m;
  // The body's poses along the arc, in the frame it starts in; the same for every point.
  constexpr double kStepM = 0.02, kStepRad = std::numbers::pi / 180.0;
  // Clamped before the conversion: a finite but huge command must not overflow the int.
  const int steps = static_cast<int>(
      std::clamp(std::ceil(std::max(travel_m / kStepM, turn_rad / kStepRad)), 1.0, 1000.0));
  struct Placed {
    double x, y, cos_t, sin_t;
  };
  std::vector<Placed> poses;
  poses.reserve(static_cast<std::size_t>(steps));
  // Straight, or the chord of a circle of radius v / w.
  const bool straight = std::abs(w_radps) < 1e-9;
  for (int k = 1; k <= steps; ++k) {
    const double t = horizon_s * k / steps;
    const double th = w_radps * t;
    const double x = straight ? v_mps * t : v_mps / w_radps * std::sin(th);
    const double y = straight ? 0.0 : v_mps / w_radps * (1.0 - std::cos(th));
    poses.push_back({x, y, std::cos(th), std::sin(th)});
  }
  for (const ObstaclePoint& o : obstacles) {
    if (o.offset_m.norm() > reach_m) continue;
    const Point2 p = body.to_body(o.offset_m);
    if (body.inside(p)) continue;
    for (const Placed& q : poses) {
      const double dx = p.x() - q.x, dy = p.y() - q.y;
      if (body.inside(Point2(q.cos_t * dx + q.sin_t * dy, -q.sin_t * dx + q.cos_t * dy))) {
        return true;
      }
    }
  }
  return false;
}

}  // namespace cogmap::mapper::nav
