#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "cogmap/mapper/nav/controller.h"
#include "cogmap/test_support/angles.h"
#include "nav/fake_grid_updater.h"
#include "nav/nav_test_util.h"

namespace cogmap::mapper::nav {
namespace {

using testing::frame_at;
using testing::integrate;

struct Fixture {
  RobotGeometry robot = p2at_geometry();
  testing::FakeGridUpdater grid{-5.0, -5.0, 10.0, -1.0f};  // all seen empty
  SensorFrame frame;

  VelocityCommand step(Controller& c, int i, const Pose2& pose) {
    frame = frame_at(i);
    return c.step({&frame, pose, &grid, &robot});
  }
};

TEST(RouteFollower, TurnsTowardAWaypointOnTheLeftThenDrives) {
  Fixture fx;
  auto c = make_route_follower(RouteOptions{}, {Point2(0.0, 2.0), Point2(2.0, 2.0)});
  const VelocityCommand turn = fx.step(*c, 0, {0.0, 0.0, 0.0});
  EXPECT_GT(turn.w_radps, 0.0);
  EXPECT_DOUBLE_EQ(turn.v_mps, 0.0);  // 90° off: turn in place
  EXPECT_DOUBLE_EQ(turn.w_radps, 1.0);
  const VelocityCommand drive = fx.step(*c, 1, {0.0, 0.0, kPi / 2});
  EXPECT_DOUBLE_EQ(drive.v_mps, 0.5);
  EXPECT_NEAR(drive.w_radps, 0.0, 1e-12);
  const VelocityCommand veer = fx.step(*c, 2, {0.0, 0.0, kPi / 2 - 0.2});
  EXPECT_GT(veer.w_radps, 0.0);
  EXPECT_GT(veer.v_mps, 0.0);
  EXPECT_LT(veer.v_mps, 0.5);  // slower while the heading is off
  EXPECT_EQ(c->trace().waypoint_index, 0u);
  EXPECT_FALSE(c->done());
}

TEST(RouteFollower, AdvancesWithinToleranceAndIsDoneAfterTheLast) {
  Fixture fx;
  auto c = make_route_follower(RouteOptions{}, {Point2(0.0, 2.0), Point2(2.0, 2.0)});
  const VelocityCommand next = fx.step(*c, 0, {0.0, 1.7, kPi / 2});  // 0.3 m < 0.4 m
  EXPECT_EQ(c->trace().waypoint_index, 1u);
  EXPECT_LT(next.w_radps, 0.0);  // (2, 2) is to the right of north
  EXPECT_FALSE(c->done());
  const VelocityCommand last = fx.step(*c, 1, {1.7, 2.0, 0.0});
  EXPECT_TRUE(c->done());
  EXPECT_EQ(c->trace().mode, NavMode::kDone);
  EXPECT_DOUBLE_EQ(last.v_mps, 0.0);
  EXPECT_DOUBLE_EQ(last.w_radps, 0.0);
  EXPECT_EQ(c->skipped_waypoints(), 0u);
}

TEST(RouteFollower, RespectsTheRobotLimitsAndStopsWithoutAFrame) {
  Fixture fx;
  fx.robot.max_speed_mps = 0.3;
  fx.robot.max_turn_rate_radps = 0.5;
  RouteOptions options;
  options.speed_mps = 1.0;
  options.max_turn_rate_radps = 2.0;
  auto c = make_route_follower(options, {Point2(0.0, 3.0)});
  EXPECT_DOUBLE_EQ(fx.step(*c, 0, {0.0, 0.0, 0.0}).w_radps, 0.5);
  EXPECT_DOUBLE_EQ(fx.step(*c, 1, {0.0, 0.0, kPi / 2}).v_mps, 0.3);
  const VelocityCommand none = c->step({nullptr, {}, nullptr, nullptr});
  EXPECT_DOUBLE_EQ(none.v_mps, 0.0);
  EXPECT_DOUBLE_EQ(none.w_radps, 0.0);
}

TEST(RouteFollower, SlowsDownNearAnObstacleAheadAndStopsWhenTooClose) {
  Fixture fx;
  // Target 20.6° right; one cell at (0.95, 0.45), 25.3° left, inside the ±30° front cone.
  fx.grid.fill_box(0.92, 0.42, 0.98, 0.48, 15.0f);
  auto c = make_route_follower(RouteOptions{}, {Point2(4.0, -1.5)});
  const VelocityCommand slowed = fx.step(*c, 0, {0.0, 0.0, 0.0});
  const double error = std::atan2(-1.5, 4.0);
  const double clearance = std::hypot(0.95, 0.45) - 0.313;  // from the bumper
  EXPECT_DOUBLE_EQ(c->trace().direction_rad, error);        // free: VFH keeps the target
  EXPECT_NEAR(c->trace().front_clearance_m, clearance, 1e-9);
  const double expected =
      0.5 * (1.0 - std::abs(error) / (kPi / 3)) * (clearance - 0.35) / (1.0 - 0.35);
  EXPECT_NEAR(slowed.v_mps, expected, 1e-9);
  EXPECT_LT(slowed.w_radps, 0.0);

  testing::FakeGridUpdater near_grid{-5.0, -5.0, 10.0, -1.0f};
  near_grid.fill_box(0.52, 0.12, 0.58, 0.18, 15.0f);  // (0.55, 0.15): 0.26 m from the bumper
  auto d = make_route_follower(RouteOptions{}, {Point2(4.0, -1.5)});
  SensorFrame f = frame_at(0);
  const VelocityCommand stopped = d->step({&f, {0.0, 0.0, 0.0}, &near_grid, &fx.robot});
  EXPECT_DOUBLE_EQ(stopped.v_mps, 0.0);
  EXPECT_LT(stopped.w_radps, 0.0);  // turning away to the right, toward the target side
}

// Steering by an offset estimate, the robot drives through the doorway 0.6 m beside the
// waypoint placed at its centre: crossing the line through the waypoint perpendicular to the
// leg passes it, so the robot does not turn back to a point it cannot reach.
TEST(RouteFollower, PassesAWaypointByCrossingItsPerpendicularLine) {
  Fixture fx;
  auto c = make_route_follower(RouteOptions{}, {Point2(2.0, 0.0), Point2(4.0, 0.0)});
  fx.step(*c, 0, {0.0, 0.0, 0.0});   // the first leg starts here, along +x
  fx.step(*c, 1, {1.95, 0.6, 0.0});  // 0.6 m beside, not yet across
  EXPECT_EQ(c->trace().waypoint_index, 0u);
  fx.step(*c, 2, {2.05, 0.6, 0.0});  // across, 0.6 m > tolerance 0.4 m away
  EXPECT_EQ(c->trace().waypoint_index, 1u);

  // Crossing far beside the waypoint (a detour round an obstacle) does not count.
  auto far = make_route_follower(RouteOptions{}, {Point2(2.0, 0.0), Point2(4.0, 0.0)});
  fx.step(*far, 0, {0.0, 0.0, 0.0});
  fx.step(*far, 1, {2.05, 1.5, 0.0});
  EXPECT_EQ(far->trace().waypoint_index, 0u);

  // Disabled: only the tolerance counts.
  RouteOptions off;
  off.pass_half_width_m = 0.0;
  auto strict = make_route_follower(off, {Point2(2.0, 0.0), Point2(4.0, 0.0)});
  fx.step(*strict, 0, {0.0, 0.0, 0.0});
  fx.step(*strict, 1, {2.05, 0.6, 0.0});
  EXPECT_EQ(strict->trace().waypoint_index, 0u);
}

// Closed loop through a 1 m doorway in a wall at x = 2: the target is 2 m beyond it.
TEST(RouteFollower, DrivesThroughAOneMetreDoorway) {
  Fixture fx;
  fx.grid.fill_box(1.92, 0.52, 1.98, 5.0, 15.0f);
  fx.grid.fill_box(1.92, -5.0, 1.98, -0.52, 15.0f);
  auto c = make_route_follower(RouteOptions{}, {Point2(4.0, 0.4)});
  Pose2 pose{0.0, -0.6, 0.3};
  double nearest_post_m = 1e9;
  int i = 0;
  for (; i < 400 && !c->done(); ++i) {
    pose = integrate(pose, fx.step(*c, i, pose));
    for (const double y : {0.55, -0.55}) {
      nearest_post_m = std::min(nearest_post_m, (pose.translation() - Point2(1.95, y)).norm());
    }
  }
  EXPECT_TRUE(c->done()) << "stopped at " << pose.x_m << ", " << pose.y_m;
  EXPECT_GT(pose.x_m, 3.0);
  EXPECT_GT(nearest_post_m, 0.25 + 0.05);  // half width + half a cell: no contact
  EXPECT_EQ(c->trace().recoveries, 0u);
}

// Closed loop around a box between the start and the goal.
TEST(RouteFollower, GoesAroundAnObstacle) {
  Fixture fx;
  fx.grid.fill_box(1.5, -0.5, 1.8, 0.5, 15.0f);
  auto c = make_route_follower(RouteOptions{}, {Point2(3.5, 0.0)});
  Pose2 pose{0.0, 0.0, 0.0};
  double nearest_m = 1e9;
  for (int i = 0; i < 400 && !c->done(); ++i) {
    pose = integrate(pose, fx.step(*c, i, pose));
    const double dx = std::max({1.5 - pose.x_m, 0.0, pose.x_m - 1.8});
    const double dy = std::max({-0.5 - pose.y_m, 0.0, pose.y_m - 0.5});
    nearest_m = std::min(nearest_m, std::hypot(dx, dy));
  }
  EXPECT_TRUE(c->done());
  EXPECT_GT(nearest_m, 0.3);
}

// A room-centre waypoint 0.7 m ahead with clutter beside the line to it (within VFH's safety
// radius, outside half of it: not "reached behind an obstacle"), and the next waypoint beyond
// the room's door. Looking past the close waypoint is for a door-centre waypoint the estimate
// puts in a jamb: the door 2.9 m from this one must not lead the robot back out of the room.
// A door-centre waypoint off the same door's centre still hands the door over.
struct ClutteredRoomCentre {
  Fixture fx;
  ClutteredRoomCentre() {
    fx.grid.fill_box(-3.0, -0.05, -0.55, 0.05, 15.0f);  // wall y = 0, door x in [-0.5, 0.5]
    fx.grid.fill_box(0.55, -0.05, 3.0, 0.05, 15.0f);
    fx.grid.fill_box(0.22, -2.78, 0.38, -2.52, 15.0f);  // clutter, 0.25-0.35 m off the line
  }
  /// Whether the door behaviour holds an opening within `cycles` at the fixed pose, and where.
  std::optional<Point2> door_held(const Point2& waypoint, const Pose2& pose, int cycles) {
    auto c = make_route_follower(RouteOptions{}, {waypoint, Point2(1.5, 1.5)});
    for (int i = 0; i < cycles; ++i) {
      fx.step(*c, i, pose);
      if (c->trace().door_active) return Point2(c->trace().door_center_m);
    }
    return std::nullopt;
  }
};

TEST(RouteFollower, DoesNotLeaveThroughTheDoorForTheWaypointAfterARoomCentre) {
  ClutteredRoomCentre room;
  EXPECT_FALSE(room.door_held(Point2(0.0, -2.9), {0.0, -2.2, -kPi / 2}, 20).has_value());
}

TEST(RouteFollower, StillLooksPastADoorCentreWaypointTheEstimatePutsInAJamb) {
  ClutteredRoomCentre room;
  // The door's waypoint 0.25 m off the opening's centre, 0.74 m from the robot: the line to
  // the waypoint after it meets the wall beside the door.
  const auto door = room.door_held(Point2(0.25, 0.0), {0.0, -0.7, kPi / 2}, 20);
  ASSERT_TRUE(door.has_value());
  EXPECT_NEAR(door->x(), 0.0, 0.15);
  EXPECT_NEAR(door->y(), 0.0, 0.15);
}

TEST(IdleController, AlwaysCommandsZero) {
  Fixture fx;
  auto c = make_idle_controller();
  for (int i = 0; i < 3; ++i) {
    const VelocityCommand cmd = fx.step(*c, i, {1.0, 2.0, 0.5});
    EXPECT_DOUBLE_EQ(cmd.v_mps, 0.0);
    EXPECT_DOUBLE_EQ(cmd.w_radps, 0.0);
  }
  EXPECT_FALSE(c->done());
  EXPECT_EQ(c->trace().mode, NavMode::kIdle);
}

}  // namespace
}  // namespace cogmap::mapper::nav
