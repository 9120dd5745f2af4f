#include "nav/turn_backs.h"

#include <gtest/gtest.h>

#include <numbers>
#include <vector>

#include "cogmap/mapper/nav/vfh.h"
#include "cogmap/test_support/angles.h"

namespace cogmap::mapper::nav {
namespace {

constexpr double kTarget = 90.0 * kDeg;

TEST(TurnBacks, TwoTurnBacksWithinTheWindowHoldTheWay) {
  TurnBacks t{VfhOptions{}};
  EXPECT_FALSE(t.holding(0.0, kTarget));
  t.record(10.0, kTarget, 180.0 * kDeg, 20.0 * kDeg);   // 160°: back the way it came
  EXPECT_FALSE(t.holding(10.1, kTarget));               // one: a dead end left
  t.record(14.0, kTarget, 20.0 * kDeg, -150.0 * kDeg);  // 170°: and back again
  EXPECT_TRUE(t.holding(14.1, kTarget));
  EXPECT_TRUE(t.holding(33.9, kTarget));   // turn_back_hold_s 20 after the second
  EXPECT_FALSE(t.holding(34.0, kTarget));  // ...and no longer
}

TEST(TurnBacks, TurnsOfNinetyDegreesOrLessAreNoTurnBacks) {
  TurnBacks t{VfhOptions{}};
  for (int k = 0; k < 10; ++k) {
    // Left and right by 90° every second: a swing, not a turn back.
    t.record(k, kTarget, (k % 2 == 0 ? 0.0 : 90.0) * kDeg, (k % 2 == 0 ? 90.0 : 0.0) * kDeg);
  }
  EXPECT_FALSE(t.holding(10.0, kTarget));
}

TEST(TurnBacks, TurnBacksFurtherApartThanTheWindowHoldNothing) {
  TurnBacks t{VfhOptions{}};
  t.record(10.0, kTarget, 180.0 * kDeg, 0.0);
  t.record(30.5, kTarget, 0.0, 180.0 * kDeg);  // 20.5 s later: outside turn_back_window_s
  EXPECT_FALSE(t.holding(30.6, kTarget));
  t.record(40.0, kTarget, 180.0 * kDeg, 0.0);  // 9.5 s after the second: a cycle
  EXPECT_TRUE(t.holding(40.1, kTarget));
}

TEST(TurnBacks, ANewTargetStartsAfresh) {
  TurnBacks t{VfhOptions{}};
  t.record(10.0, kTarget, 180.0 * kDeg, 0.0);
  t.record(12.0, kTarget, 0.0, 180.0 * kDeg);
  ASSERT_TRUE(t.holding(12.1, kTarget));
  // The bearing drifting by 40° as the robot moves is the same target...
  EXPECT_TRUE(t.holding(12.1, kTarget + 40.0 * kDeg));
  // ...a waypoint 60° away is another: nothing held for it.
  EXPECT_FALSE(t.holding(12.1, kTarget - 60.0 * kDeg));
  t.record(13.0, kTarget - 60.0 * kDeg, 180.0 * kDeg, 0.0);  // one turn-back toward it
  EXPECT_FALSE(t.holding(13.1, kTarget - 60.0 * kDeg));
  EXPECT_FALSE(t.holding(13.1, kTarget));  // the old hold ended with its target
}

TEST(TurnBacks, ALimitOfZeroNeverHolds) {
  VfhOptions off;
  off.turn_back_limit = 0;
  TurnBacks t{off};
  for (int k = 0; k < 6; ++k) t.record(k, kTarget, k % 2 == 0 ? 0.0 : 3.0, k % 2 == 0 ? 3.0 : 0.0);
  EXPECT_FALSE(t.holding(6.0, kTarget));
}

// The target (north) lies behind a wall 0.8 m ahead of the robot; a box 0.8 m west blocks the
// way the robot was going round it. Left free: east (back the way it came, but nearer the
// target) and south-west (on round the box, farther from it).
std::vector<ObstaclePoint> wall_north_box_west() {
  std::vector<ObstaclePoint> pts;
  for (int i = -30; i <= 30; ++i) pts.push_back({Point2(0.1 * i, 0.8), 15.0f});
  for (int i = -5; i <= 7; ++i) pts.push_back({Point2(-0.8, 0.1 * i), 15.0f});
  return pts;
}

TEST(VfhTurnBackHold, HoldingTheWayTakesTheValleyAheadOverTheWayBack) {
  VfhOptions o;
  o.side_switch_rad = 0.0;  // isolate the hold from the detour side's own cost
  o.heading_weight = 0.0;
  Vfh vfh{o};
  vfh.build(wall_north_box_west());
  const double previous = 180.0 * kDeg;  // last cycle: west, along the wall
  const VfhChoice free = vfh.select(kTarget, previous, previous, false);
  ASSERT_TRUE(free.found);
  // Unheld, the valley nearer the target wins: east, a turn of more than 90° back.
  EXPECT_GT(std::abs(wrap_angle_rad(free.direction_rad - previous)), 0.5 * std::numbers::pi);
  const VfhChoice held = vfh.select(kTarget, previous, previous, true);
  ASSERT_TRUE(held.found);
  // Held, it goes on round the box: within 90° of where it was going, south-west.
  EXPECT_LE(std::abs(wrap_angle_rad(held.direction_rad - previous)), 0.5 * std::numbers::pi);
  EXPECT_LT(held.direction_rad, -90.0 * kDeg);
}

TEST(VfhTurnBackHold, WithNothingAheadTheWayBackIsStillTaken) {
  // Walled in north, west and south-west but for the way back east: holding never strands
  // the robot.
  std::vector<ObstaclePoint> pts = wall_north_box_west();
  for (int i = -8; i <= 0; ++i) pts.push_back({Point2(0.1 * i, -0.8), 15.0f});
  for (int i = 6; i <= 8; ++i) pts.push_back({Point2(-0.8, -0.1 * i), 15.0f});
  Vfh vfh{VfhOptions{}};
  vfh.build(pts);
  const double previous = 180.0 * kDeg;
  const VfhChoice held = vfh.select(kTarget, previous, previous, true);
  ASSERT_TRUE(held.found);
  EXPECT_GT(std::abs(wrap_angle_rad(held.direction_rad - previous)), 0.5 * std::numbers::pi);
}

}  // namespace
}  // namespace cogmap::mapper::nav
