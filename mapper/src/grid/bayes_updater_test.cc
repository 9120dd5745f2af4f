// Bayes (§2.2.1): Table 2.2 likelihoods and Eq. 2.9 against hand-computed numbers.
// One transducer at the robot centre looking along +x, R = 5 m, β/2 = 15°; robot at
// (0.05, 0.05) in cell (60, 60) of the default 12 m room.

#include <gtest/gtest.h>

#include <cmath>

#include "cogmap/mapper/grid/grid_updater.h"
#include "grid/grid_test_support.h"
#include "grid/sensor_models.h"

namespace cogmap::mapper {
namespace {

using testing::echo;
using testing::kPi;
using testing::single_forward_sonar;

using testing::kRobot;

TEST(BayesModel, TableWeightOnAxisAndAtTheEdge) {
  EXPECT_DOUBLE_EQ(table_weight(1.0, 5.0, 0.0, kPi / 12), 0.9);  // ((4/5) + 1) / 2
  EXPECT_DOUBLE_EQ(table_weight(5.0, 5.0, kPi / 12, kPi / 12), 0.0);
  EXPECT_DOUBLE_EQ(table_weight(2.5, 5.0, kPi / 24, kPi / 12), 0.5);
  EXPECT_DOUBLE_EQ(table_weight(5.2, 5.0, kPi / 12, kPi / 12), 0.0);  // clamped
}

TEST(BayesModel, Eq29ByHand) {
  // Region I on the axis at 1 m: Pr(ς|H) = 0.9 × 0.98 = 0.882, Pr(ς|¬H) = 0.118.
  const SensorLikelihood l = bayes_region_one(0.9, 0.98);
  EXPECT_DOUBLE_EQ(l.given_occupied, 0.882);
  EXPECT_DOUBLE_EQ(l.given_empty, 1.0 - 0.882);
  EXPECT_NEAR(bayes_posterior(0.5, l), 0.882, 1e-15);
  // Second reading: 0.882² / (0.882² + 0.118²) = 0.777924 / 0.791848.
  EXPECT_NEAR(bayes_posterior(0.882, l), 0.777924 / 0.791848, 1e-12);
  // Region II: Pr(ς|¬H) = weight.
  const SensorLikelihood e = bayes_region_two(0.7);
  EXPECT_NEAR(bayes_posterior(0.6, e), 0.3 * 0.6 / (0.3 * 0.6 + 0.7 * 0.4), 1e-15);
  // Weak evidence (weight < 0.5, far and near the edge) is neutral, never contrary.
  EXPECT_DOUBLE_EQ(bayes_posterior(0.3, bayes_region_one(0.2, 0.98)), 0.3);
  EXPECT_DOUBLE_EQ(bayes_posterior(0.3, bayes_region_two(0.1)), 0.3);
  // Clamps keep cells recoverable.
  EXPECT_DOUBLE_EQ(bayes_posterior(0.5, bayes_region_two(1.0)), kMinProbability);
  EXPECT_DOUBLE_EQ(bayes_posterior(0.9999, {1.0, 0.0}), kMaxProbability);
}

TEST(BayesModel, HistogramScale) {
  EXPECT_FLOAT_EQ(bayes_to_histogram(0.5), 0.0f);
  EXPECT_FLOAT_EQ(bayes_to_histogram(1.0), 15.0f);
  EXPECT_FLOAT_EQ(bayes_to_histogram(0.0), -3.0f);
  EXPECT_FLOAT_EQ(bayes_to_histogram(0.75), 7.5f);
  EXPECT_FLOAT_EQ(bayes_to_histogram(0.25), -1.5f);
}

TEST(BayesUpdater, RegionOneRisesRegionTwoFalls) {
  auto u = make_grid_updater(GridKind::kBayes, {}, single_forward_sonar());
  u->reset({0.0, 0.0});
  ASSERT_TRUE(u->integrate(kRobot, echo(0, 1.0)));
  // Region I on the axis: cell (70, 60), centre 1.0 m ahead.
  EXPECT_NEAR(u->histogram_at({70, 60}), bayes_to_histogram(0.882), 1e-4);
  EXPECT_GT(u->histogram_at({70, 60}), 0.0f);
  // Region II on the axis, 0.5 m: weight (0.9 + 1)/2 = 0.95 -> Pr(H|ς) = 0.05.
  EXPECT_NEAR(u->histogram_at({65, 60}), bayes_to_histogram(0.05), 1e-4);
  EXPECT_LT(u->histogram_at({65, 60}), 0.0f);
  // Beyond r + tolerance (1.2 m > 1.1 m) and outside the cone (35° off axis): untouched.
  EXPECT_FLOAT_EQ(u->histogram_at({72, 60}), 0.0f);
  EXPECT_FLOAT_EQ(u->histogram_at({68, 65}), 0.0f);
}

TEST(BayesUpdater, OffAxisCellMatchesEq29) {
  auto u = make_grid_updater(GridKind::kBayes, {}, single_forward_sonar());
  u->reset({0.0, 0.0});
  ASSERT_TRUE(u->integrate(kRobot, echo(0, 1.0)));
  // Cell (70, 62): centre (1.05, 0.25), offset (1.0, 0.2) from the transducer.
  const double d = std::hypot(1.0, 0.2), alpha = std::atan2(0.2, 1.0);
  const double w = ((5.0 - d) / 5.0 + (kPi / 12 - alpha) / (kPi / 12)) / 2.0;
  const double p = w * 0.98;  // Eq. 2.9 with prior 0.5
  EXPECT_NEAR(u->histogram_at({70, 62}), bayes_to_histogram(p), 1e-4);
  ASSERT_TRUE(u->integrate(kRobot, echo(0, 1.0)));
  const double p2 = p * p / (p * p + (1 - p) * (1 - p));
  EXPECT_NEAR(u->histogram_at({70, 62}), bayes_to_histogram(p2), 1e-4);
}

TEST(BayesUpdater, RepeatedHitsConvergeHighAndCanRecover) {
  auto u = make_grid_updater(GridKind::kBayes, {}, single_forward_sonar());
  u->reset({0.0, 0.0});
  for (int i = 0; i < 30; ++i) ASSERT_TRUE(u->integrate(kRobot, echo(0, 1.0)));
  EXPECT_NEAR(u->histogram_at({70, 60}), bayes_to_histogram(kMaxProbability), 1e-4);
  EXPECT_NEAR(u->histogram_at({65, 60}), bayes_to_histogram(kMinProbability), 1e-4);
  // The obstacle goes away: the beam now reaches 2 m and passes through (70, 60).
  for (int i = 0; i < 30; ++i) ASSERT_TRUE(u->integrate(kRobot, echo(0, 2.0)));
  EXPECT_LT(u->histogram_at({70, 60}), 0.0f);
}

TEST(BayesUpdater, NoEchoOnlyLowers) {
  auto u = make_grid_updater(GridKind::kBayes, {}, single_forward_sonar());
  u->reset({0.0, 0.0});
  ASSERT_TRUE(u->integrate(kRobot, {0, 5.0, false, 0.0}));
  const HistogramGrid h = u->histogram();
  for (std::size_t i = 0; i < h.geometry().cell_count(); ++i) ASSERT_LE(h.data()[i], 0.0f);
  EXPECT_LT(u->histogram_at({70, 60}), 0.0f);
}

TEST(BayesUpdater, PathCellsReportMinus100) {
  auto u = make_grid_updater(GridKind::kBayes, {}, single_forward_sonar());
  u->reset({0.0, 0.0});
  u->mark_robot({0.55, 0.05, 0.0});
  ASSERT_TRUE(u->integrate(kRobot, echo(0, 1.0)));
  EXPECT_FLOAT_EQ(u->histogram_at({65, 60}), kRobotPathValue);
  EXPECT_FLOAT_EQ(u->histogram().get({65, 60}), kRobotPathValue);
}

}  // namespace
}  // namespace cogmap::mapper
