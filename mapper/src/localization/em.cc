// Fig. A.6: EM for a two-component Gaussian mixture over wall directions (Eqs. 3.13-3.14,
// 3.19-3.21), with per-sample weights and an optional uniform clutter component.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "cogmap/mapper/localization/em.h"

namespace cogmap::mapper {
namespace {

constexpr double kLogSqrt2Pi = 0.91893853320467274178;  // log √(2π)
constexpr double kNegInf = -std::numeric_limits<double>::infinity();

/// The per-iteration constants of the E-step: log π_k and log σ_k of both Gaussians and the
/// clutter term, computed once per mixture instead of once per sample (the same doubles).
struct LogTerms {
  double log_pi_s, log_sigma_s, log_pi_m, log_sigma_m, clutter;
  bool has_s, has_m;

  LogTerms(const GaussianMixture2& g, double log_clutter_density)
      : log_pi_s(g.pi_s <= 0.0 ? 0.0 : std::log(g.pi_s)),
        log_sigma_s(std::log(g.sigma_s)),
        log_pi_m(g.pi_m <= 0.0 ? 0.0 : std::log(g.pi_m)),
        log_sigma_m(std::log(g.sigma_m)),
        clutter(g.pi_clutter > 0.0 ? std::log(g.pi_clutter) + log_clutter_density : kNegInf),
        has_s(!(g.pi_s <= 0.0)),
        has_m(!(g.pi_m <= 0.0)) {}
};

/// log(π_k p(x | μ_k, σ_k²)) with Eq. 3.16 as the density (the appendix's "√(2πσ)" is a typo
/// for √(2π) σ, which Eq. 3.16 prints correctly).
double log_weighted_gauss(double x, bool has, double log_pi, double mu, double sigma,
                          double log_sigma) {
  if (!has) return kNegInf;
  const double z = (x - mu) / sigma;
  return log_pi - 0.5 * z * z - log_sigma - kLogSqrt2Pi;
}

/// exp(d) for d = log_term − top ≤ 0: exactly 1 at the top and 0 for an absent component, which
/// is what std::exp returns there; only the other terms need the call.
double exp_offset(double d) {
  if (d == 0.0) return 1.0;
  if (d == kNegInf) return 0.0;
  return std::exp(d);
}

/// E-step for one sample (Eq. 3.14): responsibilities ⟨q^s⟩, ⟨q^m⟩, ⟨q^clutter⟩ and, when
/// asked for, log p(x). Computed in the log domain so far samples do not underflow to 0/0.
struct Responsibility {
  std::array<double, 3> q{0.0, 0.0, 0.0};
  double log_p = 0.0;
};

Responsibility e_step(double x, EmSource source, const GaussianMixture2& g, const LogTerms& t,
                      bool with_log_p) {
  const std::array<double, 3> log_terms{
      source == EmSource::kM
          ? kNegInf
          : log_weighted_gauss(x, t.has_s, t.log_pi_s, g.mu_s, g.sigma_s, t.log_sigma_s),
      source == EmSource::kS
          ? kNegInf
          : log_weighted_gauss(x, t.has_m, t.log_pi_m, g.mu_m, g.sigma_m, t.log_sigma_m),
      t.clutter};
  const double top = *std::max_element(log_terms.begin(), log_terms.end());
  Responsibility r;
  if (top == kNegInf) return r;  // every component has zero weight: no information
  double sum = 0.0;
  for (int k = 0; k < 3; ++k) {
    r.q[k] = exp_offset(log_terms[k] - top);
    sum += r.q[k];
  }
  for (double& q : r.q) q /= sum;
  if (with_log_p) r.log_p = top + std::log(sum);
  return r;
}

EmSource source_of(std::span<const EmSource> sources, std::size_t i) {
  return sources.empty() ? EmSource::kUnknown : sources[i];
}

double log_likelihood(std::span<const double> x, std::span<const double> w,
                      std::span<const EmSource> sources, const GaussianMixture2& g,
                      double log_clutter_density) {
  double ll = 0.0;
  const LogTerms t(g, log_clutter_density);
  for (std::size_t i = 0; i < x.size(); ++i) {
    ll += (w.empty() ? 1.0 : w[i]) * e_step(x[i], source_of(sources, i), g, t, true).log_p;
  }
  return ll;
}

}  // namespace

EmResult expectation_maximization(std::span<const double> samples, std::span<const double> weights,
                                  const GaussianMixture2& initial, const EmOptions& options) {
  return expectation_maximization(samples, weights, {}, initial, options);
}

EmResult expectation_maximization(std::span<const double> samples, std::span<const double> weights,
                                  std::span<const EmSource> sources,
                                  const GaussianMixture2& initial, const EmOptions& options) {
  return expectation_maximization(samples, weights, sources, {}, initial, options);
}

EmResult expectation_maximization(std::span<const double> samples, std::span<const double> weights,
                                  std::span<const EmSource> sources,
                                  std::span<const double> spreads_rad2,
                                  const GaussianMixture2& initial, const EmOptions& options) {
  EmResult result;
  GaussianMixture2 g = initial;
  const bool clutter = options.clutter_range_rad > 0.0;
  if (!clutter) g.pi_clutter = 0.0;
  const double log_clutter_density = clutter ? -std::log(options.clutter_range_rad) : kNegInf;
  g.sigma_s = std::max(g.sigma_s, options.min_sigma_rad);
  g.sigma_m = std::max(g.sigma_m, options.min_sigma_rad);
  // Mixing weights must sum to one (the Lagrange constraint of Eq. 3.18).
  const double pi_sum = g.pi_s + g.pi_m + g.pi_clutter;
  if (pi_sum > 0.0) {
    g.pi_s /= pi_sum;
    g.pi_m /= pi_sum;
    g.pi_clutter /= pi_sum;
  }

  double total_w = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) total_w += weights.empty() ? 1.0 : weights[i];
  if (samples.empty() || total_w <= 0.0) {
    result.mixture = g;
    result.converged = true;
    return result;
  }

  std::vector<std::array<double, 3>> q(samples.size());
  for (int it = 0; it < options.max_iterations; ++it) {
    // E-step (Eq. 3.14) and the sums the M-step needs (Σ w⟨q⟩, Σ w⟨q⟩x), in one pass.
    std::array<double, 3> sum_q{0.0, 0.0, 0.0};
    std::array<double, 2> sum_qx{0.0, 0.0};
    const LogTerms t(g, log_clutter_density);
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const double w = weights.empty() ? 1.0 : weights[i];
      q[i] = e_step(samples[i], source_of(sources, i), g, t, false).q;
      for (int k = 0; k < 3; ++k) sum_q[k] += w * q[i][k];
      sum_qx[0] += w * q[i][0] * samples[i];
      sum_qx[1] += w * q[i][1] * samples[i];
    }
    // M-step: Eq. 3.19 (π̂), Eq. 3.20 (μ̂), then Eq. 3.21 (σ̂²) about the new μ̂ of the same
    // component (Fig. A.6 prints μ̂_s for σ̂_m², a slip).
    GaussianMixture2 next = g;
    const std::array<double*, 2> mu{&next.mu_s, &next.mu_m};
    for (int k = 0; k < 2; ++k) {
      if (sum_q[k] > 0.0) *mu[k] = sum_qx[k] / sum_q[k];  // an empty component keeps its μ
    }
    std::array<double, 2> sum_sq{0.0, 0.0};
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const double w = weights.empty() ? 1.0 : weights[i];
      for (int k = 0; k < 2; ++k) {
        const double d = samples[i] - *mu[k];
        if (spreads_rad2.empty()) {
          sum_sq[k] += w * q[i][k] * d * d;
        } else {
          sum_sq[k] += w * q[i][k] * (d * d + spreads_rad2[i]);
        }
      }
    }
    next.pi_s = sum_q[0] / total_w;
    next.pi_m = sum_q[1] / total_w;
    next.pi_clutter = clutter ? sum_q[2] / total_w : 0.0;
    if (sum_q[0] > 0.0) next.sigma_s = std::sqrt(sum_sq[0] / sum_q[0]);
    if (sum_q[1] > 0.0) next.sigma_m = std::sqrt(sum_sq[1] / sum_q[1]);
    next.sigma_s = std::max(next.sigma_s, options.min_sigma_rad);
    next.sigma_m = std::max(next.sigma_m, options.min_sigma_rad);

    const double error = std::abs(next.mu_s - g.mu_s) + std::abs(next.mu_m - g.mu_m);
    g = next;
    result.iterations = it + 1;
    if (error < options.tolerance_rad) {
      result.converged = true;
      break;
    }
  }
  result.mixture = g;
  result.log_likelihood = log_likelihood(samples, weights, sources, g, log_clutter_density);
  return result;
}

}  // namespace cogmap::mapper
