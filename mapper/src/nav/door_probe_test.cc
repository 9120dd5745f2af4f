// The route follower's probe (DoorOptions probe_range_m, probe_stall_s): a waypoint within
// probe_range_m behind a sensed wall is approached head-on at the door speed. The P2-AT faces
// +x at the origin; its front transducers (2-5, at ±10° and ±30°) see a wall along x = wall_x
// where their axes meet it. No grid: the obstacles are the remembered echoes, in 10 cm cells.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "cogmap/mapper/nav/controller.h"
#include "nav/nav_test_util.h"

namespace cogmap::mapper::nav {
namespace {

using testing::frame_at;

/// Readings of transducers 2-5 of `robot` (at the origin, facing +x) off a wall x = wall_x.
std::vector<SonarReading> wall_echoes(const RobotGeometry& robot, double wall_x, double time_s) {
  std::vector<SonarReading> out;
  for (int i = 2; i <= 5; ++i) {
    const SonarMount& m = robot.sonars[static_cast<std::size_t>(i)];
    out.push_back({i, (wall_x - m.x_m) / std::cos(m.heading_rad), true, time_s});
  }
  return out;
}

struct Probe {
  RobotGeometry robot = p2at_geometry();
  SensorFrame frame;

  VelocityCommand step(Controller& c, int i, double wall_x) {
    frame = frame_at(i);
    frame.sonar = wall_echoes(robot, wall_x, frame.time_s);
    return c.step({&frame, Pose2{0.0, 0.0, 0.0}, nullptr, &robot});
  }
  /// Nothing in sight: every transducer fires without an echo.
  VelocityCommand step_open(Controller& c, int i) {
    frame = frame_at(i);
    for (int k = 0; k < static_cast<int>(robot.sonars.size()); ++k) {
      frame.sonar.push_back({k, robot.sonar_max_range_m, false, frame.time_s});
    }
    return c.step({&frame, Pose2{0.0, 0.0, 0.0}, nullptr, &robot});
  }
};

// Wall at x = 1.55: the ±10° echoes fall in the cells centred (1.55, ±0.25), within the 0.33 m
// safety radius of the line to the waypoint; 1.57 m away, 1.26 m from the bumper: full speed.
TEST(DoorProbe, ClosesInOnAWaypointBehindAWallAtTheDoorSpeed) {
  Probe p;
  RouteOptions options;
  options.door.speed_mps = 0.25;  // not a value the follower would reach by another path
  auto c = make_route_follower(options, {Point2(2.0, 0.0)});
  const VelocityCommand cmd = p.step(*c, 0, 1.55);
  EXPECT_EQ(c->trace().mode, NavMode::kDoorProbe);
  EXPECT_DOUBLE_EQ(cmd.v_mps, 0.25);
  EXPECT_DOUBLE_EQ(cmd.w_radps, 0.0);
  EXPECT_DOUBLE_EQ(c->trace().target_rad, 0.0);
}

// Wall at x = 0.95: the nearest echoes fall in the cells centred (0.95, ±0.15), inside the
// front cone and nearer than slow_clearance_m from the bumper: the safety law slows the probe.
TEST(DoorProbe, SlowsDownNearTheWallByTheSafetyLaw) {
  Probe p;
  auto c = make_route_follower(RouteOptions{}, {Point2(2.0, 0.0)});
  const VelocityCommand cmd = p.step(*c, 0, 0.95);
  EXPECT_EQ(c->trace().mode, NavMode::kDoorProbe);
  const double clearance = std::hypot(0.95, 0.15) - 0.5 * p.robot.length_m;
  EXPECT_NEAR(c->trace().front_clearance_m, clearance, 1e-9);
  EXPECT_NEAR(cmd.v_mps, 0.3 * (clearance - 0.35) / (1.0 - 0.35), 1e-9);  // door speed 0.3
  EXPECT_DOUBLE_EQ(cmd.w_radps, 0.0);
}

TEST(DoorProbe, ProbesOnlyAWallWithinRangeAcrossTheLine) {
  Probe p;
  RouteOptions off;
  off.door.probe_range_m = 0.0;
  auto disabled = make_route_follower(off, {Point2(2.0, 0.0)});
  p.step(*disabled, 0, 1.55);
  EXPECT_NE(disabled->trace().mode, NavMode::kDoorProbe);

  // The wall 2.8 m away: beyond the default probe_range_m 2.5 m.
  auto far = make_route_follower(RouteOptions{}, {Point2(3.5, 0.0)});
  p.step(*far, 0, 2.8);
  EXPECT_NE(far->trace().mode, NavMode::kDoorProbe);
  // The same waypoint behind a wall 1.55 m away: the wall's distance decides, not the
  // waypoint's (a room centre beyond a door is probed like the door centre).
  auto near = make_route_follower(RouteOptions{}, {Point2(3.5, 0.0)});
  p.step(*near, 0, 1.55);
  EXPECT_EQ(near->trace().mode, NavMode::kDoorProbe);

  // Nothing sensed: the line to the waypoint is clear (VFH or the direct drive takes it).
  auto clear = make_route_follower(RouteOptions{}, {Point2(2.0, 0.0)});
  const VelocityCommand open = p.step_open(*clear, 0);
  EXPECT_NE(clear->trace().mode, NavMode::kDoorProbe);
  EXPECT_DOUBLE_EQ(open.v_mps, 0.5);  // the route speed, not the door speed
}

// A corridor's next point tens of metres beyond a wall across the line (the estimate's drift
// puts the robot at a corner it has not reached, facing the corridor's side) has no door to
// probe for: only a waypoint within the sonar's range, probe_max_goal_m (5 m), is probed.
TEST(DoorProbe, DoesNotProbeForAWaypointBeyondTheSonarsRange) {
  Probe p;
  auto corridor = make_route_follower(RouteOptions{}, {Point2(36.0, 0.0)});
  p.step(*corridor, 0, 1.55);
  EXPECT_NE(corridor->trace().mode, NavMode::kDoorProbe);

  // The same wall, the waypoint 5.1 m and 4.9 m away: the boundary is the waypoint's distance.
  auto beyond = make_route_follower(RouteOptions{}, {Point2(5.1, 0.0)});
  p.step(*beyond, 0, 1.55);
  EXPECT_NE(beyond->trace().mode, NavMode::kDoorProbe);
  auto within = make_route_follower(RouteOptions{}, {Point2(4.9, 0.0)});
  p.step(*within, 0, 1.55);
  EXPECT_EQ(within->trace().mode, NavMode::kDoorProbe);

  RouteOptions farther;
  farther.door.probe_max_goal_m = 40.0;
  auto allowed = make_route_follower(farther, {Point2(36.0, 0.0)});
  p.step(*allowed, 0, 1.55);
  EXPECT_EQ(allowed->trace().mode, NavMode::kDoorProbe);
}

// A waypoint given up (a door not found) leaves the route's next point, a room's centre, behind
// that door's wall by the room's half-depth: in rooms over 5 m beyond probe_max_goal_m. Right
// after a give-up the probe reaches probe_max_goal_after_skip_m (8 m) instead. Here the first
// waypoint, 3 m to the left, is given up after give_up_s (the robot does not move); the next,
// 7 m ahead behind the wall, is then probed for.
TEST(DoorProbe, ProbesFartherForTheWaypointAfterOneGivenUp) {
  auto run = [](const RouteOptions& options, std::vector<Point2> route) {
    Probe p;
    auto c = make_route_follower(options, std::move(route));
    for (int i = 0; i <= 15; ++i) p.step(*c, i, 1.55);  // t = 0 .. 1.5 s
    return std::pair{c->trace().mode, c->trace().skipped_waypoints};
  };
  RouteOptions options;
  options.give_up_s = 1.0;
  const auto [after_skip, skipped] = run(options, {Point2(0.0, 3.0), Point2(7.0, 0.0)});
  EXPECT_EQ(skipped, 1u);
  EXPECT_EQ(after_skip, NavMode::kDoorProbe);
  // Not without the give-up, nor with the widening off, nor beyond it.
  EXPECT_NE(run(options, {Point2(7.0, 0.0)}).first, NavMode::kDoorProbe);
  RouteOptions narrow = options;
  narrow.door.probe_max_goal_after_skip_m = narrow.door.probe_max_goal_m;
  EXPECT_NE(run(narrow, {Point2(0.0, 3.0), Point2(7.0, 0.0)}).first, NavMode::kDoorProbe);
  EXPECT_NE(run(options, {Point2(0.0, 3.0), Point2(8.1, 0.0)}).first, NavMode::kDoorProbe);
}

// Standing still in front of the wall, the probe gives up after probe_stall_s (3 s) without
// coming progress_m nearer, before the 4 s stuck recovery.
TEST(DoorProbe, GivesUpAfterProbeStallWithoutProgress) {
  Probe p;
  auto c = make_route_follower(RouteOptions{}, {Point2(2.0, 0.0)});
  for (int i = 0; i <= 29; ++i) p.step(*c, i, 1.55);  // t = 0 .. 2.9 s
  EXPECT_EQ(c->trace().mode, NavMode::kDoorProbe);
  p.step(*c, 30, 1.55);
  p.step(*c, 31, 1.55);  // t = 3.1 s
  EXPECT_NE(c->trace().mode, NavMode::kDoorProbe);
  EXPECT_EQ(c->trace().recoveries, 0u);
  p.step(*c, 32, 1.55);  // once given up, not resumed before the robot moves probe_rearm_m
  EXPECT_NE(c->trace().mode, NavMode::kDoorProbe);
}

TEST(DoorProbe, TheModeHasAName) { EXPECT_STREQ(to_string(NavMode::kDoorProbe), "door_probe"); }

}  // namespace
}  // namespace cogmap::mapper::nav
