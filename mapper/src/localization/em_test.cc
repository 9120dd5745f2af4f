#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "cogmap/mapper/localization/em.h"
#include "cogmap/test_support/angles.h"

namespace cogmap::mapper {
namespace {

struct Draw {
  std::vector<double> x;
  void gauss(std::mt19937_64& rng, int n, double mu, double sigma) {
    std::normal_distribution<double> d(mu, sigma);
    for (int i = 0; i < n; ++i) x.push_back(d(rng));
  }
};

TEST(Em, RecoversMeansSigmasAndWeightsOfASyntheticMixture) {
  std::mt19937_64 rng(42);
  Draw data;
  data.gauss(rng, 3000, -0.10, 0.02);
  data.gauss(rng, 7000, 0.15, 0.03);
  GaussianMixture2 init;
  init.mu_s = -0.05;
  init.mu_m = 0.10;
  const EmResult r = expectation_maximization(data.x, {}, init, EmOptions{});
  EXPECT_TRUE(r.converged);
  EXPECT_NEAR(r.mixture.mu_s, -0.10, 0.002);
  EXPECT_NEAR(r.mixture.mu_m, 0.15, 0.002);
  EXPECT_NEAR(r.mixture.sigma_s, 0.02, 0.002);
  EXPECT_NEAR(r.mixture.sigma_m, 0.03, 0.002);
  EXPECT_NEAR(r.mixture.pi_s, 0.3, 0.02);
  EXPECT_NEAR(r.mixture.pi_m, 0.7, 0.02);
  EXPECT_NEAR(r.mixture.pi_s + r.mixture.pi_m, 1.0, 1e-12);
}

TEST(Em, ExactTwoPointClustersGiveExactMeans) {
  // Two tight, far apart clusters: responsibilities are 0/1 to machine precision, so the
  // M-step (Eqs. 3.19-3.21) gives the plain cluster statistics.
  const std::vector<double> x{-1.0, -0.9, -1.1, 2.0, 2.2};
  GaussianMixture2 init;
  init.mu_s = -0.5;
  init.mu_m = 1.5;
  init.sigma_s = init.sigma_m = 0.3;
  const EmResult r = expectation_maximization(x, {}, init, EmOptions{});
  EXPECT_NEAR(r.mixture.mu_s, -1.0, 1e-12);
  EXPECT_NEAR(r.mixture.mu_m, 2.1, 1e-12);
  EXPECT_NEAR(r.mixture.pi_s, 0.6, 1e-12);
  EXPECT_NEAR(r.mixture.sigma_s, std::sqrt(0.02 / 3.0), 1e-12);
  EXPECT_NEAR(r.mixture.sigma_m, 0.1, 1e-12);
}

TEST(Em, PooledSamplesWithTheirSpreadFitLikeTheirMembers) {
  // One labelled component, no clutter: every responsibility is 1, so the fit is the weighted
  // mean and variance, which a pooled sample (members' mean, summed weight, their spread) keeps.
  const std::vector<double> members{0.010, 0.014, 0.020, -0.030, -0.026};
  const std::vector<double> member_w{1.0, 2.0, 1.0, 3.0, 1.0};
  const std::vector<EmSource> member_src(members.size(), EmSource::kM);
  const std::vector<double> pooled{(0.010 + 2 * 0.014 + 0.020) / 4.0, (-3 * 0.030 - 0.026) / 4.0};
  const std::vector<double> pooled_w{4.0, 4.0};
  auto spread = [](std::vector<double> x, std::vector<double> w, double mean) {
    double sum = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) sum += w[i] * (x[i] - mean) * (x[i] - mean);
    return sum / 4.0;
  };
  const std::vector<double> pooled_spread{spread({0.010, 0.014, 0.020}, {1, 2, 1}, pooled[0]),
                                          spread({-0.030, -0.026}, {3, 1}, pooled[1])};
  const std::vector<EmSource> pooled_src(2, EmSource::kM);
  GaussianMixture2 init;
  init.pi_s = 0.0;
  init.pi_m = 1.0;
  init.mu_m = 0.05;
  const EmResult a = expectation_maximization(members, member_w, member_src, init, EmOptions{});
  const EmResult b =
      expectation_maximization(pooled, pooled_w, pooled_src, pooled_spread, init, EmOptions{});
  EXPECT_NEAR(b.mixture.mu_m, a.mixture.mu_m, 1e-15);
  EXPECT_NEAR(b.mixture.sigma_m, a.mixture.sigma_m, 1e-15);
  EXPECT_NEAR(a.mixture.mu_m, -0.00725, 1e-15);
  EXPECT_NEAR(a.mixture.sigma_m, 0.0219303, 1e-7);  // √(Σ w (x − μ)² / Σ w)
  // Without the spread the pooled fit is too narrow: the spread is what keeps σ.
  const EmResult c = expectation_maximization(pooled, pooled_w, pooled_src, init, EmOptions{});
  EXPECT_LT(c.mixture.sigma_m, a.mixture.sigma_m - 1e-4);
}

TEST(Em, IntegerWeightsEqualRepeatedSamples) {
  const std::vector<double> x{0.0, 0.1, 0.5, 0.55, 0.7};
  const std::vector<double> w{2.0, 1.0, 3.0, 1.0, 1.0};
  std::vector<double> repeated;
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (int k = 0; k < static_cast<int>(w[i]); ++k) repeated.push_back(x[i]);
  }
  GaussianMixture2 init;
  init.mu_s = 0.05;
  init.mu_m = 0.6;
  const EmResult a = expectation_maximization(x, w, init, EmOptions{});
  const EmResult b = expectation_maximization(repeated, {}, init, EmOptions{});
  EXPECT_NEAR(a.mixture.mu_s, b.mixture.mu_s, 1e-12);
  EXPECT_NEAR(a.mixture.mu_m, b.mixture.mu_m, 1e-12);
  EXPECT_NEAR(a.mixture.sigma_m, b.mixture.sigma_m, 1e-12);
  EXPECT_NEAR(a.mixture.pi_s, b.mixture.pi_s, 1e-12);
  EXPECT_NEAR(a.log_likelihood, b.log_likelihood, 1e-9);
}

TEST(Em, LogLikelihoodNeverDecreases) {
  std::mt19937_64 rng(7);
  Draw data;
  data.gauss(rng, 200, 0.0, 0.05);
  data.gauss(rng, 100, 0.12, 0.02);
  GaussianMixture2 init;
  init.mu_s = -0.05;
  init.mu_m = 0.05;
  double previous = -std::numeric_limits<double>::infinity();
  for (int n = 1; n <= 30; ++n) {
    EmOptions o;
    o.max_iterations = n;
    const EmResult r = expectation_maximization(data.x, {}, init, o);
    EXPECT_GE(r.log_likelihood, previous - 1e-9) << "iteration " << n;
    previous = r.log_likelihood;
  }
}

TEST(Em, VarianceFloorKeepsIdenticalSamplesFinite) {
  const std::vector<double> x(10, 0.25);
  EmOptions o;
  o.min_sigma_rad = 1e-3;
  const EmResult r = expectation_maximization(x, {}, GaussianMixture2{}, o);
  EXPECT_TRUE(r.converged);
  EXPECT_DOUBLE_EQ(r.mixture.mu_s, 0.25);
  EXPECT_DOUBLE_EQ(r.mixture.mu_m, 0.25);
  EXPECT_DOUBLE_EQ(r.mixture.sigma_s, 1e-3);
  EXPECT_TRUE(std::isfinite(r.log_likelihood));
}

TEST(Em, ClutterComponentResistsUniformOutliers) {
  std::mt19937_64 rng(11);
  Draw data;
  data.gauss(rng, 400, 2.0 * kDeg, 1.0 * kDeg);
  data.gauss(rng, 400, 9.0 * kDeg, 1.0 * kDeg);
  std::uniform_real_distribution<double> uniform(-45.0 * kDeg, 45.0 * kDeg);
  for (int i = 0; i < 200; ++i) data.x.push_back(uniform(rng));
  GaussianMixture2 init;
  init.mu_s = 3.0 * kDeg;
  init.mu_m = 8.0 * kDeg;
  init.sigma_s = init.sigma_m = 1.0 * kDeg;
  init.pi_clutter = 0.1;
  EmOptions with_clutter;
  with_clutter.clutter_range_rad = 90.0 * kDeg;
  const EmResult robust = expectation_maximization(data.x, {}, init, with_clutter);
  EXPECT_NEAR(robust.mixture.mu_s, 2.0 * kDeg, 0.2 * kDeg);
  EXPECT_NEAR(robust.mixture.mu_m, 9.0 * kDeg, 0.2 * kDeg);
  EXPECT_NEAR(robust.mixture.pi_clutter, 0.2, 0.05);
  // The pure two-component mixture must explain the outliers with its Gaussians: it is pulled.
  const EmResult pure = expectation_maximization(data.x, {}, init, EmOptions{});
  EXPECT_EQ(pure.mixture.pi_clutter, 0.0);
  EXPECT_GT(pure.mixture.sigma_s + pure.mixture.sigma_m, 5.0 * kDeg);
}

TEST(Em, EmptyInputReturnsTheInitialMixture) {
  GaussianMixture2 init;
  init.mu_s = 0.1;
  const EmResult r = expectation_maximization({}, {}, init, EmOptions{});
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_DOUBLE_EQ(r.mixture.mu_s, 0.1);
}

}  // namespace
}  // namespace cogmap::mapper
