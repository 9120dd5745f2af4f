#include "nav/obstacle_memory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cogmap/mapper/nav/vfh.h"
#include "nav/fake_grid_updater.h"
#include "nav/nav_test_util.h"
#include "nav/obstacle_field.h"

namespace cogmap::mapper::nav {
namespace {

using testing::frame;

TEST(ObstacleMemory, PlacesEchoesOnTheTransducerAxisInTheWorld) {
  const RobotGeometry robot = p2at_geometry();
  ObstacleMemory memory{MemoryOptions{}};
  // Sonar 0 looks left (90°) from (0.147, 0.136); the robot faces north at (1, 2).
  memory.add_frame(frame(0.0, {{0, 1.0, true, 0.0}}), {1.0, 2.0, M_PI / 2}, robot);
  ASSERT_EQ(memory.hits().size(), 1u);
  EXPECT_NEAR(memory.hits()[0].world_m.x(), 1.0 - 1.136, 1e-9);
  EXPECT_NEAR(memory.hits()[0].world_m.y(), 2.0 + 0.147, 1e-9);
}

TEST(ObstacleMemory, SkipsInvalidReadingsAndForgetsOldEchoes) {
  const RobotGeometry robot = p2at_geometry();
  ObstacleMemory memory{MemoryOptions{}};  // keep 3 s, max range 3 m
  memory.add_frame(frame(0.0, {{3, 1.0, false, 0.0},
                               {3, std::numeric_limits<double>::quiet_NaN(), true, 0.0},
                               {3, 0.05, true, 0.0},
                               {3, 3.5, true, 0.0},
                               {99, 1.0, true, 0.0},
                               {4, 1.0, true, 0.0}}),
                   {}, robot);
  EXPECT_EQ(memory.hits().size(), 1u);
  memory.add_frame(frame(2.9, {}), {}, robot);
  EXPECT_EQ(memory.hits().size(), 1u);
  memory.add_frame(frame(3.0, {}), {}, robot);
  EXPECT_TRUE(memory.hits().empty());
}

TEST(ObstacleMemory, AFullMemoryForgetsItsOldestHitsFirst) {
  const RobotGeometry robot = p2at_geometry();
  MemoryOptions options;
  options.max_hits = 3;
  options.clear_half_angle_deg = 0.0;  // no clearing: only the bound removes hits
  ObstacleMemory memory{options};
  // Transducer 4 hears an echo at 1.0, 1.1, ... 1.4 m in five frames (robot at the origin).
  for (int i = 0; i < 5; ++i) {
    memory.add_frame(frame(0.1 * i, {{4, 1.0 + 0.1 * i, true, 0.0}}), {}, robot);
  }
  ASSERT_EQ(memory.hits().size(), 3u);
  // The newest three, oldest first: 1.2, 1.3 and 1.4 m from the transducer.
  const Point2 mount(robot.sonars[4].x_m, robot.sonars[4].y_m);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR((memory.hits()[static_cast<std::size_t>(k)].world_m - mount).norm(), 1.2 + 0.1 * k,
                1e-9);
  }
  // The contacts' three points into a full memory: the echoes make room.
  memory.add_contact({}, robot, 0.5, true);
  ASSERT_EQ(memory.hits().size(), 3u);
  for (const ObstacleMemory::Hit& h : memory.hits()) EXPECT_TRUE(h.contact);
}

TEST(ObstacleMemory, ContactsOutliveEchoes) {
  const RobotGeometry robot = p2at_geometry();
  ObstacleMemory memory{MemoryOptions{}};
  memory.add_contact({}, robot, 1.0, true);
  ASSERT_EQ(memory.hits().size(), 3u);
  EXPECT_NEAR(memory.hits()[1].world_m.x(), 0.313 + 0.05, 1e-9);
  memory.add_frame(frame(10.9, {}), {}, robot);
  EXPECT_EQ(memory.hits().size(), 3u);
  memory.add_frame(frame(11.0, {}), {}, robot);
  EXPECT_TRUE(memory.hits().empty());
}

TEST(ObstacleField, EchoesBlockEvenWithAnEmptyRoomGrid) {
  // Just after a doorway the new room grid knows nothing; the front sonars see a wall 0.8 m
  // ahead and VFH must block straight ahead anyway.
  const RobotGeometry robot = p2at_geometry();
  testing::FakeGridUpdater fresh{-5.0, -5.0, 10.0, 0.0f};
  ObstacleMemory memory{MemoryOptions{}};
  memory.add_frame(frame(0.0, {{3, 0.8, true, 0.0}, {4, 0.8, true, 0.0}}), {}, robot);
  ObstacleField field(VfhOptions{}, MemoryOptions{});
  field.build(Point2(0.0, 0.0), &fresh, memory);
  EXPECT_EQ(field.points().size(), 2u);
  Vfh vfh{VfhOptions{}};
  vfh.build(field.points());
  EXPECT_FALSE(vfh.blocked(0));  // one echo per cell: could be a spurious reading
  // The next cycle confirms both echoes: certainty 16 -> 15 per cell, now blocking.
  memory.add_frame(frame(0.1, {{3, 0.8, true, 0.1}, {4, 0.8, true, 0.1}}), {}, robot);
  field.build(Point2(0.0, 0.0), &fresh, memory);
  vfh.build(field.points());
  EXPECT_TRUE(vfh.blocked(0));
}

TEST(ObstacleField, GridAndMemoryMergeByMaximumNotSum) {
  const RobotGeometry robot = p2at_geometry();
  testing::FakeGridUpdater grid{-5.0, -5.0, 10.0, -1.0f};
  ObstacleMemory memory{MemoryOptions{}};
  // Sonar 3 on the axis at 10°: an echo of 1 m lands near (1.23, 0.20).
  memory.add_frame(frame(0.0, {{3, 1.0, true, 0.0}}), {}, robot);
  const Point2 hit = memory.hits()[0].world_m;
  grid.set(hit.x(), hit.y(), 12.0f);
  ObstacleField field(VfhOptions{}, MemoryOptions{});
  field.build(Point2(0.0, 0.0), &grid, memory);
  ASSERT_EQ(field.points().size(), 1u);
  EXPECT_FLOAT_EQ(field.points()[0].certainty, 12.0f);
  // Two echoes in the same cell add like HIMM increments (8 + 8, capped at 15).
  ObstacleMemory twice{MemoryOptions{}};
  twice.add_frame(frame(0.0, {{3, 1.0, true, 0.0}, {3, 1.0, true, 0.0}}), {}, robot);
  field.build(Point2(0.0, 0.0), nullptr, twice);
  ASSERT_EQ(field.points().size(), 1u);
  EXPECT_FLOAT_EQ(field.points()[0].certainty, 15.0f);
}

// Near the robot the grid only confirms recent echoes (its beam smear closes doorways); far
// cells and a grid without any live sonar still count.
TEST(ObstacleField, NearGridCellsCountOnlyWhereARecentEchoConfirmsThem) {
  const RobotGeometry robot = p2at_geometry();
  testing::FakeGridUpdater grid{-5.0, -5.0, 10.0, -1.0f};
  grid.set(0.85, -0.55, 15.0f);  // 1.0 m away: near, no echo there
  grid.set(2.05, -0.55, 15.0f);  // 2.1 m away: far
  ObstacleMemory memory{MemoryOptions{}};
  memory.add_frame(frame(0.0, {{3, 1.0, true, 0.0}}), {}, robot);  // echo near (1.23, 0.20)
  ObstacleField field(VfhOptions{}, MemoryOptions{});
  field.build(Point2(0.0, 0.0), &grid, memory);
  ASSERT_EQ(field.points().size(), 2u);  // the far cell and the echo
  for (const ObstaclePoint& p : field.points()) EXPECT_GT(p.offset_m.norm(), 1.2);

  ObstacleMemory silent{MemoryOptions{}};
  field.build(Point2(0.0, 0.0), &grid, silent);
  EXPECT_EQ(field.points().size(), 2u);  // both grid cells

  VfhOptions off;
  off.grid_min_range_m = 0.0;
  ObstacleField all(off, MemoryOptions{});
  all.build(Point2(0.0, 0.0), &grid, memory);
  EXPECT_EQ(all.points().size(), 3u);
}

}  // namespace
}  // namespace cogmap::mapper::nav
