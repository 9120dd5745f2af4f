#include "nav/frontier_planner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "nav/explore_map.h"
#include "nav/frontier_test_scene.h"

namespace cogmap::mapper::nav {
namespace {

using testing::at;
using testing::count_frontier_cells;
using testing::describe;
using testing::expect_walkable_legs;
using testing::kCellM;
using testing::Key;
using testing::kPi;
using testing::Scene;
using testing::walkable;

// A seen free disc of 2.1 m around the origin (no cell centre lies on its rim), unseen
// space all round: the frontier is the rim, its cells 1.9-2.1 m out.
ExploreMap disc_map() {
  Scene scene;
  scene.add_disc({0.0, 0.0}, 2.1);
  return scene.build();
}

TEST(FrontierPlanner, GoesToTheRimOfASeenDisc) {
  const ExploreMap map = disc_map();
  const std::optional<FrontierPlan> plan =
      plan_to_frontier(map, {0.0, 0.0, 0.0}, {}, 0.0, FrontierOptions{});
  ASSERT_TRUE(plan.has_value());
  EXPECT_GE(plan->frontier.norm(), 1.8);
  EXPECT_LE(plan->frontier.norm(), 2.1);
  EXPECT_TRUE(map.frontier(map.cell_of(plan->frontier)));
  EXPECT_LE((plan->goal - plan->frontier).norm(), FrontierOptions{}.view_m + 1e-9);
  EXPECT_TRUE(walkable(map, plan->goal));
  // The goal is the nearest place in view: no farther out than the frontier less 0.9 m, plus
  // a cell's diagonal for the lattice.
  EXPECT_LE(plan->goal.norm(), 2.1 - FrontierOptions{}.view_m + kCellM * std::sqrt(2.0));
  EXPECT_GE(plan->cost_m, plan->goal.norm() - 1e-9);
  // The whole rim is one 8-connected cluster.
  EXPECT_EQ(plan->frontier_cells, count_frontier_cells(map));
  expect_walkable_legs(map, {0.0, 0.0, 0.0}, *plan, FrontierOptions{}.max_leg_m);
}

TEST(FrontierPlanner, PrefersTheFrontierAhead) {
  const ExploreMap map = disc_map();
  FrontierOptions options;
  options.turn_cost_m = 0.6;
  for (double heading : {0.0, kPi / 2, kPi, -kPi / 2}) {
    const Point2 ahead(std::cos(heading), std::sin(heading));
    const std::optional<FrontierPlan> plan =
        plan_to_frontier(map, {0.0, 0.0, heading}, {}, 0.0, options);
    ASSERT_TRUE(plan.has_value()) << heading;
    // Within 45° of the heading, for the frontier and for the goal.
    EXPECT_GT(plan->frontier.normalized().dot(ahead), std::cos(kPi / 4))
        << heading << ": " << plan->frontier.transpose();
    EXPECT_GT(plan->goal.normalized().dot(ahead), std::cos(kPi / 4))
        << heading << ": " << plan->goal.transpose();
  }
}

TEST(FrontierPlanner, AFrontierBehindMustBeMuchNearer) {
  // A corridor along x (walls 1.6 m apart), open at both ends, the robot facing +x: the
  // frontier ahead is 3.0 m away, the one behind 1.6 m (1.4 m nearer, less than the turn's
  // turn_cost_m × π = 1.9 m), so ahead wins.
  Scene scene;
  scene.add_free(-8, -3, 15, 3);
  scene.add_open(16, -3, 16, 3);
  scene.add_open(-9, -3, -9, 3);
  const ExploreMap map = scene.build();
  FrontierOptions options;
  options.turn_cost_m = 0.6;
  const std::optional<FrontierPlan> ahead =
      plan_to_frontier(map, {0.0, 0.0, 0.0}, {}, 0.0, options);
  ASSERT_TRUE(ahead.has_value());
  EXPECT_NEAR(ahead->frontier.x(), 3.0, 1e-9) << describe(*ahead);
  // Without the turn's price the nearer end behind is chosen.
  FrontierOptions no_turn;
  no_turn.turn_cost_m = 0.0;
  const std::optional<FrontierPlan> behind =
      plan_to_frontier(map, {0.0, 0.0, 0.0}, {}, 0.0, no_turn);
  ASSERT_TRUE(behind.has_value());
  EXPECT_NEAR(behind->frontier.x(), -1.6, 1e-9) << describe(*behind);
}

TEST(FrontierPlanner, NothingLeftInAnEnclosedRoom) {
  Scene closed;
  closed.add_free(-5, -5, 5, 5);  // 2.2 m square room, walled all round
  const ExploreMap map = closed.build();
  EXPECT_FALSE(plan_to_frontier(map, {0.0, 0.0, 0.0}, {}, 0.0, FrontierOptions{}).has_value());
  FrontierOptions one;
  one.min_frontier_cells = 1;
  EXPECT_FALSE(plan_to_frontier(map, {0.0, 0.0, 0.0}, {}, 0.0, one).has_value());
}

TEST(FrontierPlanner, FrontierPiecesSmallerThanMinFrontierCellsAreIgnored) {
  Scene closed;
  closed.add_free(-5, -5, 5, 5);
  FrontierOptions three;
  three.min_frontier_cells = 3;
  // A 3-cell (0.6 m) gap in the east wall leaves a frontier of min_frontier_cells.
  Scene gap = closed;
  gap.add_open(6, -1, 6, 1);
  const std::optional<FrontierPlan> plan =
      plan_to_frontier(gap.build(), {0.0, 0.0, 0.0}, {}, 0.0, three);
  ASSERT_TRUE(plan.has_value());
  EXPECT_NEAR(plan->frontier.x(), 1.0, 1e-9);
  EXPECT_EQ(plan->frontier_cells, 3u);
  // Two cells (0.4 m) are too few for 3, enough for 2; one cell is enough for 1.
  Scene narrow = closed;
  narrow.add_open(6, 0, 6, 1);
  const ExploreMap narrow_map = narrow.build();
  EXPECT_FALSE(plan_to_frontier(narrow_map, {0.0, 0.0, 0.0}, {}, 0.0, three).has_value());
  FrontierOptions two;
  two.min_frontier_cells = 2;
  const std::optional<FrontierPlan> two_plan =
      plan_to_frontier(narrow_map, {0.0, 0.0, 0.0}, {}, 0.0, two);
  ASSERT_TRUE(two_plan.has_value());
  EXPECT_EQ(two_plan->frontier_cells, 2u);
  Scene single = closed;
  single.add_open(6, 0, 6, 0);
  const ExploreMap single_map = single.build();
  EXPECT_FALSE(plan_to_frontier(single_map, {0.0, 0.0, 0.0}, {}, 0.0, two).has_value());
  FrontierOptions one;
  one.min_frontier_cells = 1;
  const std::optional<FrontierPlan> one_plan =
      plan_to_frontier(single_map, {0.0, 0.0, 0.0}, {}, 0.0, one);
  ASSERT_TRUE(one_plan.has_value());
  EXPECT_NEAR((one_plan->frontier - Point2(1.0, 0.0)).norm(), 0.0, 1e-9);
}

TEST(FrontierPlanner, BannedFrontiersAreSkipped) {
  const ExploreMap map = disc_map();
  const std::optional<FrontierPlan> first =
      plan_to_frontier(map, {0.0, 0.0, 0.0}, {}, 0.0, FrontierOptions{});
  ASSERT_TRUE(first.has_value());
  ASSERT_GT(first->frontier.x(), 0.0);
  const std::vector<BannedFrontier> banned = {{first->frontier, std::nullopt}};
  const std::optional<FrontierPlan> second =
      plan_to_frontier(map, {0.0, 0.0, 0.0}, banned, 2.0, FrontierOptions{});
  ASSERT_TRUE(second.has_value());
  EXPECT_GT((second->frontier - first->frontier).norm(), 2.0);
  EXPECT_GE(second->frontier.norm(), 1.8);
  // Banning the whole rim leaves nothing.
  const std::vector<BannedFrontier> all = {{{0.0, 0.0}, std::nullopt}};
  EXPECT_FALSE(plan_to_frontier(map, {0.0, 0.0, 0.0}, all, 2.2, FrontierOptions{}).has_value());
}

TEST(FrontierPlanner, AFrontierInTheOpenIsNoDoorway) {
  const std::optional<FrontierPlan> plan =
      plan_to_frontier(disc_map(), {0.0, 0.0, 0.0}, {}, 0.0, FrontierOptions{});
  ASSERT_TRUE(plan.has_value());
  EXPECT_FALSE(plan->frontier_in_doorway) << describe(*plan);
}

TEST(FrontierPlanner, LegsStayOnSeenFreeCellsAndAreBounded) {
  // An L: a corridor east from the start (1.4 m wide), then north, open at the far end.
  Scene scene;
  scene.add_free(-1, -3, 30, 3);
  scene.add_free(24, 4, 30, 20);
  scene.add_open(24, 21, 30, 21);
  const ExploreMap map = scene.build();
  const Pose2 from{0.0, 0.0, 0.0};
  for (double max_leg_m : {4.0, 1.5}) {
    FrontierOptions options;
    options.max_leg_m = max_leg_m;
    const std::optional<FrontierPlan> plan = plan_to_frontier(map, from, {}, 0.0, options);
    ASSERT_TRUE(plan.has_value()) << max_leg_m;
    EXPECT_NEAR(plan->frontier.y(), 4.0, 1e-9);
    EXPECT_GE(plan->goal.y(), 3.0);
    EXPECT_GT(plan->cost_m, (plan->goal - from.translation()).norm());
    // The corner forces a bend (two legs at least), and no leg is longer than max_leg_m.
    const double straight = (plan->goal - map.center_of(map.cell_of(from.translation()))).norm();
    EXPECT_GE(plan->waypoints.size(),
              std::max<std::size_t>(2, static_cast<std::size_t>(std::ceil(straight / max_leg_m))));
    expect_walkable_legs(map, from, *plan, max_leg_m);
  }
}

// Two seen free rooms side by side, 4 m x 2 m each (cells x 0-20 and 22-42, y 0-10), the
// column of cells between them (x 4.2 m) a wall heard from the west.
ExploreMap wall_between_rooms() {
  Scene scene;
  scene.add_free(0, 0, 20, 10);
  scene.add_free(22, 0, 42, 10);
  const ExploreMap map = scene.build();
  EXPECT_TRUE(map.occupied(map.cell_of(at({21, 5}))));
  return map;
}

TEST(FrontierPlanner, APathThroughAWallHeardSinceIsBlocked) {
  const ExploreMap map = wall_between_rooms();
  const Point2 robot = at({2, 5});
  // The first leg runs east along y = 1 m through the wall; the second north in the east room.
  const std::vector<Point2> legs{robot, at({30, 5}), at({30, 9})};
  EXPECT_TRUE(path_blocked(map, legs, 0, robot, 0.31));
  // Approaching the second waypoint: only its leg is left, and it is clear.
  EXPECT_FALSE(path_blocked(map, legs, 1, at({30, 5}), 0.31));
  EXPECT_FALSE(path_blocked(map, legs, 2, at({30, 9}), 0.31));
  // A path that stays in the west room is clear.
  const std::vector<Point2> west{robot, at({18, 5}), at({18, 9})};
  EXPECT_FALSE(path_blocked(map, west, 0, robot, 0.31));
}

TEST(FrontierPlanner, ABlockedPathIgnoresTheBodysSurroundingsAndTheTrail) {
  ExploreMap map = wall_between_rooms();
  // The robot stands 0.2 m before the wall's centre line: what lies within 0.31 m of it is
  // left to VFH, and the leg is clear beyond.
  const Point2 robot = at({20, 5});
  const std::vector<Point2> legs{robot, at({30, 5})};
  EXPECT_TRUE(path_blocked(map, legs, 0, robot, 0.0));
  EXPECT_FALSE(path_blocked(map, legs, 0, robot, 0.31));
  // From farther back the wall counts, unless the robot's centre has passed through its cell
  // (the planner's way back over the trail).
  const std::vector<Point2> from_afar{at({10, 5}), at({30, 5})};
  EXPECT_TRUE(path_blocked(map, from_afar, 0, at({10, 5}), 0.31));
  map.mark_traversed(at({21, 5}));
  EXPECT_FALSE(path_blocked(map, from_afar, 0, at({10, 5}), 0.31));
  // A leg along a line through the next cell of the wall is blocked again.
  const std::vector<Point2> beside{at({10, 6}), at({30, 6})};
  EXPECT_TRUE(path_blocked(map, beside, 0, at({10, 6}), 0.31));
}

TEST(FrontierPlanner, ABlockedPathCheckEndsOnDegenerateLegs) {
  const ExploreMap map = wall_between_rooms();
  const Point2 robot = at({2, 5});
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(path_blocked(map, std::vector<Point2>{}, 0, robot, 0.31));
  EXPECT_FALSE(path_blocked(map, std::vector<Point2>{robot}, 0, robot, 0.31));
  EXPECT_FALSE(path_blocked(map, std::vector<Point2>{robot, robot}, 0, robot, 0.31));
  EXPECT_FALSE(path_blocked(map, std::vector<Point2>{robot, Point2(inf, 1.0)}, 0, robot, 0.31));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(path_blocked(map, std::vector<Point2>{robot, Point2(nan, 1.0)}, 0, robot, 0.31));
}

TEST(FrontierPlanner, WhatIsLeftOfAPathIsMeasuredAlongItsLegs) {
  // A way round a wall: 4 m south, 6 m east, 4 m north to a goal 6 m east of the start.
  const std::vector<Point2> legs{{0.0, 0.0}, {0.0, -4.0}, {6.0, -4.0}, {6.0, 0.0}};
  EXPECT_DOUBLE_EQ(remaining_path_m(legs, 0, {0.0, 0.0}), 14.0);
  // 3 m down the first leg the robot is 3 m farther from the goal as the crow flies
  // (hypot(6, 3) = 6.71 m against 6 m at the start) and 3 m nearer along the path.
  EXPECT_DOUBLE_EQ(remaining_path_m(legs, 0, {0.0, -3.0}), 11.0);
  // On the second leg: to its end (5 m), then the last leg (4 m).
  EXPECT_DOUBLE_EQ(remaining_path_m(legs, 1, {1.0, -4.0}), 9.0);
  // Off the line (0.3 m north of the second leg): straight to the waypoint ahead.
  EXPECT_DOUBLE_EQ(remaining_path_m(legs, 1, {2.0, -3.7}), std::hypot(4.0, 0.3) + 4.0);
  // Approaching the last point, and past the last waypoint: the distance to the last point.
  EXPECT_DOUBLE_EQ(remaining_path_m(legs, 2, {6.0, -1.0}), 1.0);
  EXPECT_DOUBLE_EQ(remaining_path_m(legs, 7, {6.0, 3.0}), 3.0);
  // No legs: nothing left; the start alone: the distance back to it.
  EXPECT_DOUBLE_EQ(remaining_path_m(std::vector<Point2>{}, 0, {1.0, 1.0}), 0.0);
  EXPECT_DOUBLE_EQ(remaining_path_m(std::vector<Point2>{{0.0, 0.0}}, 0, {3.0, 4.0}), 5.0);
}

TEST(ExploreMapImage, ClassifiesEveryCellAsThePlannerSeesIt) {
  // A 5 x 5 free room walled round, with one wall cell left unseen: its inner neighbour is the
  // only frontier.
  Scene scene;
  scene.add_free(0, 0, 4, 4);
  scene.add_open(5, 2, 5, 2);
  const ExploreMap map = scene.build();
  auto cell = [&](const ExploreMapImage& image, Key k) {
    return image.cells[map.index(map.cell_of(at(k)))];
  };
  const ExploreMapImage image = explore_map_image(map, {}, 0.6);
  ASSERT_EQ(image.width, map.width());
  ASSERT_EQ(image.height, map.height());
  ASSERT_EQ(image.cells.size(), static_cast<std::size_t>(map.width() * map.height()));
  EXPECT_DOUBLE_EQ(image.cell_m, kCellM);
  EXPECT_NEAR(image.origin_m.x(), map.center_of({0, 0}).x() - 0.5 * kCellM, 1e-12);
  EXPECT_NEAR(image.origin_m.y(), map.center_of({0, 0}).y() - 0.5 * kCellM, 1e-12);
  EXPECT_EQ(cell(image, {2, 2}), ExploreMapImage::kFree);
  EXPECT_EQ(cell(image, {4, 2}), ExploreMapImage::kFrontier);
  EXPECT_EQ(cell(image, {5, 2}), ExploreMapImage::kUnseen);
  EXPECT_EQ(cell(image, {5, 1}), ExploreMapImage::kObstacle);
  EXPECT_EQ(cell(image, {-1, 3}), ExploreMapImage::kObstacle);
  auto count = [](const ExploreMapImage& i, std::uint8_t v) {
    return std::count(i.cells.begin(), i.cells.end(), v);
  };
  EXPECT_EQ(count(image, ExploreMapImage::kFrontier), 1);
  EXPECT_EQ(count(image, ExploreMapImage::kObstacle), 19);  // 4 sides x 5, less the gap
  EXPECT_EQ(count(image, ExploreMapImage::kFree), 24);
  // A failed goal at the frontier gives it up; a ban 1 m away does not.
  const BannedFrontier here{at({4, 2}), std::nullopt}, far{at({4, 2}) + Point2(0.0, 1.0), {}};
  EXPECT_EQ(cell(explore_map_image(map, std::span(&here, 1), 0.6), {4, 2}),
            ExploreMapImage::kBannedFrontier);
  EXPECT_EQ(cell(explore_map_image(map, std::span(&far, 1), 0.6), {4, 2}),
            ExploreMapImage::kFrontier);
  // A look from inside the room bans the cells no farther than the frontier, not past it.
  const BannedFrontier look{at({4, 2}), at({0, 2})};
  EXPECT_EQ(cell(explore_map_image(map, std::span(&look, 1), 0.6), {4, 2}),
            ExploreMapImage::kBannedFrontier);
}

}  // namespace
}  // namespace cogmap::mapper::nav
