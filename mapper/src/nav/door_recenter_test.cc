// DoorPassage's recentering while crossing: the locked centre moves toward the middle of the
// jambs sensed beside the door line by recenter_gain of the offset per step. The door is a
// 1 m gap in a wall along x = 2 with its true middle at (2, 0); the passage is locked 0.2 m
// off, on (2, 0.2), and the robot stands still on the locked axis 0.2 m before the opening.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

#include "nav/door_passage.h"

namespace cogmap::mapper::nav {
namespace {

const Pose2 kRobot{1.8, 0.2, 0.0};
const Point2 kGoal{4.0, 0.0};

/// Obstacle points (offsets from the robot) of one jamb: the wall from the door edge at
/// y = edge_y outward (sign of `outward`), 0.7 m of it, 0.12 m thick (x = 1.94, 2.0, 2.06).
void add_jamb(std::vector<ObstaclePoint>& out, double edge_y, double outward) {
  for (int k = 0; k <= 7; ++k) {
    for (const double x : {1.94, 2.0, 2.06}) {
      out.push_back({Point2(x, edge_y + outward * 0.1 * k) - kRobot.translation(), 15.0f});
    }
  }
}

/// A passage locked on (2, 0.2) and already crossing: the first step sees nothing (so the
/// align phase's re-detection cannot move the centre) and switches to crossing because the
/// robot is less than 0.4 m before the opening.
DoorPassage crossing(const DoorOptions& options) {
  DoorPassage door(options);
  door.start(Opening{Point2(2.0, 0.2), Point2(1.0, 0.0), 1.0}, 0.0);
  const auto aim = door.step({}, kRobot, kGoal, 0.0);
  EXPECT_TRUE(aim.has_value());
  EXPECT_EQ(door.mode(), NavMode::kDoorCross);
  EXPECT_EQ(door.opening().center_m, Point2(2.0, 0.2));
  return door;
}

TEST(DoorRecenter, TheLockedCentreDecaysGeometricallyToTheMiddleOfTheJambs) {
  const DoorOptions options;  // recenter_gain 0.2
  DoorPassage door = crossing(options);
  std::vector<ObstaclePoint> points;
  add_jamb(points, 0.5, 1.0);
  add_jamb(points, -0.5, -1.0);
  // An echo inside the gap but 0.5 m beyond the door line, outside recenter_band_m (0.3 m).
  points.push_back({Point2(2.5, 0.25) - kRobot.translation(), 15.0f});

  // Step 1: jambs at +0.3 and -0.7 from the locked centre, offset -0.2: moved by 0.2·-0.2.
  auto aim = door.step(points, kRobot, kGoal, 0.1);
  ASSERT_TRUE(aim.has_value());
  EXPECT_NEAR(door.opening().center_m.y(), 0.16, 1e-12);
  EXPECT_DOUBLE_EQ(door.opening().center_m.x(), 2.0);
  EXPECT_NEAR(aim->y(), 0.16, 1e-12);  // the pursuit point follows the new centre
  // Each step removes recenter_gain of what is left: 0.2·0.8^n.
  for (int n = 2; n <= 20; ++n) {
    aim = door.step(points, kRobot, kGoal, 0.1 * n);
    ASSERT_TRUE(aim.has_value()) << n;
    ASSERT_EQ(door.mode(), NavMode::kDoorCross) << n;
    EXPECT_NEAR(door.opening().center_m.y(), 0.2 * std::pow(0.8, n), 1e-12) << n;
  }
  EXPECT_NEAR(door.opening().center_m.y(), 0.0, 0.003);  // 0.2·0.8^20 = 0.0023
  EXPECT_DOUBLE_EQ(door.opening().center_m.x(), 2.0);
  EXPECT_EQ(door.opening().normal, Point2(1.0, 0.0));
}

TEST(DoorRecenter, OneJambAloneDoesNotMoveTheCentre) {
  for (const double side : {1.0, -1.0}) {
    DoorPassage door = crossing(DoorOptions{});
    std::vector<ObstaclePoint> points;
    add_jamb(points, 0.5 * side, side);
    for (int n = 1; n <= 10; ++n) {
      ASSERT_TRUE(door.step(points, kRobot, kGoal, 0.1 * n).has_value()) << side;
    }
    EXPECT_EQ(door.opening().center_m, Point2(2.0, 0.2)) << side;
  }
}

TEST(DoorRecenter, AGapNarrowerThanMinWidthDoesNotMoveTheCentre) {
  DoorPassage door = crossing(DoorOptions{});
  std::vector<ObstaclePoint> points;
  add_jamb(points, 0.3, 1.0);  // 0.6 m < min_width_m 0.7 m
  add_jamb(points, -0.3, -1.0);
  for (int n = 1; n <= 10; ++n) ASSERT_TRUE(door.step(points, kRobot, kGoal, 0.1 * n));
  EXPECT_EQ(door.opening().center_m, Point2(2.0, 0.2));
}

TEST(DoorRecenter, ZeroGainDisablesIt) {
  DoorOptions off;
  off.recenter_gain = 0.0;
  DoorPassage door = crossing(off);
  std::vector<ObstaclePoint> points;
  add_jamb(points, 0.5, 1.0);
  add_jamb(points, -0.5, -1.0);
  for (int n = 1; n <= 10; ++n) ASSERT_TRUE(door.step(points, kRobot, kGoal, 0.1 * n));
  EXPECT_EQ(door.opening().center_m, Point2(2.0, 0.2));
}

}  // namespace
}  // namespace cogmap::mapper::nav
