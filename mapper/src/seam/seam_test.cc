#include <gtest/gtest.h>

#include <numbers>

#include "cogmap/mapper/grid/grid.h"
#include "cogmap/mapper/seam/fake_robot.h"
#include "cogmap/mapper/seam/pose2.h"
#include "cogmap/test_support/angles.h"

namespace cogmap::mapper {
namespace {

TEST(Pose2, ComposeThenInverseIsIdentity) {
  const Pose2 a{1.0, 2.0, 0.3}, b{-0.5, 4.0, -1.2};
  const Pose2 ab = a.compose(b);
  const Pose2 back = a.inverse().compose(ab);
  EXPECT_NEAR(back.x_m, b.x_m, 1e-12);
  EXPECT_NEAR(back.y_m, b.y_m, 1e-12);
  EXPECT_NEAR(back.theta_rad, b.theta_rad, 1e-12);
}

TEST(Pose2, TransformRotatesCounterClockwise) {
  const Pose2 p{1.0, 0.0, kPi / 2};
  const Point2 q = p.transform({1.0, 0.0});
  EXPECT_NEAR(q.x(), 1.0, 1e-12);
  EXPECT_NEAR(q.y(), 1.0, 1e-12);
}

TEST(Pose2, WrapAngleStaysInHalfOpenInterval) {
  EXPECT_NEAR(wrap_angle_rad(3 * kPi), kPi, 1e-12);
  EXPECT_NEAR(wrap_angle_rad(-kPi), kPi, 1e-12);
  EXPECT_NEAR(wrap_angle_rad(2 * kPi + 0.1), 0.1, 1e-12);
  EXPECT_NEAR(wrap_angle_rad(-0.1), -0.1, 1e-15);
}

TEST(Pose2, RotationAboutKeepsPivotFixed) {
  const Point2 pivot{3.0, -2.0};
  const Pose2 r = rotation_about(pivot, 0.7);
  const Point2 moved = r.transform(pivot);
  EXPECT_NEAR(moved.x(), pivot.x(), 1e-12);
  EXPECT_NEAR(moved.y(), pivot.y(), 1e-12);
  const Point2 q = r.transform(pivot + Point2{1.0, 0.0});
  EXPECT_NEAR(q.x(), pivot.x() + std::cos(0.7), 1e-12);
  EXPECT_NEAR(q.y(), pivot.y() + std::sin(0.7), 1e-12);
}

TEST(Segment, DistanceClampsToEndpoints) {
  const Segment s{{0.0, 0.0}, {2.0, 0.0}};
  EXPECT_DOUBLE_EQ(distance_to_segment_m({1.0, 3.0}, s), 3.0);
  EXPECT_DOUBLE_EQ(distance_to_segment_m({5.0, 4.0}, s), 5.0);
  EXPECT_DOUBLE_EQ(polyline_length_m({{0, 0}, {3, 4}, {3, 5}}), 6.0);
  // The nearest point: the foot of the perpendicular, an end beyond it, the lone point of a
  // segment of zero length.
  EXPECT_TRUE(closest_point_on_segment({1.0, 3.0}, s).isApprox(Point2(1.0, 0.0)));
  EXPECT_TRUE(closest_point_on_segment({5.0, 4.0}, s).isApprox(Point2(2.0, 0.0)));
  EXPECT_TRUE(closest_point_on_segment({-1.0, -1.0}, s).isApprox(Point2(0.0, 0.0)));
  EXPECT_TRUE(closest_point_on_segment({3.0, 3.0}, Segment{{1.0, 1.0}, {1.0, 1.0}})
                  .isApprox(Point2(1.0, 1.0)));
}

TEST(GridGeometry, WorldCellRoundTrip) {
  const GridGeometry g(-1.0, -2.0, 100.0, 30, 40);
  const CellIndex c = g.cell_of({0.05, 0.05});
  EXPECT_EQ(c, (CellIndex{10, 20}));
  const Point2 center = g.center_of(c);
  EXPECT_NEAR(center.x(), 0.05, 1e-12);
  EXPECT_NEAR(center.y(), 0.05, 1e-12);
  EXPECT_EQ(g.cell_of({-1.01, 0.0}).x, -1);  // floor, not truncation
  EXPECT_FALSE(g.contains({-1, 0}));
}

TEST(Grid, GrowthKeepsValuesAtTheirWorldPosition) {
  HistogramGrid grid(GridGeometry(0.0, 0.0, 100.0, 10, 10), 0.0f);
  const Point2 p{0.55, 0.35};
  grid.at(grid.geometry().cell_of(p)) = 9.0f;
  EXPECT_TRUE(grid.ensure_contains({-3.0, 5.0}, 1.0));
  EXPECT_FLOAT_EQ(grid.get(grid.geometry().cell_of(p)), 9.0f);
  EXPECT_TRUE(grid.contains(grid.geometry().cell_of({-4.0, 6.0})));
  EXPECT_FALSE(grid.ensure_contains({-3.0, 5.0}, 1.0));
  EXPECT_FLOAT_EQ(grid.get({-1000, 0}), 0.0f);  // outside reads the fill value
}

TEST(FakeRobot, ReplaysFramesThenEnds) {
  std::vector<SensorFrame> frames(2);
  frames[1].time_s = 0.1;
  FakeRobot robot(p2at_geometry(), frames);
  EXPECT_EQ(robot.geometry().sonars.size(), 16u);
  ASSERT_TRUE(robot.next_frame().has_value());
  EXPECT_DOUBLE_EQ(robot.next_frame()->time_s, 0.1);
  EXPECT_FALSE(robot.next_frame().has_value());
  robot.command({0.5, 0.1});
  robot.stop();
  ASSERT_EQ(robot.commands().size(), 2u);
  EXPECT_DOUBLE_EQ(robot.commands()[1].v_mps, 0.0);
}

TEST(P2atGeometry, MountsMatchTheParameterFile) {
  const RobotGeometry g = p2at_geometry();
  EXPECT_NEAR(g.sonars[3].x_m, 0.245, 1e-12);
  EXPECT_NEAR(g.sonars[3].heading_rad, 10.0 * kPi / 180.0, 1e-12);
  EXPECT_NEAR(g.sonars[11].heading_rad, -170.0 * kPi / 180.0, 1e-12);
}

}  // namespace
}  // namespace cogmap::mapper
