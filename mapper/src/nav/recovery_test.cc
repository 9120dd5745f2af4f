#include <gtest/gtest.h>

#include <vector>

#include "cogmap/mapper/nav/controller.h"
#include "nav/fake_grid_updater.h"
#include "nav/nav_test_util.h"

namespace cogmap::mapper::nav {
namespace {

using testing::frame_at;
using testing::integrate;

// The robot pushes against something the sonar cannot see: the pose stays put while the
// controller commands forward motion. Returns the frame index of the first reversing command.
int run_until_backing(Controller& c, const RobotGeometry& robot, const GridUpdater& grid,
                      const Pose2& pose, int from, int until) {
  for (int i = from; i < until; ++i) {
    SensorFrame f = frame_at(i);
    const VelocityCommand cmd = c.step({&f, pose, &grid, &robot});
    if (cmd.v_mps < 0.0) return i;
    EXPECT_GT(cmd.v_mps, 0.0) << "frame " << i;
  }
  return -1;
}

TEST(Recovery, StuckWhileDrivingBacksOffTurnsAndResumes) {
  const RobotGeometry robot = p2at_geometry();
  testing::FakeGridUpdater grid{-5.0, -5.0, 10.0, -1.0f};
  RouteOptions options;  // stuck_time_s = 4
  auto c = make_route_follower(options, {Point2(4.0, 0.0)});
  Pose2 pose{0.0, 0.0, 0.0};
  const int backing = run_until_backing(*c, robot, grid, pose, 0, 100);
  // The clock starts at frame 0 (nothing commanded yet): reversing at 4.0 s, not before.
  EXPECT_EQ(backing, 40);
  EXPECT_EQ(c->trace().mode, NavMode::kBackOff);
  EXPECT_EQ(c->trace().recoveries, 1u);

  // From now on the robot moves as commanded.
  std::vector<NavMode> modes;
  std::vector<VelocityCommand> cmds;
  for (int i = backing; i < backing + 80; ++i) {
    SensorFrame f = frame_at(i);
    const VelocityCommand cmd = c->step({&f, pose, &grid, &robot});
    modes.push_back(c->trace().mode);
    cmds.push_back(cmd);
    pose = integrate(pose, cmd);
  }
  // Back off ~0.4 m at 0.2 m/s, straight.
  int k = 0;
  while (k < static_cast<int>(modes.size()) && modes[k] == NavMode::kBackOff) {
    EXPECT_DOUBLE_EQ(cmds[k].v_mps, -0.2);
    EXPECT_DOUBLE_EQ(cmds[k].w_radps, 0.0);
    ++k;
  }
  EXPECT_GE(k, 19);
  EXPECT_LE(k, 21);
  // Then turn in place toward the freest sector (the contact blocks straight ahead).
  const int turn_start = k;
  while (k < static_cast<int>(modes.size()) && modes[k] == NavMode::kTurn) {
    EXPECT_DOUBLE_EQ(cmds[k].v_mps, 0.0);
    EXPECT_NE(cmds[k].w_radps, 0.0);
    ++k;
  }
  EXPECT_GT(k, turn_start);
  EXPECT_LE(k - turn_start, 15);  // at most turn_time_s = 1.5 s
  // Then normal driving resumes, forward.
  ASSERT_LT(k, static_cast<int>(modes.size()));
  EXPECT_EQ(modes[k], NavMode::kDrive);
  EXPECT_GT(cmds[k].v_mps, 0.0);
  EXPECT_FALSE(c->done());
}

TEST(Recovery, TurningInPlaceIsNotStuck) {
  const RobotGeometry robot = p2at_geometry();
  testing::FakeGridUpdater grid{-5.0, -5.0, 10.0, -1.0f};
  auto c = make_route_follower(RouteOptions{}, {Point2(-4.0, 0.01)});  // straight behind
  Pose2 pose{0.0, 0.0, 0.0};
  for (int i = 0; i < 80; ++i) {
    SensorFrame f = frame_at(i);
    const VelocityCommand cmd = c->step({&f, pose, &grid, &robot});
    EXPECT_GE(cmd.v_mps, 0.0) << i;
    pose = integrate(pose, cmd);
  }
  EXPECT_EQ(c->trace().recoveries, 0u);
}

TEST(Recovery, HeldStallFlagsTriggerRecoveryEarly) {
  const RobotGeometry robot = p2at_geometry();
  testing::FakeGridUpdater grid{-5.0, -5.0, 10.0, -1.0f};
  auto c = make_route_follower(RouteOptions{}, {Point2(4.0, 0.0)});
  Pose2 pose{0.0, 0.0, 0.0};
  int backing = -1;
  for (int i = 0; i < 30 && backing < 0; ++i) {
    SensorFrame f = frame_at(i);
    f.stall_left = i >= 10;
    const Pose2 moved{0.05 * i, 0.0, 0.0};  // encoders still count (wheels spin)
    if (c->step({&f, moved, &grid, &robot}).v_mps < 0.0) backing = i;
  }
  EXPECT_EQ(backing, 15);  // stalled from 1.0 s, held 0.5 s
  (void)pose;
}

TEST(Recovery, AWaypointThatStaysUnreachableIsSkipped) {
  const RobotGeometry robot = p2at_geometry();
  testing::FakeGridUpdater grid{-5.0, -5.0, 10.0, -1.0f};
  RouteOptions options;
  options.recovery.max_attempts = 2;
  auto c = make_route_follower(options, {Point2(4.0, 0.0), Point2(0.0, 4.0)});
  const Pose2 pose{0.0, 0.0, 0.0};  // never moves, whatever it is told
  for (int i = 0; i < 600 && c->trace().waypoint_index == 0; ++i) {
    SensorFrame f = frame_at(i);
    c->step({&f, pose, &grid, &robot});
  }
  EXPECT_EQ(c->trace().waypoint_index, 1u);
  EXPECT_EQ(c->skipped_waypoints(), 1u);
  EXPECT_EQ(c->trace().recoveries, 3u);  // two attempts, the third stuck skips
  EXPECT_FALSE(c->done());
}

}  // namespace
}  // namespace cogmap::mapper::nav
