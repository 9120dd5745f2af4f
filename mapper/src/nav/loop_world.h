#pragma once
/// Test support: small synthetic worlds of wall segments and an ideal robot in closed loop with
/// a controller: an exact, noise-free sonar (the nearest wall within ±12° of each transducer's
/// axis, four transducers per 100 ms frame) and exact odometry, so what a test checks is the
/// behaviour, not the sensing.

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "cogmap/mapper/nav/controller.h"
#include "cogmap/mapper/seam/geometry.h"
#include "nav/nav_test_util.h"

namespace cogmap::mapper::nav::testing {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

/// Distance along the ray from `o` in direction `d` (unit) to segment `s`, or infinity.
inline double ray_hit(const Point2& o, const Point2& d, const Segment& s) {
  const Point2 e = s.b - s.a;
  const double den = d.x() * e.y() - d.y() * e.x();
  if (std::abs(den) < 1e-12) return kInf;
  const Point2 w = s.a - o;
  const double t = (w.x() * e.y() - w.y() * e.x()) / den;
  const double u = (w.x() * d.y() - w.y() * d.x()) / den;
  return t > 0.0 && u >= 0.0 && u <= 1.0 ? t : kInf;
}

struct World {
  std::vector<Segment> walls;

  /// Four transducers per 100 ms frame, the ring in order (a P2-AT ring fires in ~0.4 s).
  std::vector<SonarReading> sonar(const Pose2& pose, const RobotGeometry& robot, int frame) const {
    std::vector<SonarReading> out;
    for (int k = 0; k < 4; ++k) {
      const int i = (4 * frame + k) % static_cast<int>(robot.sonars.size());
      const SonarMount& m = robot.sonars[static_cast<std::size_t>(i)];
      const Point2 origin = pose.transform(Point2(m.x_m, m.y_m));
      double range = kInf;
      for (double off = -12.0; off <= 12.0; off += 3.0) {
        const double a = pose.theta_rad + m.heading_rad + off * std::numbers::pi / 180.0;
        const Point2 d(std::cos(a), std::sin(a));
        for (const Segment& s : walls) range = std::min(range, ray_hit(origin, d, s));
      }
      const bool echo = range <= robot.sonar_max_range_m;
      out.push_back({i, echo ? range : robot.sonar_max_range_m, echo, frame * testing::kCycleS});
    }
    return out;
  }

  double clearance_m(const Point2& p) const {
    double c = kInf;
    for (const Segment& s : walls) c = std::min(c, distance_to_segment_m(p, s));
    return c;
  }
};

inline World box(double x0, double y0, double x1, double y1) {
  return {{{{x0, y0}, {x1, y0}}, {{x1, y0}, {x1, y1}}, {{x1, y1}, {x0, y1}}, {{x0, y1}, {x0, y0}}}};
}

/// Two 5 x 4 m rooms side by side (x 0-5 and 5-10), a 1 m doorway at y 1.5-2.5 between them.
inline World two_rooms() {
  return {{{{0, 0}, {10, 0}},
           {{10, 0}, {10, 4}},
           {{10, 4}, {0, 4}},
           {{0, 4}, {0, 0}},
           {{5, 0}, {5, 1.5}},
           {{5, 2.5}, {5, 4}}}};
}

struct LoopRun {
  bool done = false;
  bool complete = false;
  double time_s = 0.0;
  double min_clearance_m = kInf;  // robot centre to the nearest wall
  double max_x_m = -kInf;
  double door_search_s = 0.0;  // time in NavMode::kDoorSearch
};

inline LoopRun drive(Controller& c, const World& w, Pose2 pose, double max_s) {
  const RobotGeometry robot = p2at_geometry();
  LoopRun r;
  const int frames = static_cast<int>(max_s / testing::kCycleS);
  for (int i = 0; i < frames && !c.done(); ++i) {
    SensorFrame f = testing::frame_at(i, w.sonar(pose, robot, i));
    f.odometry = pose;  // exact odometry
    pose = testing::integrate(pose, c.step({&f, pose, nullptr, &robot}));
    if (c.trace().mode == NavMode::kDoorSearch) r.door_search_s += testing::kCycleS;
    r.min_clearance_m = std::min(r.min_clearance_m, w.clearance_m(pose.translation()));
    r.max_x_m = std::max(r.max_x_m, pose.x_m);
    r.time_s = (i + 1) * testing::kCycleS;
  }
  r.done = c.done();
  r.complete = c.trace().exploration_complete;
  return r;
}

}  // namespace cogmap::mapper::nav::testing
