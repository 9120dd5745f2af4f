// find_opening's acceptance rules on scripted obstacle points: a wall along x = 2 with points
// every 0.1 m at exact multiples of 0.1 m and a gap between two of them, the robot at the
// origin. The jamb points are exact, so the opening found is exact too.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "cogmap/test_support/angles.h"
#include "nav/door_passage.h"

namespace cogmap::mapper::nav {
namespace {

constexpr double kDoorWallX = 2.0;

/// Points (2, k·0.1) for k in [-40, 40], except lo_dm < k < hi_dm: the jambs are at
/// y = lo_dm·0.1 and hi_dm·0.1. lo_dm == hi_dm is a closed wall.
std::vector<ObstaclePoint> wall(int lo_dm, int hi_dm) {
  std::vector<ObstaclePoint> out;
  for (int k = -40; k <= 40; ++k) {
    if (k > lo_dm && k < hi_dm) continue;
    out.push_back({Point2(kDoorWallX, k / 10.0), 15.0f});
  }
  return out;
}

/// A goal 1 m beyond the wall, `deg` off the wall's normal as seen from the robot.
Point2 goal_at_angle(double deg) {
  const double x = kDoorWallX + 1.0;
  return {x, x * std::tan(deg * kPi / 180.0)};
}

std::optional<Opening> find(const std::vector<ObstaclePoint>& points, const Point2& goal,
                            const DoorOptions& options = {}) {
  return find_opening(points, Point2(0.0, 0.0), goal, options);
}

void expect_opening(const std::optional<Opening>& o, double center_y, double width) {
  ASSERT_TRUE(o.has_value());
  EXPECT_NEAR(o->center_m.x(), kDoorWallX, 1e-9);
  EXPECT_NEAR(o->center_m.y(), center_y, 1e-9);
  EXPECT_NEAR(o->normal.x(), 1.0, 1e-12);
  EXPECT_NEAR(o->normal.y(), 0.0, 1e-12);
  EXPECT_NEAR(o->width_m, width, 1e-9);
}

// The 1 m door's axis is +x; the goal direction turns away from it.
TEST(FindOpeningRules, RefusesADoorWhoseAxisIsTooFarOffTheGoalDirection) {
  const auto points = wall(-5, 5);
  DoorOptions options;
  options.max_offset_m = 3.0;  // 2·sin 65° = 1.81 m off the goal line: let only the angle count
  expect_opening(find(points, goal_at_angle(55.0), options), 0.0, 1.0);  // default limit 60°
  EXPECT_FALSE(find(points, goal_at_angle(65.0), options));
  options.max_axis_angle_deg = 70.0;
  expect_opening(find(points, goal_at_angle(65.0), options), 0.0, 1.0);
}

TEST(FindOpeningRules, MaxAxisAngleBracketsTheDoorAngle) {
  const auto points = wall(-5, 5);
  const Point2 goal = goal_at_angle(40.0);  // 1.29 m off the goal line: within max_offset_m
  DoorOptions options;
  options.max_axis_angle_deg = 45.0;
  expect_opening(find(points, goal, options), 0.0, 1.0);
  options.max_axis_angle_deg = 35.0;
  EXPECT_FALSE(find(points, goal, options));
}

// A waypoint at the nominal door centre (2, 0): the goal is in the door line, so the opening
// must lie within goal_in_door_m = 0.8 of it.
TEST(FindOpeningRules, AGoalInTheDoorLineNamesOnlyANearbyOpening) {
  const Point2 goal(kDoorWallX, 0.0);
  expect_opening(find(wall(-2, 8), goal), 0.3, 1.0);  // centre 0.3 m from the goal
  const auto far = wall(5, 15);                       // centre (2, 1.0): 1.0 m from it
  EXPECT_FALSE(find(far, goal));
  DoorOptions lenient;
  lenient.goal_in_door_m = 1.1;
  expect_opening(find(far, goal, lenient), 1.0, 1.0);
  // A goal well beyond the wall is not in the door: the same opening is found.
  expect_opening(find(far, Point2(4.0, 0.0)), 1.0, 1.0);
}

TEST(FindOpeningRules, FindsADoorLeftOrRightOfTheGoalLineAtItsCentre) {
  expect_opening(find(wall(-1, 9), Point2(4.0, 0.0)), 0.4, 1.0);
  expect_opening(find(wall(-9, 1), Point2(4.0, 0.0)), -0.4, 1.0);
}

TEST(FindOpeningRules, RefusesAGapNarrowerThanMinWidth) {
  const auto narrow = wall(-3, 3);  // 0.6 m < min_width_m 0.7 m
  EXPECT_FALSE(find(narrow, Point2(4.0, 0.0)));
  DoorOptions small;
  small.min_width_m = 0.5;
  expect_opening(find(narrow, Point2(4.0, 0.0), small), 0.0, 0.6);
}

// A wall along x = 1.2 seen from the origin with a 1 m gap whose centre is 45° or 55° off the
// wall's normal: the echoes of a wall met that obliquely are painted off its line, so only the
// first is trusted as a door (max_view_incidence_deg 50°).
TEST(FindOpeningRules, TrustsOnlyAnOpeningSeenNearItsAxis) {
  const auto oblique_wall = [](int lo_dm, int hi_dm) {
    std::vector<ObstaclePoint> out;
    for (int k = -10; k <= 40; ++k) {
      if (k > lo_dm && k < hi_dm) continue;
      out.push_back({Point2(1.2, k / 10.0), 15.0f});
    }
    return out;
  };
  const auto at_45 = find(oblique_wall(7, 17), Point2(2.2, 1.2));  // centre (1.2, 1.2): 45.0°
  ASSERT_TRUE(at_45.has_value());
  EXPECT_NEAR(at_45->center_m.x(), 1.2, 1e-9);
  EXPECT_NEAR(at_45->center_m.y(), 1.2, 1e-9);
  const auto gap_at_55 = oblique_wall(12, 22);  // centre (1.2, 1.7): 54.8° off the normal
  EXPECT_FALSE(find(gap_at_55, Point2(2.2, 1.7)));
  DoorOptions trusting;
  trusting.max_view_incidence_deg = 60.0;
  const auto at_55 = find(gap_at_55, Point2(2.2, 1.7), trusting);
  ASSERT_TRUE(at_55.has_value());
  EXPECT_NEAR(at_55->center_m.y(), 1.7, 1e-9);
}

TEST(FindOpeningRules, AClosedDoorHasNoOpening) {
  EXPECT_FALSE(find(wall(0, 0), Point2(4.0, 0.0)));
  EXPECT_FALSE(find(wall(0, 0), Point2(kDoorWallX, 0.0)));
}

}  // namespace
}  // namespace cogmap::mapper::nav
