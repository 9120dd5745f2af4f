// §3.1.9: the heading drift of a new ASR from the directions of its walls against those of the
// rooms before it, through the two-component mixture of Fig. A.6.

#include "cogmap/mapper/localization/localizer.h"

#include "cogmap/mapper/localization/direction_bins.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

namespace cogmap::mapper {
namespace {

double total_length_m(std::span<const LineDirection> directions) {
  double sum = 0.0;
  for (const LineDirection& d : directions) sum += d.length_m;
  return sum;
}

double gauss(double x, double mu, double sigma) {
  const double z = (x - mu) / sigma;
  return std::exp(-0.5 * z * z) / sigma;  // the common 1/√(2π) cancels against clutter below
}

/// Variance of the weighted mean μ_k: σ_k² / n_k, with n_k = (Σ q w)² / Σ (q w)² the Kish
/// effective number of samples EM gave to component k (q = responsibility of k, w = weight).
/// A pooled sample (a bin) counts its members: `weight_sq[i]` is Σ w_j² over them (empty: w_i²).
double mean_variance(std::span<const double> x, std::span<const double> w,
                     std::span<const double> weight_sq, std::span<const EmSource> sources,
                     EmSource own, const GaussianMixture2& g, double clutter_range_rad,
                     double min_sigma_rad) {
  const bool is_s = own == EmSource::kS;
  const double pi = is_s ? g.pi_s : g.pi_m, mu = is_s ? g.mu_s : g.mu_m;
  const double sigma_fit = is_s ? g.sigma_s : g.sigma_m;
  const double sigma = std::max(sigma_fit, min_sigma_rad);
  constexpr double kSqrt2Pi = 2.5066282746310002;
  const double clutter =
      clutter_range_rad > 0.0 ? g.pi_clutter * kSqrt2Pi / clutter_range_rad : 0.0;
  double sum = 0.0, sum_sq = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (sources[i] != own) continue;
    const double p = pi * gauss(x[i], mu, sigma_fit);
    const double q = p + clutter > 0.0 ? p / (p + clutter) : 0.0;
    sum += q * w[i];
    sum_sq += weight_sq.empty() ? (q * w[i]) * (q * w[i]) : q * q * weight_sq[i];
  }
  if (sum <= 0.0) return std::numeric_limits<double>::infinity();
  return sigma * sigma * sum_sq / (sum * sum);
}

}  // namespace

double path_length_m(std::span<const Point2> path) {
  double sum = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) sum += (path[i] - path[i - 1]).norm();
  return sum;
}

double path_rotation_rad(std::span<const Point2> path, double start_heading_rad,
                         std::optional<double> end_heading_rad, double chord_m) {
  double heading = start_heading_rad, turned = 0.0;
  std::size_t from = 0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const Point2 chord = path[i] - path[from];
    if (chord.norm() < chord_m) continue;
    const double next = std::atan2(chord.y(), chord.x());
    turned += std::abs(std::remainder(next - heading, 2.0 * std::numbers::pi));
    heading = next;
    from = i;
  }
  if (end_heading_rad) {
    turned += std::abs(std::remainder(*end_heading_rad - heading, 2.0 * std::numbers::pi));
  }
  return turned;
}

double heading_drift_sigma_rad(const HeadingDriftModel& model, double rotation_rad,
                               double distance_m) {
  const double turn = model.per_rad_turned * std::abs(rotation_rad);
  return std::sqrt(model.floor_rad * model.floor_rad + turn * turn +
                   model.rad_per_sqrt_m * model.rad_per_sqrt_m * std::max(distance_m, 0.0));
}

Localization Localizer::estimate(std::span<const Polyline> reference_world,
                                 std::span<const Polyline> current_world) const {
  return estimate(reference_world, current_world, RotationPrior{});
}

Localization Localizer::estimate(std::span<const Polyline> reference_world,
                                 std::span<const Polyline> current_world,
                                 const RotationPrior& prior) const {
  Localization out;
  out.prior_sigma_rad = prior.sigma_rad;
  // s: the new room's walls; m: the reference rooms' walls (the thesis's m is "the centre point
  // of the exit locations"; see docs for why we use the reference walls instead).
  const std::vector<LineDirection> s = line_directions(current_world);
  const std::vector<LineDirection> m_lines = line_directions(reference_world);
  const double length_s_m = total_length_m(s), length_m_m = total_length_m(m_lines);
  for (const LineDirection& d : s) out.longest_wall_m = std::max(out.longest_wall_m, d.length_m);
  if (length_s_m < options_.min_wall_length_m || length_m_m < options_.min_wall_length_m) {
    return out;
  }

  // The reference pooled in bins (options_.reference_bin_rad; 0 keeps every direction): EM's
  // work then stops growing with the number of reference rooms. Unweighted, a bin weighs its
  // count.
  const bool binned = options_.reference_bin_rad > 0.0;
  BinnedDirections m_bins;
  if (binned) {
    std::vector<LineDirection> pooled = m_lines;
    if (!options_.weight_by_length) {
      for (LineDirection& d : pooled) d.length_m = 1.0;
    }
    m_bins = bin_directions(pooled, options_.reference_bin_rad);
  }
  const std::vector<LineDirection>& m = binned ? m_bins.directions : m_lines;

  // Robust initialisation: each component starts at its own set's dominant direction.
  const double mode_s = dominant_direction_rad(s, options_.dominant);
  const double mode_m = dominant_direction_rad(m, options_.dominant);
  out.reference_direction_rad = mode_m;
  out.current_direction_rad = mode_s;

  // Directions live on a circle of circumference 90°. Centring every sample on the reference
  // direction puts the interesting part of the data far from the ±45° seam, where the plain
  // real-valued Gaussians of Eq. 3.16 are valid.
  std::vector<double> samples, weights;
  std::vector<EmSource> sources;
  samples.reserve(s.size() + m.size());
  weights.reserve(s.size() + m.size());
  sources.reserve(s.size() + m.size());
  for (const auto& [set, source] : {std::pair{&s, EmSource::kS}, std::pair{&m, EmSource::kM}}) {
    for (const LineDirection& d : *set) {
      samples.push_back(fold_direction_rad(d.angle_rad - mode_m));
      weights.push_back(options_.weight_by_length || (source == EmSource::kM && binned) ? d.length_m
                                                                                        : 1.0);
      // The source of every direction is known, so each sample is explained by its own
      // component (or clutter); pooled unlabelled, two overlapping Gaussians are not identifiable.
      sources.push_back(options_.label_sources ? source : EmSource::kUnknown);
    }
  }

  GaussianMixture2 initial;
  const double clutter = std::clamp(options_.clutter_weight, 0.0, 0.9);
  const double share_s =
      options_.weight_by_length
          ? length_s_m / (length_s_m + length_m_m)
          : static_cast<double>(s.size()) / static_cast<double>(s.size() + m_lines.size());
  initial.pi_s = (1.0 - clutter) * share_s;
  initial.pi_m = (1.0 - clutter) * (1.0 - share_s);
  initial.pi_clutter = clutter;
  initial.mu_s = fold_direction_rad(mode_s - mode_m);
  initial.mu_m = 0.0;
  const double window = options_.dominant.window_rad;
  initial.sigma_s =
      std::max(direction_spread_rad(s, mode_s, window), options_.min_initial_sigma_rad);
  initial.sigma_m =
      std::max(direction_spread_rad(m, mode_m, window), options_.min_initial_sigma_rad);

  EmOptions em_options = options_.em;
  em_options.clutter_range_rad = clutter > 0.0 ? kQuarterTurnRad : 0.0;  // folded data span 90°
  // A bin's members spread about its mean; the s samples are single directions.
  std::vector<double> spreads, weight_sq;
  if (binned) {
    spreads.assign(s.size(), 0.0);
    spreads.insert(spreads.end(), m_bins.spread_rad2.begin(), m_bins.spread_rad2.end());
    for (std::size_t i = 0; i < s.size(); ++i) weight_sq.push_back(weights[i] * weights[i]);
    weight_sq.insert(weight_sq.end(), m_bins.length_sq.begin(), m_bins.length_sq.end());
  }
  out.em = expectation_maximization(samples, weights, sources, spreads, initial, em_options);

  // Undo the centring, and turn the new room's direction onto the reference's.
  out.reference_direction_rad = fold_direction_rad(out.em.mixture.mu_m + mode_m);
  out.current_direction_rad = fold_direction_rad(out.em.mixture.mu_s + mode_m);
  out.measured_rotation_rad = fold_direction_rad(out.em.mixture.mu_m - out.em.mixture.mu_s);
  // Which set each sample came from (the EM labels may be off: label_sources = false).
  std::vector<EmSource> own(samples.size(), EmSource::kM);
  std::fill_n(own.begin(), s.size(), EmSource::kS);
  const bool has_prior = std::isfinite(prior.sigma_rad);
  const double var_prior = prior.sigma_rad * prior.sigma_rad;
  double var_em = mean_variance(samples, weights, weight_sq, own, EmSource::kS, out.em.mixture,
                                em_options.clutter_range_rad, options_.min_direction_sigma_rad) +
                  mean_variance(samples, weights, weight_sq, own, EmSource::kM, out.em.mixture,
                                em_options.clutter_range_rad, options_.min_direction_sigma_rad);
  // A room is measured as sharply as its longest wall allows, whatever EM's count of pieces
  // claims (the option's comment). A mixture EM could not bound stays unbounded.
  if (options_.measurement_sd_rad_m > 0.0 && std::isfinite(var_em)) {
    const double sd = options_.measurement_sd_rad_m / out.longest_wall_m;
    var_em = sd * sd;
  }
  const double var_meas = var_em + (has_prior && options_.smear_variance ? var_prior / 3.0 : 0.0);
  out.measurement_sigma_rad = std::sqrt(var_meas);

  // Posterior of the rotation given the odometry prior N(0, prior²) and the EM measurement
  // N(measured, meas²): mean = gain·measured with gain = prior² / (prior² + meas²).
  out.gain = has_prior && options_.prior_shrinks
                 ? (std::isfinite(var_meas) ? var_prior / (var_prior + var_meas) : 0.0)
                 : 1.0;
  out.applied = std::abs(out.measured_rotation_rad) <= options_.max_correction_rad;
  if (has_prior && out.applied) {
    const double innovation_sd = std::sqrt(var_prior + var_meas);
    out.applied = std::abs(out.measured_rotation_rad) <= options_.gate_sigmas * innovation_sd;
  }
  out.rotation_rad = out.applied ? out.gain * out.measured_rotation_rad : 0.0;
  if (!out.applied) out.gain = 0.0;
  return out;
}

}  // namespace cogmap::mapper
