// The odometry prior on EM's rotation: drift model, path rotation, shrinkage and gate.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "cogmap/mapper/localization/localizer.h"
#include "cogmap/test_support/angles.h"
#include "synthetic_rooms.h"

namespace cogmap::mapper {
namespace {

TEST(RotationPrior, PathRotationCountsTurnsAlongChords) {
  // East 2 m, then north 2 m: one 90° corner; entry heading east, exit heading north.
  std::vector<Point2> path;
  for (int i = 0; i <= 20; ++i) path.emplace_back(0.1 * i, 0.0);
  for (int i = 1; i <= 20; ++i) path.emplace_back(2.0, 0.1 * i);
  EXPECT_NEAR(path_rotation_rad(path, 0.0, std::numbers::pi / 2, 0.5), std::numbers::pi / 2, 1e-9);
  EXPECT_NEAR(path_length_m(path), 4.0, 1e-9);
  // Entering heading west adds the half turn the robot made at the start.
  EXPECT_NEAR(path_rotation_rad(path, std::numbers::pi, std::nullopt, 0.5), 1.5 * std::numbers::pi,
              1e-9);
}

TEST(RotationPrior, DriftSigmaCombinesTurnWalkAndFloor) {
  HeadingDriftModel m;
  m.per_rad_turned = 0.02;
  m.rad_per_sqrt_m = 0.005;
  m.floor_rad = 0.01;
  const double expected = std::sqrt(0.01 * 0.01 + std::pow(0.02 * 3.0, 2) + 0.005 * 0.005 * 16.0);
  EXPECT_NEAR(heading_drift_sigma_rad(m, 3.0, 16.0), expected, 1e-12);
}

TEST(RotationPrior, InfinitePriorLeavesTheEstimateUnchanged) {
  std::mt19937_64 rng(5);
  const auto reference = testing::noisy_scene(0.0, 1.0 * kDeg, 0.2, rng);
  const auto current = testing::noisy_scene(6.0 * kDeg, 1.0 * kDeg, 0.2, rng);
  const Localizer localizer{LocalizerOptions{}};
  const Localization plain = localizer.estimate(reference, current);
  const Localization with_none = localizer.estimate(reference, current, RotationPrior{});
  EXPECT_EQ(plain.rotation_rad, with_none.rotation_rad);
  EXPECT_EQ(plain.applied, with_none.applied);
}

TEST(RotationPrior, TightPriorShrinksAndGatesTheMeasurement) {
  std::mt19937_64 rng(6);
  const auto reference = testing::noisy_scene(0.0, 1.0 * kDeg, 0.2, rng);
  const auto current = testing::noisy_scene(6.0 * kDeg, 1.0 * kDeg, 0.2, rng);
  LocalizerOptions options;
  options.smear_variance = false;  // the smear term alone would cap the gain at 3/4
  options.prior_shrinks = true;
  const Localizer localizer{options};
  const Localization wide = localizer.estimate(reference, current, RotationPrior{20.0 * kDeg});
  ASSERT_TRUE(wide.applied);
  EXPECT_NEAR(wide.rotation_rad, -6.0 * kDeg, 0.5 * kDeg);  // the data dominate a wide prior
  EXPECT_GT(wide.gain, 0.9);
  const Localization medium = localizer.estimate(reference, current, RotationPrior{3.0 * kDeg});
  if (medium.applied) {
    EXPECT_LT(std::abs(medium.rotation_rad), std::abs(wide.rotation_rad));  // shrunk toward 0
  }
  // A 6° rotation is beyond 3 sd of a 0.5° prior: an outlier for this odometry, not applied.
  const Localization tight = localizer.estimate(reference, current, RotationPrior{0.5 * kDeg});
  EXPECT_FALSE(tight.applied);
  EXPECT_EQ(tight.rotation_rad, 0.0);
  EXPECT_NEAR(tight.measured_rotation_rad, wide.measured_rotation_rad, 1e-12);
}

TEST(RotationPrior, GateOnlyAppliesWhatPassesWholeAndRefusesOutliers) {
  std::mt19937_64 rng(6);
  const auto reference = testing::noisy_scene(0.0, 1.0 * kDeg, 0.2, rng);
  const auto current = testing::noisy_scene(6.0 * kDeg, 1.0 * kDeg, 0.2, rng);
  LocalizerOptions options;
  options.smear_variance = false;
  options.prior_shrinks = false;  // the prior is only the gate (the default until 2026-12-02)
  const Localizer localizer{options};
  // 6° is within 3 sd of a 3° prior: applied exactly as measured, not shrunk.
  const Localization medium = localizer.estimate(reference, current, RotationPrior{3.0 * kDeg});
  ASSERT_TRUE(medium.applied);
  EXPECT_EQ(medium.gain, 1.0);
  EXPECT_EQ(medium.rotation_rad, medium.measured_rotation_rad);
  EXPECT_NEAR(medium.rotation_rad, -6.0 * kDeg, 0.5 * kDeg);
  // Beyond 3 sd of a 0.5° prior: refused, the pose is left alone.
  const Localization tight = localizer.estimate(reference, current, RotationPrior{0.5 * kDeg});
  EXPECT_FALSE(tight.applied);
  EXPECT_EQ(tight.rotation_rad, 0.0);
}

}  // namespace
}  // namespace cogmap::mapper
