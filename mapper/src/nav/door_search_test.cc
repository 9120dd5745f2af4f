// The door search (nav/door_search.h): the blocking wall's fit, the profile of what the
// transducers heard along it (exact synthetic readings with known gaps), and the route follower
// sweeping a wall whose door its front transducers cannot see, in closed loop.
#include "nav/door_search.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "cogmap/mapper/nav/controller.h"
#include "cogmap/test_support/angles.h"
#include "nav/loop_world.h"

namespace cogmap::mapper::nav {
namespace {

// The wall y = 1 seen from below: the normal points from the robot's side (+y) to it.
WallLine wall_y1() { return {Point2(0.0, 1.0), Point2(1.0, 0.0), Point2(0.0, 1.0)}; }

// A transducer at (s, 0.5) looking straight at the wall (+y): an echo at 0.5 m marks the wall
// at s, no echo (max range) marks s open.
void hear(WallProfile& p, double s, bool wall) {
  p.add(Point2(s, 0.5), Point2(0.0, 1.0), wall ? 0.5 : 5.0, wall, 0.25, 25.0 * kDeg);
}

// Wall from s = -1.0 to -0.5 and from 0.5 to 1.0, open readings at -0.4 ... 0.4, 0.1 apart.
WallProfile door_of_width_1() {
  WallProfile p(wall_y1());
  for (int k = -10; k <= 10; ++k) hear(p, 0.1 * k, std::abs(k) >= 5);
  return p;
}

TEST(WallProfile, AGapBetweenTwoStretchesOfWallIsADoorAtItsMiddle) {
  const auto g = door_of_width_1().gap(0.45, 1.5, 0.35, 0.0);
  ASSERT_TRUE(g.has_value());
  EXPECT_NEAR(g->center_m.x(), 0.0, 1e-12);
  EXPECT_NEAR(g->center_m.y(), 1.0, 1e-12);
  EXPECT_NEAR(g->width_m, 1.0, 1e-12);  // between the inner wall echoes at -0.5 and 0.5
  EXPECT_NEAR(g->normal.y(), 1.0, 1e-12);
}

TEST(WallProfile, AGapOutsideTheWidthsIsNoDoor) {
  EXPECT_FALSE(door_of_width_1().gap(1.05, 1.5, 0.35, 0.0));   // narrower than the minimum
  EXPECT_FALSE(door_of_width_1().gap(0.45, 0.95, 0.35, 0.0));  // wider than the maximum
}

TEST(WallProfile, OneLostEchoIsNoDoor) {
  WallProfile p(wall_y1());
  for (int k = -10; k <= 10; ++k) hear(p, 0.1 * k, k != 0);  // one reading without an echo
  EXPECT_FALSE(p.gap(0.45, 1.5, 0.35, 0.0));
  // Two in a row leave 0.3 m between the echoes either side: still under the 0.45 m minimum.
  WallProfile two(wall_y1());
  for (int k = -10; k <= 10; ++k) hear(two, 0.1 * k, k != 0 && k != 1);
  EXPECT_FALSE(two.gap(0.45, 1.5, 0.35, 0.0));
}

TEST(WallProfile, AGapMustBeHeardThroughAlongItsWholeWidth) {
  // Wall echoes either side, but open readings only near one end: the middle was never heard.
  WallProfile p(wall_y1());
  for (int k = -10; k <= 10; ++k) {
    if (std::abs(k) >= 5 || k == -4 || k == -3) hear(p, 0.1 * k, std::abs(k) >= 5);
  }
  EXPECT_FALSE(p.gap(0.45, 1.5, 0.35, 0.0));
  EXPECT_TRUE(p.gap(0.45, 1.5, 0.85, 0.0).has_value());  // with a looser unseen limit: found
}

TEST(WallProfile, ObliqueReadingsAndNearerEchoesAreIgnored) {
  WallProfile p(wall_y1());
  for (int k = -10; k <= 10; ++k) {
    if (std::abs(k) >= 5) hear(p, 0.1 * k, true);
  }
  // 40° off the normal and passing beyond the line: not heard square-on, not counted.
  for (int k = -4; k <= 4; ++k) {
    p.add(Point2(0.1 * k, 0.5), Point2(std::sin(40 * kDeg), std::cos(40 * kDeg)), 5.0, false, 0.25,
          25.0 * kDeg);
  }
  EXPECT_FALSE(p.gap(0.45, 1.5, 0.35, 0.0));
  // Echoes from 0.2 m (something in front of the wall) neither mark the wall nor open it.
  WallProfile q = door_of_width_1();
  for (int k = -4; k <= 4; ++k) {
    q.add(Point2(0.1 * k + 0.05, 0.5), Point2(0.0, 1.0), 0.2, true, 0.25, 25.0 * kDeg);
  }
  const auto g = q.gap(0.45, 1.5, 0.35, 0.0);
  ASSERT_TRUE(g.has_value());
  EXPECT_NEAR(g->width_m, 1.0, 1e-12);
}

TEST(WallProfile, PrefersTheGapNearestTheWaypoint) {
  WallProfile p(wall_y1());
  // Doors at s in (-2.5, -1.5) and (1.5, 2.5).
  for (int k = -30; k <= 30; ++k) {
    const double s = 0.1 * k;
    hear(p, s, !((s > -2.45 && s < -1.55) || (s > 1.55 && s < 2.45)));
  }
  const auto right = p.gap(0.45, 1.5, 0.35, 1.0);
  ASSERT_TRUE(right.has_value());
  EXPECT_NEAR(right->center_m.x(), 2.0, 1e-9);
  const auto left = p.gap(0.45, 1.5, 0.35, -3.0);
  ASSERT_TRUE(left.has_value());
  EXPECT_NEAR(left->center_m.x(), -2.0, 1e-9);
}

TEST(WallProfile, RefitsToTheSquareOnEchoes) {
  // Started 10° off (the oblique front view), the wall is heard where it is: y = 1.
  const double a = 10.0 * kDeg;
  WallProfile p(
      {Point2(0.0, 1.0), Point2(std::cos(a), std::sin(a)), Point2(-std::sin(a), std::cos(a))});
  for (int k = -5; k <= 5; ++k) {
    p.add(Point2(0.1 * k, 0.5), Point2(0.0, 1.0), 0.5, true, 0.25, 25.0 * kDeg);
  }
  p.refit(6, 0.8, 0.1);
  EXPECT_NEAR(std::abs(p.wall().along.x()), 1.0, 1e-12);
  EXPECT_GT(p.wall().along.x(), 0.0);  // the sense is kept
  EXPECT_NEAR(p.wall().normal.y(), 1.0, 1e-12);
  EXPECT_NEAR(p.wall().point_m.y(), 1.0, 1e-12);
  EXPECT_NEAR(p.s_of(Point2(0.3, 1.0)), 0.3, 1e-12);  // s measured from the old origin's foot
  // Too few echoes, or too short a stretch: no refit.
  WallProfile q(
      {Point2(0.0, 1.0), Point2(std::cos(a), std::sin(a)), Point2(-std::sin(a), std::cos(a))});
  for (int k = 0; k < 5; ++k)
    q.add(Point2(0.1 * k, 0.5), Point2(0.0, 1.0), 0.5, true, 0.25, 25.0 * kDeg);
  q.refit(6, 0.8, 0.1);
  EXPECT_NEAR(q.wall().along.y(), std::sin(a), 1e-12);
}

std::vector<ObstaclePoint> points(const std::vector<Point2>& offsets) {
  std::vector<ObstaclePoint> out;
  for (const Point2& o : offsets) out.push_back({o, 1.0f});
  return out;
}

TEST(BlockingWall, FitsTheWallAcrossTheWay) {
  std::vector<Point2> w;
  for (int k = -8; k <= 8; ++k) w.emplace_back(0.1 * k, 1.0);
  const auto wall = blocking_wall(points(w), Point2(2.0, 3.0), Point2(2.0, 6.0), 0.33, 2.5, 0.1);
  ASSERT_TRUE(wall.has_value());
  EXPECT_NEAR(std::abs(wall->along.x()), 1.0, 1e-12);
  EXPECT_NEAR(wall->normal.y(), 1.0, 1e-12);   // from the robot toward the wall
  EXPECT_NEAR(wall->point_m.y(), 4.0, 1e-12);  // in the world: the robot is at (2, 3)
}

TEST(BlockingWall, NothingOnTheWayOrNoLineIsNoWall) {
  std::vector<Point2> w;
  for (int k = -8; k <= 8; ++k) w.emplace_back(0.1 * k, 1.0);
  EXPECT_FALSE(blocking_wall(points(w), Point2(0, 0), Point2(0, -3), 0.33, 2.5, 0.1));  // behind
  EXPECT_FALSE(blocking_wall(points(w), Point2(0, 0), Point2(0, 3), 0.33, 0.5, 0.1));   // too far
  // A cluster, not a line (clutter): rms distance 0.2 m from its best line.
  const std::vector<Point2> blob = {{0.0, 1.0},  {0.2, 1.3}, {-0.2, 0.7}, {0.1, 0.6},
                                    {-0.1, 1.4}, {0.3, 0.8}, {-0.3, 1.2}};
  EXPECT_FALSE(blocking_wall(points(blob), Point2(0, 0), Point2(0, 3), 0.33, 2.5, 0.1));
}

// A sweep starts only for a waypoint within the distance its caller allows (search_max_goal_m,
// or the route follower's wider limit right after a waypoint was given up): the wall 1 m ahead,
// the waypoint 7 m on behind it.
TEST(DoorSearch, StartsOnlyForAWaypointWithinTheGivenDistance) {
  std::vector<Point2> w;
  for (int k = -8; k <= 8; ++k) w.emplace_back(0.1 * k, 1.0);
  const Pose2 robot{0.0, 0.0, std::numbers::pi / 2.0};
  const DoorOptions options;
  DoorSearch near(options);
  EXPECT_FALSE(near.start(points(w), robot, Point2(0.0, 7.0), std::nullopt, 0.33, 0.0,
                          options.search_max_goal_m));
  EXPECT_FALSE(near.active());
  DoorSearch wide(options);
  EXPECT_TRUE(wide.start(points(w), robot, Point2(0.0, 7.0), std::nullopt, 0.33, 0.0,
                         options.probe_max_goal_after_skip_m));
  EXPECT_TRUE(wide.active());
}

// Two rooms, x 0-5 and 5-10 (5 m deep), a 0.9 m door at y 2.6-3.5 in the wall x = 5. The
// waypoint (7, 1.3) lies behind the wall 1.75 m below the door's centre. The exact sonar here
// does not smear the jambs as the simulated and real ones do (which is what makes the front
// detector lock onto gaps that are not there, docs/algorithms.md "Door search"); instead the
// front detector is told to accept only openings within 0.3 m of the line to the waypoint, so
// it cannot take this door and only a sweep finds it.
testing::World offset_door() {
  return {{{{0, 0}, {10, 0}},
           {{10, 0}, {10, 5}},
           {{10, 5}, {0, 5}},
           {{0, 5}, {0, 0}},
           {{5, 0}, {5, 2.6}},
           {{5, 3.5}, {5, 5}}}};
}

RouteOptions front_detector_off_the_line(int searches) {
  RouteOptions o;
  o.door.max_offset_m = 0.3;
  o.door.search_per_waypoint = searches;
  return o;
}

TEST(DoorSearchLoop, SweepsTheWallAndPassesTheDoorTheFrontDetectorRefuses) {
  auto c = make_route_follower(front_detector_off_the_line(2), {Point2(7.0, 1.3)});
  const testing::LoopRun r = testing::drive(*c, offset_door(), {3.0, 1.3, 0.0}, 120.0);
  EXPECT_TRUE(r.done);
  EXPECT_EQ(c->trace().skipped_waypoints, 0u);
  EXPECT_GT(r.door_search_s, 0.0);
  EXPECT_GT(r.min_clearance_m, 0.3);  // the 0.505 m body never touched a jamb
  EXPECT_LT(r.time_s, 48.0);  // 1.25x the 38.3 s measured (first down to the corner, then up)
}

// The give-up clock restarts when the sweep first hears the gap, not only when it hands the gap
// over: the drive back to the approach point and the turn to face the gap took ~5 s here, and a
// clock that ran through them gave the waypoint up in front of the door it had found (the 6 x 6
// block's seeds 1 and 3, docs/algorithms.md "Door search"). Measured on this world: with the
// restart the waypoint is passed for any give_up_s >= 15 s, without it only from 20 s.
TEST(DoorSearchLoop, AGapHeardRestartsTheGiveUpClock) {
  RouteOptions o = front_detector_off_the_line(2);
  o.give_up_s = 17.0;
  auto c = make_route_follower(o, {Point2(7.0, 1.3)});
  const testing::LoopRun r = testing::drive(*c, offset_door(), {3.0, 1.3, 0.0}, 120.0);
  EXPECT_TRUE(r.done);
  EXPECT_EQ(c->trace().skipped_waypoints, 0u);
  EXPECT_GT(r.max_x_m, 6.5);  // through the door, on to the waypoint
}

TEST(DoorSearchLoop, WithoutTheSweepTheSameWaypointIsGivenUp) {
  auto c = make_route_follower(front_detector_off_the_line(0), {Point2(7.0, 1.3)});
  const testing::LoopRun r = testing::drive(*c, offset_door(), {3.0, 1.3, 0.0}, 120.0);
  EXPECT_EQ(r.door_search_s, 0.0);
  EXPECT_EQ(c->trace().skipped_waypoints, 1u);
  EXPECT_LT(r.max_x_m, 5.0);  // never through the wall
}

}  // namespace
}  // namespace cogmap::mapper::nav
