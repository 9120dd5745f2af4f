#include "grid/sonar_projection.h"
#include "cogmap/test_support/angles.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace cogmap::mapper {
namespace {

constexpr double kTol = 1e-12;

TEST(SonarProjection, FrontTransducerAtOriginPose) {
  SonarProjector projector(p2at_geometry());
  const SonarBeam b = projector.beam({0.0, 0.0, 0.0}, 3);  // (245, 27) mm, 10°
  EXPECT_NEAR(b.origin.x(), 0.245, kTol);
  EXPECT_NEAR(b.origin.y(), 0.027, kTol);
  EXPECT_NEAR(b.cos_h, std::cos(10.0 * kPi / 180.0), kTol);
  EXPECT_NEAR(b.sin_h, std::sin(10.0 * kPi / 180.0), kTol);
  const Point2 hit = b.at(1.0);
  EXPECT_NEAR(hit.x(), 0.245 + std::cos(10.0 * kPi / 180.0), kTol);
  EXPECT_NEAR(hit.y(), 0.027 + std::sin(10.0 * kPi / 180.0), kTol);
}

TEST(SonarProjection, LeftTransducerStaysOnTheLeftDespiteEq37Typo) {
  // Eq. 3.7 as printed (sox sin h - soy cos h) would put sonar 0 at y = -0.136 with h = 0.
  SonarProjector projector(p2at_geometry());
  const SonarBeam b = projector.beam({0.0, 0.0, 0.0}, 0);  // (147, 136) mm, 90°
  EXPECT_NEAR(b.origin.x(), 0.147, kTol);
  EXPECT_NEAR(b.origin.y(), 0.136, kTol);
  EXPECT_NEAR(b.cos_h, 0.0, kTol);
  EXPECT_NEAR(b.sin_h, 1.0, kTol);
}

TEST(SonarProjection, RotatedRobotSideTransducer) {
  // Robot at (1.05, -0.95) facing +y: sonar 0 (left side) now looks towards -x.
  SonarProjector projector(p2at_geometry());
  const SonarBeam b = projector.beam({1.05, -0.95, kPi / 2}, 0);
  EXPECT_NEAR(b.origin.x(), 1.05 - 0.136, kTol);
  EXPECT_NEAR(b.origin.y(), -0.95 + 0.147, kTol);
  EXPECT_NEAR(b.cos_h, -1.0, kTol);
  EXPECT_NEAR(b.sin_h, 0.0, kTol);
  const Point2 hit = b.at(2.0);
  EXPECT_NEAR(hit.x(), 1.05 - 0.136 - 2.0, kTol);
  EXPECT_NEAR(hit.y(), -0.95 + 0.147, kTol);
}

TEST(SonarProjection, RotatedRobotRearTransducer) {
  // Sonar 11: (-241, -27) mm, -170°. Robot heading +90° -> global heading -80°.
  SonarProjector projector(p2at_geometry());
  const SonarBeam b = projector.beam({1.05, -0.95, kPi / 2}, 11);
  EXPECT_NEAR(b.origin.x(), 1.05 + 0.027, kTol);
  EXPECT_NEAR(b.origin.y(), -0.95 - 0.241, kTol);
  EXPECT_NEAR(b.cos_h, std::cos(-80.0 * kPi / 180.0), kTol);
  EXPECT_NEAR(b.sin_h, std::sin(-80.0 * kPi / 180.0), kTol);
}

TEST(SonarProjection, MatchesPoseTransformForEveryMountAndHeading) {
  const RobotGeometry robot = p2at_geometry();
  SonarProjector projector(robot);
  for (double theta : {-3.0, -1.2, 0.0, 0.4, 2.9}) {
    const Pose2 pose{-2.5, 3.25, theta};
    for (int i = 0; i < projector.count(); ++i) {
      const SonarMount& m = robot.sonars[static_cast<std::size_t>(i)];
      const Point2 expected_origin = pose.transform({m.x_m, m.y_m});
      const Point2 expected_hit = pose.transform(
          {m.x_m + 1.7 * std::cos(m.heading_rad), m.y_m + 1.7 * std::sin(m.heading_rad)});
      const SonarBeam b = projector.beam(pose, i);
      EXPECT_NEAR((b.origin - expected_origin).norm(), 0.0, 1e-12) << i << " " << theta;
      EXPECT_NEAR((b.at(1.7) - expected_hit).norm(), 0.0, 1e-12) << i << " " << theta;
    }
  }
}

}  // namespace
}  // namespace cogmap::mapper
