// Position fixes at doorways passed again, on exact synthetic passages: a new door is
// remembered and moves nothing, a door passed again pulls the estimate back by the Kalman gain
// of the drift since its last passage against two passages' scatter, and nothing moves when
// the passage could be another door, is too wide to place, or crosses another way.
#include "cogmap/mapper/localization/door_fixes.h"

#include <gtest/gtest.h>

#include <limits>
#include <numbers>

namespace cogmap::mapper {
namespace {

constexpr double kHalfPi = std::numbers::pi / 2.0;

DoorFixOptions door_fix_options() {
  DoorFixOptions o;
  o.match_radius_m = 0.8;
  o.ambiguity_ratio = 2.0;
  o.max_width_m = 1.3;
  o.door_sd_m = 0.1;        // two passages: noise variance 2 x 0.01 = 0.02 m²
  o.drift_sd_per_m = 0.01;  // 10 m since the last passage: drift variance 0.01 m²
  return o;
}

TEST(DoorMemory, ANewDoorIsRememberedAndMovesNothing) {
  DoorMemory memory(door_fix_options());
  EXPECT_FALSE(memory.pass({{5.0, 2.0}, 1.0, 0.0, 0.0}));
  EXPECT_FALSE(memory.pass({{5.0, 4.0}, 1.0, 0.0, 3.0}));  // 2 m away: another door
  ASSERT_EQ(memory.doors().size(), 2u);
  EXPECT_EQ(memory.doors()[1].center, Point2(5.0, 4.0));
}

TEST(DoorMemory, ADoorPassedAgainPullsTheEstimateBackByTheKalmanGain) {
  DoorMemory memory(door_fix_options());
  ASSERT_FALSE(memory.pass({{5.0, 2.0}, 1.0, 0.0, 0.0}));
  // Passed back the other way 10 m later, drawn 0.3 m north and 0.15 m east of itself.
  const auto shift = memory.pass({{5.15, 2.3}, 0.95, std::numbers::pi, 10.0});
  ASSERT_TRUE(shift);
  // gain = 0.01 / (0.01 + 0.02) = 1/3 of the difference (-0.15, -0.3).
  EXPECT_NEAR(shift->x(), -0.05, 1e-12);
  EXPECT_NEAR(shift->y(), -0.1, 1e-12);
  // The door stays where it was first measured; its drift clock restarts: passed again 10 m
  // later the gain is 1/3 again, not that of 20 m (0.04 / 0.06).
  EXPECT_EQ(memory.doors().size(), 1u);
  EXPECT_EQ(memory.doors()[0].center, Point2(5.0, 2.0));
  const auto again = memory.pass({{5.0, 2.6}, 1.0, 0.0, 20.0});
  ASSERT_TRUE(again);
  EXPECT_NEAR(again->y(), -0.2, 1e-12);
}

TEST(DoorMemory, AfterALongTourTheFixIsAlmostWhole) {
  DoorMemory memory(door_fix_options());
  ASSERT_FALSE(memory.pass({{0.0, 0.0}, 1.0, kHalfPi, 0.0}));
  // 200 m later: drift variance 4 m² against 0.02 m² of scatter.
  const auto shift = memory.pass({{0.5, -0.2}, 1.0, kHalfPi, 200.0});
  ASSERT_TRUE(shift);
  EXPECT_NEAR(shift->x(), -0.5 * 4.0 / 4.02, 1e-12);
  EXPECT_NEAR(shift->y(), 0.2 * 4.0 / 4.02, 1e-12);
}

TEST(DoorMemory, ThePassageItselfWithoutTravelMovesNothing) {
  DoorMemory memory(door_fix_options());
  ASSERT_FALSE(memory.pass({{0.0, 0.0}, 1.0, 0.0, 7.0}));
  const auto shift = memory.pass({{0.1, 0.1}, 1.0, 0.0, 7.0});  // no drift since: gain 0
  ASSERT_TRUE(shift);
  EXPECT_EQ(*shift, Point2(0.0, 0.0));
}

TEST(DoorMemory, APassageBetweenTwoKnownDoorsFixesNeither) {
  DoorMemory memory(door_fix_options());
  ASSERT_FALSE(memory.pass({{0.0, 0.0}, 1.0, 0.0, 0.0}));
  ASSERT_FALSE(memory.pass({{0.0, 1.0}, 1.0, 0.0, 5.0}));
  // 0.45 m from the first, 0.55 m from the second: the second is not twice as far.
  EXPECT_FALSE(memory.pass({{0.0, 0.45}, 1.0, 0.0, 50.0}));
  // 0.2 m from the first, 0.8 m from the second: the first.
  EXPECT_TRUE(memory.pass({{0.0, 0.2}, 1.0, 0.0, 50.0}));
  EXPECT_EQ(memory.doors().size(), 2u);  // neither passage was a new door
}

TEST(DoorMemory, AnotherWidthOrAxisOrAWideGapIsNoFix) {
  DoorMemory memory(door_fix_options());
  ASSERT_FALSE(memory.pass({{0.0, 0.0}, 0.9, 0.0, 0.0}));
  EXPECT_FALSE(memory.pass({{0.2, 0.0}, 1.25, 0.0, 50.0}));     // 0.35 m wider
  EXPECT_FALSE(memory.pass({{0.2, 0.0}, 0.9, kHalfPi, 50.0}));  // crossed at right angles
  EXPECT_FALSE(memory.pass({{0.2, 0.0}, 0.9, 0.9, 50.0}));      // 52° off the first axis
  EXPECT_TRUE(memory.pass({{0.2, 0.0}, 0.9, 0.7, 50.0}));       // 40° off: the same door
  // A 1.6 m gap neither fixes nor is remembered: its centre is placed too poorly.
  DoorMemory wide(door_fix_options());
  EXPECT_FALSE(wide.pass({{0.0, 0.0}, 1.6, 0.0, 0.0}));
  EXPECT_TRUE(wide.doors().empty());
}

TEST(DoorMemory, APassageBeyondTheRadiusIsANewDoor) {
  DoorMemory memory(door_fix_options());
  ASSERT_FALSE(memory.pass({{0.0, 0.0}, 1.0, 0.0, 0.0}));
  EXPECT_FALSE(memory.pass({{0.0, 0.85}, 1.0, 0.0, 50.0}));
  EXPECT_EQ(memory.doors().size(), 2u);
}

TEST(DoorMemory, APassageWithoutFiniteFiguresIsIgnored) {
  // A log's garbage must neither move the estimate nor become a door later passages match.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  DoorMemory memory(door_fix_options());
  EXPECT_FALSE(memory.pass({{nan, 0.0}, 1.0, 0.0, 0.0}));
  EXPECT_FALSE(memory.pass({{0.0, 0.0}, nan, 0.0, 0.0}));
  EXPECT_FALSE(memory.pass({{0.0, 0.0}, 1.0, nan, 0.0}));
  EXPECT_FALSE(memory.pass({{0.0, 0.0}, 1.0, 0.0, inf}));
  EXPECT_TRUE(memory.doors().empty());
  ASSERT_FALSE(memory.pass({{0.0, 0.0}, 1.0, 0.0, 0.0}));
  EXPECT_FALSE(memory.pass({{0.1, inf}, 1.0, 0.0, 10.0}));
  EXPECT_EQ(memory.doors().size(), 1u);
}

}  // namespace
}  // namespace cogmap::mapper
