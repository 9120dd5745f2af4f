// Counter unwrapping per P2AT.md and rebasing across reconnections.
#include "cogmap/hw/odometry_unwrap.h"

#include <gtest/gtest.h>

namespace cogmap::hw {
namespace {

TEST(OdometryUnwrap, DeltaRule) {
  EXPECT_EQ(OdometryUnwrapper::position_delta(0x0005, 0x7FFB), 10);      // forward across 0x7FFF
  EXPECT_EQ(OdometryUnwrapper::position_delta(0x7FFB, 0x0005), -10);     // backward across 0
  EXPECT_EQ(OdometryUnwrapper::position_delta(0x1000, 0x0000), 0x1000);  // exactly the bound
  EXPECT_EQ(OdometryUnwrapper::position_delta(0x1001, 0x0000), 0x1001 - 0x8000);
  EXPECT_EQ(OdometryUnwrapper::position_delta(0x8005, 0x0003), 2);  // bit 15 ignored
  EXPECT_EQ(OdometryUnwrapper::heading_delta(5, 4090), 11);
  EXPECT_EQ(OdometryUnwrapper::heading_delta(4090, 5), -11);
}

TEST(OdometryUnwrap, ContinuousAcrossManyWraps) {
  OdometryUnwrapper u;  // p2at: 1.32 mm per unit
  std::uint16_t x = 0x7000;
  u.update(x, 0, 0);
  const double start = u.pose().x_m;
  for (int i = 0; i < 1000; ++i) {  // 1000 x 100 units = 3 wraps of 0x8000
    x = static_cast<std::uint16_t>((x + 100) & 0x7FFF);
    u.update(x, 0, 0);
  }
  EXPECT_NEAR(u.pose().x_m - start, 100000 * 1.32 / 1000.0, 1e-9);
}

TEST(OdometryUnwrap, RebaseContinuesFromLastPose) {
  OdometryUnwrapper u;
  u.update(1000, 500, 1024);  // 90 degrees
  const mapper::Pose2 before = u.update(1100, 500, 1024);
  u.rebase();
  const mapper::Pose2 after = u.update(0, 0, 0);  // reset controller: counters at zero
  EXPECT_NEAR(after.x_m, before.x_m, 1e-12);
  EXPECT_NEAR(after.y_m, before.y_m, 1e-12);
  EXPECT_NEAR(after.theta_rad, before.theta_rad, 1e-12);
  // Forward motion after the reset continues along the pose's heading (90 degrees: +y).
  const mapper::Pose2 moved = u.update(100, 0, 0);
  EXPECT_NEAR(moved.x_m, before.x_m, 1e-9);
  EXPECT_NEAR(moved.y_m, before.y_m + 0.132, 1e-9);
}

TEST(OdometryUnwrap, ImplausibleJumpAfterSilenceRebases) {
  OdometryUnwrapper u;
  u.update(1000, 0, 0);
  u.rebase_if_implausible(1.0);
  EXPECT_NEAR(u.update(1500, 0, 0).x_m, 1.32 * 1500 / 1000, 1e-9);  // 0.66 m: kept
  u.rebase_if_implausible(1.0);
  EXPECT_NEAR(u.update(0, 0, 0).x_m, 1.32 * 1500 / 1000, 1e-9);  // 1.98 m back: rebased
}

}  // namespace
}  // namespace cogmap::hw
