// The model table against figures typed from ARIA's parameter files (params/*.p), not from the
// table itself.
#include <gtest/gtest.h>

#include <numbers>

#include "cogmap/mapper/seam/robot_models.h"
#include "cogmap/test_support/angles.h"

namespace cogmap::mapper {
namespace {

void expect_mount(const RobotGeometry& g, std::size_t i, double x_mm, double y_mm, double deg) {
  ASSERT_LT(i, g.sonars.size());
  EXPECT_NEAR(g.sonars[i].x_m, x_mm / 1000.0, 1e-12) << "sonar " << i;
  EXPECT_NEAR(g.sonars[i].y_m, y_mm / 1000.0, 1e-12) << "sonar " << i;
  EXPECT_NEAR(g.sonars[i].heading_rad, deg * kDeg, 1e-12) << "sonar " << i;
}

TEST(RobotModels, EveryIssueModelIsKnownInOrder) {
  EXPECT_EQ(robot_model_names(), "p2at, p2at8, p3at, p3dx, p2dx, p2de, peoplebot");
  for (const RobotModel& m : robot_models()) {
    ASSERT_NE(find_robot_model(m.name), nullptr) << m.name;
    EXPECT_EQ(find_robot_model(m.name)->name, m.name);
  }
  EXPECT_EQ(find_robot_model("pioneer9"), nullptr);
  EXPECT_EQ(find_robot_model(""), nullptr);
}

TEST(RobotModels, P2atMatchesTheP2atParameterFile) {
  const RobotGeometry g = find_robot_model("p2at")->geometry;
  ASSERT_EQ(g.sonars.size(), 16u);
  expect_mount(g, 0, 147, 136, 90);
  expect_mount(g, 3, 245, 27, 10);
  expect_mount(g, 7, 147, -136, -90);
  expect_mount(g, 8, -144, -136, -90);
  expect_mount(g, 15, -144, 136, 90);
  EXPECT_DOUBLE_EQ(g.length_m, 0.626);
  EXPECT_DOUBLE_EQ(g.width_m, 0.505);
  EXPECT_EQ(find_robot_model("p2at")->geometry.drive, DriveKind::kSkidSteer);
  // DiffConvFactor 0.0034 -> 2 / 0.0034 mm = 588 mm (docs/p2at.md).
  EXPECT_NEAR(find_robot_model("p2at")->geometry.odometry_track_m, 0.5882, 1e-4);
}

TEST(RobotModels, P2atGeometryIsTheTableEntry) {
  const RobotGeometry a = p2at_geometry();
  const RobotGeometry& b = find_robot_model("p2at")->geometry;
  ASSERT_EQ(a.sonars.size(), b.sonars.size());
  for (std::size_t i = 0; i < a.sonars.size(); ++i) {
    EXPECT_EQ(a.sonars[i].x_m, b.sonars[i].x_m);
    EXPECT_EQ(a.sonars[i].heading_rad, b.sonars[i].heading_rad);
  }
  EXPECT_EQ(a.max_speed_mps, 0.75);
  EXPECT_EQ(a.max_turn_rate_radps, 1.74);
}

TEST(RobotModels, P3dxIsADifferentialDriveWithTheDxRing) {
  const RobotModel& m = *find_robot_model("p3dx");
  EXPECT_EQ(m.geometry.drive, DriveKind::kDifferential);
  EXPECT_EQ(m.aria_params, "p3dx.p");
  ASSERT_EQ(m.geometry.sonars.size(), 16u);
  expect_mount(m.geometry, 0, 69, 136, 90);
  expect_mount(m.geometry, 1, 114, 119, 50);
  expect_mount(m.geometry, 2, 148, 78, 30);
  expect_mount(m.geometry, 3, 166, 27, 10);
  expect_mount(m.geometry, 4, 166, -27, -10);
  expect_mount(m.geometry, 11, -255, -27, -170);
  EXPECT_DOUBLE_EQ(m.geometry.length_m, 0.511);
  EXPECT_DOUBLE_EQ(m.geometry.width_m, 0.425);
  EXPECT_DOUBLE_EQ(m.geometry.max_speed_mps, 1.0);
  EXPECT_NEAR(m.geometry.odometry_track_m, 2.0 / 0.0056 / 1000.0, 1e-12);
}

TEST(RobotModels, PeopleBotHasThirtyTwoSonars) {
  const RobotGeometry& g = find_robot_model("peoplebot")->geometry;
  ASSERT_EQ(g.sonars.size(), 32u);
  expect_mount(g, 15, -157, 136, 90);
  expect_mount(g, 16, -20, 136, 90);
  expect_mount(g, 19, 77, 27, 10);
  expect_mount(g, 24, -191, -136, -90);
  expect_mount(g, 27, -290, -27, -170);
  expect_mount(g, 31, -191, 136, 90);
}

TEST(RobotModels, Sync2SubclassesMapToTheirModels) {
  EXPECT_EQ(find_robot_model("p3dx-sh")->name, "p3dx");
  EXPECT_EQ(find_robot_model("P3AT-SH")->name, "p3at");
  EXPECT_EQ(find_robot_model("p2at8+")->name, "p2at8");
  EXPECT_EQ(find_robot_model("p2d8+")->name, "p2dx");
  EXPECT_EQ(find_robot_model("peoplebot-sh")->name, "peoplebot");
  EXPECT_EQ(find_robot_model("P2DE")->name, "p2de");
}

}  // namespace
}  // namespace cogmap::mapper
