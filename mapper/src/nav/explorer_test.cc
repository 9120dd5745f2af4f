#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "cogmap/mapper/nav/controller.h"
#include "cogmap/test_support/angles.h"
#include "nav/fake_grid_updater.h"
#include "nav/nav_test_util.h"

namespace cogmap::mapper::nav {
namespace {

using testing::frame_at;
using testing::integrate;

// These tests cover the thesis's Fig. 1.2 explorer (frontier_explorer_test.cc the default).
ExploreOptions heading_options() {
  ExploreOptions o;
  o.strategy = ExploreStrategy::kHeading;
  return o;
}

// One knob for the door search: the route follower sweeps (2 per waypoint), the explorer, whose
// door behaviour is the same DoorOptions, does not unless told to (docs/algorithms.md, "Door
// search"); everything else of the door behaviour is the route follower's.
TEST(ExploreOptions, TheDoorBehaviourIsTheRouteFollowersWithoutTheSweep) {
  const DoorOptions route = RouteOptions{}.door;
  const DoorOptions explore = ExploreOptions{}.door;
  EXPECT_EQ(route.search_per_waypoint, 2);
  EXPECT_EQ(explore.search_per_waypoint, 0);
  EXPECT_EQ(explore.enabled, route.enabled);
  EXPECT_EQ(explore.speed_mps, route.speed_mps);
  EXPECT_EQ(explore.search_timeout_s, route.search_timeout_s);
  // Pockets: refused and a goal in one given up by the explorer only (docs/algorithms.md).
  EXPECT_EQ(route.beyond_clear_m, 0.0);
  EXPECT_EQ(explore.beyond_clear_m, 1.1);
  EXPECT_FALSE(route.give_up_goal_in_pocket);
  EXPECT_TRUE(explore.give_up_goal_in_pocket);
}

VelocityCommand step(Controller& c, const GridUpdater& grid, int i, const Pose2& pose) {
  static const RobotGeometry kRobot = p2at_geometry();
  SensorFrame f = frame_at(i);
  return c.step({&f, pose, &grid, &kRobot});
}

TEST(Explorer, ChoosesTheSideThatIsStillUnexplored) {
  testing::FakeGridUpdater left{-5.0, -5.0, 10.0, -1.0f};
  left.fill_box(-5.0, 0.5, 5.0, 5.0, 0.0f);  // unexplored only for y > 0.5
  auto c = make_explorer(heading_options());
  const VelocityCommand cmd = step(*c, left, 0, {0.0, 0.0, 0.0});
  EXPECT_GT(cmd.w_radps, 0.0);
  EXPECT_GT(c->trace().direction_rad, 45.0 * kDeg)
      << c->trace().target_rad << " mode " << int(c->trace().mode) << " v " << cmd.v_mps;
  EXPECT_LT(c->trace().direction_rad, 135.0 * kDeg);
  EXPECT_FALSE(c->done());

  testing::FakeGridUpdater right{-5.0, -5.0, 10.0, -1.0f};
  right.fill_box(-5.0, -5.0, 5.0, -0.5, 0.0f);
  auto d = make_explorer(heading_options());
  EXPECT_LT(step(*d, right, 0, {0.0, 0.0, 0.0}).w_radps, 0.0);
  EXPECT_LT(d->trace().direction_rad, -45.0 * kDeg);
  EXPECT_GT(d->trace().direction_rad, -135.0 * kDeg);
}

TEST(Explorer, KeepsItsHeadingWhenEverythingIsEquallyUnexplored) {
  testing::FakeGridUpdater unknown{-10.0, -10.0, 20.0, 0.0f};
  auto c = make_explorer(heading_options());
  const VelocityCommand cmd = step(*c, unknown, 0, {0.0, 0.0, 0.3});
  EXPECT_NEAR(c->trace().direction_rad, 0.3, 2.5 * kDeg + 1e-9);  // the sector holding 0.3
  EXPECT_DOUBLE_EQ(cmd.v_mps > 0.0, true);
}

TEST(Explorer, DoesNotCountCellsBehindAWall) {
  // Unexplored beyond a wall ahead (x > 1.6), seen-empty everywhere else except a small
  // unexplored pocket to the right that is reachable.
  testing::FakeGridUpdater grid{-5.0, -5.0, 10.0, -1.0f};
  grid.fill_box(1.6, -5.0, 5.0, 5.0, 0.0f);
  grid.fill_box(1.5, -5.0, 1.6, 5.0, 15.0f);
  grid.fill_box(-0.2, -3.0, 0.2, -2.0, 0.0f);
  auto c = make_explorer(heading_options());
  step(*c, grid, 0, {0.0, 0.0, 0.0});
  EXPECT_LT(c->trace().target_rad, -60.0 * kDeg);
  EXPECT_GT(c->trace().target_rad, -120.0 * kDeg);
}

TEST(Explorer, AvoidsItsOwnRecentPath) {
  // Everything unexplored; the robot has just come from the left (+y) heading south, then
  // stops facing west. Without the penalty north and south would tie on unexplored cells.
  testing::FakeGridUpdater unknown{-10.0, -10.0, 20.0, 0.0f};
  ExploreOptions options = heading_options();
  options.hysteresis_bonus = 0.0;
  auto c = make_explorer(options);
  int i = 0;
  for (double y = 3.0; y >= 0.0; y -= 0.1) step(*c, unknown, i++, {0.0, y, -kDeg * 90.0});
  step(*c, unknown, i++, {0.0, 0.0, kDeg * 180.0});
  const double chosen = c->trace().target_rad;
  EXPECT_GT(std::abs(std::remainder(chosen - kDeg * 90.0, 2.0 * std::numbers::pi)), 60.0 * kDeg)
      << chosen / kDeg;
}

TEST(Explorer, ExploresAClosedRoomWithoutCollision) {
  // A 6 m x 4 m room, walls known, floor unexplored; the floor around the robot
  // (within the grid window w = 2 m) becomes seen as it drives. The explorer must keep moving, stay
  // off the walls and uncover most of the floor in two simulated minutes.
  testing::FakeGridUpdater room{-5.0, -5.0, 10.0, 0.0f};
  room.fill_box(-3.05, -2.05, 3.05, -1.95, 15.0f);
  room.fill_box(-3.05, 1.95, 3.05, 2.05, 15.0f);
  room.fill_box(-3.05, -2.05, -2.95, 2.05, 15.0f);
  room.fill_box(2.95, -2.05, 3.05, 2.05, 15.0f);
  auto c = make_explorer(heading_options());
  Pose2 pose{0.0, 0.0, 0.0};
  double travelled = 0.0;
  for (int i = 0; i < 1200; ++i) {
    room.reveal(pose.translation(), 2.0);  // the grid window w
    const Pose2 next = integrate(pose, step(*c, room, i, pose));
    travelled += (next.translation() - pose.translation()).norm();
    pose = next;
    ASSERT_LT(std::abs(pose.x_m), 3.0 - 0.05 - 0.25) << i;
    ASSERT_LT(std::abs(pose.y_m), 2.0 - 0.05 - 0.25) << i;
  }
  EXPECT_GT(travelled, 20.0);
  int floor_cells = 0, seen = 0;  // cell centres strictly inside the walls
  for (int y = 0; y < 100; ++y) {
    for (int x = 0; x < 100; ++x) {
      const Point2 p = room.geometry().center_of({x, y});
      if (std::abs(p.x()) > 2.9 || std::abs(p.y()) > 1.9) continue;
      ++floor_cells;
      seen += room.histogram_at({x, y}) == -1.0f;
    }
  }
  EXPECT_EQ(floor_cells, 58 * 38);
  EXPECT_GT(seen, floor_cells * 9 / 10) << seen << " of " << floor_cells;
  EXPECT_FALSE(c->done());
}

}  // namespace
}  // namespace cogmap::mapper::nav
