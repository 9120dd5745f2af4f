#include "nav/explore_reopen.h"

#include <gtest/gtest.h>

#include <numbers>
#include <vector>

#include "nav/fake_grid_updater.h"

namespace cogmap::mapper::nav {
namespace {

using testing::FakeGridUpdater;

// One transducer at the robot's centre looking ahead; a body that marks no cell.
RobotGeometry one_sonar_robot() {
  RobotGeometry robot;
  robot.sonars = {{0.0, 0.0, 0.0}};
  robot.sonar_min_range_m = 0.1;
  robot.sonar_max_range_m = 5.0;
  robot.sonar_beam_width_rad = 30.0 * std::numbers::pi / 180.0;
  robot.width_m = 0.0;
  return robot;
}

// An explore map with cell centres on multiples of 0.2 m and one obstacle cell, centred on
// (1.0, 0.0): an echo at 1 m straight ahead marks the axis cell alone (its ±6° arc spans
// ±0.1 m there), and the cells before it swept free.
ExploreMap map_with_one_echo() {
  ExploreMap map;
  map.mark_body(Point2(0.1, 0.1), 0.0);
  SensorFrame frame;
  frame.sonar = {{0, 1.0, true, 0.0}};
  map.add_frame(frame, Pose2{}, one_sonar_robot());
  return map;
}

// The four 0.1 m room-grid cells inside the explore cell (0.9..1.1, -0.1..0.1).
constexpr double kX0 = 0.9, kY0 = -0.1, kX1 = 1.1, kY1 = 0.1;

class ExploreReopen : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(map_.occupied(echo_cell_)); }
  ExploreMap map_ = map_with_one_echo();
  ExploreMap::Cell echo_cell_ = map_.cell_of(Point2(1.0, 0.0));
  FakeGridUpdater room_{-2.0, -2.0, 4.0, 0.0f};  // unexplored everywhere
};

TEST_F(ExploreReopen, ReopensACellTheRoomGridSweptAndNeverEchoed) {
  room_.fill_box(kX0, kY0, kX1, kY1, -1.0f);
  EXPECT_EQ(reopen_swept_cells(map_, room_, 1.0), 1u);
  EXPECT_FALSE(map_.occupied(echo_cell_));
  EXPECT_EQ(map_.hit_weight(echo_cell_), 0.0f);
  EXPECT_TRUE(map_.seen(echo_cell_));  // still seen: it becomes free, not unknown
}

TEST_F(ExploreReopen, OneSweptRoomCellIsEnoughWhileTheOthersAreUnexplored) {
  room_.set(1.05, 0.05, -1.0f);
  EXPECT_EQ(reopen_swept_cells(map_, room_, 1.0), 1u);
}

TEST_F(ExploreReopen, TheRobotsOwnPathCountsAsSwept) {
  room_.set(0.95, -0.05, kRobotPathValue);
  EXPECT_EQ(reopen_swept_cells(map_, room_, 1.0), 1u);
}

TEST_F(ExploreReopen, KeepsACellWithAnEchoOnAnAxis) {
  room_.fill_box(kX0, kY0, kX1, kY1, -1.0f);
  room_.set(1.05, -0.05, 3.0f);  // one axis echo (+2.5, +0.5)
  EXPECT_EQ(reopen_swept_cells(map_, room_, 1.0), 0u);
  EXPECT_TRUE(map_.occupied(echo_cell_));
}

TEST_F(ExploreReopen, TheThresholdIsTheFirstValueThatCountsAsAnEcho) {
  room_.fill_box(kX0, kY0, kX1, kY1, -1.0f);
  room_.set(1.05, -0.05, 1.0f);
  EXPECT_EQ(reopen_swept_cells(map_, room_, 1.0), 0u);
  room_.set(1.05, -0.05, 0.5f);  // a jamb's neighbour increment: no echo of its own
  EXPECT_EQ(reopen_swept_cells(map_, room_, 1.0), 1u);
}

TEST_F(ExploreReopen, KeepsACellTheRoomGridNeverSwept) {
  EXPECT_EQ(reopen_swept_cells(map_, room_, 1.0), 0u);
  EXPECT_TRUE(map_.occupied(echo_cell_));
}

TEST_F(ExploreReopen, KeepsCellsTheRoomGridDoesNotHold) {
  FakeGridUpdater elsewhere{5.0, 5.0, 4.0, -1.0f};  // swept, but 4 m away
  EXPECT_EQ(reopen_swept_cells(map_, elsewhere, 1.0), 0u);
  // A room grid ending inside the explore cell decides nothing either.
  FakeGridUpdater partial{1.0, -2.0, 4.0, -1.0f};
  EXPECT_EQ(reopen_swept_cells(map_, partial, 1.0), 0u);
  EXPECT_TRUE(map_.occupied(echo_cell_));
}

}  // namespace
}  // namespace cogmap::mapper::nav
