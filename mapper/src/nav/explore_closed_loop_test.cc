// The explorers in closed loop with an ideal robot in small synthetic worlds: an exact,
// noise-free sonar (the nearest wall within ±12° of each transducer's axis) and exact
// odometry, so what is tested is the behaviour, not the sensing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "cogmap/mapper/nav/controller.h"
#include "nav/nav_test_util.h"

namespace cogmap::mapper::nav {
namespace {

using testing::frame_at;
using testing::integrate;

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Distance along the ray from `o` in direction `d` (unit) to segment `s`, or infinity.
double ray_hit(const Point2& o, const Point2& d, const Segment& s) {
  const Point2 e = s.b - s.a;
  const double den = d.x() * e.y() - d.y() * e.x();
  if (std::abs(den) < 1e-12) return kInf;
  const Point2 w = s.a - o;
  const double t = (w.x() * e.y() - w.y() * e.x()) / den;
  const double u = (w.x() * d.y() - w.y() * d.x()) / den;
  return t > 0.0 && u >= 0.0 && u <= 1.0 ? t : kInf;
}

double point_segment_m(const Point2& p, const Segment& s) {
  const Point2 e = s.b - s.a;
  const double t = std::clamp((p - s.a).dot(e) / e.squaredNorm(), 0.0, 1.0);
  return (p - (s.a + t * e)).norm();
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
    for (const Segment& s : walls) c = std::min(c, point_segment_m(p, s));
    return c;
  }
};

World box(double x0, double y0, double x1, double y1) {
  return {{{{x0, y0}, {x1, y0}}, {{x1, y0}, {x1, y1}}, {{x1, y1}, {x0, y1}}, {{x0, y1}, {x0, y0}}}};
}

/// Two 5 x 4 m rooms side by side (x 0-5 and 5-10), a 1 m doorway at y 1.5-2.5 between them.
World two_rooms() {
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
};

LoopRun drive(Controller& c, const World& w, Pose2 pose, double max_s) {
  const RobotGeometry robot = p2at_geometry();
  LoopRun r;
  const int frames = static_cast<int>(max_s / testing::kCycleS);
  for (int i = 0; i < frames && !c.done(); ++i) {
    SensorFrame f = frame_at(i, w.sonar(pose, robot, i));
    f.odometry = pose;  // exact odometry
    pose = integrate(pose, c.step({&f, pose, nullptr, &robot}));
    r.min_clearance_m = std::min(r.min_clearance_m, w.clearance_m(pose.translation()));
    r.max_x_m = std::max(r.max_x_m, pose.x_m);
    r.time_s = (i + 1) * testing::kCycleS;
  }
  r.done = c.done();
  r.complete = c.trace().exploration_complete;
  return r;
}

TEST(FrontierExplorerLoop, ExploresAClosedRoomAndStops) {
  auto c = make_explorer(ExploreOptions{});
  const LoopRun r = drive(*c, box(0, 0, 5, 4), {1.0, 1.0, 0.3}, 400.0);
  EXPECT_TRUE(r.done);
  EXPECT_TRUE(r.complete);
  EXPECT_LT(r.time_s, 52.0);  // 1.25x the 41.3 s measured
  // The body's half-diagonal is 0.4 m: the centre never came near enough to touch.
  EXPECT_GT(r.min_clearance_m, 0.4);
}

TEST(FrontierExplorerLoop, FindsTheDoorwayAndExploresTheSecondRoom) {
  auto c = make_explorer(ExploreOptions{});
  const LoopRun r = drive(*c, two_rooms(), {1.0, 2.0, 0.0}, 900.0);
  EXPECT_GT(r.max_x_m, 6.0);  // well inside the second room
  EXPECT_TRUE(r.complete);
  EXPECT_LT(r.time_s, 141.0);  // 1.25x the 112.5 s measured
  EXPECT_GT(r.min_clearance_m, 0.4);
}

TEST(FrontierExplorerLoop, ABudgetEndsTheExplorationUnfinished) {
  ExploreOptions o;
  o.time_budget_s = 20.0;
  auto c = make_explorer(o);
  const LoopRun r = drive(*c, two_rooms(), {1.0, 2.0, 0.0}, 100.0);
  EXPECT_TRUE(r.done);
  EXPECT_FALSE(r.complete);
  EXPECT_NEAR(r.time_s, 20.1, 0.15);  // the frame at which 20 s had passed
}

TEST(FrontierExplorerLoop, AnUnusableEstimateStopsTheRobotButEndsNothing) {
  const RobotGeometry robot = p2at_geometry();
  auto c = make_explorer(ExploreOptions{});
  const World w = box(0, 0, 5, 4);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int i = 0; i < 20; ++i) {
    const Pose2 pose{nan, 1.0, 0.0};
    SensorFrame f = frame_at(i, w.sonar({1.0, 1.0, 0.0}, robot, i));
    const VelocityCommand cmd = c->step({&f, pose, nullptr, &robot});
    EXPECT_EQ(cmd.v_mps, 0.0);
    EXPECT_EQ(cmd.w_radps, 0.0);
  }
  EXPECT_FALSE(c->done());
  EXPECT_FALSE(c->trace().exploration_complete);
  // A usable estimate again: it explores.
  SensorFrame f = frame_at(20, w.sonar({1.0, 1.0, 0.0}, robot, 20));
  c->step({&f, {1.0, 1.0, 0.0}, nullptr, &robot});
  EXPECT_FALSE(c->done());
}

TEST(FrontierExplorerLoop, ASonarThatStartsLateDoesNotEndTheExploration) {
  // A real P2-AT's sonar starts a moment after its motors: 3 s of frames without a reading.
  const RobotGeometry robot = p2at_geometry();
  auto c = make_explorer(ExploreOptions{});
  const World w = box(0, 0, 5, 4);
  Pose2 pose{1.0, 1.0, 0.3};
  for (int i = 0; i < 30; ++i) {
    SensorFrame f = frame_at(i);
    f.odometry = pose;
    pose = integrate(pose, c->step({&f, pose, nullptr, &robot}));
  }
  EXPECT_FALSE(c->done());
  EXPECT_FALSE(c->trace().exploration_complete);
  const LoopRun r = drive(*c, w, pose, 400.0);  // then the sonar: the room is explored
  EXPECT_TRUE(r.complete);
  EXPECT_GT(r.min_clearance_m, 0.4);
}

TEST(HeadingExplorerLoop, ABudgetEndsIt) {
  ExploreOptions o;
  o.strategy = ExploreStrategy::kHeading;
  o.distance_budget_m = 3.0;  // by the odometry
  auto c = make_explorer(o);
  const LoopRun r = drive(*c, box(0, 0, 5, 4), {1.0, 1.0, 0.0}, 400.0);
  EXPECT_TRUE(r.done);
  EXPECT_FALSE(r.complete);   // the heading explorer never completes
  EXPECT_LT(r.time_s, 30.0);  // 3 m at up to 0.5 m/s, with turning
}

TEST(EdgeExplorerLoop, WalksTheRoomsEdgeAndClosesTheTour) {
  ExploreOptions o;
  o.strategy = ExploreStrategy::kEdge;
  auto c = make_explorer(o);
  const LoopRun r = drive(*c, box(0, 0, 5, 4), {1.0, 1.0, 0.0}, 400.0);
  EXPECT_TRUE(r.done);
  EXPECT_TRUE(r.complete);
  EXPECT_LT(r.time_s, 52.0);  // 1.25x the 41.1 s measured
  EXPECT_GT(r.min_clearance_m, 0.4);
}

TEST(EdgeExplorerLoop, TakesTheDoorwayOnItsRight) {
  ExploreOptions o;
  o.strategy = ExploreStrategy::kEdge;
  auto c = make_explorer(o);
  const LoopRun r = drive(*c, two_rooms(), {1.0, 2.0, 0.0}, 900.0);
  EXPECT_GT(r.max_x_m, 6.0);   // through the doorway, well inside the second room
  EXPECT_TRUE(r.complete);     // and back round to where the tour began
  EXPECT_LT(r.time_s, 205.0);  // 1.25x the 164.0 s measured
  EXPECT_GT(r.min_clearance_m, 0.4);
}

}  // namespace
}  // namespace cogmap::mapper::nav
