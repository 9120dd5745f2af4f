#include "nav/side_walls.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cogmap/mapper/asr/stages.h"

namespace cogmap::mapper::nav {

std::vector<ObstaclePoint> side_wall_points(const std::vector<ObstaclePoint>& obstacles,
                                            double heading_rad, double half_length_m,
                                            double half_width_m, const SideWallOptions& o) {
  std::vector<ObstaclePoint> out;
  if (!o.enabled || !(o.reach_m > 0.0) || !(o.step_m > 0.0)) return out;
  const double c = std::cos(heading_rad), s = std::sin(heading_rad);
  const double max_angle_rad = o.max_angle_deg * std::numbers::pi / 180.0;
  for (const int side : {1, -1}) {  // left, right
    // The echoes beside the body on this side, in the body frame (x ahead, y out to the side).
    std::vector<Point2> beside;
    for (const ObstaclePoint& p : obstacles) {
      const double along = c * p.offset_m.x() + s * p.offset_m.y();
      const double lateral = side * (-s * p.offset_m.x() + c * p.offset_m.y());
      if (lateral < half_width_m || lateral > half_width_m + o.reach_m) continue;
      if (std::abs(along) > half_length_m + o.reach_m) continue;
      beside.emplace_back(along, lateral);
    }
    if (static_cast<int>(beside.size()) < std::max(o.min_points, 2)) continue;
    const LineFit fit = fit_line(beside);  // the ASR stage's orthogonal fit (§3.1.8)
    if (!fit.valid) continue;
    const Point2 dir = fit.direction.x() < 0.0 ? Point2(-fit.direction) : fit.direction;
    if (std::abs(std::atan2(dir.y(), dir.x())) > max_angle_rad) continue;
    const Point2 normal(-dir.y(), dir.x());
    double lo = 0.0, hi = 0.0, squares = 0.0;
    for (std::size_t i = 0; i < beside.size(); ++i) {
      const Point2 d = beside[i] - fit.point;
      const double t = d.dot(dir);
      lo = i == 0 ? t : std::min(lo, t);
      hi = i == 0 ? t : std::max(hi, t);
      squares += d.dot(normal) * d.dot(normal);
    }
    if (hi - lo < o.min_span_m) continue;
    if (std::sqrt(squares / static_cast<double>(beside.size())) > o.max_rms_m) continue;
    // On ahead of the farthest echo, back in the robot-centred world-aligned frame.
    for (double t = hi + o.step_m;; t += o.step_m) {
      const Point2 q = fit.point + t * dir;
      if (q.x() > o.ahead_m) break;
      const double lateral = side * q.y();
      out.push_back({Point2(c * q.x() - s * lateral, s * q.x() + c * lateral), 1.0f});
    }
  }
  return out;
}

}  // namespace cogmap::mapper::nav
