// The frontier planner at doorways: a look through a door, a doorway painted narrow or shut by
// the jambs' echoes (the last resort, the room grid's last look, the way back over the trail),
// and a room's own frontiers before those behind a doorway.

#include <gtest/gtest.h>

#include <optional>
#include <vector>

#include "nav/explore_map.h"
#include "nav/explore_reopen.h"
#include "nav/fake_grid_updater.h"
#include "nav/frontier_planner.h"
#include "nav/frontier_test_scene.h"

namespace cogmap::mapper::nav {
namespace {

using testing::describe;
using testing::expect_walkable_legs;
using testing::kPi;
using testing::Scene;
using testing::walkable;

// A closed room x -2.0 .. 0.8 m, y -1.0 .. 1.0 m, whose east wall (x = 1.0) has a doorway of
// cells door_y0 .. door_y1, and beyond it the next room seen as far as cell far_x (its side
// walls one cell either side of the doorway), unseen past it: the map after a look through.
ExploreMap door_map(int door_y0, int door_y1, int far_x) {
  Scene scene;
  scene.add_free(-10, -5, 4, 5);
  scene.add_free(5, door_y0, far_x, door_y1);
  scene.add_open(far_x + 1, door_y0, far_x + 1, door_y1);
  return scene.build();
}

// A 1 m doorway (y -0.4 .. 0.4) with the first 0.4 m beyond it seen (frontier at x = 1.4).
ExploreMap looked_through_door_map() { return door_map(-2, 2, 7); }

TEST(FrontierPlanner, ALookBansTheDoorButNotWhatItRevealedBeyond) {
  const ExploreMap map = looked_through_door_map();
  const Pose2 from{-1.0, 0.0, 0.0};
  const Point2 door(1.0, 0.0);
  const std::optional<FrontierPlan> open = plan_to_frontier(map, from, {}, 0.0, FrontierOptions{});
  ASSERT_TRUE(open.has_value());
  EXPECT_NEAR(open->frontier.x(), 1.4, 1e-9) << describe(*open);
  EXPECT_TRUE(open->frontier_in_doorway) << describe(*open);
  // A goal given up bans everything within the radius, the far side's frontier included.
  const std::vector<BannedFrontier> failed = {{door, std::nullopt}};
  EXPECT_FALSE(plan_to_frontier(map, from, failed, 0.6, FrontierOptions{}).has_value());
  // A look from inside the room leaves the cells beyond the door (2.4 m from the viewer,
  // the door 2.0 m) open...
  const std::vector<BannedFrontier> looked = {{door, from.translation()}};
  const std::optional<FrontierPlan> beyond =
      plan_to_frontier(map, from, looked, 0.6, FrontierOptions{});
  ASSERT_TRUE(beyond.has_value());
  EXPECT_NEAR(beyond->frontier.x(), 1.4, 1e-9) << describe(*beyond);
  // ...but one from the far side bans them: they lie between that viewer and the door.
  const std::vector<BannedFrontier> from_far_side = {{door, Point2(2.4, 0.0)}};
  EXPECT_FALSE(plan_to_frontier(map, from, from_far_side, 0.6, FrontierOptions{}).has_value());
}

// The same room with its doorway painted down to two cells (y 0.0 .. 0.2 at x = 1.0, as the
// jambs' echoes paint a 1 m door), and 0.6 m of the far side seen (frontier at x = 1.6): no
// place 0.35 m clear views that frontier from within 0.9 m.
TEST(FrontierPlanner, ADoorwayPaintedNarrowIsTheLastResort) {
  const ExploreMap map = door_map(0, 1, 8);
  const Pose2 from{-1.0, 0.0, 0.0};
  const std::optional<FrontierPlan> plan = plan_to_frontier(map, from, {}, 0.0, FrontierOptions{});
  ASSERT_TRUE(plan.has_value());
  EXPECT_NEAR(plan->frontier.x(), 1.6, 1e-9) << describe(*plan);
  EXPECT_NEAR(plan->goal.x(), 1.0, 1e-9) << describe(*plan);  // in the doorway itself
  expect_walkable_legs(map, from, *plan, FrontierOptions{}.max_leg_m);
  FrontierOptions no_last_resort;
  no_last_resort.doorway_goal_clearance_m = -1.0;
  EXPECT_FALSE(plan_to_frontier(map, from, {}, 0.0, no_last_resort).has_value());
  // A frontier that a place 0.35 m clear views is taken the usual way, from that place.
  const std::optional<FrontierPlan> open =
      plan_to_frontier(looked_through_door_map(), from, {}, 0.0, FrontierOptions{});
  ASSERT_TRUE(open.has_value());
  EXPECT_LE(open->goal.x(), 0.6) << describe(*open);
}

// The doorway painted shut altogether (its five cells at x = 1.0 obstacles, the far side seen
// to x = 1.6 through it before the jambs' echoes closed it): nothing is reachable, until the
// room grid, which saw beams pass through the door's cells and no echo there, reopens them
// (FrontierOptions::reopen_echo_himm, the explorer's last look before it stops).
TEST(FrontierPlanner, ADoorwayPaintedShutIsReopenedByTheRoomGrid) {
  Scene scene;
  scene.add_free(-10, -5, 4, 5);
  scene.add_free(6, -2, 8, 2);
  scene.add_open(9, -2, 9, 2);
  ExploreMap map = scene.build();
  const Pose2 from{-1.0, 0.0, 0.0};
  ASSERT_FALSE(plan_to_frontier(map, from, {}, 0.0, FrontierOptions{}).has_value());
  // The room grid: 0.1 m cells, unexplored but for the doorway, swept by beams (-1).
  testing::FakeGridUpdater room(-3.0, -2.0, 6.0, 0.0f);
  room.fill_box(0.9, -0.5, 1.1, 0.5, -1.0f);
  const double echo_himm = FrontierOptions{}.reopen_echo_himm;
  ExploreMap same = map;
  EXPECT_EQ(reopen_swept_cells(same, room, echo_himm), 5u);  // the five door cells, no jamb
  const std::optional<FrontierPlan> plan = plan_to_frontier(same, from, {}, 0.0, FrontierOptions{});
  ASSERT_TRUE(plan.has_value());
  EXPECT_NEAR(plan->frontier.x(), 1.6, 1e-9) << describe(*plan);
  expect_walkable_legs(same, from, *plan, FrontierOptions{}.max_leg_m);
  // An echo on an axis in the doorway's middle cell (a post there) keeps that cell shut.
  room.set(1.05, 0.05, 3.0f);
  ExploreMap walled = map;
  EXPECT_EQ(reopen_swept_cells(walled, room, echo_himm), 4u);
  EXPECT_TRUE(walled.occupied(walled.cell_of(Point2(1.0, 0.0))));
  EXPECT_FALSE(walled.occupied(walled.cell_of(Point2(1.0, 0.2))));
}

// The same doorway painted shut after the robot walked through it and back (its centre's
// trail along y = 0 from x = -1.0 to 1.4): with the trail passable (the explorer's plan when
// nothing else is reachable, ExploreOptions::plan_over_trail) the plan goes through the
// doorway along the trail; a trail that stopped short of the door opens nothing.
TEST(FrontierPlanner, ADoorwayWalkedThroughStaysAWayBackOverTheTrail) {
  Scene scene;
  scene.add_free(-10, -5, 4, 5);
  scene.add_free(6, -2, 8, 2);
  scene.add_open(9, -2, 9, 2);
  const ExploreMap painted = scene.build();
  const Pose2 from{-1.0, 0.0, 0.0};
  FrontierOptions over_trail;
  over_trail.trail_passable = true;
  ASSERT_FALSE(plan_to_frontier(painted, from, {}, 0.0, over_trail).has_value());

  ExploreMap walked = painted;
  for (double x = -1.0; x <= 1.4 + 1e-9; x += 0.05) walked.mark_traversed({x, 0.01});
  ASSERT_TRUE(walked.occupied(walked.cell_of(Point2(1.0, 0.0))));  // still painted shut
  EXPECT_FALSE(plan_to_frontier(walked, from, {}, 0.0, FrontierOptions{}).has_value());
  const std::optional<FrontierPlan> plan = plan_to_frontier(walked, from, {}, 0.0, over_trail);
  ASSERT_TRUE(plan.has_value());
  EXPECT_NEAR(plan->frontier.x(), 1.6, 1e-9) << describe(*plan);
  // Every leg keeps to seen free cells or to the trail.
  Point2 a = walked.center_of(walked.cell_of(from.translation()));
  for (const Point2& b : plan->waypoints) {
    const double len = (b - a).norm();
    for (double t = 0.0; t <= len; t += 0.02) {
      const Point2 p = a + (t / len) * (b - a);
      EXPECT_TRUE(walkable(walked, p) || walked.traversed(walked.cell_of(p)))
          << "leg " << a.transpose() << " -> " << b.transpose() << " crosses " << p.transpose();
    }
    a = b;
  }
  EXPECT_GT(plan->waypoints.back().x(), 1.0) << describe(*plan);  // beyond the door

  ExploreMap short_of_door = painted;
  for (double x = -1.0; x <= 0.6 + 1e-9; x += 0.05) short_of_door.mark_traversed({x, 0.01});
  EXPECT_FALSE(plan_to_frontier(short_of_door, from, {}, 0.0, over_trail).has_value());
}

// A room x -2.0 .. 2.4, y -1.0 .. 1.0, open to the east (frontier at x = 2.4). Its west wall
// (x = -2.2) has a gap of `gap_cells` cells from y = -0.2 up into a strip x -3.0 .. -2.4 open
// to the west (frontier at x = -3.0). From x = -1.2 the strip's goal (about 1.4 m away,
// through the gap) is nearer than the room's (about 2.8 m); the doorway's cost (8 m) must
// reverse that. Both ways start with a quarter turn.
void expect_open_frontier_first(int gap_cells) {
  Scene scene;
  scene.add_free(-10, -5, 12, 5);
  scene.add_free(-11, -1, -11, -2 + gap_cells);
  scene.add_free(-15, -5, -12, 5);
  scene.add_open(13, -5, 13, 5);
  scene.add_open(-16, -5, -16, 5);
  const ExploreMap map = scene.build();
  const Pose2 from{-1.2, 0.0, kPi / 2};
  FrontierOptions doors;
  doors.pinch_m = 0.7;
  doors.doorway_cost_m = 8.0;
  const std::optional<FrontierPlan> plan = plan_to_frontier(map, from, {}, 0.0, doors);
  ASSERT_TRUE(plan.has_value());
  EXPECT_NEAR(plan->frontier.x(), 2.4, 1e-9) << describe(*plan);
  EXPECT_GT(plan->goal.x(), 1.4);
  // Without the doorway's cost the strip's frontier is the cheaper one.
  FrontierOptions free_doors = doors;
  free_doors.doorway_cost_m = 0.0;
  const std::optional<FrontierPlan> through = plan_to_frontier(map, from, {}, 0.0, free_doors);
  ASSERT_TRUE(through.has_value());
  EXPECT_NEAR(through->frontier.x(), -3.0, 1e-9) << describe(*through);
  EXPECT_LT(through->goal.x(), -2.2);        // beyond the gap
  EXPECT_LT(through->cost_m, plan->cost_m);  // the open route costs the same either way
}

TEST(FrontierPlanner, OpenFrontierBeforeOneThroughA06mDoorway) { expect_open_frontier_first(3); }

// pinch_m promises a doorway for gaps under 1.4 m; a 0.8 m door is the common case.
TEST(FrontierPlanner, OpenFrontierBeforeOneThroughA08mDoorway) { expect_open_frontier_first(4); }

}  // namespace
}  // namespace cogmap::mapper::nav
