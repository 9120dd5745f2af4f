#pragma once
// Shared by the facade's tests: a robot driving waypoints past straight walls with an ideal
// sonar (the axis ray only), and the map's median distance to those walls.

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "cogmap/mapper/mapper.h"

namespace cogmap::mapper::test {

/// Range along a ray to the nearest of `walls`, or nullopt beyond `max_range_m`.
inline std::optional<double> cast(const Point2& origin, double heading_rad,
                                  const std::vector<Segment>& walls, double max_range_m) {
  const Point2 d{std::cos(heading_rad), std::sin(heading_rad)};
  double best = std::numeric_limits<double>::infinity();
  for (const Segment& w : walls) {
    const Point2 e = w.b - w.a;
    const double denom = d.x() * e.y() - d.y() * e.x();
    if (std::abs(denom) < 1e-12) continue;
    const Point2 ao = w.a - origin;
    const double t = (ao.x() * e.y() - ao.y() * e.x()) / denom;
    const double u = (ao.x() * d.y() - ao.y() * d.x()) / denom;
    if (t > 0.0 && u >= 0.0 && u <= 1.0) best = std::min(best, t);
  }
  if (best > max_range_m) return std::nullopt;
  return best;
}

/// Frames of a robot driving the waypoints at 0.5 m/s with ideal sonar (axis ray only).
/// `drift_rad_per_m` rotates the odometry heading in proportion to the distance driven;
/// `slip_m_per_m` moves the odometry sideways (to the left of the heading) as it drives.
inline std::vector<SensorFrame> drive(const std::vector<Point2>& waypoints,
                                      const std::vector<Segment>& walls, const RobotGeometry& robot,
                                      double drift_rad_per_m, double slip_m_per_m = 0.0) {
  std::vector<SensorFrame> frames;
  const double step_m = 0.05;  // 0.5 m/s at 10 Hz
  double time_s = 0.0, travelled_m = 0.0;
  Pose2 odom{waypoints[0].x(), waypoints[0].y(), 0.0};
  for (std::size_t w = 1; w < waypoints.size(); ++w) {
    const Point2 a = waypoints[w - 1], b = waypoints[w];
    const double heading = std::atan2(b.y() - a.y(), b.x() - a.x());
    const int steps = static_cast<int>(std::round((b - a).norm() / step_m));
    for (int i = 1; i <= steps; ++i) {
      const Point2 p = a + (b - a) * (static_cast<double>(i) / steps);
      const Pose2 truth{p.x(), p.y(), heading};
      travelled_m += step_m;
      const double odom_heading = heading + drift_rad_per_m * travelled_m;
      odom = {odom.x_m + step_m * (std::cos(odom_heading) - slip_m_per_m * std::sin(odom_heading)),
              odom.y_m + step_m * (std::sin(odom_heading) + slip_m_per_m * std::cos(odom_heading)),
              wrap_angle_rad(odom_heading)};
      SensorFrame f;
      time_s += 0.1;
      f.time_s = time_s;
      f.true_pose = truth;
      // The odometry frame starts at the start pose, so the mapper's start pose is identity.
      f.odometry = odom;
      for (int s = 0; s < static_cast<int>(robot.sonars.size()); ++s) {
        const SonarMount& m = robot.sonars[s];
        const Point2 origin = truth.transform({m.x_m, m.y_m});
        const auto r =
            cast(origin, truth.theta_rad + m.heading_rad, walls, robot.sonar_max_range_m);
        f.sonar.push_back({s, r.value_or(robot.sonar_max_range_m), r.has_value(), time_s});
      }
      frames.push_back(f);
    }
  }
  return frames;
}

inline std::vector<Segment> rectangle(double x0, double y0, double x1, double y1) {
  return {{{x0, y0}, {x1, y0}}, {{x1, y0}, {x1, y1}}, {{x1, y1}, {x0, y1}}, {{x0, y1}, {x0, y0}}};
}

inline double distance_to_walls(const Point2& p, const std::vector<Segment>& walls) {
  double best = std::numeric_limits<double>::infinity();
  for (const Segment& w : walls) best = std::min(best, distance_to_segment_m(p, w));
  return best;
}

/// Median distance of 5 cm samples of the map to the true walls.
inline double median_wall_error(const std::vector<Mapper::MapSegment>& map,
                                const std::vector<Segment>& walls) {
  std::vector<double> errors;
  for (const auto& m : map) {
    const int n = std::max(1, static_cast<int>(m.segment.length_m() / 0.05));
    for (int i = 0; i <= n; ++i) {
      const Point2 p = m.segment.a + (m.segment.b - m.segment.a) * (static_cast<double>(i) / n);
      errors.push_back(distance_to_walls(p, walls));
    }
  }
  if (errors.empty()) return std::numeric_limits<double>::infinity();
  std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
  return errors[errors.size() / 2];
}

}  // namespace cogmap::mapper::test
