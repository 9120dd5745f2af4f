#include "cogmap/mapper/localization/odometry_recalibration.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cogmap::mapper {
namespace {

constexpr double kTrack = 0.591;

TEST(SpinFraction, StraightSpinPivotAndArc) {
  EXPECT_DOUBLE_EQ(spin_fraction(0.5, 0.0, kTrack), 0.0);
  EXPECT_DOUBLE_EQ(spin_fraction(0.0, 0.3, kTrack), 1.0);
  EXPECT_DOUBLE_EQ(spin_fraction(0.0, -0.3, kTrack), 1.0);
  // A pivot on the left wheel: dl = 0, dr = turn·track.
  EXPECT_DOUBLE_EQ(spin_fraction(0.5 * 0.4 * kTrack, 0.4, kTrack), 1.0);
  // 1 m forward turning 0.5 rad on a 0.6 m track: wheels 0.85 and 1.15 m, s = 0.3 / 2.
  EXPECT_NEAR(spin_fraction(1.0, 0.5, 0.6), 0.15, 1e-15);
  EXPECT_NEAR(spin_fraction(-1.0, 0.5, 0.6), 0.15, 1e-15);  // backwards the same
  EXPECT_DOUBLE_EQ(spin_fraction(0.0, 0.0, kTrack), 0.0);   // standing still
}

TEST(OdometryRecalibrator, ZeroGainReturnsTheReportedPoses) {
  OdometryRecalibrator r(0.0, kTrack);
  for (int k = 0; k < 50; ++k) {
    const Pose2 raw{0.1 * k, std::sin(0.3 * k), wrap_angle_rad(0.7 * k)};
    const Pose2 out = r.update(raw);
    EXPECT_EQ(out.x_m, raw.x_m);
    EXPECT_EQ(out.y_m, raw.y_m);
    EXPECT_EQ(out.theta_rad, raw.theta_rad);
  }
}

TEST(OdometryRecalibrator, SpinOnTheSpotIsLeftAlone) {
  // s = 1: the firmware's track is the spin's own, whatever the gain.
  OdometryRecalibrator r(0.08, kTrack);
  Pose2 raw{1.0, 2.0, 0.3};
  Pose2 out = r.update(raw);
  for (int k = 0; k < 40; ++k) {
    raw.theta_rad = wrap_angle_rad(raw.theta_rad + 0.05);
    out = r.update(raw);
  }
  EXPECT_NEAR(out.x_m, 1.0, 1e-12);
  EXPECT_NEAR(out.y_m, 2.0, 1e-12);
  EXPECT_NEAR(out.theta_rad, wrap_angle_rad(0.3 + 40 * 0.05), 1e-12);
}

/// Drives wheel travel `dl`, `dr` per step for `steps` steps through the skid-steer law of
/// docs/odometry-model.md (without noise): the odometry turns by (dr − dl)/B_cal, the body by
/// (dr − dl)/B_eff. Both integrate at the midpoint heading. Feeds the odometry to a recalibrator
/// with the true gain and checks it follows the body.
void expect_follows_the_body(double dl, double dr, int steps, double gain) {
  const double s = std::abs(dr - dl) / (std::abs(dl) + std::abs(dr));
  const double effective_track = kTrack * (1.0 + gain * (s - 1.0));
  const double forward = 0.5 * (dl + dr);
  Pose2 odometry, body;
  OdometryRecalibrator r(gain, kTrack);
  Pose2 out = r.update(odometry);
  auto advance = [forward](Pose2& p, double turn) {
    const double mid = p.theta_rad + 0.5 * turn;
    p = {p.x_m + forward * std::cos(mid), p.y_m + forward * std::sin(mid),
         wrap_angle_rad(p.theta_rad + turn)};
  };
  for (int k = 0; k < steps; ++k) {
    advance(odometry, (dr - dl) / kTrack);
    advance(body, (dr - dl) / effective_track);
    out = r.update(odometry);
  }
  EXPECT_NEAR(out.x_m, body.x_m, 1e-9);
  EXPECT_NEAR(out.y_m, body.y_m, 1e-9);
  EXPECT_NEAR(wrap_angle_rad(out.theta_rad - body.theta_rad), 0.0, 1e-12);
  // And the odometry itself was off by the share the law predicts, so the test means something.
  EXPECT_GT(std::abs(wrap_angle_rad(odometry.theta_rad - body.theta_rad)), 0.01);
}

TEST(OdometryRecalibrator, FollowsTheBodyOnAGentleArc) {
  expect_follows_the_body(0.040, 0.045, 200, 0.05);  // 9 m, ~97° to the left
}

TEST(OdometryRecalibrator, FollowsTheBodyOnATightArcToTheRight) {
  expect_follows_the_body(0.050, 0.020, 120, 0.08);
}

TEST(OdometryRecalibrator, FollowsTheBodyBackwards) {
  expect_follows_the_body(-0.030, -0.036, 150, 0.05);
}

TEST(OdometryRecalibrator, ANegativeGainTurnsTheOtherWay) {
  expect_follows_the_body(0.040, 0.045, 200, -0.04);
}

}  // namespace
}  // namespace cogmap::mapper
