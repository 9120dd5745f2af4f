#include "nav/steering.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace cogmap::mapper::nav {

double clearance_m(const std::vector<ObstaclePoint>& obstacles, double heading_rad,
                   double half_angle_rad, double length_m) {
  double nearest = std::numeric_limits<double>::infinity();
  // Most points lie clearly inside or outside the cone: their offset along and across the
  // heading decides without the bearing's atan2, against the cone's edge moved in or out by a
  // margin far above the rounding of either test (1e-16 rad, more for a heading wound up to
  // large values). Only points within the margin of the edge take the bearing below.
  const double margin_rad = 1e-9 * (1.0 + std::abs(heading_rad));
  const double inner_rad = half_angle_rad - margin_rad, outer_rad = half_angle_rad + margin_rad;
  const bool by_offsets = inner_rad > 0.0 && outer_rad < 0.5 * std::numbers::pi;
  const Point2 ahead(std::cos(heading_rad), std::sin(heading_rad));
  const double tan_inner = by_offsets ? std::tan(inner_rad) : 0.0;
  const double tan_outer = by_offsets ? std::tan(outer_rad) : 0.0;
  for (const ObstaclePoint& o : obstacles) {
    // A point no nearer than the nearest so far cannot change it: skip its bearing's atan2.
    const double distance = o.offset_m.norm() - 0.5 * length_m;
    if (!(distance < nearest)) continue;
    if (by_offsets) {
      const double along = ahead.dot(o.offset_m);
      const double across = std::abs(cross(ahead, o.offset_m));
      if (along > 0.0) {
        if (across < along * tan_inner) {
          nearest = distance;
          continue;
        }
        if (across > along * tan_outer) continue;
      } else if (along < 0.0 || across > 0.0) {
        continue;  // 90° or more off the heading, and the cone is narrower
      }
    }
    const double bearing = std::atan2(o.offset_m.y(), o.offset_m.x());
    if (std::abs(wrap_angle_rad(bearing - heading_rad)) > half_angle_rad) continue;
    nearest = distance;
  }
  return nearest;
}

double lane_clearance_m(const std::vector<ObstaclePoint>& obstacles, double heading_rad,
                        double half_width_m, double length_m, const DoorBand* skip) {
  const double c = std::cos(heading_rad), s = std::sin(heading_rad);
  double nearest = std::numeric_limits<double>::infinity();
  for (const ObstaclePoint& o : obstacles) {
    if (skip &&
        std::abs((o.offset_m - skip->center_offset_m).dot(skip->normal)) <= skip->half_depth_m) {
      continue;
    }
    const double ahead = c * o.offset_m.x() + s * o.offset_m.y();
    const double lateral = -s * o.offset_m.x() + c * o.offset_m.y();
    if (ahead <= 0.0 || std::abs(lateral) > half_width_m) continue;
    nearest = std::min(nearest, ahead - 0.5 * length_m);
  }
  return nearest;
}

VelocityCommand steer(double heading_error_rad, double front_clearance_m, double speed_mps,
                      double max_turn_radps, const SafetyOptions& options) {
  const double turn_in_place = deg_to_rad(options.turn_in_place_deg);
  const double error = wrap_angle_rad(heading_error_rad);
  VelocityCommand cmd;
  cmd.w_radps = std::clamp(options.heading_gain * error, -max_turn_radps, max_turn_radps);
  if (std::abs(error) > turn_in_place) {
    cmd.w_radps = std::copysign(max_turn_radps, error);
    return cmd;
  }
  if (front_clearance_m <= options.stop_clearance_m) {
    // Too close to drive: turn toward the chosen direction, and turn decisively even when it
    // is nearly straight ahead (the obstacle sits just inside the front cone).
    const double min_turn = max_turn_radps / 3.0;
    if (std::abs(cmd.w_radps) < min_turn) cmd.w_radps = std::copysign(min_turn, error);
    return cmd;
  }
  const double span = std::max(1e-6, options.slow_clearance_m - options.stop_clearance_m);
  const double proximity =
      std::clamp((front_clearance_m - options.stop_clearance_m) / span, 0.0, 1.0);
  cmd.v_mps = speed_mps * (1.0 - std::abs(error) / turn_in_place) * proximity;
  return cmd;
}

}  // namespace cogmap::mapper::nav
