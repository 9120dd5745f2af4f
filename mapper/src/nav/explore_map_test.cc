#include "nav/explore_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace cogmap::mapper {
namespace {

// The suite shares the class's name, so the class is `Map` here.
using Map = nav::ExploreMap;
using nav::ExploreMapOptions;

// A robot with one transducer at its centre looking straight ahead and a second one 0.2 m
// ahead looking left; its body (0.2 m wide) covers only the cell it stands on.
RobotGeometry test_robot() {
  RobotGeometry robot;
  robot.sonars = {{0.0, 0.0, 0.0}, {0.2, 0.0, std::numbers::pi / 2}};
  robot.sonar_min_range_m = 0.1;
  robot.sonar_max_range_m = 5.0;
  robot.sonar_beam_width_rad = 30.0 * std::numbers::pi / 180.0;
  robot.width_m = 0.2;
  return robot;
}

SensorFrame frame(std::vector<SonarReading> sonar) {
  SensorFrame f;
  f.sonar = std::move(sonar);
  return f;
}

SonarReading echo_ahead(double range_m) { return {0, range_m, true, 0.0}; }
SonarReading silence() { return {0, 5.0, false, 0.0}; }

// A map whose cell centres lie on multiples of 0.2 m (the first growth puts cell (0, 0)'s
// corner 8 m before the first box; a zero-radius body at (0.1, 0.1) marks no cell), so every
// point named below is a cell centre, 0.1 m from any cell border.
Map pinned_map(const ExploreMapOptions& options = {}) {
  Map map(options);
  map.mark_body(Point2(0.1, 0.1), 0.0);
  return map;
}

class ExploreMap : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(map_.seen_count(), 0u);
    ASSERT_NEAR((map_.center_of(cell({0.0, 0.0})) - Point2(0.0, 0.0)).norm(), 0.0, 1e-9);
  }
  Map::Cell cell(Point2 p) const { return map_.cell_of(p); }
  bool seen(double x, double y) const { return map_.seen(cell({x, y})); }
  bool occupied(double x, double y) const { return map_.occupied(cell({x, y})); }
  float hits(double x, double y) const { return map_.hit_weight(cell({x, y})); }
  float misses(double x, double y) const { return map_.miss_weight(cell({x, y})); }
  float total_hits() const {
    float sum = 0.0f;
    for (int y = 0; y < map_.height(); ++y) {
      for (int x = 0; x < map_.width(); ++x) sum += map_.hit_weight({x, y});
    }
    return sum;
  }
  void ping(std::vector<SonarReading> sonar, const Pose2& pose = {}) {
    map_.add_frame(frame(std::move(sonar)), pose, robot_);
  }

  RobotGeometry robot_ = test_robot();
  Map map_ = pinned_map();
};

TEST_F(ExploreMap, EchoHitsTheAxisCellAndSweepsTheConeBeforeIt) {
  ping({echo_ahead(1.0)});
  // The echo's cell: (weight_range_m / 1.0)² = 1, seen (1.0 <= wall_sense_m), an obstacle.
  EXPECT_FLOAT_EQ(hits(1.0, 0.0), 1.0f);
  EXPECT_FLOAT_EQ(misses(1.0, 0.0), 0.0f);
  EXPECT_TRUE(seen(1.0, 0.0));
  EXPECT_TRUE(occupied(1.0, 0.0));
  // The arc is only ±6° wide at 1 m (±0.105 m): the cells beside it are untouched.
  EXPECT_FLOAT_EQ(hits(1.0, 0.2), 0.0f);
  EXPECT_FLOAT_EQ(hits(1.0, -0.2), 0.0f);
  EXPECT_FALSE(seen(1.0, 0.2));
  // Before the echo: 0.4 m weighs (1 / 0.4)² = 6.25, capped at max_weight 4; 0.6 m weighs
  // (1 / 0.6)², under the cap.
  EXPECT_FLOAT_EQ(misses(0.4, 0.0), 4.0f);
  EXPECT_NEAR(misses(0.6, 0.0), 1.0 / 0.36, 1e-5);
  EXPECT_TRUE(seen(0.4, 0.0));
  EXPECT_TRUE(seen(0.6, 0.0));
  EXPECT_FLOAT_EQ(hits(0.6, 0.0), 0.0f);
  EXPECT_FALSE(occupied(0.6, 0.0));
  // Seen, free and next to unseen cells: a frontier; the echo's cell is not (an obstacle).
  EXPECT_TRUE(map_.frontier(cell({0.6, 0.0})));
  EXPECT_FALSE(map_.frontier(cell({1.0, 0.0})));
  // Outside the ±12° core: 45° (0.57 m away) and 18° (0.63 m away) off the axis.
  EXPECT_FALSE(seen(0.4, 0.4));
  EXPECT_FLOAT_EQ(misses(0.4, 0.4), 0.0f);
  EXPECT_FALSE(seen(0.6, 0.2));
  EXPECT_FALSE(seen(0.6, -0.2));
  // Nothing behind the transducer.
  EXPECT_FALSE(seen(-0.4, 0.0));
}

TEST_F(ExploreMap, MountAndPoseAreApplied) {
  // Facing +y, sonar 1 (0.2 m ahead, looking left) sits at (0, 0.2) and looks along -x.
  ping({{1, 1.0, true, 0.0}}, {0.0, 0.0, std::numbers::pi / 2});
  EXPECT_FLOAT_EQ(hits(-1.0, 0.2), 1.0f);
  EXPECT_TRUE(occupied(-1.0, 0.2));
  EXPECT_TRUE(seen(-0.4, 0.2));
  EXPECT_FLOAT_EQ(total_hits(), 1.0f);
  EXPECT_FALSE(seen(0.4, 0.2));
}

TEST_F(ExploreMap, EchoesOutweighingTheFreeSweepsMakeAnObstacle) {
  // Three silent pings sweep the cell at 1.0 m free: 3 × (1 / 1.0)².
  for (int i = 0; i < 3; ++i) ping({silence()});
  ASSERT_FLOAT_EQ(misses(1.0, 0.0), 3.0f);
  ASSERT_FLOAT_EQ(hits(1.0, 0.0), 0.0f);
  ping({echo_ahead(1.0)});
  EXPECT_FLOAT_EQ(hits(1.0, 0.0), 1.0f);
  EXPECT_FALSE(occupied(1.0, 0.0));  // 1 < occupied_ratio 0.5 × 3
  ping({echo_ahead(1.0)});
  EXPECT_FLOAT_EQ(hits(1.0, 0.0), 2.0f);
  EXPECT_FLOAT_EQ(misses(1.0, 0.0), 3.0f);
  EXPECT_TRUE(occupied(1.0, 0.0));  // 2 >= 1.5 and >= occupied_min_weight
}

TEST_F(ExploreMap, FarEchoesNeedTwoToReachTheMinimumWeight) {
  ping({echo_ahead(2.0)});
  EXPECT_FLOAT_EQ(hits(2.0, 0.0), 0.25f);  // (1 / 2)²
  EXPECT_FALSE(occupied(2.0, 0.0));        // < occupied_min_weight 0.5, with no misses
  ping({echo_ahead(2.0)});
  EXPECT_FLOAT_EQ(hits(2.0, 0.0), 0.5f);
  EXPECT_TRUE(occupied(2.0, 0.0));
}

TEST_F(ExploreMap, FarEchoIsHitButNotSeenWhileTheFloorBeforeItIs) {
  ping({echo_ahead(2.0)});
  // At 2 m the ±6° arc spans ±0.21 m: three cells, each (1 / 2)², none seen (> wall_sense_m).
  for (double y : {-0.2, 0.0, 0.2}) {
    EXPECT_FLOAT_EQ(hits(2.0, y), 0.25f) << y;
    EXPECT_FALSE(seen(2.0, y)) << y;
  }
  EXPECT_FLOAT_EQ(hits(2.0, 0.4), 0.0f);
  EXPECT_FLOAT_EQ(total_hits(), 0.75f);
  // Free up to the echo less free_margin_m (1.8 m), seen within free_sense_m.
  EXPECT_TRUE(seen(1.4, 0.0));
  EXPECT_TRUE(seen(1.6, 0.0));
  EXPECT_NEAR(misses(1.6, 0.0), 1.0 / (1.6 * 1.6), 1e-5);
  EXPECT_FLOAT_EQ(hits(1.6, 0.0), 0.0f);
  // The last free_margin_m before the echo is left alone: (1.8, 0.2) is 1.81 m away.
  EXPECT_FALSE(seen(1.8, 0.2));
  EXPECT_FLOAT_EQ(misses(1.8, 0.2), 0.0f);
}

TEST_F(ExploreMap, WallSenseLimitsWhichEchoesSeeTheirCell) {
  ping({echo_ahead(1.2)});
  EXPECT_TRUE(seen(1.2, 0.0));  // 1.2 <= wall_sense_m 1.3
  Map far = pinned_map();
  far.add_frame(frame({echo_ahead(1.4)}), {}, robot_);
  const Map::Cell c = far.cell_of({1.4, 0.0});
  EXPECT_NEAR(far.hit_weight(c), 1.0 / (1.4 * 1.4), 1e-5);
  EXPECT_FALSE(far.seen(c));  // 1.4 > 1.3
}

TEST_F(ExploreMap, EchoBeyondOccupancyRangeMarksNoHit) {
  ping({echo_ahead(3.4)});  // > occupancy_max_range_m 3.0: swept free up to free_sense_m only
  EXPECT_FLOAT_EQ(total_hits(), 0.0f);
  EXPECT_TRUE(seen(2.4, 0.0));
  EXPECT_FALSE(seen(2.6, 0.0));
  EXPECT_FLOAT_EQ(misses(3.0, 0.0), 0.0f);
  EXPECT_FALSE(seen(3.4, 0.0));
}

TEST_F(ExploreMap, SilentPingSweepsFreeOnlyToNoEchoFree) {
  ping({silence()});
  EXPECT_TRUE(seen(1.4, 0.0));
  EXPECT_NEAR(misses(1.4, 0.0), 1.0 / (1.4 * 1.4), 1e-5);
  EXPECT_TRUE(seen(1.0, 0.2));   // 11.3° off the axis: inside the ±12° core
  EXPECT_FALSE(seen(0.8, 0.2));  // 14.0°: inside the 30° beam, outside the core
  EXPECT_FALSE(seen(1.6, 0.0));  // beyond no_echo_free_m 1.5
  EXPECT_FALSE(seen(2.0, 0.0));
  EXPECT_FLOAT_EQ(misses(1.6, 0.0), 0.0f);
  EXPECT_FLOAT_EQ(total_hits(), 0.0f);
  // The core's cells within 1.5 m: one per column at x = 0.2 .. 0.8, three at 1.0 .. 1.4;
  // plus the body's cell.
  EXPECT_EQ(map_.seen_count(), 4u + 9u + 1u);
}

TEST_F(ExploreMap, ObstacleHidesWhatLiesBehindIt) {
  ping({echo_ahead(1.0)});
  ASSERT_TRUE(occupied(1.0, 0.0));
  const float before = misses(0.6, 0.0);
  ping({echo_ahead(2.2)});
  EXPECT_FALSE(seen(1.6, 0.0));  // behind the obstacle at 1.0 m
  EXPECT_FLOAT_EQ(misses(1.6, 0.0), 0.0f);
  EXPECT_FALSE(seen(1.4, 0.0));
  EXPECT_NEAR(misses(0.6, 0.0), before + 1.0 / 0.36, 1e-5);  // before it: swept again
  EXPECT_TRUE(occupied(1.0, 0.0));

  // Without the obstacle the same echo sweeps 1.6 m free and seen.
  Map open = pinned_map();
  open.add_frame(frame({echo_ahead(2.2)}), {}, robot_);
  EXPECT_TRUE(open.seen(open.cell_of({1.6, 0.0})));
  EXPECT_NEAR(open.miss_weight(open.cell_of({1.6, 0.0})), 1.0 / (1.6 * 1.6), 1e-5);
}

TEST_F(ExploreMap, MarkBodyClearsEchoesAndMarksTheDiscSeen) {
  ping({echo_ahead(1.0)});
  ASSERT_TRUE(occupied(1.0, 0.0));
  ASSERT_FALSE(seen(1.0, 0.2));
  ASSERT_FALSE(seen(1.4, 0.0));
  const std::size_t before = map_.seen_count();
  map_.mark_body({1.2, 0.0}, 0.3);  // cells x 1.0 .. 1.4, y -0.2 .. 0.2 (centres <= 0.283 m)
  EXPECT_FLOAT_EQ(hits(1.0, 0.0), 0.0f);
  EXPECT_FALSE(occupied(1.0, 0.0));
  EXPECT_FLOAT_EQ(misses(1.0, 0.0), 8.0f);  // weight_cap / 2
  for (double x : {1.0, 1.2, 1.4}) {
    for (double y : {-0.2, 0.0, 0.2}) EXPECT_TRUE(seen(x, y)) << x << " " << y;
  }
  EXPECT_EQ(map_.seen_count(), before + 8);  // (1.0, 0) was seen already
  EXPECT_FALSE(seen(1.2, 0.4));              // 0.4 m from the centre
  EXPECT_FALSE(seen(1.6, 0.0));
  // The disc's middle has seen cells all round; its rim borders unseen ones.
  EXPECT_FALSE(map_.frontier(cell({1.2, 0.0})));
  EXPECT_TRUE(map_.frontier(cell({1.2, 0.2})));
}

TEST_F(ExploreMap, RepeatedEvidenceIsHalvedAtTheCap) {
  ping({echo_ahead(0.4)});
  ASSERT_FLOAT_EQ(hits(0.4, 0.0), 4.0f);  // (1 / 0.4)² capped at max_weight
  const float expected[] = {4.0f, 8.0f, 12.0f};
  for (float m : expected) {
    ping({silence()});
    EXPECT_FLOAT_EQ(misses(0.4, 0.0), m);
    EXPECT_FLOAT_EQ(hits(0.4, 0.0), 4.0f);
  }
  EXPECT_FALSE(occupied(0.4, 0.0));  // 4 < 0.5 × 12
  ping({silence()});                 // misses reach weight_cap 16: both halve
  EXPECT_FLOAT_EQ(misses(0.4, 0.0), 8.0f);
  EXPECT_FLOAT_EQ(hits(0.4, 0.0), 2.0f);
}

TEST_F(ExploreMap, GrowingKeepsTheLatticeAndEarlierCells) {
  ping({echo_ahead(1.0)});
  const int width = map_.width(), height = map_.height();
  const float at_06 = misses(0.6, 0.0);
  const std::size_t before = map_.seen_count();
  ping({echo_ahead(1.0)}, {-30.0, -20.0, 0.0});  // grows towards -x and -y: the old cells move
  EXPECT_GT(map_.width(), width);
  EXPECT_GT(map_.height(), height);
  // The far echo's cell, a whole number of cells from the first ones.
  EXPECT_FLOAT_EQ(hits(-29.0, -20.0), 1.0f);
  EXPECT_TRUE(occupied(-29.0, -20.0));
  EXPECT_TRUE(seen(-29.4, -20.0));
  EXPECT_NEAR((map_.center_of(cell({-29.0, -20.0})) - Point2(-29.0, -20.0)).norm(), 0.0, 1e-6);
  EXPECT_NEAR((map_.center_of(cell({1.0, 0.0})) - Point2(1.0, 0.0)).norm(), 0.0, 1e-6);
  // The first cells moved with the growth.
  EXPECT_FLOAT_EQ(hits(1.0, 0.0), 1.0f);
  EXPECT_TRUE(occupied(1.0, 0.0));
  EXPECT_FLOAT_EQ(misses(0.6, 0.0), at_06);
  EXPECT_TRUE(seen(0.6, 0.0));
  EXPECT_FALSE(seen(0.6, 0.2));
  EXPECT_FLOAT_EQ(total_hits(), 2.0f);
  EXPECT_GT(map_.seen_count(), before);
  // The centre's trail moved with the growth too.
  EXPECT_TRUE(map_.traversed(cell({0.0, 0.0})));
  EXPECT_TRUE(map_.traversed(cell({-30.0, -20.0})));
  EXPECT_FALSE(map_.traversed(cell({0.2, 0.0})));
}

TEST_F(ExploreMap, TheCentresTrailOutlastsTheEchoesPaintedOnIt) {
  robot_.width_m = 0.5;
  ping({silence()}, {1.0, 0.0, 0.0});  // the robot stood at (1.0, 0): its body's cells cleared
  EXPECT_TRUE(map_.traversed(cell({1.0, 0.0})));
  EXPECT_FALSE(map_.traversed(cell({1.2, 0.0})));  // under the body, not under its centre
  EXPECT_TRUE(seen(1.2, 0.0));
  // Later, from elsewhere, echoes paint the cell: an obstacle for the map, still the trail.
  for (int k = 0; k < 5; ++k) ping({echo_ahead(1.0)});  // 5 × weight 1 ≥ half the body's 8
  EXPECT_TRUE(occupied(1.0, 0.0));
  EXPECT_TRUE(map_.traversed(cell({1.0, 0.0})));
  EXPECT_FALSE(map_.traversed(cell({0.6, 0.0})));  // swept, never stood on
}

TEST_F(ExploreMap, NeverGrowsBeyondMaxSpan) {
  ExploreMapOptions options;
  options.max_span_m = 30.0;
  Map map = pinned_map(options);
  const RobotGeometry& robot = robot_;
  map.add_frame(frame({echo_ahead(1.0)}), {}, robot);
  const std::size_t before = map.seen_count();
  const int width = map.width();
  map.add_frame(frame({echo_ahead(1.0)}), {30.0, -20.0, 0.0}, robot);
  EXPECT_EQ(map.width(), width);
  EXPECT_EQ(map.seen_count(), before);
  EXPECT_FLOAT_EQ(map.hit_weight(map.cell_of({31.0, -20.0})), 0.0f);
  EXPECT_FLOAT_EQ(map.hit_weight(map.cell_of({1.0, 0.0})), 1.0f);
}

TEST_F(ExploreMap, InvalidReadingsChangeNothing) {
  ping({});  // the body's cell alone
  ASSERT_EQ(map_.seen_count(), 1u);
  ping({{-1, 1.0, true, 0.0},
        {2, 1.0, true, 0.0},
        {0, std::numeric_limits<double>::quiet_NaN(), true, 0.0},
        {0, std::numeric_limits<double>::infinity(), false, 0.0},
        {0, 0.05, true, 0.0},
        {0, 0.05, false, 0.0}});
  EXPECT_EQ(map_.seen_count(), 1u);
  EXPECT_FLOAT_EQ(total_hits(), 0.0f);
  EXPECT_FLOAT_EQ(misses(0.4, 0.0), 0.0f);
  // The same frame with one valid reading does change the map.
  ping({{2, 1.0, true, 0.0}, echo_ahead(1.0)});
  EXPECT_GT(map_.seen_count(), 1u);
  EXPECT_FLOAT_EQ(total_hits(), 1.0f);
}

TEST_F(ExploreMap, ReadingBeyondMaxRangeIsNoEcho) {
  ping({echo_ahead(5.5)});  // > sonar_max_range_m 5: as if silent
  EXPECT_FLOAT_EQ(total_hits(), 0.0f);
  EXPECT_TRUE(seen(1.4, 0.0));
  EXPECT_FALSE(seen(1.6, 0.0));
  EXPECT_EQ(map_.seen_count(), 14u);  // as in SilentPingSweepsFreeOnlyToNoEchoFree
  // An echo at exactly max range is an echo: too far to hit, but it sweeps to free_sense_m.
  Map at_max = pinned_map();
  at_max.add_frame(frame({echo_ahead(5.0)}), {}, robot_);
  EXPECT_TRUE(at_max.seen(at_max.cell_of({2.0, 0.0})));
  EXPECT_TRUE(at_max.seen(at_max.cell_of({2.4, 0.0})));
}

TEST_F(ExploreMap, FarOffOrNonFinitePosesChangeNothingAndMapToNoCell) {
  ping({echo_ahead(1.0)});
  const std::size_t before = map_.seen_count();
  const int width = map_.width();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ping({echo_ahead(1.0)}, {nan, 0.0, 0.0});
  ping({echo_ahead(1.0)}, {0.0, 0.0, nan});
  ping({echo_ahead(1.0)}, {1e12, -1e12, 0.0});
  map_.mark_body(Point2(nan, 1.0), 0.3);
  EXPECT_EQ(map_.seen_count(), before);
  EXPECT_EQ(map_.width(), width);
  for (const Point2& p : {Point2(nan, 0.0), Point2(1e12, 0.0), Point2(-1e300, 1e300)}) {
    EXPECT_FALSE(map_.inside(map_.cell_of(p)));
    EXPECT_FALSE(map_.seen(map_.cell_of(p)));
  }
}

}  // namespace
}  // namespace cogmap::mapper
