// Walls met at a grazing angle (side_walls.h): a line through the echoes beside the body,
// carried on ahead, and the door crossing that stops where that line enters its lane.

#include "nav/side_walls.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "cogmap/mapper/seam/robot_geometry.h"
#include "nav/fake_grid_updater.h"
#include "nav/nav_constants.h"
#include "nav/nav_core.h"
#include "nav/nav_test_util.h"
#include "nav/steering.h"

namespace cogmap::mapper::nav {
namespace {

using testing::kHalfLength;
constexpr double kHalfWidth = 0.2525;  // ...0.505 m wide

/// The check as `controller.grazing_walls: true` turns it on.
SideWallOptions on() {
  SideWallOptions o;
  o.enabled = true;
  return o;
}

/// Points every 0.1 m along x in [x0, x1] on the line lateral = y0 + slope·x (body frame:
/// x ahead, y left), turned by `heading_rad` into the world-aligned offsets the field holds.
std::vector<ObstaclePoint> line_points(double y0, double slope, double x0, double x1,
                                       double heading_rad = 0.0) {
  std::vector<ObstaclePoint> out;
  const double c = std::cos(heading_rad), s = std::sin(heading_rad);
  for (double x = x0; x <= x1 + 1e-9; x += 0.1) {
    const double y = y0 + slope * x;
    out.push_back({Point2(c * x - s * y, s * x + c * y), 15.0f});
  }
  return out;
}

/// The body-frame lateral offset of `p` for a robot heading `heading_rad`.
Point2 body(const ObstaclePoint& p, double heading_rad) {
  const double c = std::cos(heading_rad), s = std::sin(heading_rad);
  return {c * p.offset_m.x() + s * p.offset_m.y(), -s * p.offset_m.x() + c * p.offset_m.y()};
}

TEST(SideWalls, AWallClosingInOnTheRightIsCarriedOnAheadOnItsLine) {
  // A wall on the right at 20° to the heading: 0.55 m out abeam, closing in ahead.
  const double slope = std::tan(20.0 * std::numbers::pi / 180.0);
  const auto echoes = line_points(-0.55, slope, -0.6, 0.3);
  const SideWallOptions o = on();
  const auto ahead = side_wall_points(echoes, 0.0, kHalfLength, kHalfWidth, o);
  ASSERT_FALSE(ahead.empty());
  double last_x = 0.3;
  for (const ObstaclePoint& p : ahead) {
    EXPECT_NEAR(p.offset_m.y(), -0.55 + slope * p.offset_m.x(), 1e-9);  // on the wall's line
    EXPECT_NEAR(p.offset_m.x() - last_x, o.step_m * std::cos(std::atan(slope)), 1e-9);
    last_x = p.offset_m.x();
  }
  EXPECT_LE(last_x, o.ahead_m);
  EXPECT_GT(last_x, o.ahead_m - o.step_m);
  // It enters the half-width + 5 cm lane at x = (0.55 - 0.3025) / tan 20° = 0.680 m.
  const double entry_x = (0.55 - kHalfWidth - o.lane_margin_m) / slope;
  const double lane = lane_clearance_m(ahead, 0.0, kHalfWidth + o.lane_margin_m, 2 * kHalfLength);
  EXPECT_GE(lane, entry_x - kHalfLength - 1e-9);
  EXPECT_LT(lane, entry_x - kHalfLength + o.step_m);
  // The echoes themselves lie beside the lane: the lane check alone sees nothing.
  EXPECT_EQ(lane_clearance_m(echoes, 0.0, kHalfWidth + o.lane_margin_m, 2 * kHalfLength), kInf);
}

TEST(SideWalls, TheSameWallOnTheLeftAndAtAnyHeading) {
  const double slope = std::tan(20.0 * std::numbers::pi / 180.0);
  const SideWallOptions o = on();
  const auto right =
      side_wall_points(line_points(-0.55, slope, -0.6, 0.3), 0.0, kHalfLength, kHalfWidth, o);
  const auto left =
      side_wall_points(line_points(0.55, -slope, -0.6, 0.3), 0.0, kHalfLength, kHalfWidth, o);
  ASSERT_EQ(left.size(), right.size());
  for (std::size_t i = 0; i < left.size(); ++i) {
    EXPECT_NEAR(left[i].offset_m.x(), right[i].offset_m.x(), 1e-9);
    EXPECT_NEAR(left[i].offset_m.y(), -right[i].offset_m.y(), 1e-9);
  }
  const double heading = 2.3;
  const auto turned = side_wall_points(line_points(-0.55, slope, -0.6, 0.3, heading), heading,
                                       kHalfLength, kHalfWidth, o);
  ASSERT_EQ(turned.size(), right.size());
  for (std::size_t i = 0; i < turned.size(); ++i) {
    const Point2 b = body(turned[i], heading);
    EXPECT_NEAR(b.x(), right[i].offset_m.x(), 1e-9);
    EXPECT_NEAR(b.y(), right[i].offset_m.y(), 1e-9);
  }
}

TEST(SideWalls, AParallelWallStaysBesideTheLane) {
  const auto ahead =
      side_wall_points(line_points(-0.5, 0.0, -0.6, 0.4), 0.0, kHalfLength, kHalfWidth, on());
  ASSERT_FALSE(ahead.empty());
  for (const ObstaclePoint& p : ahead) EXPECT_NEAR(p.offset_m.y(), -0.5, 1e-9);
  EXPECT_EQ(lane_clearance_m(ahead, 0.0, kHalfWidth + 0.05, 2 * kHalfLength), kInf);
}

TEST(SideWalls, NoLineWhereTheEchoesDoNotMakeOne) {
  const SideWallOptions o = on();
  // A wall across the way (a doorway's own wall, 40° off the heading and steeper): the front
  // transducers hear it.
  const double steep = std::tan(40.0 * std::numbers::pi / 180.0);
  EXPECT_TRUE(side_wall_points(line_points(-0.7, steep, -0.3, 0.4), 0.0, kHalfLength, kHalfWidth, o)
                  .empty());
  // Two echoes are no line; nor are three within 0.2 m.
  EXPECT_TRUE(
      side_wall_points(line_points(-0.5, 0.1, 0.0, 0.1), 0.0, kHalfLength, kHalfWidth, o).empty());
  EXPECT_TRUE(
      side_wall_points(line_points(-0.5, 0.1, 0.0, 0.2), 0.0, kHalfLength, kHalfWidth, o).empty());
  ASSERT_FALSE(
      side_wall_points(line_points(-0.5, 0.1, 0.0, 0.3), 0.0, kHalfLength, kHalfWidth, o).empty());
  // Scattered echoes (a chair's legs, clutter): residual beyond max_rms_m.
  const std::vector<ObstaclePoint> scattered = {{Point2(-0.4, -0.3), 1.0f},
                                                {Point2(-0.2, -0.7), 1.0f},
                                                {Point2(0.0, -0.3), 1.0f},
                                                {Point2(0.2, -0.7), 1.0f},
                                                {Point2(0.4, -0.3), 1.0f}};
  EXPECT_TRUE(side_wall_points(scattered, 0.0, kHalfLength, kHalfWidth, o).empty());
  // Echoes beyond reach_m of the side, or ahead of the body by more than reach_m, are not
  // fitted; reach 0 turns the check off, as does the default (enabled false).
  EXPECT_TRUE(
      side_wall_points(line_points(-0.8, 0.0, -0.6, 0.4), 0.0, kHalfLength, kHalfWidth, o).empty());
  EXPECT_TRUE(
      side_wall_points(line_points(-0.5, 0.0, 0.9, 1.3), 0.0, kHalfLength, kHalfWidth, o).empty());
  SideWallOptions no_reach = on();
  no_reach.reach_m = 0.0;
  EXPECT_TRUE(
      side_wall_points(line_points(-0.55, 0.36, -0.6, 0.3), 0.0, kHalfLength, kHalfWidth, no_reach)
          .empty());
  ASSERT_FALSE(
      side_wall_points(line_points(-0.55, 0.36, -0.6, 0.3), 0.0, kHalfLength, kHalfWidth, o)
          .empty());
  EXPECT_TRUE(side_wall_points(line_points(-0.55, 0.36, -0.6, 0.3), 0.0, kHalfLength, kHalfWidth,
                               SideWallOptions{})
                  .empty());  // the default: off
}

/// A robot at the origin facing +x whose room grid holds a wall on its right at 25° to the
/// heading, 0.45 m out abeam: beside the body it is clear of the lane, 0.32 m ahead of the
/// centre it is in it. No sonar has been heard, so the grid's cells count at any range.
struct GrazingWall {
  RobotGeometry robot = p2at_geometry();
  testing::FakeGridUpdater grid{-3.0, -3.0, 6.0, -1.0f};
  SensorFrame frame;
  NavInput input;

  GrazingWall() {
    const double slope = std::tan(25.0 * std::numbers::pi / 180.0);
    for (double x = -0.7; x <= 0.25; x += 0.05) grid.set(x, -0.45 + slope * x, 15.0f);
    input.frame = &frame;
    input.robot = &robot;
    input.grid = &grid;
  }
  VelocityCommand cross(const SideWallOptions& walls) {
    CoreOptions o;
    o.cross_side_walls = walls;
    NavCore core(o);
    core.sense(input);
    return core.drive_direct(input, 0.0, 0.3, NavMode::kDoorCross);
  }
};

TEST(SideWalls, TheCrossingStopsWhereAGrazingWallEntersItsLane) {
  GrazingWall w;
  const VelocityCommand blind = w.cross(SideWallOptions{});  // off, the default
  EXPECT_DOUBLE_EQ(blind.v_mps, 0.3);  // the lane ahead holds no echo: full crossing speed
  const VelocityCommand guarded = w.cross(on());
  EXPECT_EQ(guarded.v_mps, 0.0);  // the wall's line is in the lane at the bumper
  EXPECT_NE(guarded.w_radps, 0.0);
}

}  // namespace
}  // namespace cogmap::mapper::nav
