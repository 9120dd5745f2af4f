#include "cogmap/mapper/nav/vfh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cogmap/test_support/angles.h"
#include "nav/fake_grid_updater.h"
#include "nav/obstacle_field.h"
#include "nav/obstacle_memory.h"

namespace cogmap::mapper::nav {
namespace {

// A wall across the x axis at x = 1.05 (one column of cells), certainty 15, with a gap between
// y = -gap/2 and +gap/2 (cell edges), like a doorway in front of a robot at the origin.
constexpr double kVfhWallX = 1.05;
testing::FakeGridUpdater doorway(double gap_m) {
  testing::FakeGridUpdater grid(-5.0, -5.0, 10.0, -1.0f);
  grid.fill_box(kVfhWallX - 0.03, 0.5 * gap_m + 0.02, kVfhWallX + 0.03, 2.5, 15.0f);
  grid.fill_box(kVfhWallX - 0.03, -2.5, kVfhWallX + 0.03, -0.5 * gap_m - 0.02, 15.0f);
  return grid;
}

VfhChoice choose(const GridUpdater& grid, const Point2& robot, double target_rad,
                 Vfh* out = nullptr) {
  VfhOptions options;
  ObstacleMemory memory{MemoryOptions{}};
  ObstacleField field(options, MemoryOptions{});
  field.build(robot, &grid, memory);
  Vfh vfh(options);
  vfh.build(field.points());
  if (out) *out = vfh;
  return vfh.select(target_rad);
}

TEST(Vfh, SectorsAreCentredOnMultiplesOfTheSweepIncrement) {
  Vfh vfh{VfhOptions{}};
  EXPECT_EQ(vfh.sector_count(), 72);
  EXPECT_EQ(vfh.sector_of(0.0), 0);
  EXPECT_EQ(vfh.sector_of(2.4 * kDeg), 0);
  EXPECT_EQ(vfh.sector_of(-2.4 * kDeg), 0);
  EXPECT_EQ(vfh.sector_of(2.6 * kDeg), 1);
  EXPECT_EQ(vfh.sector_of(-2.6 * kDeg), 71);
  EXPECT_EQ(vfh.sector_of(90.0 * kDeg + 2.0 * std::numbers::pi), 18);
  EXPECT_NEAR(vfh.sector_center_rad(71), -5.0 * kDeg, 1e-12);
}

// sector_of folds any angle the way std::fmod would: the reference below is the plain
// definition, checked on both sides of every multiple of 2π from -6π to 8π and between them.
TEST(Vfh, SectorOfFoldsAnyAngleLikeFmod) {
  const Vfh vfh{VfhOptions{}};
  const double two_pi = 2.0 * std::numbers::pi;
  const double sector = two_pi / vfh.sector_count();
  const auto reference = [&](double angle_rad) {
    double a = std::fmod(angle_rad + 0.5 * sector, two_pi);
    if (a < 0.0) a += two_pi;
    const int k = static_cast<int>(std::floor(a / sector)) % vfh.sector_count();
    return k < 0 ? k + vfh.sector_count() : k;
  };
  std::vector<double> angles;
  for (int m = -3; m <= 4; ++m) {
    const double edge = m * two_pi - 0.5 * sector;  // where the fold happens
    for (const double a : {edge, m * two_pi, m * two_pi + 1e-9}) {
      angles.push_back(a);
      angles.push_back(std::nextafter(a, -1e9));
      angles.push_back(std::nextafter(a, 1e9));
    }
  }
  for (int i = 0; i <= 20000; ++i) angles.push_back(-3.0 * two_pi + i * (7.0 * two_pi / 20000));
  for (const double a : angles) EXPECT_EQ(vfh.sector_of(a), reference(a)) << "angle " << a;
}

TEST(Vfh, CloserObstaclesWeighMore) {
  Vfh vfh{VfhOptions{}};
  EXPECT_GT(vfh.kappa_at(0.5), vfh.kappa_at(2.0));
  EXPECT_DOUBLE_EQ(vfh.kappa_at(2.5), 0.0);
  vfh.build({{Point2(0.5, 0.0), 10.0f}});
  const double near = vfh.density()[0];
  vfh.build({{Point2(2.0, 0.0), 10.0f}});
  EXPECT_DOUBLE_EQ(near, 100.0 * (1.0 - 0.5 / 2.5));  // Eq. 2.16: c² κ(d)
  EXPECT_LT(vfh.density()[0], near);
}

TEST(Vfh, ObstacleAheadBlocksTheSectorsAroundZeroAndIsAvoided) {
  Vfh vfh{VfhOptions{}};
  vfh.build({{Point2(1.0, 0.0), 15.0f}});
  // Enlarged by asin(0.33 / 1.0) = 19.3°: sectors -4..4 (-20°..20°) blocked, 25° free.
  for (int k = -4; k <= 4; ++k) EXPECT_TRUE(vfh.blocked(k)) << k;
  EXPECT_FALSE(vfh.blocked(5));
  EXPECT_FALSE(vfh.blocked(-5));
  EXPECT_FALSE(vfh.blocked(18));
  const VfhChoice choice = vfh.select(0.0);
  ASSERT_TRUE(choice.found);
  EXPECT_GT(std::abs(choice.direction_rad), std::asin(0.33));
  EXPECT_LT(std::abs(choice.direction_rad), 60.0 * kDeg);
}

TEST(Vfh, FreeTargetInAWideValleyIsKeptExactly) {
  Vfh vfh{VfhOptions{}};
  vfh.build({{Point2(-1.0, 0.0), 15.0f}});  // behind the robot
  const VfhChoice choice = vfh.select(12.3 * kDeg);
  ASSERT_TRUE(choice.found);
  EXPECT_DOUBLE_EQ(choice.direction_rad, 12.3 * kDeg);
}

TEST(Vfh, EverySectorBlockedFindsNothing) {
  Vfh vfh{VfhOptions{}};
  vfh.build({{Point2(0.2, 0.0), 15.0f}, {Point2(-0.2, 0.0), 15.0f}});  // inside r: half planes
  EXPECT_FALSE(vfh.select(0.0).found);
}

TEST(Vfh, HysteresisKeepsAWeaklyOccupiedSectorBlocked) {
  VfhOptions options;
  options.threshold = 100.0;
  Vfh vfh(options);
  vfh.build({{Point2(1.0, 0.0), 15.0f}});  // 225·0.6 = 135 > τ_high
  EXPECT_TRUE(vfh.blocked(0));
  vfh.build({{Point2(1.0, 0.0), 10.0f}});  // 100·0.6 = 60: between τ_low and τ_high
  EXPECT_TRUE(vfh.blocked(0));
  vfh.build({{Point2(1.0, 0.0), 5.0f}});  // 15 < τ_low = 50
  EXPECT_FALSE(vfh.blocked(0));
  vfh.build({{Point2(1.0, 0.0), 10.0f}});
  EXPECT_FALSE(vfh.blocked(0));
}

TEST(Vfh, OneMetreDoorwayIsPassableWithTheTargetBeyond) {
  const auto grid = doorway(1.0);
  const VfhChoice choice = choose(grid, Point2(0.0, 0.0), 0.0);
  ASSERT_TRUE(choice.found);
  // The line along the chosen direction crosses the wall between the door posts with the
  // robot's half-width (0.2525 m) to spare.
  const double y_at_wall = kVfhWallX * std::tan(choice.direction_rad);
  EXPECT_LT(std::abs(y_at_wall), 0.5 - 0.2525);
}

TEST(Vfh, OneMetreDoorwayIsPassableFromOffCentreAndOblique) {
  const auto grid = doorway(1.0);
  // 20 cm off the door's axis, the target 3 m beyond and slightly to the left.
  const Point2 robot(0.0, 0.2);
  const double target = std::atan2(0.3 - 0.2, 3.0);
  const VfhChoice choice = choose(grid, robot, target);
  ASSERT_TRUE(choice.found);
  const double y_at_wall = robot.y() + kVfhWallX * std::tan(choice.direction_rad);
  EXPECT_LT(std::abs(y_at_wall), 0.5 - 0.2525);
}

TEST(Vfh, NinetyCentimetreDoorwayIsPassable) {
  const auto grid = doorway(0.9);
  const VfhChoice choice = choose(grid, Point2(0.0, 0.0), 0.0);
  ASSERT_TRUE(choice.found);
  EXPECT_LT(std::abs(kVfhWallX * std::tan(choice.direction_rad)), 0.45 - 0.2525);
}

TEST(Vfh, FortyCentimetreGapIsNotPassable) {
  const auto grid = doorway(0.4);
  Vfh vfh{VfhOptions{}};
  const VfhChoice choice = choose(grid, Point2(0.0, 0.0), 0.0, &vfh);
  EXPECT_TRUE(vfh.blocked(0));
  EXPECT_TRUE(vfh.blocked(-1));
  EXPECT_TRUE(vfh.blocked(1));
  ASSERT_TRUE(choice.found);  // the wall ends inside the window: it may go around
  const double y_at_wall = kVfhWallX * std::tan(choice.direction_rad);
  EXPECT_TRUE(std::abs(choice.direction_rad) >= 0.5 * std::numbers::pi ||
              std::abs(y_at_wall) > 0.2 + 0.2525)
      << choice.direction_rad / kDeg;
}

TEST(Vfh, FreestSectorPrefersTheGivenDirectionAmongEquals) {
  Vfh vfh{VfhOptions{}};
  vfh.build({{Point2(1.0, 0.0), 15.0f}});
  EXPECT_EQ(vfh.freest_sector(90.0 * kDeg), 18);
  const int k = vfh.freest_sector(0.0);
  EXPECT_FALSE(vfh.blocked(k));
  EXPECT_DOUBLE_EQ(vfh.smoothed()[k], 0.0);
  EXPECT_LE(std::abs(vfh.sector_center_rad(k)), 35.0 * kDeg);
}

}  // namespace
}  // namespace cogmap::mapper::nav

namespace cogmap::mapper::nav {
namespace {

// A wall 0.8 m ahead across the whole view, the target straight through it: the valleys lie
// left and right of the wall, and the choice goes round it on one side.
std::vector<ObstaclePoint> long_wall_ahead() {
  std::vector<ObstaclePoint> pts;
  for (int i = -30; i <= 30; ++i) pts.push_back({Point2(0.8, 0.1 * i), 15.0f});
  return pts;
}

TEST(VfhDetourSide, KeepsItsSideUntilTheOtherIsMuchCheaper) {
  Vfh vfh{VfhOptions{}};
  vfh.build(long_wall_ahead());
  const double target = 5.0 * kDeg;  // slightly left: without memory the left side wins
  const VfhChoice fresh = vfh.select(target, target);
  ASSERT_TRUE(fresh.found);
  EXPECT_GT(fresh.direction_rad, 0.5);
  // Last cycle went round on the right: 10° of asymmetry is not worth a 180° turn.
  const VfhChoice right = vfh.select(target, target, -1.6);
  ASSERT_TRUE(right.found);
  EXPECT_LT(right.direction_rad, -0.5);
  // 40° left: the left side is now 80° (1.4 rad) cheaper, more than the 1 rad switch.
  const VfhChoice far_left = vfh.select(40.0 * kDeg, 40.0 * kDeg, -1.6);
  ASSERT_TRUE(far_left.found);
  EXPECT_GT(far_left.direction_rad, 0.5);
  // The option off: the memoryless choice of the thesis.
  VfhOptions off;
  off.side_switch_rad = 0.0;
  Vfh plain{off};
  plain.build(long_wall_ahead());
  EXPECT_GT(plain.select(target, target, -1.6).direction_rad, 0.5);
  // Not a detour (the previous choice was near the target): no side to keep.
  EXPECT_DOUBLE_EQ(vfh.side_switch_cost(-1.6, target, 0.1), 0.0);
  EXPECT_DOUBLE_EQ(vfh.side_switch_cost(-1.6, target, 1.6), VfhOptions{}.side_switch_rad);
  EXPECT_DOUBLE_EQ(vfh.side_switch_cost(-1.6, target, -1.2), 0.0);
}

}  // namespace
}  // namespace cogmap::mapper::nav
