#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "cogmap/mapper/localization/localizer.h"
#include "cogmap/test_support/angles.h"
#include "synthetic_rooms.h"

namespace cogmap::mapper {
namespace {

/// The best any estimator can do from the data: the length-weighted mean direction of the
/// true walls (pieces within 5° of the known truth) of each set, reference minus current.
double oracle_rotation_rad(const std::vector<Polyline>& reference, double reference_rad,
                           const std::vector<Polyline>& current, double current_rad) {
  auto mean_near = [](const std::vector<Polyline>& lines, double truth_rad) {
    std::vector<double> angles, weights;
    for (const LineDirection& d : line_directions(lines)) {
      if (std::abs(fold_direction_rad(d.angle_rad - truth_rad)) > 5.0 * kDeg) continue;
      angles.push_back(d.angle_rad);
      weights.push_back(d.length_m);
    }
    return mean_direction_rad(angles, weights);
  };
  return fold_direction_rad(mean_near(reference, reference_rad) - mean_near(current, current_rad));
}

/// Reference: the scene (rectangle + L-shape) already corrected, in a building whose walls run
/// at `building_deg`; current: the same scene drifted by `injected_deg`, with independent
/// noise. 1° Gaussian direction noise per piece, ~20 % short clutter at random angles. The
/// correct fix undoes the drift: rotation = −injected.
struct Trial {
  Localization result;
  double oracle_rad = 0.0;
};

Trial run(double injected_deg, double building_deg, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const auto reference = testing::noisy_scene(building_deg * kDeg, 1.0 * kDeg, 0.2, rng);
  const auto current =
      testing::noisy_scene((building_deg + injected_deg) * kDeg, 1.0 * kDeg, 0.2, rng);
  return {Localizer(LocalizerOptions{}).estimate(reference, current),
          oracle_rotation_rad(reference, building_deg * kDeg, current,
                              (building_deg + injected_deg) * kDeg)};
}

class InjectedRotation : public ::testing::TestWithParam<double> {};

TEST_P(InjectedRotation, RecoveredWithinHalfADegree) {
  const double injected = GetParam();
  for (double building : {0.0, 30.0, 40.0, -44.0}) {  // 40° and −44° put data across the seam
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      const Trial t = run(injected, building, seed);
      ASSERT_TRUE(t.result.applied) << "building " << building << " seed " << seed;
      EXPECT_NEAR(t.result.rotation_rad / kDeg, -injected, 0.5)
          << "building " << building << " seed " << seed;
      // Clutter must not bias the answer: EM lands on what the true walls alone say.
      EXPECT_NEAR(t.result.rotation_rad / kDeg, t.oracle_rad / kDeg, 0.1)
          << "building " << building << " seed " << seed;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Localizer, InjectedRotation, ::testing::Values(3.0, 7.0, -12.0));

TEST(Localizer, NoDriftGivesNearlyZero) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const Trial t = run(0.0, 20.0, seed);
    ASSERT_TRUE(t.result.applied);
    EXPECT_NEAR(t.result.rotation_rad / kDeg, 0.0, 0.5) << "seed " << seed;
    EXPECT_NEAR(t.result.rotation_rad / kDeg, t.oracle_rad / kDeg, 0.1) << "seed " << seed;
  }
}

TEST(Localizer, PooledUnlabelledMixtureIsTheThesisVariant) {
  // label_sources = false runs the thesis's pooled mixture. With 12° between s and m the two
  // Gaussians are well apart and it still finds the drift.
  std::mt19937_64 rng(4);
  const auto reference = testing::noisy_scene(0.0, 1.0 * kDeg, 0.0, rng);
  const auto current = testing::noisy_scene(12.0 * kDeg, 1.0 * kDeg, 0.0, rng);
  LocalizerOptions options;
  options.label_sources = false;
  const Localization r = Localizer(options).estimate(reference, current);
  ASSERT_TRUE(r.applied);
  EXPECT_NEAR(r.rotation_rad / kDeg, -12.0, 0.5);
}

TEST(Localizer, ExactWallsGiveExactRotation) {
  std::mt19937_64 rng(3);
  const auto reference = testing::noisy_room(testing::rectangle_room(), 0.0, 0.0, 0.0, rng);
  const auto current = testing::noisy_room(testing::l_shaped_room(), 5.0 * kDeg, 0.0, 0.0, rng);
  const Localization r = Localizer(LocalizerOptions{}).estimate(reference, current);
  ASSERT_TRUE(r.applied);
  EXPECT_NEAR(r.rotation_rad, -5.0 * kDeg, 1e-6);
  EXPECT_NEAR(r.reference_direction_rad, 0.0, 1e-6);
  EXPECT_NEAR(r.current_direction_rad, 5.0 * kDeg, 1e-6);
}

TEST(Localizer, TooLittleWallIsNotApplied) {
  const std::vector<Polyline> reference{{Point2{0, 0}, Point2{5, 0}, Point2{5, 4}}};
  const std::vector<Polyline> short_walls{{Point2{0, 0}, Point2{0.5, 0.05}},
                                          {Point2{1, 1}, Point2{1.02, 1.4}}};
  const Localizer localizer(LocalizerOptions{});
  const Localization a = localizer.estimate(reference, short_walls);
  EXPECT_FALSE(a.applied);
  EXPECT_EQ(a.rotation_rad, 0.0);
  EXPECT_NEAR(a.longest_wall_m, std::hypot(0.5, 0.05), 1e-12);  // reported all the same
  EXPECT_FALSE(localizer.estimate(short_walls, reference).applied);
  EXPECT_FALSE(localizer.estimate({}, reference).applied);
}

TEST(Localizer, CorrectionBeyondTheLimitIsNotApplied) {
  std::mt19937_64 rng(5);
  const auto reference = testing::noisy_room(testing::rectangle_room(), 0.0, 0.0, 0.0, rng);
  const auto current = testing::noisy_room(testing::l_shaped_room(), 30.0 * kDeg, 0.0, 0.0, rng);
  const Localization r = Localizer(LocalizerOptions{}).estimate(reference, current);
  EXPECT_FALSE(r.applied);
  EXPECT_EQ(r.rotation_rad, 0.0);
  EXPECT_NEAR(r.current_direction_rad, 30.0 * kDeg, 1e-6);  // the evidence is still reported
}

TEST(Localizer, ABinnedReferenceMeasuresWhatTheWholeReferenceDoes) {
  // 32 rooms' worth of reference (the default reference_rooms), each with its own noise, and a
  // room drifted by 4°: pooling the reference's ~2 000 directions in 0.25° bins leaves the
  // answer and its sd where the directions one by one put them.
  for (const std::uint64_t seed : {1u, 2u, 3u, 4u, 5u}) {
    std::mt19937_64 rng(seed);
    std::vector<Polyline> reference;
    for (int room = 0; room < 32; ++room) {
      const auto walls = testing::noisy_scene(12.0 * kDeg, 1.0 * kDeg, 0.2, rng);
      reference.insert(reference.end(), walls.begin(), walls.end());
    }
    const auto current = testing::noisy_scene(16.0 * kDeg, 1.0 * kDeg, 0.2, rng);
    LocalizerOptions pooled;
    pooled.reference_bin_rad = 0.25 * kDeg;
    const Localization binned = Localizer(pooled).estimate(reference, current);
    const Localization exact = Localizer(LocalizerOptions{}).estimate(reference, current);
    ASSERT_TRUE(binned.applied);
    EXPECT_NEAR(exact.measured_rotation_rad, -4.0 * kDeg, 0.5 * kDeg);
    EXPECT_NEAR(binned.measured_rotation_rad, exact.measured_rotation_rad, 0.002 * kDeg);
    EXPECT_NEAR(binned.measurement_sigma_rad / exact.measurement_sigma_rad, 1.0, 0.002);
  }
}

TEST(Localizer, AMeasurementAsSharpAsItsLongestWall) {
  // A room of three exact walls, the longest 2.5 m, drifted by 3° against a square reference:
  // with measurement_sd_rad_m the sd is k / 2.5 m, plus a third of the prior's variance when a
  // prior is given, whatever EM's count of pieces says; the longest piece is reported either way.
  const std::vector<Polyline> reference{
      {Point2{0, 0}, Point2{5, 0}, Point2{5, 5}, Point2{0, 5}, Point2{0, 0}}};
  const double c = std::cos(3.0 * kDeg), s = std::sin(3.0 * kDeg);
  const auto turned = [&](double x, double y) { return Point2{c * x - s * y, s * x + c * y}; };
  const std::vector<Polyline> current{{turned(0, 0), turned(2.5, 0), turned(2.5, 1.5)},
                                      {turned(1, 3), turned(1, 4.2)}};
  LocalizerOptions own;
  LocalizerOptions by_wall;
  by_wall.measurement_sd_rad_m = 0.077;
  const Localization a = Localizer(own).estimate(reference, current);
  const Localization b = Localizer(by_wall).estimate(reference, current);
  EXPECT_DOUBLE_EQ(a.longest_wall_m, 2.5);
  EXPECT_DOUBLE_EQ(b.longest_wall_m, 2.5);
  EXPECT_NEAR(b.measured_rotation_rad, -3.0 * kDeg, 1e-6);
  EXPECT_EQ(b.measured_rotation_rad, a.measured_rotation_rad);  // only the sd changes
  EXPECT_NEAR(b.measurement_sigma_rad, 0.077 / 2.5, 1e-12);
  EXPECT_GT(std::abs(a.measurement_sigma_rad - b.measurement_sigma_rad), 1e-3);

  const RotationPrior prior{2.0 * kDeg};
  const Localization p = Localizer(by_wall).estimate(reference, current, prior);
  const double var_meas = std::pow(0.077 / 2.5, 2) + std::pow(2.0 * kDeg, 2) / 3.0;
  EXPECT_NEAR(p.measurement_sigma_rad, std::sqrt(var_meas), 1e-12);
  const double var_prior = std::pow(2.0 * kDeg, 2);
  EXPECT_NEAR(p.gain, var_prior / (var_prior + var_meas), 1e-12);
  ASSERT_TRUE(p.applied);
  EXPECT_NEAR(p.rotation_rad, p.gain * p.measured_rotation_rad, 1e-15);

  // The same room with its walls broken into 0.5 m pieces is measured five times less sharply.
  std::vector<Polyline> broken;
  for (const Polyline& line : current) {
    for (std::size_t i = 1; i < line.size(); ++i) {
      const int pieces = static_cast<int>(std::ceil((line[i] - line[i - 1]).norm() / 0.5 - 1e-9));
      for (int k = 0; k < pieces; ++k) {
        const Point2 from = line[i - 1] + (line[i] - line[i - 1]) * (double(k) / pieces);
        const Point2 to = line[i - 1] + (line[i] - line[i - 1]) * (double(k + 1) / pieces);
        broken.push_back({from, to});
      }
    }
  }
  const Localization q = Localizer(by_wall).estimate(reference, broken);
  EXPECT_NEAR(q.longest_wall_m, 0.5, 1e-9);
  EXPECT_NEAR(q.measurement_sigma_rad, 0.077 / 0.5, 1e-9);
}

TEST(Localizer, IsDeterministic) {
  const Trial a = run(7.0, 10.0, 99), b = run(7.0, 10.0, 99);
  EXPECT_EQ(a.result.rotation_rad, b.result.rotation_rad);
  EXPECT_EQ(a.result.em.iterations, b.result.em.iterations);
}

}  // namespace
}  // namespace cogmap::mapper
